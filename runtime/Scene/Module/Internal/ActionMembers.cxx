// ros2vtk — find_action_members: the synthesized members of an action's types, checked;
// find_action_endpoints: what an action client and server share before they create endpoints.
#include "ActionMembers.hpp"

#include "ros2vtk/wire/Participant.hpp"

#include "ros2vtk/action_msgs/msg/goal_status_array.hpp"
#include "ros2vtk/action_msgs/srv/cancel_goal.hpp"
#include "ros2vtk/builtin_interfaces/msg/time.hpp"
#include "ros2vtk/unique_identifier_msgs/msg/uuid.hpp"

namespace ros2vtk {
namespace scene {
namespace {

using wire::FieldType;
using wire::MessageTypeSupport;

bool offset_of(const MessageTypeSupport& type, const char* name, FieldType fieldType,
  const MessageTypeSupport* nested, size_t& offset, std::string* error)
{
  for (uint32_t i = 0; i < type.field_count; ++i)
  {
    const wire::FieldInfo& field = type.fields[i];
    if (std::string(field.name) != name)
    {
      continue;
    }
    if (field.type != fieldType || field.container != wire::Container::None ||
      (nested && (!field.nested || field.nested() != nested)))
    {
      break;
    }
    offset = field.offset;
    return true;
  }
  *error = std::string(type.ros_type) + " has no member '" + name + "' of type " +
    (nested ? nested->ros_type : wire::field_type_name(fieldType)) +
    " (not an action type as rosidl synthesizes it)";
  return false;
}

} // namespace

bool find_action_members(const wire::ActionTypeSupport& type, ActionMembers& at, std::string* error)
{
  if (type.cancel_goal() != &action_msgs::srv::CancelGoal::type_support() ||
    type.status() != &action_msgs::msg::GoalStatusArray::type_support())
  {
    *error =
      std::string("the table of ") + type.ros_type + " does not use ros2vtk's action_msgs types";
    return false;
  }
  const MessageTypeSupport* uuid = &unique_identifier_msgs::msg::UUID::type_support();
  const MessageTypeSupport* time = &builtin_interfaces::msg::Time::type_support();
  const wire::ServiceTypeSupport& sendGoal = *type.send_goal();
  const wire::ServiceTypeSupport& getResult = *type.get_result();
  const MessageTypeSupport& feedback = *type.feedback_message();
  return offset_of(
           *sendGoal.request(), "goal_id", FieldType::Message, uuid, at.SendGoalId, error) &&
    offset_of(
      *sendGoal.request(), "goal", FieldType::Message, type.goal(), at.SendGoalGoal, error) &&
    offset_of(*sendGoal.response(), "accepted", FieldType::Bool, nullptr, at.Accepted, error) &&
    offset_of(*sendGoal.response(), "stamp", FieldType::Message, time, at.AcceptedStamp, error) &&
    offset_of(*getResult.request(), "goal_id", FieldType::Message, uuid, at.GetResultId, error) &&
    offset_of(*getResult.response(), "status", FieldType::Int8, nullptr, at.ResultStatus, error) &&
    offset_of(
      *getResult.response(), "result", FieldType::Message, type.result(), at.ResultResult, error) &&
    offset_of(feedback, "goal_id", FieldType::Message, uuid, at.FeedbackId, error) &&
    offset_of(
      feedback, "feedback", FieldType::Message, type.feedback(), at.FeedbackFeedback, error);
}

bool find_action_endpoints(const wire::Participant& participant, const std::string& type,
  const std::string& action, ActionEndpoints& endpoints, std::string* error)
{
  ActionEndpoints found;
  found.Type = wire::find_action_type(type, error);
  if (!found.Type || !participant.resolve_name(action, found.ResolvedName, error) ||
    !find_action_members(*found.Type, found.At, error))
  {
    return false;
  }
  const std::string prefix = found.ResolvedName + "/_action/";
  found.SendGoal = prefix + "send_goal";
  found.GetResult = prefix + "get_result";
  found.CancelGoal = prefix + "cancel_goal";
  found.Feedback = prefix + "feedback";
  found.Status = prefix + "status";
  endpoints = std::move(found);
  return true;
}

} // namespace scene
} // namespace ros2vtk
