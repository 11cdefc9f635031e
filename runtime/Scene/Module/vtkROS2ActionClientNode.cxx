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
#include <random>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkROS2ActionClientNode);

namespace
{
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

  MessagePtr Goal;         // X_Goal the next SendGoal sends
  MessagePtr GoalRequest;  // X_SendGoal_Request of the current goal
  MessagePtr LastFeedback; // X_Feedback
  MessagePtr Result;       // X_Result
  bool HasGoal = false;
  UUID GoalId;
  int State = vtkROS2ActionClientNode::Idle;
  int ResultStatus = 0;
  int LastCancelReturnCode = -1;
  int64_t GoalSequence = -1;
  int64_t ResultSequence = -1;
  int64_t CancelSequence = -1;
  Clock::time_point Deadline;
  Clock::time_point CancelDeadline;
  double GoalTimeout = 0;
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

  bool GoalActive() const
  {
    return this->State == vtkROS2ActionClientNode::Accepted || this->State == vtkROS2ActionClientNode::Executing ||
      this->State == vtkROS2ActionClientNode::Canceling;
  }

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
bool vtkROS2ActionClientNode::Attach(vtkROS2NodeNode* rosNode, const std::string& type, const std::string& action)
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
  auto sendGoalClient = participant.create_service_client(sendGoal, endpoints.SendGoal, endpoints.ServiceQoS, &error);
  auto getResultClient = sendGoalClient
    ? participant.create_service_client(*support->get_result(), endpoints.GetResult, endpoints.ServiceQoS, &error)
    : nullptr;
  auto cancelClient = getResultClient
    ? participant.create_service_client(*support->cancel_goal(), endpoints.CancelGoal, endpoints.ServiceQoS, &error)
    : nullptr;
  auto feedback = cancelClient ? participant.create_subscription(*support->feedback_message(), endpoints.Feedback,
                                   endpoints.FeedbackQoS, &error)
                               : nullptr;
  auto status = feedback
    ? participant.create_subscription(*support->status(), endpoints.Status, endpoints.StatusQoS, &error)
    : nullptr;
  if (!status)
  {
    vtkErrorMacro("action client " << action << ": " << error);
    return false;
  }
  if (internals.Type != support || !internals.Goal)
  {
    internals.Goal = NewMessage(*support->goal());
    internals.GoalRequest = NewMessage(*sendGoal.request());
    internals.LastFeedback = NewMessage(*support->feedback());
    internals.Result = NewMessage(*support->result());
  }
  internals.Type = support;
  internals.At = endpoints.At;
  internals.SendGoalClient = std::move(sendGoalClient);
  internals.GetResultClient = std::move(getResultClient);
  internals.CancelClient = std::move(cancelClient);
  internals.FeedbackSubscription = std::move(feedback);
  internals.StatusSubscription = std::move(status);
  internals.ActionTypeRegistration = participant.type_cache().add(support->type_hash, support->description);
  this->EndpointAttached(rosNode, support->ros_type, action, endpoints.ResolvedName);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ActionClientNode::Detach()
{
  vtkInternals& internals = *this->Internals;
  if (internals.State == WaitingForServer || internals.State == WaitingForAcceptance)
  {
    internals.State = Failed;
    internals.LastError = "the ROS node was destroyed before the goal was answered";
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
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->goal(), internals.Goal.get()) : "";
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
  if (!ros2vtk::scene::set_field_from_text(*internals.Type->goal(), internals.Goal.get(), path, value, &error))
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
  internals.GoalId = RandomGoalId();
  internals.HasGoal = true;
  internals.GoalRequest = NewMessage(*type.send_goal()->request());
  member<UUID>(internals.GoalRequest.get(), internals.At.SendGoalId) = internals.GoalId;
  type.goal()->copy(internals.Goal.get(), static_cast<char*>(internals.GoalRequest.get()) + internals.At.SendGoalGoal);
  internals.LastFeedback = NewMessage(*type.feedback());
  internals.Result = NewMessage(*type.result());
  internals.Feedbacks = 0;
  internals.ResultStatus = 0;
  internals.LastCancelReturnCode = -1;
  internals.GoalSequence = internals.ResultSequence = internals.CancelSequence = -1;
  internals.LastError.clear();
  internals.GoalTimeout = this->EndpointTimeout;
  internals.Deadline =
    Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(this->EndpointTimeout));
  // Written at once when the server is there; otherwise on the spin that sees it (requests
  // are volatile: one written before the server's reader matched would be lost).
  internals.State = WaitingForServer;
  if (internals.ServerReady())
  {
    internals.GoalSequence = internals.SendGoalClient->send_request(internals.GoalRequest.get());
    internals.State = internals.GoalSequence >= 0 ? WaitingForAcceptance : WaitingForServer;
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
  vtkInternals& internals = *this->Internals;
  if (!internals.CancelClient || !internals.GoalActive())
  {
    vtkErrorMacro("CancelGoal: no accepted goal is running (status: " << this->GetStatusAsString() << ")");
    return false;
  }
  ros2vtk::action_msgs::srv::CancelGoal_Request request;
  request.goal_info.goal_id = internals.GoalId; // stamp 0: this goal only
  internals.CancelSequence = internals.CancelClient->send_request(&request);
  if (internals.CancelSequence < 0)
  {
    internals.LastError = "Fast DDS refused to write the cancel request to " + std::string(this->GetActionName());
    return false;
  }
  internals.CancelDeadline =
    Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(this->EndpointTimeout));
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
  std::vector<unsigned long> events;
  const Clock::time_point now = Clock::now();

