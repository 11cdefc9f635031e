#include "vtkROS2TransformNode.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkROS2TransformNode);

//------------------------------------------------------------------------------
vtkROS2TransformNode::vtkROS2TransformNode()
  : MatrixTransformToParent(vtkMatrix4x4::New())
{
}

//------------------------------------------------------------------------------
vtkROS2TransformNode::~vtkROS2TransformNode()
{
  this->MatrixTransformToParent->Delete();
}

//------------------------------------------------------------------------------
vtkMatrix4x4* vtkROS2TransformNode::GetMatrixTransformToParent()
{
  return this->MatrixTransformToParent;
}

//------------------------------------------------------------------------------
void vtkROS2TransformNode::GetMatrixTransformToParent(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    matrix->DeepCopy(this->MatrixTransformToParent);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2TransformNode::CopyContentFrom(vtkObject* data, std::string* error)
{
  auto* matrix = vtkMatrix4x4::SafeDownCast(data);
  if (!matrix)
  {
    return this->Superclass::CopyContentFrom(data, error);
  }
  this->SetMatrixTransformToParent(matrix);
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2TransformNode::SetMatrixTransformToParent(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    vtkErrorMacro("SetMatrixTransformToParent: null matrix");
    return false;
  }
  return this->SetMatrixTransformToParent(matrix->GetData());
}

//------------------------------------------------------------------------------
bool vtkROS2TransformNode::SetMatrixTransformToParent(const double elements[16])
{
  const double* current = this->MatrixTransformToParent->GetData();
  if (std::equal(elements, elements + 16, current))
  {
    return false;
  }
  this->MatrixTransformToParent->DeepCopy(elements);
  this->Modified();
  this->InvokeEvent(TransformModifiedEvent);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2TransformNode::SetParentTransformNodeID(const char* id)
{
  const char* current = this->GetParentTransformNodeID();
  if ((current ? std::string(current) : std::string()) == (id ? std::string(id) : std::string()))
  {
    return;
  }
  this->SetNodeReferenceID("transform", id);
  this->InvokeEvent(TransformModifiedEvent);
}

//------------------------------------------------------------------------------
const char* vtkROS2TransformNode::GetParentTransformNodeID() const
{
  return this->GetNodeReferenceID("transform");
}

//------------------------------------------------------------------------------
vtkROS2TransformNode* vtkROS2TransformNode::GetParentTransformNode() const
{
  return vtkROS2TransformNode::SafeDownCast(this->GetNodeReference("transform"));
}

//------------------------------------------------------------------------------
void vtkROS2TransformNode::GetMatrixTransformToWorld(vtkMatrix4x4* matrixToWorld)
{
  if (!matrixToWorld)
  {
    return;
  }
  matrixToWorld->DeepCopy(this->MatrixTransformToParent);
  std::set<const vtkROS2TransformNode*> visited{ this };
  for (vtkROS2TransformNode* parent = this->GetParentTransformNode(); parent;
       parent = parent->GetParentTransformNode())
  {
    if (!visited.insert(parent).second)
    {
      vtkWarningMacro(
        "transform hierarchy of " << this->GetID() << " has a cycle; cut at " << parent->GetID());
      break;
    }
    vtkMatrix4x4::Multiply4x4(parent->GetMatrixTransformToParent(), matrixToWorld, matrixToWorld);
  }
}

//------------------------------------------------------------------------------
void vtkROS2TransformNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  std::ostringstream values;
  values.precision(17);
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      values << (i || j ? " " : "") << this->MatrixTransformToParent->GetElement(i, j);
    }
  }
  element->SetAttribute("matrixTransformToParent", values.str().c_str());
}

//------------------------------------------------------------------------------
bool vtkROS2TransformNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  const char* text = element->GetAttribute("matrixTransformToParent");
  if (!text)
  {
    return true;
  }
  std::istringstream values(text);
  vtkNew<vtkMatrix4x4> matrix;
  for (int k = 0; k < 16; ++k)
  {
    double value = 0;
    if (!(values >> value))
    {
      vtkErrorMacro("ReadXML: matrixTransformToParent needs 16 numbers, got '" << text << "'");
      return false;
    }
    matrix->SetElement(k / 4, k % 4, value);
  }
  this->SetMatrixTransformToParent(matrix);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2TransformNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MatrixTransformToParent:\n";
  this->MatrixTransformToParent->PrintSelf(os, indent.GetNextIndent());
}
