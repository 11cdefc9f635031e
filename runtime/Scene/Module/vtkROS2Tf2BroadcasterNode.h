// ros2vtk — broadcasts a matrix as a tf2 transform (parent <- child), dynamic on /tf or static
// on /tf_static, stamped with the current time (never zero). Millimetres in VTK become metres
// on the wire unless ScaleLengths is off. It can follow a transform node and broadcast on every
// change of it (SlicerROS2's ObserveTransformNode).
#ifndef vtkROS2Tf2BroadcasterNode_h
#define vtkROS2Tf2BroadcasterNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2SceneNode.h"

#include <string> // for std::string

class vtkMatrix4x4;
class vtkROS2NodeNode;
class vtkROS2TransformNode;

class ROS2VTKSCENE_EXPORT vtkROS2Tf2BroadcasterNode : public vtkROS2SceneNode
{
public:
  static vtkROS2Tf2BroadcasterNode* New();
  vtkTypeMacro(vtkROS2Tf2BroadcasterNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetParentID(const char* frame);
  const char* GetParentID() const { return this->ParentFrame.c_str(); }
  void SetChildID(const char* frame);
  const char* GetChildID() const { return this->ChildFrame.c_str(); }
  bool IsParentAndChildSet() const
  {
    return !this->ParentFrame.empty() && !this->ChildFrame.empty();
  }

  /// Static transforms go to /tf_static (latched for late joiners), e.g. a registration.
  vtkSetMacro(Static, bool);
  vtkGetMacro(Static, bool);
  vtkBooleanMacro(Static, bool);
  vtkSetMacro(ScaleLengths, bool);
  vtkGetMacro(ScaleLengths, bool);
  vtkBooleanMacro(ScaleLengths, bool);

  /// Sends `matrix` (must be rigid). False with vtkErrorMacro when frames are unset, the node is
  /// not attached to a created ROS node, or the matrix is not a rigid transform.
  bool Broadcast(vtkMatrix4x4* matrix);
  /// Sends `node`'s matrix to parent once (SlicerROS2's Broadcast(transformNode)).
  bool Broadcast(vtkROS2TransformNode* node);
  /// Broadcasts the transform node's matrix to parent now and on each of its changes
  /// (nullptr stops observing).
  bool ObserveTransformNode(vtkROS2TransformNode* node);
  int GetNumberOfBroadcasts() const { return this->NumberOfBroadcasts; }

  vtkROS2NodeNode* GetROS2Node() const;

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

  /// Index key among the ROS node's broadcasters: "parent<newline>child".
  std::string GetROS2NodeChildKey() const override
  {
    return this->ParentFrame + '\n' + this->ChildFrame;
  }

protected:
  vtkROS2Tf2BroadcasterNode();
  ~vtkROS2Tf2BroadcasterNode() override;
  void OnRemovedFromScene() override;

  std::string ParentFrame;
  std::string ChildFrame;
  bool Static = false;
  bool ScaleLengths = true;
  int NumberOfBroadcasts = 0;
  vtkROS2TransformNode* ObservedNode = nullptr;
  unsigned long ObserverTag = 0;

private:
  vtkROS2Tf2BroadcasterNode(const vtkROS2Tf2BroadcasterNode&) = delete;
  void operator=(const vtkROS2Tf2BroadcasterNode&) = delete;
};

#endif
