// ros2vtk — vtkROS2ActionServerNode: goals of any generated action type served over three wire
// service servers and two publishers (rcl_action's endpoints), answered on the ROS node's spin.
// Per-type parts come from the generated wire::ActionTypeSupport table (ActionMembers); only the
// fixed action protocol (action_msgs, unique_identifier_msgs) is named here.
#include "vtkROS2ActionServerNode.h"

#include "Internal/ActionMembers.hpp"
#include "Internal/MessageFields.hpp"
#include "Internal/RateLimitedReport.hpp"
#include "vtkROS2NodeNode.h"

#include "ros2vtk/action_msgs/msg/goal_status.hpp"
#include "ros2vtk/action_msgs/msg/goal_status_array.hpp"
#include "ros2vtk/action_msgs/srv/cancel_goal.hpp"
#include "ros2vtk/builtin_interfaces/msg/time.hpp"
#include "ros2vtk/unique_identifier_msgs/msg/uuid.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Service.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

vtkStandardNewMacro(vtkROS2ActionServerNode);

namespace {
using ros2vtk::scene::member;
using ros2vtk::wire::MessagePtr;
using ros2vtk::wire::MessageTypeSupport;
using GoalStatus = ros2vtk::action_msgs::msg::GoalStatus;
using GoalInfo = ros2vtk::action_msgs::msg::GoalInfo;
using CancelResponse = ros2vtk::action_msgs::srv::CancelGoal_Response;
using Time = ros2vtk::builtin_interfaces::msg::Time;
using UUID = ros2vtk::unique_identifier_msgs::msg::UUID;

MessagePtr NewMessage(const MessageTypeSupport& type)
{
  return MessagePtr(&type, type.create());
}

Time ToTime(int64_t nanoseconds)
{
  Time time;
  time.sec = static_cast<int32_t>(nanoseconds / 1000000000);
  time.nanosec = static_cast<uint32_t>(nanoseconds % 1000000000);
  return time;
}

bool IsZero(const UUID& id)
{
  return std::all_of(id.uuid.begin(), id.uuid.end(), [](uint8_t b) { return b == 0; });
}

int64_t Nanoseconds(const Time& time)
{
  return static_cast<int64_t>(time.sec) * 1000000000 + time.nanosec;
}
}

// rclpy's ActionServer(result_timeout=900), in seconds.
constexpr double kDefaultResultTimeout = 900.0;

//------------------------------------------------------------------------------
class vtkROS2ActionServerNode::vtkInternals
{
public:
  struct Goal
  {
    GoalInfo Info;
    int8_t Status = GoalStatus::STATUS_EXECUTING;
    bool CancelRequested = false;
    MessagePtr Request;     // X_Goal
    MessagePtr Result;      // X_Result once finished
    int64_t FinishedAt = 0; // node time (ns) when it ended: the result timeout runs from there
    std::vector<ros2vtk::wire::RequestId> ResultWaiters;
  };

  const ros2vtk::wire::ActionTypeSupport* Type = nullptr;
  ros2vtk::scene::ActionMembers At;
  vtkROS2NodeNode* ROSNode = nullptr;
  std::unique_ptr<ros2vtk::wire::ServiceServer> SendGoalServer;
  std::unique_ptr<ros2vtk::wire::ServiceServer> GetResultServer;
  std::unique_ptr<ros2vtk::wire::ServiceServer> CancelServer;
  std::unique_ptr<ros2vtk::wire::Publisher> FeedbackPublisher;
  std::unique_ptr<ros2vtk::wire::Publisher> StatusPublisher;
  // The action type (pkg/action/X) in the node's type cache while the endpoints exist, as
  // rcl_action registers it: ~/get_type_description serves it (docs/wire-interop.md).
  ros2vtk::wire::NodeTypeCache::Registration ActionTypeRegistration;
  std::vector<Goal> Goals;
  const void* Deciding = nullptr; // X_Goal under GoalReceivedEvent
  bool RejectDeciding = false;
  vtkTypeInt64 Received = 0, Accepted = 0, Rejected = 0, Cancels = 0, ResultsSent = 0, Expired = 0;
  double ResultTimeout = kDefaultResultTimeout;
  // Malformed requests (rejected by the wire servers): counted, and reported as a warning at
  // most every 5 s.
  uint64_t MalformedSeen = 0;
  vtkTypeInt64 Malformed = 0;
  ros2vtk::scene::RateLimitedReport MalformedReport{ std::chrono::seconds(5) };

