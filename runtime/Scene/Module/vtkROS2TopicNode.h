// ros2vtk — what publisher and subscriber nodes share: a topic, a message type, QoS, the units
// policy, and attachment to a ROS node (vtkROS2NodeNode) of the same scene.
//
// Abstract. vtkROS2PublisherNode and vtkROS2SubscriberNode derive from it; generated classes
// derive from those and only supply their message type and conversions.
#ifndef vtkROS2TopicNode_h
#define vtkROS2TopicNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SceneNode.h"

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2NodeNode;

namespace ros2vtk {
namespace wire {
class Participant;
struct MessageTypeSupport;
struct QoS;
}
}

class ROS2VTKSCENE_EXPORT vtkROS2TopicNode : public vtkROS2SceneNode
{
public:
  vtkTypeMacro(vtkROS2TopicNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Creates the DDS endpoint on `topic` in the ROS node `nodeID` (a vtkROS2NodeNode of the same
  /// scene, already created). False (vtkErrorMacro) when the node is missing, the topic name is
  /// invalid or this node is already added (remove it first).
  bool AddToROS2Node(const char* nodeID, const char* topic);
  /// Destroys the DDS endpoint; the node stays in the scene. False when it was not added.
  bool RemoveFromROS2Node();
  /// Destroy hook: the endpoint lives in the participant (vtkROS2SceneNode::OnROS2NodeDestroyed).
  void OnROS2NodeDestroyed(vtkROS2NodeNode*) override { this->RemoveFromROS2Node(); }
  bool IsAddedToROS2Node() const;
  /// The ROS node this endpoint belongs to (nullptr when not added).
  vtkROS2NodeNode* GetROS2Node() const;

  /// The topic as given (resolved name once added, e.g. "/pub").
  const char* GetTopic() const;
  /// "std_msgs/msg/String"; empty when the type is not known yet (generic node before SetROSType).
  const char* GetROSType() const;
  /// The VTK/C++ side of the conversion ("std::string", "vtkMatrix4x4", "YAML" for generic nodes).
  virtual const char* GetSlicerType() const = 0;

  /// QoS, by profile name ("default", "sensor_data", "transient_local" (alias "latched"),
  /// "services_default", "parameters", "parameter_events") or by policy. Changing QoS of an
  /// added node re-creates its DDS endpoint (DDS fixes QoS at creation). False (vtkErrorMacro
  /// listing the accepted values) for unknown names.
  bool SetQoSProfile(const char* profile);
  bool SetReliability(const char* reliability); ///< "reliable" | "best_effort"
  bool SetDurability(const char* durability);   ///< "volatile" | "transient_local"
  bool SetHistory(const char* history);         ///< "keep_last" | "keep_all"
  bool SetHistoryDepth(int depth);              ///< >= 1
  const char* GetReliability() const;
  const char* GetDurability() const;
  const char* GetHistory() const;
  int GetHistoryDepth() const;
  /// "reliable, volatile, keep_last(10)".
  std::string GetQoSDescription() const;

  /// SlicerROS2's QoS setters and their enum values (`pub.SetQoSReliability(pub.Reliable)`), so
  /// its scripts run unchanged; the string setters above are the same settings. The system
  /// defaults are the rmw defaults (reliable, volatile); getters report the policy in effect.
  enum QoSReliabilityValue
  {
    ReliabilitySystemDefault = 0,
    Reliable = 1,
    BestEffort = 2
  };
  enum QoSDurabilityValue
  {
    DurabilitySystemDefault = 0,
    TransientLocal = 1,
    Volatile = 2
  };
  bool SetQoSHistoryDepth(int depth) { return this->SetHistoryDepth(depth); }
  int GetQoSHistoryDepth() const { return this->GetHistoryDepth(); }
  bool SetQoSReliability(int reliability);
  int GetQoSReliability() const;
  bool SetQoSDurability(int durability);
  int GetQoSDurability() const;

  /// Units policy (msg_specs/mappings/README.md): ROS lengths are metres, VTK lengths millimetres;
  /// when on (the default) subclasses scale lengths x1000 into VTK and /1000 out of it.
  vtkSetMacro(ScaleLengths, bool);
  vtkGetMacro(ScaleLengths, bool);
  vtkBooleanMacro(ScaleLengths, bool);

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  /// Re-attaches to the saved ROS node and topic.
  void OnSceneRestored() override;

#ifndef __VTK_WRAP__
  const ros2vtk::wire::QoS& GetQoS() const;
  /// False (vtkErrorMacro) if re-creating the endpoint of an added node fails.
  bool SetQoS(const ros2vtk::wire::QoS& qos);
#endif

  /// Index key among the ROS node's publishers / subscribers (the resolved topic).
  std::string GetROS2NodeChildKey() const override
  {
    return this->GetTopic();
  }

protected:
  vtkROS2TopicNode();
  ~vtkROS2TopicNode() override;

  /// The message type of this node (a generated table). Only called when
  /// HasMessageTypeSupport() is true.
  virtual const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const = 0;
  /// False while the type is unknown (generic nodes before SetROSType).
  virtual bool HasMessageTypeSupport() const
  {
    return true;
  }

  /// Direction-specific DDS endpoint: create on `participant` (false and `error` on failure),
  /// destroy (idempotent).
  virtual bool CreateEndpoint(ros2vtk::wire::Participant& participant, const std::string& topic,
    const ros2vtk::wire::QoS& qos, std::string* error) = 0;
  virtual void DestroyEndpoint() = 0;
  virtual bool HasEndpoint() const = 0;
  /// The role under which the ROS node references endpoints of this direction.
  virtual const char* GetROS2NodeReferenceRole() const = 0;

  void OnRemovedFromScene() override;

  bool ScaleLengths = true;

private:
  vtkROS2TopicNode(const vtkROS2TopicNode&) = delete;
  void operator=(const vtkROS2TopicNode&) = delete;

  bool RecreateEndpoint();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
