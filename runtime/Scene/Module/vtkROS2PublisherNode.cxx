#include "vtkROS2PublisherNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "vtkROS2Message.h"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"

//------------------------------------------------------------------------------
class vtkROS2PublisherNode::vtkInternals
{
public:
  std::unique_ptr<ros2vtk::wire::Publisher> Publisher;
};

//------------------------------------------------------------------------------
vtkROS2PublisherNode::vtkROS2PublisherNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2PublisherNode::~vtkROS2PublisherNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2PublisherNode::CreateEndpoint(ros2vtk::wire::Participant& participant,
  const std::string& topic, const ros2vtk::wire::QoS& qos, std::string* error)
{
  this->Internals->Publisher =
    participant.create_publisher(this->GetMessageTypeSupport(), topic, qos, error);
  return this->Internals->Publisher != nullptr;
}

//------------------------------------------------------------------------------
void vtkROS2PublisherNode::DestroyEndpoint()
{
  this->Internals->Publisher.reset();
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherNode::HasEndpoint() const
{
  return this->Internals->Publisher != nullptr;
}

//------------------------------------------------------------------------------
int vtkROS2PublisherNode::GetNumberOfMatchedSubscriptions() const
{
  return this->Internals->Publisher
    ? static_cast<int>(this->Internals->Publisher->matched_subscriptions())
    : 0;
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherNode::PublishMessage(const void* rosMessage)
{
  ++this->NumberOfCalls;
  if (!this->Internals->Publisher)
  {
    this->LastPublishError = "Publish: not added to a ROS node (call AddToROS2Node or use "
                             "vtkROS2NodeNode::CreateAndAddPublisherNode)";
    vtkErrorMacro(<< this->LastPublishError);
    return false;
  }
  if (!rosMessage)
  {
    this->LastPublishError = "Publish: no message";
    vtkErrorMacro(<< this->LastPublishError);
    return false;
  }
  if (!this->Internals->Publisher->publish(rosMessage))
  {
    this->LastPublishError =
      "Publish: DDS refused the sample on '" + std::string(this->GetTopic()) + "'";
    vtkErrorMacro(<< this->LastPublishError);
    return false;
  }
  this->LastPublishError.clear();
  ++this->NumberOfMessagesSent; // no ModifiedEvent: publishing is not a change of the node
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherNode::PublishMessageObject(vtkROS2Message* message)
{
  if (!message || !message->GetTypeSupport())
  {
    this->RecordFailedPublish("PublishMessageObject: the message object has no type");
    return false;
  }
  if (!this->HasMessageTypeSupport() || message->GetTypeSupport() != &this->GetMessageTypeSupport())
  {
    const std::string reason = std::string("PublishMessageObject: a ") + message->GetROSType() +
      " cannot go on a " +
      (this->HasMessageTypeSupport() ? this->GetMessageTypeSupport().ros_type : "(type not set)") +
      " publisher";
    this->RecordFailedPublish(reason.c_str());
    return false;
  }
  return this->PublishMessage(message->GetRawMessage());
}

//------------------------------------------------------------------------------
vtkROS2Message* vtkROS2PublisherNode::CreateMessageObject() const
{
  if (!this->HasMessageTypeSupport())
  {
    return nullptr;
  }
  vtkROS2Message* message = vtkROS2Message::New();
  message->SetROSType(this->GetMessageTypeSupport().ros_type);
  return message;
}

//------------------------------------------------------------------------------
void vtkROS2PublisherNode::SetHeaderStamp(int sec, unsigned int nanosec)
{
  if (nanosec >= 1000000000u)
  {
    vtkErrorMacro("SetHeaderStamp: nanosec " << nanosec << " is not below 1e9");
    return;
  }
  this->HeaderStampIsFixed = true;
  this->FixedHeaderStampNanoseconds = static_cast<vtkTypeInt64>(sec) * 1000000000 + nanosec;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2PublisherNode::UseNodeClockForHeaderStamp()
{
  if (this->HeaderStampIsFixed)
  {
    this->HeaderStampIsFixed = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2PublisherNode::GetStampTimeNanoseconds() const
{
  if (this->HeaderStampIsFixed)
  {
    return this->FixedHeaderStampNanoseconds;
  }
  const vtkROS2NodeNode* rosNode = this->GetROS2Node();
  return rosNode ? rosNode->GetNodeTimeNanoseconds() : 0;
}

//------------------------------------------------------------------------------
void vtkROS2PublisherNode::RecordFailedPublish(const char* reason)
{
  ++this->NumberOfCalls;
  this->LastPublishError = reason ? reason : "failed";
  vtkErrorMacro("Publish on '" << this->GetTopic() << "': " << (reason ? reason : "failed"));
}

//------------------------------------------------------------------------------
int vtkROS2PublisherNode::PublishObject(vtkObject* object)
{
  if (auto* message = vtkROS2Message::SafeDownCast(object))
  {
    return this->PublishMessageObject(message) ? 1 : 0;
  }
  const std::string reason = std::string("PublishObject: ") + this->GetClassName() + " publishes " +
    this->GetSlicerType() + ", not " + (object ? object->GetClassName() : "a null object");
  this->RecordFailedPublish(reason.c_str());
  return 0;
}

//------------------------------------------------------------------------------
int vtkROS2PublisherNode::PublishValue(const vtkVariant& value)
{
  const std::string reason = std::string("PublishValue: ") + this->GetClassName() + " publishes " +
    this->GetSlicerType() + ", not a " + (value.IsValid() ? value.GetTypeAsString() : "invalid") +
    " value";
  this->RecordFailedPublish(reason.c_str());
  return 0;
}

//------------------------------------------------------------------------------
void vtkROS2PublisherNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCalls: " << this->NumberOfCalls << "\n";
  os << indent << "NumberOfMessagesSent: " << this->NumberOfMessagesSent << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2PublisherNode* vtkROS2NodeNode::GetPublisherNodeByTopic(const char* topic)
{
  return vtkROS2PublisherNode::SafeDownCast(this->FindChildByName(PublisherRole, topic));
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetNumberOfPublisherNodes()
{
  return this->GetNumberOfNodeReferences(PublisherRole);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeletePublisherNode(const char* topic)
{
  vtkROS2PublisherNode* node = this->GetPublisherNodeByTopic(topic);
  if (!node)
  {
    vtkErrorMacro(
      "RemoveAndDeletePublisherNode: no publisher on '" << (topic ? topic : "(null)") << "'");
    return false;
  }
  node->RemoveFromROS2Node();
  return this->Scene ? this->Scene->RemoveNode(node) : true;
}

//------------------------------------------------------------------------------
const char* vtkROS2PublisherNode::GetROS2NodeReferenceRole() const
{
  return vtkROS2NodeNode::PublisherRole;
}