  Goal* Current()
  {
    auto it = std::find_if(this->Goals.begin(), this->Goals.end(), [](const Goal& g) {
      return g.Status == GoalStatus::STATUS_EXECUTING || g.Status == GoalStatus::STATUS_CANCELING;
    });
    return it == this->Goals.end() ? nullptr : &*it;
  }

  Goal* Find(const UUID& id)
  {
    auto it = std::find_if(
      this->Goals.begin(), this->Goals.end(), [&](const Goal& g) { return g.Info.goal_id == id; });
    return it == this->Goals.end() ? nullptr : &*it;
  }

  void PublishStatus()
  {
    ros2vtk::action_msgs::msg::GoalStatusArray array;
    for (const Goal& goal : this->Goals)
    {
      GoalStatus status;
      status.goal_info = goal.Info;
      status.status = goal.Status;
      array.status_list.push_back(status);
    }
    this->StatusPublisher->publish(&array);
  }

  /// The X_GetResult_Response of `goal` (status UNKNOWN and a blank result when null).
  MessagePtr ResultResponse(const Goal* goal) const
  {
    MessagePtr response = NewMessage(*this->Type->get_result()->response());
    member<int8_t>(response.get(), this->At.ResultStatus) =
      goal ? goal->Status : GoalStatus::STATUS_UNKNOWN;
    if (goal && goal->Result)
    {
      this->Type->result()->copy(
        goal->Result.get(), static_cast<char*>(response.get()) + this->At.ResultResult);
    }
    return response;
  }

