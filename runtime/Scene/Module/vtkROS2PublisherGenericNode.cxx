#include "vtkROS2PublisherGenericNode.h"

#include "vtkROS2NodeNode.h"

#include "Internal/GenericMessageType.hpp"

#include "ros2vtk/wire/Participant.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

#include <memory>

vtkStandardNewMacro(vtkROS2PublisherGenericNode);

namespace {
/// What CreateAndAddPublisherNode makes for a type without a mapping rule.
vtkROS2TopicNode* NewGeneric(const char* rosType)
{
  vtkROS2PublisherGenericNode* node = vtkROS2PublisherGenericNode::New();
  // A full type name nothing registers is learnt from a peer on the topic (issue 13).
  const bool registered = rosType && ros2vtk::wire::find_message_type(rosType);
  if (!(registered ? node->SetROSType(rosType) : node->SetROSTypeResolvedAtRuntime(rosType)))
  {
    node->Delete();
    return nullptr;
  }
  return node;
}
} // namespace

//------------------------------------------------------------------------------
vtkROS2PublisherGenericNode::vtkROS2PublisherGenericNode()
  : Learnt(new ros2vtk::scene::LearntMessageType)
{
}

//------------------------------------------------------------------------------
vtkROS2PublisherGenericNode::~vtkROS2PublisherGenericNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::SetROSType(const char* rosType)
{
  bool changed = false;
  const std::string error =
    this->Learnt->set_registered(rosType, this->IsAddedToROS2Node(), this->Type, changed);
  return ros2vtk::scene::finish_type_change(this, "SetROSType", error, changed);
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::SetROSTypeResolvedAtRuntime(const char* rosType)
{
  bool changed = false;
  const std::string error =
    this->Learnt->set_resolved_at_runtime(rosType, this->IsAddedToROS2Node(), this->Type,
      ros2vtk::scene::LearntMessageType::Peers::SubscriptionsThenPublishers, changed);
  return ros2vtk::scene::finish_type_change(this, "SetROSTypeResolvedAtRuntime", error, changed);
}

//------------------------------------------------------------------------------
const char* vtkROS2PublisherGenericNode::GetTypeStatus() const
{
  return this->Learnt->status().c_str();
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::IsWaitingForType() const
{
  return this->Type == nullptr && !this->Learnt->empty();
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::HasMessageTypeSupport() const
{
  return this->Type != nullptr || !this->Learnt->empty();
}

//------------------------------------------------------------------------------
const ros2vtk::wire::MessageTypeSupport& vtkROS2PublisherGenericNode::GetMessageTypeSupport() const
{
  // callers check HasMessageTypeSupport() first; while the type is learnt, a table naming it
  return this->Type ? *this->Type : this->Learnt->named_only();
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::CreateEndpoint(ros2vtk::wire::Participant& participant,
  const std::string& topic, const ros2vtk::wire::QoS& qos, std::string* error)
{
  // No writer yet: the graph is watched, the spin creates the writer once the type is known.
  return this->Learnt->watch_unless_known(this->Type, participant, topic) ||
    this->Superclass::CreateEndpoint(participant, topic, qos, error);
}

//------------------------------------------------------------------------------
void vtkROS2PublisherGenericNode::DestroyEndpoint()
{
  this->Superclass::DestroyEndpoint();
  this->Learnt->stop_unless_known(this->Type);
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::HasEndpoint() const
{
  return this->Learnt->asking() || this->Superclass::HasEndpoint();
}

//------------------------------------------------------------------------------
int vtkROS2PublisherGenericNode::OnROS2NodeSpin(vtkROS2NodeNode* rosNode)
{
  if (!this->Learnt->asking())
  {
    return this->Superclass::OnROS2NodeSpin(rosNode);
  }
  this->Learnt->spin_node(this, this->Type, rosNode ? rosNode->GetParticipant() : nullptr,
    "publish", [this](ros2vtk::wire::Participant& participant, std::string& error) {
      return this->Superclass::CreateEndpoint(
        participant, this->GetTopic(), this->GetQoS(), &error);
    });
  return 0;
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::PublishYAML(const char* yaml)
{
  if (!this->Type)
  {
    this->RecordFailedPublish(this->Learnt->empty()
        ? "the message type is not set (SetROSType)"
        : ("the message type is not known yet: " + this->Learnt->status()).c_str());
    return false;
  }
  const ros2vtk::wire::MessageTypeSupport& type = *this->Type;
  std::unique_ptr<void, void (*)(void*)> message(type.create(), type.destroy);
  std::string error;
  if (!ros2vtk::wire::from_yaml(type, yaml ? yaml : "", message.get(), &error))
  {
    this->RecordFailedPublish(
      ("invalid YAML for " + std::string(type.ros_type) + ": " + error).c_str());
    return false;
  }
  return this->PublishMessage(message.get());
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::ReadXML(vtkXMLDataElement* element)
{
  const char* rosType = ros2vtk::scene::saved_generic_type(element);
  if (rosType && !this->SetROSTypeResolvedAtRuntime(rosType))
  {
    return false;
  }
  return this->Superclass::ReadXML(element);
}

//------------------------------------------------------------------------------
void vtkROS2PublisherGenericNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2PublisherNode* vtkROS2NodeNode::CreateAndAddPublisherNode(
  const char* type, const char* topic)
{
  return vtkROS2PublisherNode::SafeDownCast(
    this->CreateAndAddTopicNode(true, type, topic, &NewGeneric));
}
