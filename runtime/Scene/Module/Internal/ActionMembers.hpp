// ros2vtk — where the members rosidl synthesizes for every action (goal_id, goal, accepted,
// stamp, status, result, feedback) sit in one action's generated types. The action client and
// server nodes reach them through these offsets, checked once against the type's field table,
// so neither names a per-action type.
#ifndef ros2vtk_scene_ActionMembers_hpp
#define ros2vtk_scene_ActionMembers_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/QoS.hpp"

#include <cstddef>
#include <string>

namespace ros2vtk {
namespace wire {
class Participant;
}
namespace scene {

struct ActionMembers
{
  size_t SendGoalId = 0, SendGoalGoal = 0;     // X_SendGoal_Request
  size_t Accepted = 0, AcceptedStamp = 0;      // X_SendGoal_Response
  size_t GetResultId = 0;                      // X_GetResult_Request
  size_t ResultStatus = 0, ResultResult = 0;   // X_GetResult_Response
  size_t FeedbackId = 0, FeedbackFeedback = 0; // X_FeedbackMessage
};

/// Fills `members` from `type`'s tables; false with `error` when a table does not have the
/// members of rosidl's action synthesis, or does not use the action_msgs,
/// unique_identifier_msgs and builtin_interfaces types of ros2vtk::Messages.
bool find_action_members(
  const wire::ActionTypeSupport& type, ActionMembers& members, std::string* error);

/// What an action client and its server agree on before creating their endpoints: the action's
/// generated tables, its resolved name, where the synthesized members sit, and rcl_action's
/// endpoint names and QoS (docs/wire-notes.md §8.1), kept here once so the two sides cannot drift.
struct ActionEndpoints
{
  const wire::ActionTypeSupport* Type = nullptr;
  std::string ResolvedName;
  ActionMembers At;
  std::string SendGoal, GetResult, CancelGoal, Feedback, Status; // <resolved>/_action/<endpoint>
  wire::QoS ServiceQoS = wire::QoS::services();
  wire::QoS FeedbackQoS = wire::QoS::default_profile();
  wire::QoS StatusQoS = wire::QoS::transient_local(1);
};

/// Finds the action type `type` ("pkg/action/X" or "pkg/X"), resolves `action` on
/// `participant` and fills `endpoints`; false with `error`.
bool find_action_endpoints(const wire::Participant& participant, const std::string& type,
  const std::string& action, ActionEndpoints& endpoints, std::string* error);

/// The member at `offset` of a message struct.
template<typename T>
T& member(void* message, size_t offset)
{
  return *reinterpret_cast<T*>(static_cast<char*>(message) + offset);
}

template<typename T>
const T& member(const void* message, size_t offset)
{
  return *reinterpret_cast<const T*>(static_cast<const char*>(message) + offset);
}

} // namespace scene
} // namespace ros2vtk

#endif