  void Release()
  {
    this->SendGoalServer.reset();
    this->GetResultServer.reset();
    this->CancelServer.reset();
    this->FeedbackPublisher.reset();
    this->StatusPublisher.reset();
    this->ActionTypeRegistration = ros2vtk::wire::NodeTypeCache::Registration();
    this->ROSNode = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkROS2ActionServerNode::vtkROS2ActionServerNode()
  : vtkROS2EndpointNode("action", nullptr)
  , Internals(new vtkInternals)
{
}

vtkROS2ActionServerNode::~vtkROS2ActionServerNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::Attach(
  vtkROS2NodeNode* rosNode, const std::string& type, const std::string& action)
{
  vtkInternals& internals = *this->Internals;
  if (!rosNode || !rosNode->GetParticipant())
  {
    vtkErrorMacro("action server " << action << ": the ROS node is not created");
    return false;
  }
  ros2vtk::wire::Participant& participant = *rosNode->GetParticipant();
  std::string error;
  ros2vtk::scene::ActionEndpoints endpoints;
  if (!ros2vtk::scene::find_action_endpoints(participant, type, action, endpoints, &error))
  {
    vtkErrorMacro("action server " << action << ": " << error);
    return false;
  }
  const ros2vtk::wire::ActionTypeSupport* support = endpoints.Type;
  auto sendGoal = participant.create_service_server(
    *support->send_goal(), endpoints.SendGoal, endpoints.ServiceQoS, &error);
  auto getResult = sendGoal ? participant.create_service_server(*support->get_result(),
                                endpoints.GetResult, endpoints.ServiceQoS, &error)
                            : nullptr;
  auto cancel = getResult ? participant.create_service_server(*support->cancel_goal(),
                              endpoints.CancelGoal, endpoints.ServiceQoS, &error)
                          : nullptr;
  auto feedback = cancel ? participant.create_publisher(*support->feedback_message(),
                             endpoints.Feedback, endpoints.FeedbackQoS, &error)
                         : nullptr;
  auto status = feedback ? participant.create_publisher(
                             *support->status(), endpoints.Status, endpoints.StatusQoS, &error)
                         : nullptr;
  if (!status)
  {
    vtkErrorMacro("action server " << action << ": " << error);
    return false;
  }
  internals.Type = support;
  internals.At = endpoints.At;
  internals.ROSNode = rosNode;
  internals.SendGoalServer = std::move(sendGoal);
  internals.GetResultServer = std::move(getResult);
  internals.CancelServer = std::move(cancel);
  internals.FeedbackPublisher = std::move(feedback);
  internals.StatusPublisher = std::move(status);
  internals.ActionTypeRegistration =
    participant.type_cache().add(support->type_hash, support->description);
  internals.Goals.clear();
  this->EndpointAttached(rosNode, support->ros_type, action, endpoints.ResolvedName);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ActionServerNode::Detach()
{
  this->Internals->Release();
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::IsEndpointAttached() const
{
  return this->Internals->SendGoalServer != nullptr;
}

//------------------------------------------------------------------------------
int vtkROS2ActionServerNode::ProcessRequests()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.SendGoalServer)
  {
    return 0;
  }
  int handled = 0;
  bool statusChanged = false;
  const ros2vtk::wire::ActionTypeSupport& type = *internals.Type;

  std::vector<ros2vtk::wire::ServiceRequest> requests;
  internals.SendGoalServer->take(requests);
  for (auto& request : requests)
  {
    ++handled;
    ++internals.Received;
    const UUID& id = member<UUID>(request.request.get(), internals.At.SendGoalId);
    const void* goal = static_cast<const char*>(request.request.get()) + internals.At.SendGoalGoal;
    bool accept = !internals.Find(id); // a goal id already tracked is refused (as rclpy)
    if (accept)
    {
      internals.Deciding = goal;
      internals.RejectDeciding = false;
      this->InvokeEvent(GoalReceivedEvent);
      internals.Deciding = nullptr;
      accept = !internals.RejectDeciding;
    }
    const int64_t now = internals.ROSNode ? internals.ROSNode->GetNodeTimeNanoseconds() : 0;
    MessagePtr response = NewMessage(*type.send_goal()->response());
    member<bool>(response.get(), internals.At.Accepted) = accept;
    member<Time>(response.get(), internals.At.AcceptedStamp) = ToTime(now);
    if (accept)
    {
      vtkInternals::Goal tracked;
      tracked.Info.goal_id = id;
      tracked.Info.stamp = ToTime(now);
      tracked.Request = NewMessage(*type.goal());
      type.goal()->copy(goal, tracked.Request.get());
      internals.Goals.push_back(std::move(tracked));
      ++internals.Accepted;
      statusChanged = true;
    }
    else
    {
      ++internals.Rejected;
    }
    internals.SendGoalServer->send_response(request.id, response.get());
  }

  requests.clear();
  internals.GetResultServer->take(requests);
  for (auto& request : requests)
  {
    ++handled;
    vtkInternals::Goal* goal =
      internals.Find(member<UUID>(request.request.get(), internals.At.GetResultId));
    if (goal && !goal->Result)
    {
      goal->ResultWaiters.push_back(request.id); // answered when the goal ends
      continue;
    }
    // Finished, or unknown (status UNKNOWN and a blank result, as rcl_action answers).
    MessagePtr response = internals.ResultResponse(goal);
    internals.GetResultServer->send_response(request.id, response.get());
    internals.ResultsSent += goal ? 1 : 0;
  }

  requests.clear();
  internals.CancelServer->take(requests);
  bool cancelRequested = false;
  for (auto& request : requests)
  {
    ++handled;
    const GoalInfo& asked =
      static_cast<const ros2vtk::action_msgs::srv::CancelGoal_Request*>(request.request.get())
        ->goal_info;
    CancelResponse response;
    response.return_code = CancelResponse::ERROR_NONE;
    const bool byId = !IsZero(asked.goal_id);
    const bool byTime = Nanoseconds(asked.stamp) != 0;
    // rcl_action_process_cancel_request (docs/wire-notes.md §8.3): one goal, all goals, or goals
    // accepted up to a time (plus the named one).
    vtkInternals::Goal* named = byId ? internals.Find(asked.goal_id) : nullptr;
    if (byId && !byTime && !named)
    {
      response.return_code = CancelResponse::ERROR_UNKNOWN_GOAL_ID;
    }
    else if (byId && !byTime && named->Status != GoalStatus::STATUS_EXECUTING)
    {
      response.return_code = CancelResponse::ERROR_GOAL_TERMINATED;
    }
    else
    {
      for (auto& goal : internals.Goals)
      {
        const bool chosen = byTime
          ? (Nanoseconds(goal.Info.stamp) <= Nanoseconds(asked.stamp) || &goal == named)
          : (!byId || &goal == named);
        if (chosen && goal.Status == GoalStatus::STATUS_EXECUTING)
        {
          goal.Status = GoalStatus::STATUS_CANCELING;
          goal.CancelRequested = true;
          response.goals_canceling.push_back(goal.Info);
        }
      }
      if (!response.goals_canceling.empty())
      {
        ++internals.Cancels;
        statusChanged = cancelRequested = true;
      }
    }
    internals.CancelServer->send_response(request.id, &response);
  }

  // rcl_action_expire_goals: finished goals older than the result timeout leave the status list
  // and no longer have a result to serve. A clock that went back (sim time restarted) expires
  // nothing until it passes the finish time again.
  const int64_t now = internals.ROSNode ? internals.ROSNode->GetNodeTimeNanoseconds() : 0;
  const int64_t keep = static_cast<int64_t>(internals.ResultTimeout * 1e9);
  const size_t before = internals.Goals.size();
  internals.Goals.erase(std::remove_if(internals.Goals.begin(), internals.Goals.end(),
                          [&](const vtkInternals::Goal& goal) {
                            return goal.Result && goal.ResultWaiters.empty() &&
                              now - goal.FinishedAt > keep;
                          }),
    internals.Goals.end());
  if (internals.Goals.size() != before)
  {
    internals.Expired += static_cast<vtkTypeInt64>(before - internals.Goals.size());
    statusChanged = true;
  }

  const uint64_t malformed = internals.SendGoalServer->rejected_count() +
    internals.GetResultServer->rejected_count() + internals.CancelServer->rejected_count();
  const uint64_t fresh =
    malformed > internals.MalformedSeen ? malformed - internals.MalformedSeen : 0;
  internals.MalformedSeen = malformed;
  internals.Malformed += static_cast<vtkTypeInt64>(fresh);
  if (const uint64_t due =
        internals.MalformedReport.record(fresh, std::chrono::steady_clock::now()))
  {
    std::string reason = internals.SendGoalServer->last_rejection();
    for (const auto* server : { internals.GetResultServer.get(), internals.CancelServer.get() })
    {
      reason = reason.empty() ? server->last_rejection() : reason;
    }
    vtkWarningMacro("action '" << this->GetActionName() << "': " << due
                               << " malformed request(s) rejected (total " << internals.Malformed
                               << "; latest: " << reason << ")");
  }

  if (statusChanged)
  {
    internals.PublishStatus();
    this->Modified();
  }
  if (cancelRequested)
  {
    this->InvokeEvent(CancelRequestedEvent);
  }
  return handled;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::RejectGoal()
{
  if (!this->Internals->Deciding)
  {
    vtkErrorMacro("RejectGoal: only from a GoalReceivedEvent observer");
    return false;
  }
  this->Internals->RejectDeciding = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::HasActiveGoal() const
{
  return this->Internals->Deciding || this->Internals->Current();
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionServerNode::GetGoalYAML() const
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type)
  {
    return "";
  }
  if (internals.Deciding)
  {
    return ros2vtk::wire::to_yaml(*internals.Type->goal(), internals.Deciding);
  }
  const vtkInternals::Goal* goal = internals.Current();
  return goal ? ros2vtk::wire::to_yaml(*internals.Type->goal(), goal->Request.get()) : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionServerNode::GetGoalField(const char* path) const
{
  vtkInternals& internals = *this->Internals;
  const vtkInternals::Goal* goal = internals.Current();
  const void* message = internals.Deciding ? internals.Deciding
    : goal                                 ? goal->Request.get()
                                           : nullptr;
  std::string value;
  std::string error = "no goal is running";
  if (!internals.Type || !path || !message ||
    !ros2vtk::scene::get_field_as_text(*internals.Type->goal(), message, path, value, &error))
  {
    vtkErrorMacro("GetGoalField: " << error);
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionServerNode::GetGoalIdAsString() const
{
  const vtkInternals::Goal* goal = this->Internals->Current();
  if (!goal)
  {
    return "";
  }
  std::string text;
  char digits[3];
  for (const uint8_t byte : goal->Info.goal_id.uuid)
  {
    std::snprintf(digits, sizeof(digits), "%02x", byte);
    text += digits;
  }
  return text;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::IsCancelRequested() const
{
  const vtkInternals::Goal* goal = this->Internals->Current();
  return goal && goal->CancelRequested;
}

//------------------------------------------------------------------------------
int vtkROS2ActionServerNode::GetGoalStatus() const
{
  const vtkInternals::Goal* goal = this->Internals->Current();
  return goal ? goal->Status : 0;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::PublishFeedbackYAML(const char* yaml)
{
  vtkInternals& internals = *this->Internals;
  vtkInternals::Goal* goal = internals.Current();
  if (!internals.FeedbackPublisher || !goal)
  {
    vtkErrorMacro("PublishFeedbackYAML: no goal is running");
    return false;
  }
  MessagePtr message = NewMessage(*internals.Type->feedback_message());
  std::string error;
  void* feedback = static_cast<char*>(message.get()) + internals.At.FeedbackFeedback;
  if (!ros2vtk::wire::from_yaml(*internals.Type->feedback(), yaml ? yaml : "", feedback, &error))
  {
    vtkErrorMacro(
      "PublishFeedbackYAML: invalid " << internals.Type->feedback()->ros_type << ": " << error);
    return false;
  }
  member<UUID>(message.get(), internals.At.FeedbackId) = goal->Info.goal_id;
  return internals.FeedbackPublisher->publish(message.get());
}

//------------------------------------------------------------------------------
bool vtkROS2ActionServerNode::Finish(int status, const char* resultYAML, const char* what)
{
  vtkInternals& internals = *this->Internals;
  vtkInternals::Goal* goal = internals.Current();
  if (!internals.StatusPublisher || !goal)
  {
    vtkErrorMacro("" << what << ": no goal is running");
    return false;
  }
  if (status == GoalStatus::STATUS_CANCELED && goal->Status != GoalStatus::STATUS_CANCELING)
  {
    vtkErrorMacro("" << what << ": no cancel was requested for the current goal");
    return false;
  }
  MessagePtr result = NewMessage(*internals.Type->result());
  std::string error;
  if (resultYAML && *resultYAML &&
    !ros2vtk::wire::from_yaml(*internals.Type->result(), resultYAML, result.get(), &error))
  {
    vtkErrorMacro(
      "" << what << ": invalid " << internals.Type->result()->ros_type << ": " << error);
    return false;
  }
  goal->Status = static_cast<int8_t>(status);
  goal->Result = std::move(result);
  goal->FinishedAt = internals.ROSNode ? internals.ROSNode->GetNodeTimeNanoseconds() : 0;
  internals.PublishStatus();
  MessagePtr response = internals.ResultResponse(goal);
  for (const auto& waiter : goal->ResultWaiters)
  {
    internals.GetResultServer->send_response(waiter, response.get());
    ++internals.ResultsSent;
  }
  goal->ResultWaiters.clear();
  this->Modified();
  return true;
}

bool vtkROS2ActionServerNode::SucceedGoal(const char* resultYAML)
{
  return this->Finish(GoalStatus::STATUS_SUCCEEDED, resultYAML, "SucceedGoal");
}

bool vtkROS2ActionServerNode::AbortGoal(const char* resultYAML)
{
  return this->Finish(GoalStatus::STATUS_ABORTED, resultYAML, "AbortGoal");
}

bool vtkROS2ActionServerNode::ConfirmGoalCanceled(const char* resultYAML)
{
  return this->Finish(GoalStatus::STATUS_CANCELED, resultYAML, "ConfirmGoalCanceled");
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfGoalsReceived() const
{
  return this->Internals->Received;
}
vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfGoalsAccepted() const
{
  return this->Internals->Accepted;
}
vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfGoalsRejected() const
{
  return this->Internals->Rejected;
}
vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfCancelRequests() const
{
  return this->Internals->Cancels;
}
vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfResultsSent() const
{
  return this->Internals->ResultsSent;
}

void vtkROS2ActionServerNode::SetResultTimeout(double seconds)
{
  if (!(seconds >= 0) || !std::isfinite(seconds))
  {
    vtkErrorMacro("SetResultTimeout: " << seconds << " is not a non-negative number of seconds");
    return;
  }
  if (seconds != this->Internals->ResultTimeout)
  {
    this->Internals->ResultTimeout = seconds;
    this->Modified();
  }
}

double vtkROS2ActionServerNode::GetResultTimeout() const
{
  return this->Internals->ResultTimeout;
}

vtkTypeInt64 vtkROS2ActionServerNode::GetNumberOfExpiredGoals() const
{
  return this->Internals->Expired;
}

void vtkROS2ActionServerNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  if (this->Internals->ResultTimeout !=
    kDefaultResultTimeout) // files with the default stay as before
  {
    element->SetDoubleAttribute("resultTimeout", this->Internals->ResultTimeout);
  }
}

bool vtkROS2ActionServerNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  double seconds = 0; // absent in files of earlier versions: the default stays
  if (element->GetScalarAttribute("resultTimeout", seconds) && seconds >= 0 &&
    std::isfinite(seconds))
  {
    this->Internals->ResultTimeout = seconds;
  }
  return true;
}

int vtkROS2ActionServerNode::GetNumberOfGoals() const
{
  return static_cast<int>(this->Internals->Goals.size());
}

int vtkROS2ActionServerNode::GetNumberOfActiveGoals() const
{
  return static_cast<int>(std::count_if(this->Internals->Goals.begin(),
    this->Internals->Goals.end(), [](const vtkInternals::Goal& g) { return !g.Result; }));
}

//------------------------------------------------------------------------------
void vtkROS2ActionServerNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Goals: " << this->Internals->Goals.size() << "\n";
  os << indent << "ResultTimeout: " << this->Internals->ResultTimeout << " s\n";
  os << indent << "ExpiredGoals: " << this->Internals->Expired << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's methods for this kind live with the kind (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2ActionServerNode* vtkROS2NodeNode::CreateAndAddActionServerNode(
  const char* type, const char* action)
{
  vtkNew<vtkROS2ActionServerNode> node;
  const bool attached = this->AdoptKeyedChild("CreateAndAddActionServerNode", ActionServerRole,
    node, type, action, "action", "this node serves ",
    "ros2:action_server:", [&] { return node->Attach(this, type, action); });
  return attached ? node.GetPointer() : nullptr; // the scene holds it
}

//------------------------------------------------------------------------------
vtkROS2ActionServerNode* vtkROS2NodeNode::GetActionServerNodeByAction(const char* action)
{
  return vtkROS2ActionServerNode::SafeDownCast(this->FindChildByName(ActionServerRole, action));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteActionServerNode(const char* action)
{
  return this->RemoveKeyedChild(
    "RemoveAndDeleteActionServerNode", ActionServerRole, action, "no server of ");
}
