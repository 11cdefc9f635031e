#include "vtkROS2ModelNode.h"

#include "vtkROS2TransformNode.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkXMLDataElement.h"

#include <sstream>

vtkStandardNewMacro(vtkROS2ModelNode);

//------------------------------------------------------------------------------
vtkROS2ModelNode::vtkROS2ModelNode()
  : MatrixModelToParent(vtkMatrix4x4::New())
{
}

//------------------------------------------------------------------------------
vtkROS2ModelNode::~vtkROS2ModelNode()
{
  if (this->PolyData)
  {
    this->PolyData->Delete();
  }
  this->MatrixModelToParent->Delete();
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::SetPolyData(vtkPolyData* polyData)
{
  if (polyData == this->PolyData)
  {
    return;
  }
  if (polyData)
  {
    polyData->Register(this);
  }
  if (this->PolyData)
  {
    this->PolyData->UnRegister(this);
  }
  this->PolyData = polyData;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::SetMatrixModelToParent(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    vtkErrorMacro("SetMatrixModelToParent: null matrix");
    return;
  }
  this->MatrixModelToParent->DeepCopy(matrix);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::SetParentTransformNodeID(const char* id)
{
  this->SetNodeReferenceID("transform", id);
}

//------------------------------------------------------------------------------
const char* vtkROS2ModelNode::GetParentTransformNodeID() const
{
  return this->GetNodeReferenceID("transform");
}

//------------------------------------------------------------------------------
vtkROS2TransformNode* vtkROS2ModelNode::GetParentTransformNode() const
{
  return vtkROS2TransformNode::SafeDownCast(this->GetNodeReference("transform"));
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::GetMatrixModelToWorld(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    return;
  }
  vtkROS2TransformNode* parent = this->GetParentTransformNode();
  if (!parent)
  {
    matrix->DeepCopy(this->MatrixModelToParent);
    return;
  }
  vtkNew<vtkMatrix4x4> parentToWorld;
  parent->GetMatrixTransformToWorld(parentToWorld);
  vtkMatrix4x4::Multiply4x4(parentToWorld, this->MatrixModelToParent, matrix);
}

//------------------------------------------------------------------------------
bool vtkROS2ModelNode::CopyContentFrom(vtkObject* data, std::string* error)
{
  auto* polyData = vtkPolyData::SafeDownCast(data);
  if (!polyData)
  {
    return this->Superclass::CopyContentFrom(data, error);
  }
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(polyData);
  this->SetPolyData(copy);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetVectorAttribute("color", 3, this->Color);
  element->SetDoubleAttribute("opacity", this->Opacity);
  element->SetIntAttribute("visibility", this->Visibility ? 1 : 0);
  element->SetIntAttribute("scalarVisibility", this->ScalarVisibility ? 1 : 0);
  element->SetIntAttribute("representation", this->Representation);
  element->SetDoubleAttribute("pointSize", this->PointSize);
  std::ostringstream values;
  values.precision(17);
  for (int k = 0; k < 16; ++k)
  {
    values << (k ? " " : "") << this->MatrixModelToParent->GetElement(k / 4, k % 4);
  }
  element->SetAttribute("matrixModelToParent", values.str().c_str());
}

//------------------------------------------------------------------------------
bool vtkROS2ModelNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  element->GetVectorAttribute("color", 3, this->Color);
  element->GetScalarAttribute("opacity", this->Opacity);
  int visibility = 1;
  if (element->GetScalarAttribute("visibility", visibility))
  {
    this->Visibility = visibility != 0;
  }
  int scalarVisibility = 0;
  if (element->GetScalarAttribute("scalarVisibility", scalarVisibility))
  {
    this->ScalarVisibility = scalarVisibility != 0;
  }
  int representation = Surface;
  if (element->GetScalarAttribute("representation", representation))
  {
    if (representation < Points || representation > Surface)
    {
      vtkErrorMacro("ReadXML: representation must be 0 (points), 1 (wireframe) or 2 (surface), not "
        << representation);
      return false;
    }
    this->Representation = representation;
  }
  double pointSize = 1.0;
  if (element->GetScalarAttribute("pointSize", pointSize))
  {
    if (!(pointSize >= 1.0 && pointSize <= 100.0))
    {
      vtkErrorMacro("ReadXML: pointSize must be within 1..100 pixels, not " << pointSize);
      return false;
    }
    this->PointSize = pointSize;
  }
  if (const char* text = element->GetAttribute("matrixModelToParent"))
  {
    std::istringstream values(text);
    for (int k = 0; k < 16; ++k)
    {
      double value = 0;
      if (!(values >> value))
      {
        vtkErrorMacro("ReadXML: matrixModelToParent needs 16 numbers");
        return false;
      }
      this->MatrixModelToParent->SetElement(k / 4, k % 4, value);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ModelNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Color: " << this->Color[0] << " " << this->Color[1] << " " << this->Color[2]
     << "\n";
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "Visibility: " << this->Visibility << "\n";
  os << indent << "ScalarVisibility: " << this->ScalarVisibility << "\n";
  os << indent << "Representation: " << this->Representation << "\n";
  os << indent << "PointSize: " << this->PointSize << "\n";
  os << indent << "PolyData: " << this->PolyData << "\n";
}
