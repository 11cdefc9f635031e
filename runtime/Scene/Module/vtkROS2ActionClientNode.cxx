// ros2vtk — vtkROS2ActionClientNode: goals of any generated action type over three wire
// service clients and two subscriptions (rcl_action's endpoints), advanced on the ROS node's
// spin. What is per action type (goal, result, feedback, the synthesized services) comes from
// the generated wire::ActionTypeSupport table; only the fixed action protocol (action_msgs,
// unique_identifier_msgs and the member names rosidl gives every synthesized type) is named here.
#include "vtkROS2ActionClientNode.h"

#include "Internal/ActionMembers.hpp"
#include "Internal/MessageFields.hpp"
#include "Internal/RateLimitedReport.hpp"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/action_msgs/msg/goal_status.hpp"
#include "ros2vtk/action_msgs/msg/goal_status_array.hpp"
#include "ros2vtk/action_msgs/srv/cancel_goal.hpp"
#include "ros2vtk/builtin_interfaces/msg/time.hpp"
#include "ros2vtk/unique_identifier_msgs/msg/uuid.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Service.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

#include <poll.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkROS2ActionClientNode);

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk::scene::member;
using ros2vtk::wire::MessagePtr;
using ros2vtk::wire::MessageTypeSupport;
using UUID = ros2vtk::unique_identifier_msgs::msg::UUID;
using GoalStatus = ros2vtk::action_msgs::msg::GoalStatus;

MessagePtr NewMessage(const MessageTypeSupport& type)
{
  return MessagePtr(&type, type.create());
}

std::string FormatSeconds(double seconds)
{
  std::ostringstream text;
  text << seconds << " s";
  return text.str();
}

std::string IdText(const UUID& id)
{
  std::string text;
  char digits[3];
  for (const uint8_t byte : id.uuid)
  {
    std::snprintf(digits, sizeof(digits), "%02x", byte);
    text += digits;
  }
  return text;
}

UUID RandomGoalId()
{
  // As rclpy (uuid4) and rclcpp: 16 random bytes.
  static std::mt19937_64 engine{ std::random_device{}() };
  UUID id;
  for (size_t i = 0; i < id.uuid.size(); i += 8)
  {
    const uint64_t bits = engine();
    for (size_t j = 0; j < 8; ++j)
    {
      id.uuid[i + j] = static_cast<uint8_t>(bits >> (8 * j));
    }
  }
  return id;
}
}

//------------------------------------------------------------------------------
class vtkROS2ActionClientNode::vtkInternals
{
public:
  const ros2vtk::wire::ActionTypeSupport* Type = nullptr;
  ros2vtk::scene::ActionMembers At; // where the synthesized members sit in this action's types
  std::unique_ptr<ros2vtk::wire::ServiceClient> SendGoalClient;
  std::unique_ptr<ros2vtk::wire::ServiceClient> GetResultClient;
  std::unique_ptr<ros2vtk::wire::ServiceClient> CancelClient;
  std::unique_ptr<ros2vtk::wire::Subscription> FeedbackSubscription;
  std::unique_ptr<ros2vtk::wire::Subscription> StatusSubscription;
  // The action type (pkg/action/X) in the node's type cache while the endpoints exist, as
  // rcl_action registers it: ~/get_type_description serves it (docs/wire-interop.md).
  ros2vtk::wire::NodeTypeCache::Registration ActionTypeRegistration;

  MessagePtr Goal;          // X_Goal the next SendGoal sends
  MessagePtr BlankFeedback; // X_Feedback and X_Result shown before the first goal
  MessagePtr BlankResult;

  /// One goal sent by this client (rclpy's ClientGoalHandle): tracked until the node goes.
  struct GoalRecord
  {
    UUID GoalId;
    std::string IdText;      // 32 hex digits
    MessagePtr GoalRequest;  // X_SendGoal_Request
    MessagePtr LastFeedback; // X_Feedback
    MessagePtr Result;       // X_Result
    int State = vtkROS2ActionClientNode::Idle;
    int ResultStatus = 0;
    int32_t AcceptedSec = 0; // the server's stamp in the SendGoal response
    uint32_t AcceptedNanosec = 0;
    int64_t GoalSequence = -1;
    int64_t ResultSequence = -1;
    Clock::time_point Deadline;
    double GoalTimeout = 0;
    vtkTypeInt64 Feedbacks = 0;
    std::string Error;

    bool Active() const
    {
      return this->State == vtkROS2ActionClientNode::Accepted ||
        this->State == vtkROS2ActionClientNode::Executing ||
        this->State == vtkROS2ActionClientNode::Canceling;
    }
  };
  std::vector<std::unique_ptr<GoalRecord>> Goals; // in the order sent
  GoalRecord* Current = nullptr;                  // the last goal sent (the single-goal API)
  int MaximumFinishedGoals = 100;                 // finished goals kept beyond: oldest dropped
  std::string EventGoalId;                        // the goal of the event being invoked

