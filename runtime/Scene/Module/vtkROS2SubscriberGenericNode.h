// ros2vtk — a subscriber for any registered message type that has no mapping rule: the newest
// message is exposed as YAML (as `ros2 topic echo` prints it), so no per-type code is needed.
#ifndef vtkROS2SubscriberGenericNode_h
#define vtkROS2SubscriberGenericNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SubscriberNode.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string (GetLastMessage)

namespace ros2vtk {
namespace scene {
class LearntMessageType;
}
}

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

  /// Takes a type no library of this process registers ("pkg/msg/Type" or "pkg/Type"): once
  /// added to a ROS node, the subscriber asks the first publisher of its topic with that type
  /// for the type's description (REP 2011 `<node>/get_type_description`), builds the type at run
  /// time and subscribes; until then it receives nothing and GetTypeStatus() says why. A
  /// registered type is simply set (SetROSType). CreateAndAddSubscriberNode uses this for
  /// unknown full type names. False for a text that is no type name.
  bool SetROSTypeResolvedAtRuntime(const char* rosType);
  /// "" when the type is known; otherwise what the subscriber waits for ("waiting for the type
  /// description of pkg/msg/T from /node", "the publisher /node does not serve type descriptions
  /// (...)") or why it gave up.
  const char* GetTypeStatus() const;
  /// True while the type is still to be learnt from a publisher.
  bool IsWaitingForType() const;

  /// Learns the type (when waiting for it), then takes the queued messages.
  int OnROS2NodeSpin(vtkROS2NodeNode* rosNode) override;

  /// The newest message as YAML (same as GetLastMessageYAML; the SlicerROS2 getter name).
  std::string GetLastMessage() const { return this->GetLastMessageYAML(); }

  const char* GetSlicerType() const override { return "YAML"; }

  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2SubscriberGenericNode();
  ~vtkROS2SubscriberGenericNode() override;

  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
  bool HasMessageTypeSupport() const override;
  bool CreateEndpoint(ros2vtk::wire::Participant& participant, const std::string& topic,
    const ros2vtk::wire::QoS& qos, std::string* error) override;
  void DestroyEndpoint() override;
  bool HasEndpoint() const override;

private:
  vtkROS2SubscriberGenericNode(const vtkROS2SubscriberGenericNode&) = delete;
  void operator=(const vtkROS2SubscriberGenericNode&) = delete;

  const ros2vtk::wire::MessageTypeSupport* Type = nullptr;
  /// A type learnt at run time from the topic's publisher (empty for a registered type).
  std::unique_ptr<ros2vtk::scene::LearntMessageType> Learnt;
};

#endif
