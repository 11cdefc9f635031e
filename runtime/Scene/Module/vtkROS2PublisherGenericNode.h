// ros2vtk — a publisher for any registered message type that has no mapping rule: the message
// is given as YAML (the syntax `ros2 topic pub` takes), so no per-type code is needed.
#ifndef vtkROS2PublisherGenericNode_h
#define vtkROS2PublisherGenericNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2PublisherNode.h"

#include <memory> // for std::unique_ptr

namespace ros2vtk {
namespace scene {
class LearntMessageType;
}
}

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

  /// Takes a type no library of this process registers ("pkg/msg/Type" or "pkg/Type"): once
  /// added to a ROS node, the publisher asks a node that already uses the type on its topic — a
  /// subscription first (the node the messages are for), else another publisher — for the type's
  /// description (REP 2011 `<node>/get_type_description`), builds the type at run time and
  /// creates its writer; until then PublishYAML refuses and GetTypeStatus() says why. A
  /// registered type is simply set (SetROSType). CreateAndAddPublisherNode uses this for
  /// unknown full type names. False for a text that is no type name.
  bool SetROSTypeResolvedAtRuntime(const char* rosType);
  /// "" when the type is known; otherwise what the publisher waits for ("waiting for a
  /// subscriber or publisher of pkg/msg/T on /topic to learn the type from", "the subscriber
  /// /node does not serve type descriptions (...)") or why it gave up.
  const char* GetTypeStatus() const;
  /// True while the type is still to be learnt from a peer.
  bool IsWaitingForType() const;

  /// Learns the type while waiting for it.
  int OnROS2NodeSpin(vtkROS2NodeNode* rosNode) override;

  /// Publishes a message given as YAML ("{x: 1.0, y: 2.0}" or block style); fields left out
  /// keep their default. False (vtkErrorMacro with the parser's message) on invalid YAML.
  bool PublishYAML(const char* yaml);

  const char* GetSlicerType() const override { return "YAML"; }

  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2PublisherGenericNode();
  ~vtkROS2PublisherGenericNode() override;

  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
  bool HasMessageTypeSupport() const override;
  bool CreateEndpoint(ros2vtk::wire::Participant& participant, const std::string& topic,
    const ros2vtk::wire::QoS& qos, std::string* error) override;
  void DestroyEndpoint() override;
  bool HasEndpoint() const override;

private:
  vtkROS2PublisherGenericNode(const vtkROS2PublisherGenericNode&) = delete;
  void operator=(const vtkROS2PublisherGenericNode&) = delete;

  const ros2vtk::wire::MessageTypeSupport* Type = nullptr;
  /// A type learnt at run time from a peer on the topic (empty for a registered type).
  std::unique_ptr<ros2vtk::scene::LearntMessageType> Learnt;
};

#endif