  // A goal waiting for the server goes out on the first spin that sees it.
  if (internals.State == WaitingForServer && internals.ServerReady())
  {
    internals.GoalSequence = internals.SendGoalClient->send_request(internals.GoalRequest.get());
    if (internals.GoalSequence < 0)
    {
      internals.State = Failed;
      internals.LastError = "Fast DDS refused to write the goal to " + std::string(this->GetActionName());
      events.push_back(GoalFailedEvent);
    }
    else
    {
      internals.State = WaitingForAcceptance;
    }
  }

  std::vector<ros2vtk::wire::ServiceResponse> responses;
  internals.SendGoalClient->take(responses);
  for (auto& response : responses)
  {
    if (internals.State != WaitingForAcceptance || response.sequence_number != internals.GoalSequence)
    {
      continue; // an earlier goal's answer, or a second server's duplicate
    }
    if (member<bool>(response.response.get(), internals.At.Accepted))
    {
      internals.State = Accepted;
      ++internals.GoalsAccepted;
      auto request = NewMessage(*internals.Type->get_result()->request());
      member<UUID>(request.get(), internals.At.GetResultId) = internals.GoalId;
      // Asked at once (as rclcpp does with a result callback); the server answers when done.
      internals.ResultSequence = internals.GetResultClient->send_request(request.get());
      if (internals.ResultSequence < 0)
      {
        internals.State = Failed;
        internals.LastError = "Fast DDS refused to write the result request to " + std::string(this->GetActionName());
      }
    }
    else
    {
      internals.State = Rejected;
      internals.LastError = "goal rejected by " + std::string(this->GetActionName());
    }
    events.push_back(GoalResponseEvent);
  }

  std::vector<MessagePtr> messages;
  internals.FeedbackSubscription->take(messages);
  for (auto& message : messages)
  {
    if (!internals.HasGoal || internals.State == WaitingForServer ||
      member<UUID>(message.get(), internals.At.FeedbackId) != internals.GoalId)
    {
      continue; // feedback goes to every client; each keeps its own goals' (docs/wire-notes.md §8.3)
    }
    internals.Type->feedback()->copy(
      static_cast<const char*>(message.get()) + internals.At.FeedbackFeedback, internals.LastFeedback.get());
    ++internals.Feedbacks;
    events.push_back(FeedbackReceivedEvent);
  }

  messages.clear();
  internals.StatusSubscription->take(messages);
  for (auto& message : messages)
  {
    const auto& array = *static_cast<const ros2vtk::action_msgs::msg::GoalStatusArray*>(message.get());
    for (const auto& status : array.status_list)
    {
      if (!internals.GoalActive() || status.goal_info.goal_id != internals.GoalId)
      {
        continue;
      }
      // Terminal states come with the result (its own status); the topic gives the way there.
      const int before = internals.State;
      if (status.status == GoalStatus::STATUS_EXECUTING && internals.State == Accepted)
      {
        internals.State = Executing;
      }
      else if (status.status == GoalStatus::STATUS_CANCELING)
      {
        internals.State = Canceling;
      }
      if (internals.State != before)
      {
        this->Modified();
      }
    }
  }

