// ros2vtk — an image held in the scene (see the header).
#include "vtkROS2VolumeNode.h"

#include "vtkROS2TransformNode.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkROS2VolumeNode);

//------------------------------------------------------------------------------
vtkROS2VolumeNode::vtkROS2VolumeNode()
{
  this->SetSaveWithScene(false);
}

//------------------------------------------------------------------------------
vtkROS2VolumeNode::~vtkROS2VolumeNode()
{
  this->SetImageData(nullptr);
}

//------------------------------------------------------------------------------
void vtkROS2VolumeNode::SetImageData(vtkImageData* image)
{
  if (image == this->ImageData)
  {
    return;
  }
  if (image)
  {
    image->Register(this);
  }
  if (this->ImageData)
  {
    this->ImageData->UnRegister(this);
  }
  this->ImageData = image;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2VolumeNode::SetParentTransformNodeID(const char* id)
{
  this->SetNodeReferenceID("transform", id);
}

//------------------------------------------------------------------------------
const char* vtkROS2VolumeNode::GetParentTransformNodeID() const
{
  return this->GetNodeReferenceID("transform");
}

//------------------------------------------------------------------------------
vtkROS2TransformNode* vtkROS2VolumeNode::GetParentTransformNode() const
{
  return vtkROS2TransformNode::SafeDownCast(this->GetNodeReference("transform"));
}

//------------------------------------------------------------------------------
void vtkROS2VolumeNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageData: " << this->ImageData << "\n";
  os << indent << "Window: " << this->Window << " Level: " << this->Level << "\n";
  os << indent << "Visibility: " << this->Visibility << "\n";
}
