#include "vtkROS2SubscriberGenericNode.h"

#include "GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"


vtkStandardNewMacro(vtkROS2SubscriberGenericNode);

//------------------------------------------------------------------------------
vtkROS2SubscriberGenericNode::vtkROS2SubscriberGenericNode() = default;

//------------------------------------------------------------------------------
vtkROS2SubscriberGenericNode::~vtkROS2SubscriberGenericNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2SubscriberGenericNode::SetROSType(const char* rosType)
{
  if (this->IsAddedToROS2Node())
  {
    vtkErrorMacro("SetROSType: cannot change the type while added to a ROS node");
    return false;
  }
  std::string error;
  const ros2vtk::wire::MessageTypeSupport* type = ros2vtk::scene::find_generic_type(rosType, error);
  if (!type)
  {
    vtkErrorMacro("SetROSType: " << error);
    return false;
  }
  if (type != this->Type)
  {
    this->Type = type;
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
  const char* rosType = element ? element->GetAttribute("rosType") : nullptr;
  if (rosType && *rosType && !this->SetROSType(rosType))
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