  responses.clear();
  internals.GetResultClient->take(responses);
  for (auto& response : responses)
  {
    if (!internals.GoalActive() || response.sequence_number != internals.ResultSequence)
    {
      continue;
    }
    const void* answer = response.response.get();
    internals.ResultStatus = member<int8_t>(answer, internals.At.ResultStatus);
    internals.Type->result()->copy(static_cast<const char*>(answer) + internals.At.ResultResult, internals.Result.get());
    ++internals.Results;
    switch (internals.ResultStatus)
    {
      case GoalStatus::STATUS_SUCCEEDED: internals.State = Succeeded; break;
      case GoalStatus::STATUS_CANCELED: internals.State = Canceled; break;
      case GoalStatus::STATUS_ABORTED: internals.State = Aborted; break;
      default:
        internals.State = Failed;
        internals.LastError = std::string(this->GetActionName()) + " sent a result with status " +
          std::to_string(internals.ResultStatus) + " (not succeeded, canceled or aborted)";
    }
    events.push_back(ResultReceivedEvent);
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
      static_cast<const ros2vtk::action_msgs::srv::CancelGoal_Response*>(response.response.get())->return_code;
    if (internals.LastCancelReturnCode != 0)
    {
      internals.LastError = std::string(this->GetActionName()) + " refused to cancel the goal (return code " +
        std::to_string(internals.LastCancelReturnCode) + ")";
    }
    events.push_back(CancelResponseEvent);
  }
  if (internals.CancelSequence >= 0 && now >= internals.CancelDeadline)
  {
    internals.CancelSequence = -1;
    internals.LastError = "timed out: " + std::string(this->GetActionName()) + " did not answer the cancel request within " +
      FormatSeconds(this->EndpointTimeout);
    events.push_back(CancelResponseEvent);
  }

  if ((internals.State == WaitingForServer || internals.State == WaitingForAcceptance) && now >= internals.Deadline)
  {
    internals.LastError = internals.State == WaitingForServer
      ? "timed out: no server for " + std::string(this->GetActionName()) + " (" + std::string(this->GetActionType()) + ") appeared within " +
        FormatSeconds(internals.GoalTimeout)
      : "timed out: " + std::string(this->GetActionName()) + " did not answer the goal within " + FormatSeconds(internals.GoalTimeout);
    internals.State = TimedOut;
    events.push_back(GoalFailedEvent);
  }

  const uint64_t rejected =
    internals.FeedbackSubscription->rejected_count() + internals.StatusSubscription->rejected_count();
  const uint64_t fresh = rejected > internals.RejectedSeen ? rejected - internals.RejectedSeen : 0;
  internals.RejectedSeen = rejected;
  internals.Rejected += static_cast<vtkTypeInt64>(fresh);
  if (const uint64_t due = internals.RejectionReport.record(fresh, now))
  {
    const std::string reason = internals.StatusSubscription->last_rejection().empty()
      ? internals.FeedbackSubscription->last_rejection()
      : internals.StatusSubscription->last_rejection();
    vtkWarningMacro("action '" << this->GetActionName() << "': " << due
                               << " malformed feedback/status sample(s) rejected (total " << internals.Rejected
                               << "; latest: " << reason << ")");
  }