  int LastCancelReturnCode = -1;
  int64_t CancelSequence = -1;
  Clock::time_point CancelDeadline;
  std::string LastError;
  vtkTypeInt64 GoalsSent = 0;
  vtkTypeInt64 GoalsAccepted = 0;
  vtkTypeInt64 Results = 0;
  vtkTypeInt64 Feedbacks = 0;
  bool InWait = false;
  // Malformed feedback / status samples (rejected by the wire subscriptions): counted, and
  // reported as a warning at most every 5 s.
  uint64_t RejectedSeen = 0;
  vtkTypeInt64 Rejected = 0;
  ros2vtk::scene::RateLimitedReport RejectionReport{ std::chrono::seconds(5) };

  bool ServerReady() const
  {
    return this->SendGoalClient && this->SendGoalClient->is_server_available() &&
      this->GetResultClient->is_server_available() && this->CancelClient->is_server_available() &&
      this->FeedbackSubscription->matched_publications() > 0 &&
      this->StatusSubscription->matched_publications() > 0;
  }

  bool GoalActive() const { return this->Current && this->Current->Active(); }

  GoalRecord* Find(const char* id)
  {
    for (auto& goal : this->Goals)
    {
      if (id && goal->IdText == id)
      {
        return goal.get();
      }
    }
    return nullptr;
  }
  const GoalRecord* Find(const char* id) const { return const_cast<vtkInternals*>(this)->Find(id); }

  void Release()
  {
    this->SendGoalClient.reset();
    this->GetResultClient.reset();
    this->CancelClient.reset();
    this->FeedbackSubscription.reset();
    this->StatusSubscription.reset();
    this->ActionTypeRegistration = ros2vtk::wire::NodeTypeCache::Registration();
  }
};

//------------------------------------------------------------------------------
vtkROS2ActionClientNode::vtkROS2ActionClientNode()
  : vtkROS2EndpointNode("action", "timeout")
  , Internals(new vtkInternals)
{
}

