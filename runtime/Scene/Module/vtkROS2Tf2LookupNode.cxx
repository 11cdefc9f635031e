#include "vtkROS2Tf2LookupNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/convert/Units.hpp"
#include "ros2vtk/tf2/BufferCore.hpp"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

vtkStandardNewMacro(vtkROS2Tf2LookupNode);

//------------------------------------------------------------------------------
vtkROS2Tf2LookupNode::vtkROS2Tf2LookupNode()
  : LastResult(new ros2vtk::tf2::LookupResult())
{
}
vtkROS2Tf2LookupNode::~vtkROS2Tf2LookupNode() = default;

//------------------------------------------------------------------------------
void vtkROS2Tf2LookupNode::SetParentID(const char* frame)
{
  const std::string value = frame ? frame : "";
  if (value != this->ParentFrame)
  {
    this->ParentFrame = value;
    this->Status = 0;
    this->ROS2NodeChildKeyChanged();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkROS2Tf2LookupNode::SetChildID(const char* frame)
{
  const std::string value = frame ? frame : "";
  if (value != this->ChildFrame)
  {
    this->ChildFrame = value;
    this->Status = 0;
    this->ROS2NodeChildKeyChanged();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkROS2Tf2LookupNode::OnROS2NodeSpin(vtkROS2NodeNode* rosNode)
{
  const ros2vtk::tf2::BufferCore* buffer = rosNode->GetTf2Buffer();
  return buffer && this->UpdateFromBuffer(*buffer) ? 1 : 0;
}

//------------------------------------------------------------------------------
const char* vtkROS2Tf2LookupNode::GetLookupStatus() const
{
  return this->Status == 1 ? "ok" : this->Status == 2 ? "failed" : "waiting";
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2LookupNode::IsDifferentFromLast(int sec, int nsec) const
{
  return this->LastStampNanoseconds != static_cast<long long>(sec) * 1000000000LL + nsec;
}

//------------------------------------------------------------------------------
double vtkROS2Tf2LookupNode::GetLastLookupAge() const
{
  const vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (!rosNode || this->Status == 0)
  {
    return -1.0;
  }
  return static_cast<double>(rosNode->GetNodeTimeNanoseconds() - this->LastStampNanoseconds) / 1e9;
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2Tf2LookupNode::GetROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2LookupNode::UpdateFromBuffer(const ros2vtk::tf2::BufferCore& buffer)
{
  if (!this->IsParentAndChildSet())
  {
    return false;
  }
  ros2vtk::tf2::LookupResult& result = *this->LastResult; // reused: see BufferCore
  const bool wasOk = this->Status == 1;
  const ros2vtk::tf2::Transform previous = result.transform;
  buffer.lookup_transform(this->ParentFrame, this->ChildFrame, ros2vtk::tf2::kLatestTime, result);
  if (!result.ok)
  {
    // Reported once per failure episode (SlicerROS2 logs it at every spin, 50 times a second).
    // Waiting for frames at start-up is normal: only a lookup that used to work is logged.
    this->LastError = result.message;
    if (this->Status == 1)
    {
      vtkWarningMacro("tf2 lookup " << this->ParentFrame << " <- " << this->ChildFrame
                                    << " failed: " << result.message);
      this->Status = 2;
      this->Modified();
    }
    return false;
  }
  this->Status = 1;
  this->LastError.clear();
  const bool newStamp = result.stamp != this->LastStampNanoseconds;
  this->LastStampNanoseconds = result.stamp;
  this->LastStamp = static_cast<double>(result.stamp) * 1e-9;
  const double scale = this->ScaleLengths ? ros2vtk::convert::kMillimetresPerMetre : 1.0;
  bool changed = false;
  if (!wasOk || result.transform != previous || scale != this->AppliedScale ||
    this->MatrixTransformToParent->GetMTime() != this->AppliedMatrixTime)
  {
    double elements[16];
    ros2vtk::convert::isometry_to_elements(result.isometry(), scale, elements);
    changed = this->SetMatrixTransformToParent(elements);
    this->AppliedScale = scale;
    this->AppliedMatrixTime = this->MatrixTransformToParent->GetMTime();
  }
  if (!changed && newStamp && this->ModifiedOnLookup)
  {
    this->Modified();
  }
  return changed;
}

//------------------------------------------------------------------------------
void vtkROS2Tf2LookupNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute("parentFrame", this->ParentFrame.c_str());
  element->SetAttribute("childFrame", this->ChildFrame.c_str());
  element->SetIntAttribute("scaleLengths", this->ScaleLengths ? 1 : 0);
  element->SetIntAttribute("modifiedOnLookup", this->ModifiedOnLookup ? 1 : 0);
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2LookupNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  this->SetParentID(element->GetAttribute("parentFrame"));
  this->SetChildID(element->GetAttribute("childFrame"));
  int scale = 1;
  if (element->GetScalarAttribute("scaleLengths", scale))
  {
    this->ScaleLengths = scale != 0;
  }
  int modifiedOnLookup = 0;
  if (element->GetScalarAttribute("modifiedOnLookup", modifiedOnLookup))
  {
    this->ModifiedOnLookup = modifiedOnLookup != 0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2Tf2LookupNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParentID: " << this->ParentFrame << "\n";
  os << indent << "ChildID: " << this->ChildFrame << "\n";
  os << indent << "LookupStatus: " << this->GetLookupStatus() << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2Tf2LookupNode* vtkROS2NodeNode::CreateAndAddTf2LookupNode(
  const char* parentFrame, const char* childFrame)
{
  if (!this->CheckReadyFor("CreateAndAddTf2LookupNode") || !this->GetTf2Buffer())
  {
    return nullptr;
  }
  if (!parentFrame || !*parentFrame || !childFrame || !*childFrame)
  {
    vtkErrorMacro("CreateAndAddTf2LookupNode: parent and child frames are required");
    return nullptr;
  }
  if (this->FindChildByFrames(Tf2LookupRole, parentFrame, childFrame))
  {
    vtkErrorMacro(
      "CreateAndAddTf2LookupNode: " << parentFrame << " <- " << childFrame << " exists already");
    return nullptr;
  }
  vtkNew<vtkROS2Tf2LookupNode> node;
  node->SetParentID(parentFrame);
  node->SetChildID(childFrame);
  node->SetName((std::string("ros2:tf2lookup:") + parentFrame + "To" + childFrame).c_str());
  this->Scene->AddNode(node);
  this->AddChild(Tf2LookupRole, node);
  // A first lookup right away, so data already in the buffer shows without waiting for a spin.
  node->UpdateFromBuffer(*this->GetTf2Buffer());
  return node;
}

//------------------------------------------------------------------------------
vtkROS2Tf2LookupNode* vtkROS2NodeNode::GetTf2LookupNodeByParentChild(
  const char* parentFrame, const char* childFrame)
{
  return vtkROS2Tf2LookupNode::SafeDownCast(
    this->FindChildByFrames(Tf2LookupRole, parentFrame, childFrame));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2LookupNode(const char* parentFrame, const char* childFrame)
{
  vtkROS2Tf2LookupNode* node = this->GetTf2LookupNodeByParentChild(parentFrame, childFrame);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2LookupNode: no lookup "
      << (parentFrame ? parentFrame : "") << " <- " << (childFrame ? childFrame : ""));
    return false;
  }
  return this->RemoveChild(Tf2LookupRole, node);
}

//------------------------------------------------------------------------------
vtkROS2Tf2LookupNode* vtkROS2NodeNode::GetTf2LookupNodeByID(const char* nodeID)
{
  return vtkROS2Tf2LookupNode::SafeDownCast(this->FindChildByID(Tf2LookupRole, nodeID));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2LookupNode(const char* nodeID)
{
  vtkROS2SceneNode* node = this->FindChildByID(Tf2LookupRole, nodeID);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2LookupNode: " << (nodeID ? nodeID : "(null)")
                                                   << " is not a tf2 lookup of this node");
    return false;
  }
  return this->RemoveChild(Tf2LookupRole, node);
}
