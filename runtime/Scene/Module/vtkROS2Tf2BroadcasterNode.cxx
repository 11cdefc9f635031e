#include "vtkROS2Tf2BroadcasterNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2TransformNode.h"

#include "ros2vtk/convert/RigidTransform.hpp"
#include "ros2vtk/convert/Units.hpp"
#include "ros2vtk/tf2_ros/TransformBroadcaster.hpp"

#include "vtkCallbackCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLDataElement.h"

vtkStandardNewMacro(vtkROS2Tf2BroadcasterNode);

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode::vtkROS2Tf2BroadcasterNode() = default;

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode::~vtkROS2Tf2BroadcasterNode()
{
  this->ObserveTransformNode(nullptr);
}

//------------------------------------------------------------------------------
void vtkROS2Tf2BroadcasterNode::OnRemovedFromScene()
{
  this->ObserveTransformNode(nullptr);
}

//------------------------------------------------------------------------------
void vtkROS2Tf2BroadcasterNode::SetParentID(const char* frame)
{
  this->ParentFrame = frame ? frame : "";
  this->ROS2NodeChildKeyChanged();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2Tf2BroadcasterNode::SetChildID(const char* frame)
{
  this->ChildFrame = frame ? frame : "";
  this->ROS2NodeChildKeyChanged();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2Tf2BroadcasterNode::GetROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2BroadcasterNode::Broadcast(vtkROS2TransformNode* node)
{
  if (!node)
  {
    vtkErrorMacro("Broadcast: no transform node");
    return false;
  }
  return this->Broadcast(node->GetMatrixTransformToParent());
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2BroadcasterNode::Broadcast(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    vtkErrorMacro("Broadcast: null matrix");
    return false;
  }
  if (!this->IsParentAndChildSet())
  {
    vtkErrorMacro("Broadcast: set the parent and child frame ids first");
    return false;
  }
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  ros2vtk::tf2_ros::TransformBroadcaster* broadcaster =
    rosNode ? rosNode->GetTf2Broadcaster(this->Static) : nullptr;
  if (!broadcaster)
  {
    vtkErrorMacro("Broadcast: " << this->ParentFrame << " <- " << this->ChildFrame
                                << ": not attached to a created ROS node");
    return false;
  }
  ros2vtk::convert::RigidPose pose;
  std::string error;
  const double scale = this->ScaleLengths ? ros2vtk::convert::kMillimetresPerMetre : 1.0;
  if (!ros2vtk::convert::matrix_to_pose(matrix, scale, &pose, &error))
  {
    vtkErrorMacro("Broadcast: " << error);
    return false;
  }
  ros2vtk::tf2::TransformStamped transform;
  transform.frame_id = this->ParentFrame;
  transform.child_frame_id = this->ChildFrame;
  // The ROS node's clock: simulated time when its use_sim_time is on (tf2_ros stamps with the
  // node clock too), so lookups by peers in the same time base succeed.
  transform.stamp = rosNode->GetNodeTimeNanoseconds();
  transform.transform.translation =
    Eigen::Vector3d(pose.translation[0], pose.translation[1], pose.translation[2]);
  transform.transform.rotation =
    Eigen::Quaterniond(pose.rotation[3], pose.rotation[0], pose.rotation[1], pose.rotation[2]);
  if (!broadcaster->send(transform, &error))
  {
    vtkErrorMacro("Broadcast: " << error);
    return false;
  }
  ++this->NumberOfBroadcasts;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2BroadcasterNode::ObserveTransformNode(vtkROS2TransformNode* node)
{
  if (this->ObservedNode)
  {
    this->ObservedNode->RemoveObserver(this->ObserverTag);
    this->ObservedNode->UnRegister(this);
    this->ObservedNode = nullptr;
  }
  if (!node)
  {
    return true;
  }
  this->ObservedNode = node;
  node->Register(this);
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(this);
  callback->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
    auto* self = static_cast<vtkROS2Tf2BroadcasterNode*>(clientData);
    self->Broadcast(static_cast<vtkROS2TransformNode*>(caller)->GetMatrixTransformToParent());
  });
  this->ObserverTag = node->AddObserver(vtkROS2TransformNode::TransformModifiedEvent, callback);
  return this->Broadcast(node->GetMatrixTransformToParent());
}

//------------------------------------------------------------------------------
void vtkROS2Tf2BroadcasterNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute("parentFrame", this->ParentFrame.c_str());
  element->SetAttribute("childFrame", this->ChildFrame.c_str());
  element->SetIntAttribute("static", this->Static ? 1 : 0);
  element->SetIntAttribute("scaleLengths", this->ScaleLengths ? 1 : 0);
}

