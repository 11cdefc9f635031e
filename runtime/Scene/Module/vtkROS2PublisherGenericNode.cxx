#include "vtkROS2PublisherGenericNode.h"

#include "vtkROS2NodeNode.h"

#include "Internal/GenericMessageType.hpp"

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
  if (!node->SetROSType(rosType))
  {
    node->Delete();
    return nullptr;
  }
  return node;
}
} // namespace

//------------------------------------------------------------------------------
vtkROS2PublisherGenericNode::vtkROS2PublisherGenericNode() = default;

//------------------------------------------------------------------------------
vtkROS2PublisherGenericNode::~vtkROS2PublisherGenericNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::SetROSType(const char* rosType)
{
  bool changed = false;
  const std::string error =
    ros2vtk::scene::assign_generic_type(rosType, this->IsAddedToROS2Node(), this->Type, changed);
  if (!error.empty())
  {
    vtkErrorMacro("SetROSType: " << error);
    return false;
  }
  if (changed)
  {
    this->Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
const ros2vtk::wire::MessageTypeSupport& vtkROS2PublisherGenericNode::GetMessageTypeSupport() const
{
  return *this->Type; // callers check HasMessageTypeSupport() first
}

//------------------------------------------------------------------------------
bool vtkROS2PublisherGenericNode::PublishYAML(const char* yaml)
{
  if (!this->Type)
  {
    this->RecordFailedPublish("the message type is not set (SetROSType)");
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
  if (rosType && !this->SetROSType(rosType))
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
