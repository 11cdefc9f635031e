// ros2vtk — a publisher for any registered message type that has no mapping rule: the message
// is given as YAML (the syntax `ros2 topic pub` takes), so no per-type code is needed.
#ifndef vtkROS2PublisherGenericNode_h
#define vtkROS2PublisherGenericNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2PublisherNode.h"

class ROS2VTKSCENE_EXPORT vtkROS2PublisherGenericNode : public vtkROS2PublisherNode
{
public:
  static vtkROS2PublisherGenericNode* New();
  vtkTypeMacro(vtkROS2PublisherGenericNode, vtkROS2PublisherNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Chooses the message type ("geometry_msgs/msg/Point" or "geometry_msgs/Point"). Only
  /// before the node is added to a ROS node. False (vtkErrorMacro listing the registered
  /// types) for an unknown type.
  bool SetROSType(const char* rosType);

  /// Publishes a message given as YAML ("{x: 1.0, y: 2.0}" or block style); fields left out
  /// keep their default. False (vtkErrorMacro with the parser's message) on invalid YAML.
  bool PublishYAML(const char* yaml);

  const char* GetSlicerType() const override { return "YAML"; }

  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2PublisherGenericNode();
  ~vtkROS2PublisherGenericNode() override;

  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
  bool HasMessageTypeSupport() const override { return this->Type != nullptr; }

private:
  vtkROS2PublisherGenericNode(const vtkROS2PublisherGenericNode&) = delete;
  void operator=(const vtkROS2PublisherGenericNode&) = delete;

  const ros2vtk::wire::MessageTypeSupport* Type = nullptr;
};

#endif