vtkROS2ActionClientNode::~vtkROS2ActionClientNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::Attach(
  vtkROS2NodeNode* rosNode, const std::string& type, const std::string& action)
{
  vtkInternals& internals = *this->Internals;
  if (!rosNode || !rosNode->GetParticipant())
  {
    vtkErrorMacro("action client " << action << ": the ROS node is not created");
    return false;
  }
  ros2vtk::wire::Participant& participant = *rosNode->GetParticipant();
  std::string error;
  ros2vtk::scene::ActionEndpoints endpoints;
  if (!ros2vtk::scene::find_action_endpoints(participant, type, action, endpoints, &error))
  {
    vtkErrorMacro("action client " << action << ": " << error);
    return false;
  }
  const ros2vtk::wire::ActionTypeSupport* support = endpoints.Type;
  const auto& sendGoal = *support->send_goal();
  auto sendGoalClient =
    participant.create_service_client(sendGoal, endpoints.SendGoal, endpoints.ServiceQoS, &error);
  auto getResultClient = sendGoalClient ? participant.create_service_client(*support->get_result(),
                                            endpoints.GetResult, endpoints.ServiceQoS, &error)
                                        : nullptr;
  auto cancelClient = getResultClient ? participant.create_service_client(*support->cancel_goal(),
                                          endpoints.CancelGoal, endpoints.ServiceQoS, &error)
                                      : nullptr;
  auto feedback = cancelClient ? participant.create_subscription(*support->feedback_message(),
                                   endpoints.Feedback, endpoints.FeedbackQoS, &error)
                               : nullptr;
  auto status = feedback ? participant.create_subscription(
                             *support->status(), endpoints.Status, endpoints.StatusQoS, &error)
                         : nullptr;
  if (!status)
  {
    vtkErrorMacro("action client " << action << ": " << error);
    return false;
  }
  if (internals.Type != support || !internals.Goal)
  {
    internals.Goal = NewMessage(*support->goal());
    internals.BlankFeedback = NewMessage(*support->feedback());
    internals.BlankResult = NewMessage(*support->result());
  }
  internals.Type = support;
  internals.At = endpoints.At;
  internals.SendGoalClient = std::move(sendGoalClient);
  internals.GetResultClient = std::move(getResultClient);
  internals.CancelClient = std::move(cancelClient);
  internals.FeedbackSubscription = std::move(feedback);
  internals.StatusSubscription = std::move(status);
  internals.ActionTypeRegistration =
    participant.type_cache().add(support->type_hash, support->description);
  this->EndpointAttached(rosNode, support->ros_type, action, endpoints.ResolvedName);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::Detach()
{
  vtkInternals& internals = *this->Internals;
  for (auto& goal : internals.Goals)
  {
    if (goal->State == WaitingForServer || goal->State == WaitingForAcceptance)
    {
      goal->State = Failed;
      goal->Error = internals.LastError = "the ROS node was destroyed before the goal was answered";
    }
  }
  internals.Release();
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::IsEndpointAttached() const
{
  return this->Internals->SendGoalClient != nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::IsServerReady() const
{
  return this->Internals->ServerReady();
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::SetGoalYAML(const char* yaml)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type)
  {
    vtkErrorMacro("SetGoalYAML: the client has no action type yet");
    return false;
  }
  std::string error;
  MessagePtr goal = NewMessage(*internals.Type->goal());
  if (!ros2vtk::wire::from_yaml(*internals.Type->goal(), yaml ? yaml : "", goal.get(), &error))
  {
    vtkErrorMacro("SetGoalYAML: invalid " << internals.Type->goal()->ros_type << ": " << error);
    return false;
  }
  internals.Goal = std::move(goal);
  return true;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetGoalYAML() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->goal(), internals.Goal.get())
                        : "";
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::SetGoalField(const char* path, const char* value)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type || !path || !value)
  {
    vtkErrorMacro("SetGoalField: needs an action type, a field path and a value");
    return false;
  }
  std::string error;
  if (!ros2vtk::scene::set_field_from_text(
        *internals.Type->goal(), internals.Goal.get(), path, value, &error))
  {
    vtkErrorMacro("SetGoalField: " << error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::ResetGoal()
{
  if (this->Internals->Type)
  {
    this->Internals->Goal = NewMessage(*this->Internals->Type->goal());
  }
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::SendGoal()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.SendGoalClient)
  {
    vtkErrorMacro("SendGoal: the client is not attached to a created ROS node");
    return -1;
  }
  const ros2vtk::wire::ActionTypeSupport& type = *internals.Type;
  ++internals.GoalsSent;
  // Earlier goals stay tracked (by id); this one becomes the current goal.
  internals.Goals.push_back(std::make_unique<vtkInternals::GoalRecord>());
  vtkInternals::GoalRecord& goal = *internals.Goals.back();
  internals.Current = &goal;
  goal.GoalId = RandomGoalId();
  goal.IdText = IdText(goal.GoalId);
  goal.GoalRequest = NewMessage(*type.send_goal()->request());
  member<UUID>(goal.GoalRequest.get(), internals.At.SendGoalId) = goal.GoalId;
  type.goal()->copy(
    internals.Goal.get(), static_cast<char*>(goal.GoalRequest.get()) + internals.At.SendGoalGoal);
  goal.LastFeedback = NewMessage(*type.feedback());
  goal.Result = NewMessage(*type.result());
  internals.LastCancelReturnCode = -1;
  internals.LastError.clear();
  goal.GoalTimeout = this->EndpointTimeout;
  goal.Deadline = Clock::now() +
    std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(this->EndpointTimeout));
  // Written at once when the server is there; otherwise on the spin that sees it (requests
  // are volatile: one written before the server's reader matched would be lost).
  goal.State = WaitingForServer;
  if (internals.ServerReady())
  {
    goal.GoalSequence = internals.SendGoalClient->send_request(goal.GoalRequest.get());
    goal.State = goal.GoalSequence >= 0 ? WaitingForAcceptance : WaitingForServer;
  }
  this->Modified();
  return internals.GoalsSent;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::SendGoalYAML(const char* yaml)
{
  return this->SetGoalYAML(yaml) ? this->SendGoal() : -1;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::CancelGoal()
{
  return this->CancelGoalById(
    this->Internals->Current ? this->Internals->Current->IdText.c_str() : "");
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::CancelGoalById(const char* goalId)
{
  const vtkInternals::GoalRecord* goal = this->Internals->Find(goalId);
  if (!this->Internals->CancelClient || !goal || !goal->Active())
  {
    const std::string which = goalId && *goalId ? std::string(goalId) + " " : std::string();
    vtkErrorMacro("CancelGoal: no accepted goal "
      << which << "is running (status: " << this->GetStatusAsStringById(goalId) << ")");
    return false;
  }
  ros2vtk::action_msgs::srv::CancelGoal_Request request;
  request.goal_info.goal_id = goal->GoalId; // stamp 0: this goal only
  return this->SendCancelRequest(&request);
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::CancelAllGoals()
{
  if (!this->Internals->CancelClient)
  {
    vtkErrorMacro("CancelAllGoals: the client is not attached to a created ROS node");
    return false;
  }
  // Zero goal id and zero stamp: every goal of the server (rcl_action_process_cancel_request),
  // as rclcpp's async_cancel_all_goals.
  ros2vtk::action_msgs::srv::CancelGoal_Request request;
  return this->SendCancelRequest(&request);
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::CancelGoalsBefore(int sec, unsigned int nanosec)
{
  if (!this->Internals->CancelClient)
  {
    vtkErrorMacro("CancelGoalsBefore: the client is not attached to a created ROS node");
    return false;
  }
  if (sec < 0 || nanosec >= 1000000000u)
  {
    vtkErrorMacro("CancelGoalsBefore: " << sec << " s " << nanosec
                                        << " ns is not a time (seconds >= 0, nanoseconds < 1e9)");
    return false;
  }
  // Zero goal id and a stamp: every goal accepted at or before it
  // (rcl_action_process_cancel_request).
  ros2vtk::action_msgs::srv::CancelGoal_Request request;
  request.goal_info.stamp.sec = sec;
  request.goal_info.stamp.nanosec = nanosec;
  return this->SendCancelRequest(&request);
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::SendCancelRequest(const void* request)
{
  vtkInternals& internals = *this->Internals;
  internals.CancelSequence = internals.CancelClient->send_request(request);
  if (internals.CancelSequence < 0)
  {
    internals.LastError =
      "Fast DDS refused to write the cancel request to " + std::string(this->GetActionName());
    return false;
  }
  internals.CancelDeadline = Clock::now() +
    std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(this->EndpointTimeout));
  return true;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::ProcessAction()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.SendGoalClient)
  {
    return 0;
  }
  // Goals that finished on earlier spins (their events are invoked) beyond the bound go first.
  this->DropFinishedGoalsBeyondMaximum();
  // (event, goal id) in the order they happened; observers read GetLastEventGoalId.
  std::vector<std::pair<unsigned long, std::string>> events;
  const Clock::time_point now = Clock::now();
  using GoalRecord = vtkInternals::GoalRecord;
  auto fail = [&](GoalRecord& goal, const std::string& error) {
    goal.Error = internals.LastError = error;
  };

  // Goals waiting for the server go out on the first spin that sees it.
  const bool ready = internals.ServerReady();
  for (auto& goal : internals.Goals)
  {
    if (goal->State != WaitingForServer || !ready)
    {
      continue;
    }
    goal->GoalSequence = internals.SendGoalClient->send_request(goal->GoalRequest.get());
    if (goal->GoalSequence < 0)
    {
      goal->State = Failed;
      fail(*goal, "Fast DDS refused to write the goal to " + std::string(this->GetActionName()));
      events.emplace_back(GoalFailedEvent, goal->IdText);
    }
    else
    {
      goal->State = WaitingForAcceptance;
    }
  }

  std::vector<ros2vtk::wire::ServiceResponse> responses;
  internals.SendGoalClient->take(responses);
  for (auto& response : responses)
  {
    GoalRecord* goal = nullptr;
    for (auto& candidate : internals.Goals)
    {
      if (candidate->State == WaitingForAcceptance &&
        response.sequence_number == candidate->GoalSequence)
      {
        goal = candidate.get();
      }
    }
    if (!goal)
    {
      continue; // a second server's duplicate, or an answer after the timeout
    }
    if (member<bool>(response.response.get(), internals.At.Accepted))
    {
      goal->State = Accepted;
      ++internals.GoalsAccepted;
      const auto& stamp = member<ros2vtk::builtin_interfaces::msg::Time>(
        response.response.get(), internals.At.AcceptedStamp);
      goal->AcceptedSec = stamp.sec;
      goal->AcceptedNanosec = stamp.nanosec;
      auto request = NewMessage(*internals.Type->get_result()->request());
      member<UUID>(request.get(), internals.At.GetResultId) = goal->GoalId;
      // Asked at once (as rclcpp does with a result callback); the server answers when done.
      goal->ResultSequence = internals.GetResultClient->send_request(request.get());
      if (goal->ResultSequence < 0)
      {
        goal->State = Failed;
        fail(*goal,
          "Fast DDS refused to write the result request to " + std::string(this->GetActionName()));
      }
    }
    else
    {
      goal->State = Rejected;
      fail(*goal, "goal rejected by " + std::string(this->GetActionName()));
    }
    events.emplace_back(GoalResponseEvent, goal->IdText);
  }

  std::vector<MessagePtr> messages;
  internals.FeedbackSubscription->take(messages);
  for (auto& message : messages)
  {
    const UUID& id = member<UUID>(message.get(), internals.At.FeedbackId);
    for (auto& goal : internals.Goals)
    {
      if (goal->State == WaitingForServer || goal->GoalId != id)
      {
        continue; // feedback goes to every client; each keeps its own goals' (docs/wire-notes.md
                  // §8.3)
      }
      internals.Type->feedback()->copy(
        static_cast<const char*>(message.get()) + internals.At.FeedbackFeedback,
        goal->LastFeedback.get());
      ++goal->Feedbacks;
      events.emplace_back(FeedbackReceivedEvent, goal->IdText);
    }
  }

  messages.clear();
  internals.StatusSubscription->take(messages);
  for (auto& message : messages)
  {
    const auto& array =
      *static_cast<const ros2vtk::action_msgs::msg::GoalStatusArray*>(message.get());
    for (const auto& status : array.status_list)
    {
      for (auto& goal : internals.Goals)
      {
        if (!goal->Active() || status.goal_info.goal_id != goal->GoalId)
        {
          continue;
        }
        // Terminal states come with the result (its own status); the topic gives the way there.
        const int before = goal->State;
        if (status.status == GoalStatus::STATUS_EXECUTING && goal->State == Accepted)
        {
          goal->State = Executing;
        }
        else if (status.status == GoalStatus::STATUS_CANCELING)
        {
          goal->State = Canceling;
        }
        if (goal->State != before)
        {
          this->Modified();
        }
      }
    }
  }

  responses.clear();
  internals.GetResultClient->take(responses);
  for (auto& response : responses)
  {
    GoalRecord* goal = nullptr;
    for (auto& candidate : internals.Goals)
    {
      if (candidate->Active() && response.sequence_number == candidate->ResultSequence)
      {
        goal = candidate.get();
      }
    }
    if (!goal)
    {
      continue;
    }
    const void* answer = response.response.get();
    goal->ResultStatus = member<int8_t>(answer, internals.At.ResultStatus);
    internals.Type->result()->copy(
      static_cast<const char*>(answer) + internals.At.ResultResult, goal->Result.get());
    ++internals.Results;
    switch (goal->ResultStatus)
    {
      case GoalStatus::STATUS_SUCCEEDED:
        goal->State = Succeeded;
        break;
      case GoalStatus::STATUS_CANCELED:
        goal->State = Canceled;
        break;
      case GoalStatus::STATUS_ABORTED:
        goal->State = Aborted;
        break;
      default:
        goal->State = Failed;
        fail(*goal,
          std::string(this->GetActionName()) + " sent a result with status " +
            std::to_string(goal->ResultStatus) + " (not succeeded, canceled or aborted)");
    }
    events.emplace_back(ResultReceivedEvent, goal->IdText);
  }

  responses.clear();
  internals.CancelClient->take(responses);
  for (auto& response : responses)
  {
    if (internals.CancelSequence < 0 || response.sequence_number != internals.CancelSequence)
    {
      continue;
    }
    internals.CancelSequence = -1;
    internals.LastCancelReturnCode =
      static_cast<const ros2vtk::action_msgs::srv::CancelGoal_Response*>(response.response.get())
        ->return_code;
    if (internals.LastCancelReturnCode != 0)
    {
      internals.LastError = std::string(this->GetActionName()) +
        " refused to cancel the goal (return code " +
        std::to_string(internals.LastCancelReturnCode) + ")";
    }
    events.emplace_back(CancelResponseEvent, "");
  }
  if (internals.CancelSequence >= 0 && now >= internals.CancelDeadline)
  {
    internals.CancelSequence = -1;
    internals.LastError = "timed out: " + std::string(this->GetActionName()) +
      " did not answer the cancel request within " + FormatSeconds(this->EndpointTimeout);
    events.emplace_back(CancelResponseEvent, "");
  }

  for (auto& goal : internals.Goals)
  {
    if ((goal->State == WaitingForServer || goal->State == WaitingForAcceptance) &&
      now >= goal->Deadline)
    {
      fail(*goal,
        goal->State == WaitingForServer ? "timed out: no server for " +
            std::string(this->GetActionName()) + " (" + std::string(this->GetActionType()) +
            ") appeared within " + FormatSeconds(goal->GoalTimeout)
                                        : "timed out: " + std::string(this->GetActionName()) +
            " did not answer the goal within " + FormatSeconds(goal->GoalTimeout));
      goal->State = TimedOut;
      events.emplace_back(GoalFailedEvent, goal->IdText);
    }
  }

  const uint64_t rejected = internals.FeedbackSubscription->rejected_count() +
    internals.StatusSubscription->rejected_count();
  const uint64_t fresh = rejected > internals.RejectedSeen ? rejected - internals.RejectedSeen : 0;
  internals.RejectedSeen = rejected;
  internals.Rejected += static_cast<vtkTypeInt64>(fresh);
  if (const uint64_t due = internals.RejectionReport.record(fresh, now))
  {
    const std::string reason = internals.StatusSubscription->last_rejection().empty()
      ? internals.FeedbackSubscription->last_rejection()
      : internals.StatusSubscription->last_rejection();
    vtkWarningMacro("action '" << this->GetActionName() << "': " << due
                               << " malformed feedback/status sample(s) rejected (total "
                               << internals.Rejected << "; latest: " << reason << ")");
  }

  if (events.empty())
  {
    return 0;
  }
  this->Modified();
  for (const auto& event : events)
  {
    internals.EventGoalId = event.second;
    this->InvokeEvent(event.first);
  }
  internals.EventGoalId.clear();
  return static_cast<int>(events.size());
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::SpinSceneUntil(
  double timeoutSeconds, bool (*done)(const vtkROS2ActionClientNode*))
{
  vtkInternals& internals = *this->Internals;
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (!internals.SendGoalClient || !rosNode)
  {
    vtkErrorMacro("the action client is not attached to a created ROS node");
    return false;
  }
  if (internals.InWait)
  {
    vtkErrorMacro("already waiting on this action client (called from an observer?)");
    return false;
  }
  internals.InWait = true;
  const Clock::time_point end = Clock::now() +
    std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeoutSeconds));
  const int fd = rosNode->GetWakeUpFileDescriptor();
  bool finished = done(this);
  while (!finished && Clock::now() < end)
  {
    // Short waits while no server is there (matching raises no wake-up), else until data.
    pollfd wait{ fd, POLLIN, 0 };
    ::poll(&wait, 1, 10);
    // Every ROS node of the scene: a server on another node of this process must answer too.
    vtkROS2Scene* scene = this->GetScene();
    const int count = scene ? scene->GetNumberOfNodesByClass("vtkROS2NodeNode") : 0;
    for (int i = 0; i < count; ++i)
    {
      if (auto* node =
            vtkROS2NodeNode::SafeDownCast(scene->GetNthNodeByClass(i, "vtkROS2NodeNode")))
      {
        node->Spin();
      }
    }
    if (!scene)
    {
      rosNode->Spin();
    }
    finished = done(this);
  }
  if (!finished)
  {
    this->ProcessAction(); // a goal deadline that fell at the very end
    finished = done(this);
  }
  internals.InWait = false;
  return finished;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::SendGoalAndWait(const char* goalYAML, double timeoutSeconds)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.SendGoalClient || !this->GetROS2Node())
  {
    vtkErrorMacro("SendGoalAndWait: the client is not attached to a created ROS node");
    return "";
  }
  if (internals.InWait)
  {
    vtkErrorMacro(
      "SendGoalAndWait: already waiting on this action client (called from an observer?)");
    return "";
  }
  const double seconds =
    timeoutSeconds > 0 && std::isfinite(timeoutSeconds) ? timeoutSeconds : this->EndpointTimeout;
  const double savedTimeout = this->EndpointTimeout;
  this->EndpointTimeout = seconds; // the goal's own deadline for server and acceptance
  const vtkTypeInt64 goal = this->SendGoalYAML(goalYAML);
  this->EndpointTimeout = savedTimeout;
  if (goal < 0)
  {
    internals.LastError = "invalid goal YAML";
    return "";
  }
  if (!this->SpinSceneUntil(
        seconds, [](const vtkROS2ActionClientNode* self) { return self->IsGoalDone(); }))
  {
    if (internals.LastError.empty())
    {
      internals.LastError = "timed out: " + std::string(this->GetActionName()) +
        " sent no result within " + FormatSeconds(seconds) + " (the goal is " +
        this->GetStatusAsString() + ")";
    }
    vtkErrorMacro("SendGoalAndWait " << this->GetActionName() << ": " << internals.LastError);
    return "";
  }
  const int state = this->GetGoalStatus();
  if (state == Rejected || state == TimedOut || state == Failed)
  {
    vtkErrorMacro("SendGoalAndWait " << this->GetActionName() << ": " << internals.LastError);
    return "";
  }
  return this->GetResultYAML();
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::WaitForGoal(double timeoutSeconds)
{
  if (!(timeoutSeconds > 0) || !std::isfinite(timeoutSeconds))
  {
    vtkErrorMacro("WaitForGoal: " << timeoutSeconds << " is not a positive number of seconds");
    return false;
  }
  return this->SpinSceneUntil(
    timeoutSeconds, [](const vtkROS2ActionClientNode* self) { return self->IsGoalDone(); });
}

//------------------------------------------------------------------------------
namespace {
const char* StateText(int state)
{
  switch (state)
  {
    case vtkROS2ActionClientNode::WaitingForServer:
      return "waiting for server";
    case vtkROS2ActionClientNode::WaitingForAcceptance:
      return "waiting for acceptance";
    case vtkROS2ActionClientNode::Rejected:
      return "rejected";
    case vtkROS2ActionClientNode::Accepted:
      return "accepted";
    case vtkROS2ActionClientNode::Executing:
      return "executing";
    case vtkROS2ActionClientNode::Canceling:
      return "canceling";
    case vtkROS2ActionClientNode::Succeeded:
      return "succeeded";
    case vtkROS2ActionClientNode::Canceled:
      return "canceled";
    case vtkROS2ActionClientNode::Aborted:
      return "aborted";
    case vtkROS2ActionClientNode::TimedOut:
      return "timed out";
    case vtkROS2ActionClientNode::Failed:
      return "failed";
    default:
      return "idle";
  }
}

bool StateDone(int state)
{
  switch (state)
  {
    case vtkROS2ActionClientNode::Rejected:
    case vtkROS2ActionClientNode::Succeeded:
    case vtkROS2ActionClientNode::Canceled:
    case vtkROS2ActionClientNode::Aborted:
    case vtkROS2ActionClientNode::TimedOut:
    case vtkROS2ActionClientNode::Failed:
      return true;
    default:
      return false;
  }
}
} // namespace

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::CurrentGoalId() const
{
  return this->Internals->Current ? this->Internals->Current->IdText.c_str() : "";
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetGoalStatus() const
{
  return this->GetGoalStatusById(this->CurrentGoalId());
}

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::GetStatusAsString() const
{
  return StateText(this->GetGoalStatus());
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::IsGoalDone() const
{
  return StateDone(this->GetGoalStatus());
}

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::GetLastError() const
{
  return this->Internals->LastError.c_str();
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetGoalIdAsString() const
{
  return this->CurrentGoalId();
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfFeedbacks() const
{
  return this->GetNumberOfFeedbacksById(this->CurrentGoalId());
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetLastFeedbackYAML() const
{
  return this->GetLastFeedbackYAMLById(this->CurrentGoalId());
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetFeedbackField(const char* path) const
{
  const vtkInternals& internals = *this->Internals;
  const auto* goal = internals.Find(this->CurrentGoalId());
  std::string value;
  std::string error;
  if (!internals.Type || !path ||
    !ros2vtk::scene::get_field_as_text(*internals.Type->feedback(),
      goal ? goal->LastFeedback.get() : internals.BlankFeedback.get(), path, value, &error))
  {
    vtkErrorMacro(
      "GetFeedbackField: " << (internals.Type ? error : "the client has no action type yet"));
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultYAML() const
{
  return this->GetResultYAMLById(this->CurrentGoalId());
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultField(const char* path) const
{
  return this->GetResultFieldById(this->CurrentGoalId(), path);
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetResultStatus() const
{
  return this->GetResultStatusById(this->CurrentGoalId());
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetNumberOfGoals() const
{
  return static_cast<int>(this->Internals->Goals.size());
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetNthGoalId(int i) const
{
  const auto& goals = this->Internals->Goals;
  return i >= 0 && i < static_cast<int>(goals.size()) ? goals[static_cast<size_t>(i)]->IdText
                                                      : std::string();
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetLastEventGoalId() const
{
  return this->Internals->EventGoalId;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetGoalStatusById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->State : Idle;
}

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::GetStatusAsStringById(const char* goalId) const
{
  return StateText(this->GetGoalStatusById(goalId));
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::IsGoalDoneById(const char* goalId) const
{
  return StateDone(this->GetGoalStatusById(goalId));
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::ForgetGoalById(const char* goalId)
{
  vtkInternals& internals = *this->Internals;
  auto& goals = internals.Goals;
  for (auto it = goals.begin(); it != goals.end(); ++it)
  {
    if (goalId && (*it)->IdText == goalId)
    {
      if (!StateDone((*it)->State))
      {
        vtkErrorMacro("ForgetGoalById: goal "
          << goalId << " is not finished (status: " << StateText((*it)->State) << ")");
        return false;
      }
      if (internals.Current == it->get())
      {
        internals.Current = nullptr;
      }
      goals.erase(it);
      this->Modified();
      return true;
    }
  }
  vtkErrorMacro("ForgetGoalById: no goal " << (goalId ? goalId : "(null)") << " is tracked");
  return false;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::ForgetFinishedGoals()
{
  vtkInternals& internals = *this->Internals;
  auto& goals = internals.Goals;
  const size_t before = goals.size();
  goals.erase(std::remove_if(goals.begin(), goals.end(),
                [&internals](const std::unique_ptr<vtkInternals::GoalRecord>& goal) {
                  if (!StateDone(goal->State))
                  {
                    return false;
                  }
                  if (internals.Current == goal.get())
                  {
                    internals.Current = nullptr;
                  }
                  return true;
                }),
    goals.end());
  const int dropped = static_cast<int>(before - goals.size());
  if (dropped)
  {
    this->Modified();
  }
  return dropped;
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::DropFinishedGoalsBeyondMaximum()
{
  vtkInternals& internals = *this->Internals;
  auto& goals = internals.Goals;
  size_t finished = 0;
  for (const auto& goal : goals)
  {
    finished += StateDone(goal->State) ? 1 : 0;
  }
  const size_t keep = static_cast<size_t>(internals.MaximumFinishedGoals);
  if (finished <= keep)
  {
    return;
  }
  size_t drop = finished - keep; // the oldest finished goals (Goals is in the order sent)
  goals.erase(std::remove_if(goals.begin(), goals.end(),
                [&](const std::unique_ptr<vtkInternals::GoalRecord>& goal) {
                  if (drop == 0 || !StateDone(goal->State))
                  {
                    return false;
                  }
                  --drop;
                  if (internals.Current == goal.get())
                  {
                    internals.Current = nullptr;
                  }
                  return true;
                }),
    goals.end());
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::SetMaximumFinishedGoals(int maximum)
{
  if (maximum < 0)
  {
    vtkErrorMacro("SetMaximumFinishedGoals: " << maximum << " is negative");
    return;
  }
  if (this->Internals->MaximumFinishedGoals != maximum)
  {
    this->Internals->MaximumFinishedGoals = maximum;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetMaximumFinishedGoals() const
{
  return this->Internals->MaximumFinishedGoals;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetGoalAcceptedSecById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->AcceptedSec : 0;
}

//------------------------------------------------------------------------------
unsigned int vtkROS2ActionClientNode::GetGoalAcceptedNanosecById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->AcceptedNanosec : 0u;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::AreAllGoalsDone() const
{
  for (const auto& goal : this->Internals->Goals)
  {
    if (!StateDone(goal->State))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::WaitForAllGoals(double timeoutSeconds)
{
  if (!(timeoutSeconds > 0) || !std::isfinite(timeoutSeconds))
  {
    vtkErrorMacro("WaitForAllGoals: " << timeoutSeconds << " is not a positive number of seconds");
    return false;
  }
  return this->SpinSceneUntil(
    timeoutSeconds, [](const vtkROS2ActionClientNode* self) { return self->AreAllGoalsDone(); });
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetGoalErrorById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->Error : std::string();
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfFeedbacksById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->Feedbacks : 0;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetLastFeedbackYAMLById(const char* goalId) const
{
  const vtkInternals& internals = *this->Internals;
  const auto* goal = internals.Find(goalId);
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->feedback(),
                            goal ? goal->LastFeedback.get() : internals.BlankFeedback.get())
                        : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultYAMLById(const char* goalId) const
{
  const vtkInternals& internals = *this->Internals;
  const auto* goal = internals.Find(goalId);
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->result(),
                            goal ? goal->Result.get() : internals.BlankResult.get())
                        : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultFieldById(const char* goalId, const char* path) const
{
  const vtkInternals& internals = *this->Internals;
  const auto* goal = internals.Find(goalId);
  std::string value;
  std::string error;
  if (!internals.Type || !path ||
    !ros2vtk::scene::get_field_as_text(*internals.Type->result(),
      goal ? goal->Result.get() : internals.BlankResult.get(), path, value, &error))
  {
    vtkErrorMacro(
      "GetResultField: " << (internals.Type ? error : "the client has no action type yet"));
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetResultStatusById(const char* goalId) const
{
  const auto* goal = this->Internals->Find(goalId);
  return goal ? goal->ResultStatus : 0;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetLastCancelReturnCode() const
{
  return this->Internals->LastCancelReturnCode;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfGoalsSent() const
{
  return this->Internals->GoalsSent;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfGoalsAccepted() const
{
  return this->Internals->GoalsAccepted;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfResults() const
{
  return this->Internals->Results;
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ServerReady: " << this->IsServerReady() << "\n";
  os << indent << "Status: " << this->GetStatusAsString() << "\n";
  os << indent << "Feedbacks: " << this->GetNumberOfFeedbacks() << "\n";
  os << indent << "Goals: " << this->Internals->Goals.size() << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…) live with the
// kind, so that the ROS node's own file includes no child kind (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2ActionClientNode* vtkROS2NodeNode::CreateAndAddActionClientNode(
  const char* type, const char* action)
{
  vtkNew<vtkROS2ActionClientNode> node;
  const bool attached = this->AdoptKeyedChild("CreateAndAddActionClientNode", ActionClientRole,
    node, type, action, "action", "this node has a client of ",
    "ros2:action_client:", [&] { return node->Attach(this, type, action); });
  return attached ? node.GetPointer() : nullptr; // the scene holds it
}

//------------------------------------------------------------------------------
vtkROS2ActionClientNode* vtkROS2NodeNode::GetActionClientNodeByAction(const char* action)
{
  return vtkROS2ActionClientNode::SafeDownCast(this->FindChildByName(ActionClientRole, action));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteActionClientNode(const char* action)
{
  return this->RemoveKeyedChild(
    "RemoveAndDeleteActionClientNode", ActionClientRole, action, "no client of ");
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetRegisteredActionTypes() const
{
  std::string names;
  for (const auto& name : ros2vtk::wire::registered_action_types())
  {
    names += (names.empty() ? "" : " ") + name;
  }
  return names;
}