  if (events.empty())
  {
    return 0;
  }
  this->Modified();
  for (const unsigned long event : events)
  {
    this->InvokeEvent(event);
  }
  return static_cast<int>(events.size());
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::SpinSceneUntil(double timeoutSeconds, bool (*done)(const vtkROS2ActionClientNode*))
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
  const Clock::time_point end =
    Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeoutSeconds));
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
      if (auto* node = vtkROS2NodeNode::SafeDownCast(scene->GetNthNodeByClass(i, "vtkROS2NodeNode")))
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
    vtkErrorMacro("SendGoalAndWait: already waiting on this action client (called from an observer?)");
    return "";
  }
  const double seconds = timeoutSeconds > 0 && std::isfinite(timeoutSeconds) ? timeoutSeconds : this->EndpointTimeout;
  const double savedTimeout = this->EndpointTimeout;
  this->EndpointTimeout = seconds; // the goal's own deadline for server and acceptance
  const vtkTypeInt64 goal = this->SendGoalYAML(goalYAML);
  this->EndpointTimeout = savedTimeout;
  if (goal < 0)
  {
    internals.LastError = "invalid goal YAML";
    return "";
  }
  if (!this->SpinSceneUntil(seconds, [](const vtkROS2ActionClientNode* self) { return self->IsGoalDone(); }))
  {
    if (internals.LastError.empty())
    {
      internals.LastError = "timed out: " + std::string(this->GetActionName()) + " sent no result within " + FormatSeconds(seconds) +
        " (the goal is " + this->GetStatusAsString() + ")";
    }
    vtkErrorMacro("SendGoalAndWait " << this->GetActionName() << ": " << internals.LastError);
    return "";
  }
  if (internals.Results == 0 || internals.State == Rejected || internals.State == TimedOut || internals.State == Failed)
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
  return this->SpinSceneUntil(timeoutSeconds, [](const vtkROS2ActionClientNode* self) { return self->IsGoalDone(); });
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetGoalStatus() const
{
  return this->Internals->State;
}

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::GetStatusAsString() const
{
  switch (this->Internals->State)
  {
    case WaitingForServer: return "waiting for server";
    case WaitingForAcceptance: return "waiting for acceptance";
    case Rejected: return "rejected";
    case Accepted: return "accepted";
    case Executing: return "executing";
    case Canceling: return "canceling";
    case Succeeded: return "succeeded";
    case Canceled: return "canceled";
    case Aborted: return "aborted";
    case TimedOut: return "timed out";
    case Failed: return "failed";
    default: return "idle";
  }
}

//------------------------------------------------------------------------------
bool vtkROS2ActionClientNode::IsGoalDone() const
{
  switch (this->Internals->State)
  {
    case Rejected:
    case Succeeded:
    case Canceled:
    case Aborted:
    case TimedOut:
    case Failed: return true;
    default: return false;
  }
}

//------------------------------------------------------------------------------
const char* vtkROS2ActionClientNode::GetLastError() const
{
  return this->Internals->LastError.c_str();
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetGoalIdAsString() const
{
  if (!this->Internals->HasGoal)
  {
    return "";
  }
  std::string text;
  char digits[3];
  for (const uint8_t byte : this->Internals->GoalId.uuid)
  {
    std::snprintf(digits, sizeof(digits), "%02x", byte);
    text += digits;
  }
  return text;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ActionClientNode::GetNumberOfFeedbacks() const
{
  return this->Internals->Feedbacks;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetLastFeedbackYAML() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->feedback(), internals.LastFeedback.get()) : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetFeedbackField(const char* path) const
{
  const vtkInternals& internals = *this->Internals;
  std::string value;
  std::string error;
  if (!internals.Type || !path ||
    !ros2vtk::scene::get_field_as_text(*internals.Type->feedback(), internals.LastFeedback.get(), path, value, &error))
  {
    vtkErrorMacro("GetFeedbackField: " << (internals.Type ? error : "the client has no action type yet"));
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultYAML() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Type ? ros2vtk::wire::to_yaml(*internals.Type->result(), internals.Result.get()) : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ActionClientNode::GetResultField(const char* path) const
{
  const vtkInternals& internals = *this->Internals;
  std::string value;
  std::string error;
  if (!internals.Type || !path ||
    !ros2vtk::scene::get_field_as_text(*internals.Type->result(), internals.Result.get(), path, value, &error))
  {
    vtkErrorMacro("GetResultField: " << (internals.Type ? error : "the client has no action type yet"));
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
int vtkROS2ActionClientNode::GetResultStatus() const
{
  return this->Internals->ResultStatus;
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
  os << indent << "Feedbacks: " << this->Internals->Feedbacks << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…) live with the
// kind, so that the ROS node's own file includes no child kind (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2ActionClientNode* vtkROS2NodeNode::CreateAndAddActionClientNode(const char* type, const char* action)
{
  vtkNew<vtkROS2ActionClientNode> node;
  const bool attached = this->AdoptKeyedChild("CreateAndAddActionClientNode", ActionClientRole, node, type, action, "action",
    "this node has a client of ", "ros2:action_client:", [&] { return node->Attach(this, type, action); });
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
  return this->RemoveKeyedChild("RemoveAndDeleteActionClientNode", ActionClientRole, action, "no client of ");
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
