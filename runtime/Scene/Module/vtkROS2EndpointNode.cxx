// ros2vtk — vtkROS2EndpointNode: the type, name, timeout, scene-file attributes and life cycle
// shared by the service and action endpoint nodes.
#include "vtkROS2EndpointNode.h"

#include "vtkROS2NodeNode.h"

#include "vtkXMLDataElement.h"

#include <cctype>
#include <cmath>

//------------------------------------------------------------------------------
vtkROS2EndpointNode::vtkROS2EndpointNode(const char* kind, const char* timeoutAttribute)
  : Kind(kind)
  , TimeoutAttribute(timeoutAttribute)
{
}

vtkROS2EndpointNode::~vtkROS2EndpointNode() = default;

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::EndpointAttached(
  vtkROS2NodeNode* rosNode, const char* type, const std::string& name, const std::string& resolved)
{
  this->EndpointType = type;
  this->Name = name;
  this->ResolvedName = resolved;
  this->SetNodeReferenceID(ROS2NodeReferenceRole, rosNode->GetID());
}

//------------------------------------------------------------------------------
const char* vtkROS2EndpointNode::GetEndpointName() const
{
  return this->IsEndpointAttached() ? this->ResolvedName.c_str() : this->Name.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::SetEndpointTimeout(const char* method, double seconds)
{
  if (!(seconds > 0) || !std::isfinite(seconds))
  {
    vtkErrorMacro(<< method << ": " << seconds << " is not a positive number of seconds");
    return;
  }
  if (seconds != this->EndpointTimeout)
  {
    this->EndpointTimeout = seconds;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::OnRemovedFromScene()
{
  this->Detach();
  this->Superclass::OnRemovedFromScene();
}

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::OnSceneRestored()
{
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (rosNode && rosNode->GetParticipant() && !this->IsEndpointAttached() &&
    !this->EndpointType.empty())
  {
    // A copy: Attach records the name it is given.
    const std::string type = this->EndpointType;
    const std::string name = this->Name;
    this->Attach(rosNode, type, name);
  }
}

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute((this->Kind + "Type").c_str(), this->EndpointType.c_str());
  element->SetAttribute((this->Kind + "Name").c_str(), this->Name.c_str());
  if (this->TimeoutAttribute)
  {
    element->SetDoubleAttribute(this->TimeoutAttribute, this->EndpointTimeout);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2EndpointNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  if (const char* type = element->GetAttribute((this->Kind + "Type").c_str()))
  {
    this->EndpointType = type;
  }
  if (const char* name = element->GetAttribute((this->Kind + "Name").c_str()))
  {
    this->Name = name;
  }
  double timeout = 0;
  if (this->TimeoutAttribute && element->GetScalarAttribute(this->TimeoutAttribute, timeout) &&
    timeout > 0 && std::isfinite(timeout))
  {
    this->EndpointTimeout = timeout;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2EndpointNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  std::string label = this->Kind;
  if (!label.empty())
  {
    label[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(label[0])));
  }
  os << indent << label << "Name: " << this->GetEndpointName() << "\n";
  os << indent << label << "Type: " << this->EndpointType << "\n";
  if (this->TimeoutAttribute)
  {
    os << indent << "Timeout: " << this->EndpointTimeout << "\n";
  }
}
