#include "vtkROS2SubscriberGenericNode.h"

#include "vtkROS2NodeNode.h"

#include "Internal/GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"

#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

vtkStandardNewMacro(vtkROS2SubscriberGenericNode);

namespace {
/// What CreateAndAddSubscriberNode makes for a type without a mapping rule.
vtkROS2TopicNode* NewGeneric(const char* rosType)
{
  vtkROS2SubscriberGenericNode* node = vtkROS2SubscriberGenericNode::New();
  // A full type name nothing registers is learnt from the topic's publisher (issue 13).
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
vtkROS2SubscriberGenericNode::vtkROS2SubscriberGenericNode()
  : Learnt(new ros2vtk::scene::LearntMessageType)
{
}

//------------------------------------------------------------------------------
vtkROS2SubscriberGenericNode::~vtkROS2SubscriberGenericNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::SetROSType(const char* rosType)
{
  bool changed = false;
  const std::string error =
    this->Learnt->set_registered(rosType, this->IsAddedToROS2Node(), this->Type, changed);
  return ros2vtk::scene::finish_type_change(this, "SetROSType", error, changed);
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::SetROSTypeResolvedAtRuntime(const char* rosType)
{
  bool changed = false;
  const std::string error =
    this->Learnt->set_resolved_at_runtime(rosType, this->IsAddedToROS2Node(), this->Type,
      ros2vtk::scene::LearntMessageType::Peers::Publishers, changed);
  return ros2vtk::scene::finish_type_change(this, "SetROSTypeResolvedAtRuntime", error, changed);
}

//------------------------------------------------------------------------------
const char* vtkROS2SubscriberGenericNode::GetTypeStatus() const
{
  return this->Learnt->status().c_str();
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::IsWaitingForType() const
{
  return this->Type == nullptr && !this->Learnt->empty();
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::HasMessageTypeSupport() const
{
  return this->Type != nullptr || !this->Learnt->empty();
}

//------------------------------------------------------------------------------
const ros2vtk::wire::MessageTypeSupport& vtkROS2SubscriberGenericNode::GetMessageTypeSupport() const
{
  // callers check HasMessageTypeSupport() first; while the type is learnt, a table naming it
  return this->Type ? *this->Type : this->Learnt->named_only();
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::CreateEndpoint(ros2vtk::wire::Participant& participant,
  const std::string& topic, const ros2vtk::wire::QoS& qos, std::string* error)
{
  // No subscription yet: the graph is watched, the spin subscribes once the type is known.
  return this->Learnt->watch_unless_known(this->Type, participant, topic) ||
    this->Superclass::CreateEndpoint(participant, topic, qos, error);
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberGenericNode::DestroyEndpoint()
{
  this->Superclass::DestroyEndpoint();
  this->Learnt->stop_unless_known(this->Type);
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::HasEndpoint() const
{
  return this->Learnt->asking() || this->Superclass::HasEndpoint();
}

//------------------------------------------------------------------------------
int vtkROS2SubscriberGenericNode::OnROS2NodeSpin(vtkROS2NodeNode* rosNode)
{
  if (!this->Learnt->asking())
  {
    return this->Superclass::OnROS2NodeSpin(rosNode);
  }
  this->Learnt->spin_node(this, this->Type, rosNode ? rosNode->GetParticipant() : nullptr,
    "subscribe", [this](ros2vtk::wire::Participant& participant, std::string& error) {
      return this->Superclass::CreateEndpoint(
        participant, this->GetTopic(), this->GetQoS(), &error);
    });
  return 0;
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::ReadXML(vtkXMLDataElement* element)
{
  const char* rosType = ros2vtk::scene::saved_generic_type(element);
  if (rosType && !this->SetROSTypeResolvedAtRuntime(rosType))
  {
    return false;
  }
  return this->Superclass::ReadXML(element);
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberGenericNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2SubscriberNode* vtkROS2NodeNode::CreateAndAddSubscriberNode(
  const char* type, const char* topic)
{
  return vtkROS2SubscriberNode::SafeDownCast(
    this->CreateAndAddTopicNode(false, type, topic, &NewGeneric));
}
