// ros2vtk — a subscriber for any registered message type that has no mapping rule: the newest
// message is exposed as YAML (as `ros2 topic echo` prints it), so no per-type code is needed.
#ifndef vtkROS2SubscriberGenericNode_h
#define vtkROS2SubscriberGenericNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SubscriberNode.h"

class ROS2VTKSCENE_EXPORT vtkROS2SubscriberGenericNode : public vtkROS2SubscriberNode
{
public:
  static vtkROS2SubscriberGenericNode* New();
  vtkTypeMacro(vtkROS2SubscriberGenericNode, vtkROS2SubscriberNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Chooses the message type ("geometry_msgs/msg/Point" or "geometry_msgs/Point"). Only
  /// before the node is added to a ROS node. False (vtkErrorMacro listing the registered
  /// types) for an unknown type.
  bool SetROSType(const char* rosType);

  /// The newest message as YAML (same as GetLastMessageYAML; the SlicerROS2 getter name).
  std::string GetLastMessage() const { return this->GetLastMessageYAML(); }

  const char* GetSlicerType() const override { return "YAML"; }

  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2SubscriberGenericNode();
  ~vtkROS2SubscriberGenericNode() override;

  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
  bool HasMessageTypeSupport() const override { return this->Type != nullptr; }

private:
  vtkROS2SubscriberGenericNode(const vtkROS2SubscriberGenericNode&) = delete;
  void operator=(const vtkROS2SubscriberGenericNode&) = delete;

  const ros2vtk::wire::MessageTypeSupport* Type = nullptr;
};

#endif