//------------------------------------------------------------------------------
bool vtkROS2Tf2BroadcasterNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  this->SetParentID(element->GetAttribute("parentFrame"));
  this->SetChildID(element->GetAttribute("childFrame"));
  int value = 0;
  if (element->GetScalarAttribute("static", value))
    this->Static = value != 0;
  if (element->GetScalarAttribute("scaleLengths", value))
    this->ScaleLengths = value != 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2Tf2BroadcasterNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParentID: " << this->ParentFrame << "\n";
  os << indent << "ChildID: " << this->ChildFrame << "\n";
  os << indent << "Static: " << this->Static << "\n";
  os << indent << "NumberOfBroadcasts: " << this->NumberOfBroadcasts << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode* vtkROS2NodeNode::CreateAndAddTf2BroadcasterNode(
  const char* parentFrame, const char* childFrame)
{
  if (!this->CheckReadyFor("CreateAndAddTf2BroadcasterNode"))
  {
    return nullptr;
  }
  if (!parentFrame || !*parentFrame || !childFrame || !*childFrame)
  {
    vtkErrorMacro("CreateAndAddTf2BroadcasterNode: parent and child frames are required");
    return nullptr;
  }
  if (this->FindChildByFrames(Tf2BroadcasterRole, parentFrame, childFrame))
  {
    vtkErrorMacro("CreateAndAddTf2BroadcasterNode: " << parentFrame << " <- " << childFrame
                                                     << " exists already");
    return nullptr;
  }
  vtkNew<vtkROS2Tf2BroadcasterNode> node;
  node->SetParentID(parentFrame);
  node->SetChildID(childFrame);
  node->SetName((std::string("ros2:tf2broadcaster:") + parentFrame + "To" + childFrame).c_str());
  this->Scene->AddNode(node);
  this->AddChild(Tf2BroadcasterRole, node);
  return node;
}

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode* vtkROS2NodeNode::GetTf2BroadcasterNodeByParentChild(
  const char* parentFrame, const char* childFrame)
{
  return vtkROS2Tf2BroadcasterNode::SafeDownCast(
    this->FindChildByFrames(Tf2BroadcasterRole, parentFrame, childFrame));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2BroadcasterNode(
  const char* parentFrame, const char* childFrame)
{
  vtkROS2Tf2BroadcasterNode* node =
    this->GetTf2BroadcasterNodeByParentChild(parentFrame, childFrame);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2BroadcasterNode: no broadcaster "
      << (parentFrame ? parentFrame : "") << " <- " << (childFrame ? childFrame : ""));
    return false;
  }
  return this->RemoveChild(Tf2BroadcasterRole, node);
}

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode* vtkROS2NodeNode::GetTf2BroadcasterNodeByID(const char* nodeID)
{
  return vtkROS2Tf2BroadcasterNode::SafeDownCast(this->FindChildByID(Tf2BroadcasterRole, nodeID));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2BroadcasterNode(const char* nodeID)
{
  vtkROS2SceneNode* node = this->FindChildByID(Tf2BroadcasterRole, nodeID);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2BroadcasterNode: "
      << (nodeID ? nodeID : "(null)") << " is not a tf2 broadcaster of this node");
    return false;
  }
  return this->RemoveChild(Tf2BroadcasterRole, node);
}
