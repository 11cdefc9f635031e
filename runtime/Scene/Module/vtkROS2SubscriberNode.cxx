#include "vtkROS2SubscriberNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "vtkROS2Message.h"

#include "Internal/RateLimitedReport.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include "vtkCommand.h"

#include <chrono>
#include <vector>

namespace {
// At most one warning about malformed samples per subscriber in this interval.
constexpr std::chrono::seconds RejectionReportInterval(5);
} // namespace

//------------------------------------------------------------------------------
class vtkROS2SubscriberNode::vtkInternals
{
public:
  std::unique_ptr<ros2vtk::wire::Subscription> Subscription;
  // Messages of the latest spin that brought any; the newest is Batch.back().
  std::vector<ros2vtk::wire::MessagePtr> Batch;
  int NumberOfNewMessages = 0;
  std::chrono::steady_clock::time_point LastMessageArrival{};
  bool HasMessage = false;
  uint64_t RejectedSeen = 0; // rejected_count() of the current subscription already counted
  std::string LastRejectionReason;
  uint64_t IncompatibleSeen = 0; // incompatible_qos_count() of the current subscription reported
  std::string LastIncompatibleQoSPolicy;
  std::string LastTargetError; // reported once per distinct reason
  ros2vtk::scene::RateLimitedReport RejectionReport{ RejectionReportInterval };
};

