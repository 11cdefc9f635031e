#include "vtkROS2SubscriberGenericNode.h"

#include "vtkROS2NodeNode.h"

#include "Internal/GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/TypeDescriptionClient.hpp"

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
vtkROS2SubscriberGenericNode::vtkROS2SubscriberGenericNode() = default;

//------------------------------------------------------------------------------
vtkROS2SubscriberGenericNode::~vtkROS2SubscriberGenericNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::SetROSType(const char* rosType)
{
  bool changed = false;
  const std::string error =
    ros2vtk::scene::assign_generic_type(rosType, this->IsAddedToROS2Node(), this->Type, changed);
  if (!error.empty())
  {
    vtkErrorMacro("SetROSType: " << error);
    return false;
  }
  if (!this->RuntimeTypeName.empty())
  {
    this->RuntimeTypeName.clear(); // a registered type replaces one to be learnt
    this->NamedOnlyType.reset();
    this->TypeStatus.clear();
    changed = true;
  }
  if (changed)
  {
    this->Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::SetROSTypeResolvedAtRuntime(const char* rosType)
{
  if (rosType && ros2vtk::wire::find_message_type(rosType))
  {
    return this->SetROSType(rosType);
  }
  std::string name = rosType ? rosType : "";
  if (!ros2vtk::scene::runtime_type_name(name))
  {
    vtkErrorMacro("SetROSTypeResolvedAtRuntime: '"
      << (rosType ? rosType : "(null)") << "' is not a message type name (pkg/msg/Type)");
    return false;
  }
  if (this->IsAddedToROS2Node())
  {
    vtkErrorMacro("SetROSTypeResolvedAtRuntime: cannot change the type while added to a ROS node");
    return false;
  }
  if (name == this->RuntimeTypeName && !this->Type)
  {
    return true;
  }
  this->Type = nullptr;
  this->RuntimeTypeName = name;
  this->NamedOnlyType.reset(new ros2vtk::wire::MessageTypeSupport{});
  this->NamedOnlyType->ros_type = this->RuntimeTypeName.c_str();
  this->NamedOnlyType->dds_type_name = "";
  this->NamedOnlyType->type_hash = "";
  this->TypeStatus = "waiting to be added to a ROS node to learn " + name + " from a publisher";
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
const ros2vtk::wire::MessageTypeSupport& vtkROS2SubscriberGenericNode::GetMessageTypeSupport() const
{
  // callers check HasMessageTypeSupport() first; while the type is learnt, a table naming it
  return this->Type ? *this->Type : *this->NamedOnlyType;
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::CreateEndpoint(ros2vtk::wire::Participant& participant,
  const std::string& topic, const ros2vtk::wire::QoS& qos, std::string* error)
{
  if (this->Type)
  {
    return this->Superclass::CreateEndpoint(participant, topic, qos, error);
  }
  // No subscription yet: the resolver watches the graph, the spin subscribes once it knows.
  this->Resolver.reset(
    new ros2vtk::wire::RuntimeTypeResolver(participant, topic, this->RuntimeTypeName));
  this->TypeStatus = this->Resolver->status();
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2SubscriberGenericNode::DestroyEndpoint()
{
  this->Resolver.reset();
  this->Superclass::DestroyEndpoint();
  if (!this->Type && !this->RuntimeTypeName.empty())
  {
    this->TypeStatus =
      "waiting to be added to a ROS node to learn " + this->RuntimeTypeName + " from a publisher";
  }
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::HasEndpoint() const
{
  return this->Resolver != nullptr || this->Superclass::HasEndpoint();
}

//------------------------------------------------------------------------------
int vtkROS2SubscriberGenericNode::OnROS2NodeSpin(vtkROS2NodeNode* rosNode)
{
  if (this->Resolver)
  {
    const auto state = this->Resolver->poll();
    if (this->Resolver->status() != this->TypeStatus)
    {
      this->TypeStatus = this->Resolver->status();
      this->Modified();
    }
    if (state == ros2vtk::wire::RuntimeTypeResolver::State::Ready)
    {
      ros2vtk::wire::Participant* participant = rosNode ? rosNode->GetParticipant() : nullptr;
      this->Type = this->Resolver->type();
      this->Resolver.reset();
      std::string error;
      if (!participant ||
        !this->Superclass::CreateEndpoint(*participant, this->GetTopic(), this->GetQoS(), &error))
      {
        this->TypeStatus = "learnt " + this->RuntimeTypeName + " but cannot subscribe: " + error;
        vtkErrorMacro(<< this->TypeStatus);
        this->Type = nullptr;
      }
      this->Modified();
    }
    return 0;
  }
  return this->Superclass::OnROS2NodeSpin(rosNode);
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
