#include "vtkROS2SubscriberGenericNode.h"

#include "vtkROS2NodeNode.h"

#include "GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"


vtkStandardNewMacro(vtkROS2SubscriberGenericNode);

namespace
{
/// What CreateAndAddSubscriberNode makes for a type without a mapping rule.
vtkROS2TopicNode* NewGeneric(const char* rosType)
{
  vtkROS2SubscriberGenericNode* node = vtkROS2SubscriberGenericNode::New();
  if (!node->SetROSType(rosType))
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
  if (changed)
  {
    this->Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
const ros2vtk::wire::MessageTypeSupport& vtkROS2SubscriberGenericNode::GetMessageTypeSupport() const
{
  return *this->Type; // callers check HasMessageTypeSupport() first
}

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::ReadXML(vtkXMLDataElement* element)
{
  const char* rosType = ros2vtk::scene::saved_generic_type(element);
  if (rosType && !this->SetROSType(rosType))
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
// live with the kind, so that the ROS node's own file includes no child kind (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2SubscriberNode* vtkROS2NodeNode::CreateAndAddSubscriberNode(const char* type, const char* topic)
{
  return vtkROS2SubscriberNode::SafeDownCast(this->CreateAndAddTopicNode(false, type, topic, &NewGeneric));
}