//------------------------------------------------------------------------------
vtkROS2SubscriberNode::vtkROS2SubscriberNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2SubscriberNode::~vtkROS2SubscriberNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2SubscriberNode::CreateEndpoint(ros2vtk::wire::Participant& participant,
  const std::string& topic, const ros2vtk::wire::QoS& qos, std::string* error)
{
  this->Internals->Subscription =
    participant.create_subscription(this->GetMessageTypeSupport(), topic, qos, error);
  this->Internals->RejectedSeen = 0;
  this->Internals->IncompatibleSeen = 0;
  return this->Internals->Subscription != nullptr;
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::DestroyEndpoint()
{
  this->Internals->Subscription.reset();
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberNode::HasEndpoint() const
{
  return this->Internals->Subscription != nullptr;
}

//------------------------------------------------------------------------------
int vtkROS2SubscriberNode::GetNumberOfMatchedPublications() const
{
  return this->Internals->Subscription
    ? static_cast<int>(this->Internals->Subscription->matched_publications())
    : 0;
}

const char* const vtkROS2SubscriberNode::TargetNodeReferenceRole = "target";

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::SetTargetNodeID(const char* nodeID)
{
  this->SetNodeReferenceID(TargetNodeReferenceRole, nodeID && *nodeID ? nodeID : nullptr);
  this->Internals->LastTargetError.clear();
}

//------------------------------------------------------------------------------
const char* vtkROS2SubscriberNode::GetTargetNodeID() const
{
  return this->GetNodeReferenceID(TargetNodeReferenceRole);
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::UpdateTargetNode()
{
  const char* targetID = this->GetTargetNodeID();
  if (!targetID)
  {
    return;
  }
  std::string error;
  vtkROS2SceneNode* target = this->GetNodeReference(TargetNodeReferenceRole);
  if (!target)
  {
    error = std::string("target node '") + targetID + "' is not in the scene";
  }
  else if (vtkObject* message = this->GetLastMessageAsObject())
  {
    if (target->CopyContentFrom(message, &error))
    {
      this->Internals->LastTargetError.clear();
      return;
    }
  }
  else
  {
    error = std::string("a ") + this->GetSlicerType() +
      " subscriber has no VTK object to copy into target node '" + targetID + "'";
  }
  if (error != this->Internals->LastTargetError) // once per reason, not once per spin
  {
    this->Internals->LastTargetError = error;
    vtkErrorMacro("subscriber on '" << this->GetTopic() << "': " << error);
  }
}

//------------------------------------------------------------------------------
int vtkROS2SubscriberNode::ProcessIncomingMessages()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Subscription)
  {
    return 0;
  }
  this->ReportRejections();
  this->ReportIncompatibleQoS();

  std::vector<ros2vtk::wire::MessagePtr> taken;
  internals.Subscription->take(taken);
  internals.NumberOfNewMessages = static_cast<int>(taken.size());
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  this->SpinTimeNanoseconds = rosNode ? rosNode->GetNodeTimeNanoseconds() : 0;
  const bool expired = this->ExpireKeptState(this->SpinTimeNanoseconds);
  if (taken.empty())
  {
    if (expired)
    {
      int none = 0;
      this->UpdateTargetNode();
      this->MTime.Modified();
      this->InvokeEvent(vtkCommand::ModifiedEvent, &none);
    }
    return 0;
  }
  internals.Batch = std::move(taken);
  internals.LastMessageArrival = std::chrono::steady_clock::now();
  internals.HasMessage = true;
  this->NumberOfMessages += internals.NumberOfNewMessages;
  this->OnNewMessages();
  this->UpdateTargetNode();

  // One event per spin, with the count: MTime is bumped by hand because vtkObject::Modified()
  // would fire its own ModifiedEvent without call data.
  int count = internals.NumberOfNewMessages;
  this->MTime.Modified();
  this->InvokeEvent(vtkCommand::ModifiedEvent, &count);
  return count;
}

//------------------------------------------------------------------------------
double vtkROS2SubscriberNode::GetSecondsSinceLastMessage() const
{
  if (!this->Internals->HasMessage)
  {
    return -1.0;
  }
  return std::chrono::duration<double>(
    std::chrono::steady_clock::now() - this->Internals->LastMessageArrival)
    .count();
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::ReportRejections()
{
  vtkInternals& internals = *this->Internals;
  const uint64_t rejected = internals.Subscription->rejected_count();
  const uint64_t fresh = rejected > internals.RejectedSeen ? rejected - internals.RejectedSeen : 0;
  internals.RejectedSeen = rejected;
  if (fresh > 0)
  {
    this->NumberOfRejectedMessages += static_cast<vtkTypeInt64>(fresh);
    internals.LastRejectionReason = internals.Subscription->last_rejection();
  }
  const uint64_t due =
    internals.RejectionReport.record(fresh, ros2vtk::scene::RateLimitedReport::Clock::now());
  if (due > 0)
  {
    vtkWarningMacro("topic '" << this->GetTopic() << "': " << due
                              << " malformed sample(s) rejected (total "
                              << this->NumberOfRejectedMessages
                              << "); latest: " << internals.LastRejectionReason);
  }
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::ReportIncompatibleQoS()
{
  vtkInternals& internals = *this->Internals;
  const uint64_t incompatible = internals.Subscription->incompatible_qos_count();
  if (incompatible <= internals.IncompatibleSeen)
  {
    return;
  }
  const uint64_t fresh = incompatible - internals.IncompatibleSeen;
  internals.IncompatibleSeen = incompatible;
  this->NumberOfIncompatibleQoSPublishers += static_cast<vtkTypeInt64>(fresh);
  internals.LastIncompatibleQoSPolicy = internals.Subscription->last_incompatible_qos_policy();
  vtkWarningMacro(
    "topic '" << this->GetTopic() << "': " << fresh
              << " publisher(s) offering incompatible QoS; no messages will arrive from "
                 "them. Last incompatible policy: "
              << internals.LastIncompatibleQoSPolicy << " (this subscriber requests "
              << this->GetQoSDescription() << ")");
}

//------------------------------------------------------------------------------
const char* vtkROS2SubscriberNode::GetLastIncompatibleQoSPolicy() const
{
  return this->Internals->LastIncompatibleQoSPolicy.c_str();
}

//------------------------------------------------------------------------------
const char* vtkROS2SubscriberNode::GetLastRejectionReason() const
{
  return this->Internals->LastRejectionReason.c_str();
}

//------------------------------------------------------------------------------
const void* vtkROS2SubscriberNode::GetLastRawMessage() const
{
  return this->Internals->Batch.empty() ? nullptr : this->Internals->Batch.back().get();
}

//------------------------------------------------------------------------------
int vtkROS2SubscriberNode::GetNumberOfNewMessages() const
{
  return this->Internals->NumberOfNewMessages;
}

//------------------------------------------------------------------------------
const void* vtkROS2SubscriberNode::GetNewRawMessage(int i) const
{
  if (i < 0 || i >= this->Internals->NumberOfNewMessages)
  {
    return nullptr;
  }
  return this->Internals->Batch[static_cast<size_t>(i)].get();
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::WarnIfNeverSpun(const char* call) const
{
  vtkROS2NodeNode* node = this->GetROS2Node();
  if (this->WarnedNeverSpun || !node || !node->GetParticipant() || node->GetSpinning())
  {
    return;
  }
  this->WarnedNeverSpun = true;
  // vtkWarningMacro fires WarningEvent on `this`, which is not const.
  auto* self = const_cast<vtkROS2SubscriberNode*>(this);
  vtkWarningWithObjectMacro(
    self, << call << " on " << this->GetTopic() << ": ROS node " << node->GetROS2NodeName()
          << " has never spun, so nothing is received; call logic.Spin() "
          << "in your loop, or logic.SpinFor(seconds) / logic.AttachToInteractor(interactor)");
}

//------------------------------------------------------------------------------
std::string vtkROS2SubscriberNode::GetLastMessageYAML() const
{
  this->WarnIfNeverSpun("GetLastMessageYAML");
  const void* message = this->GetLastRawMessage();
  if (!message)
  {
    return std::string();
  }
  return ros2vtk::wire::to_yaml(*this->Internals->Batch.back().type(), message);
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberNode::GetLastMessageStringField(
  const char* fieldName, std::string& value) const
{
  const void* message = this->GetLastRawMessage();
  if (!message || !fieldName)
  {
    return false;
  }
  const ros2vtk::wire::MessageTypeSupport& type = *this->Internals->Batch.back().type();
  for (uint32_t i = 0; i < type.field_count; ++i)
  {
    const ros2vtk::wire::FieldInfo& field = type.fields[i];
    if (field.type == ros2vtk::wire::FieldType::String &&
      field.container == ros2vtk::wire::Container::None && std::string(field.name) == fieldName)
    {
      // Generated structs hold `string` fields as std::string at the recorded offset.
      value =
        *reinterpret_cast<const std::string*>(static_cast<const char*>(message) + field.offset);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberNode::GetLastMessageObject(vtkROS2Message* message) const
{
  const void* raw = this->GetLastRawMessage();
  if (!raw || !message)
  {
    return false;
  }
  message->CopyFromRaw(*this->Internals->Batch.back().type(), raw);
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberNode::GetNewMessageObject(int i, vtkROS2Message* message) const
{
  const void* raw = this->GetNewRawMessage(i);
  if (!raw || !message)
  {
    return false;
  }
  message->CopyFromRaw(*this->Internals->Batch[static_cast<size_t>(i)].type(), raw);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfMessages: " << this->NumberOfMessages << "\n";
  os << indent << "NumberOfRejectedMessages: " << this->NumberOfRejectedMessages << "\n";
  os << indent << "LastRejectionReason: " << this->Internals->LastRejectionReason << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2SubscriberNode* vtkROS2NodeNode::GetSubscriberNodeByTopic(const char* topic)
{
  return vtkROS2SubscriberNode::SafeDownCast(this->FindChildByName(SubscriberRole, topic));
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetNumberOfSubscriberNodes()
{
  return this->GetNumberOfNodeReferences(SubscriberRole);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteSubscriberNode(const char* topic)
{
  vtkROS2SubscriberNode* node = this->GetSubscriberNodeByTopic(topic);
  if (!node)
  {
    vtkErrorMacro(
      "RemoveAndDeleteSubscriberNode: no subscriber on '" << (topic ? topic : "(null)") << "'");
    return false;
  }
  node->RemoveFromROS2Node();
  return this->Scene ? this->Scene->RemoveNode(node) : true;
}

//------------------------------------------------------------------------------
const char* vtkROS2SubscriberNode::GetROS2NodeReferenceRole() const
{
  return vtkROS2NodeNode::SubscriberRole;
}
