// ros2vtk — base class of every publisher node (vtkROS2Publisher<Short>Node, generic).
//
// Abstract. A subclass supplies its message type (GetMessageTypeSupport) and a Publish(...)
// taking its VTK/C++ value, converts it into a message struct and hands it to PublishMessage().
// Counts calls and messages sent, as SlicerROS2 does. PublishObject / PublishValue are the one
// generic entry for callers that hold a value and a publisher of any class (the OpenIGTLink
// connector's device → topic mappings): the generated classes route them to their Publish.
#ifndef vtkROS2PublisherNode_h
#define vtkROS2PublisherNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2TopicNode.h"
#include "vtkVariant.h" // for PublishValue

class vtkObject;

class vtkROS2Message;

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class ROS2VTKSCENE_EXPORT vtkROS2PublisherNode : public vtkROS2TopicNode
{
public:
  vtkTypeMacro(vtkROS2PublisherNode, vtkROS2TopicNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Calls of Publish (successful or not) and messages actually handed to DDS.
  vtkTypeInt64 GetNumberOfCalls() const { return this->NumberOfCalls; }
  vtkTypeInt64 GetNumberOfMessagesSent() const { return this->NumberOfMessagesSent; }
  /// Subscriptions (local or remote) currently matched with this publisher; 0 when not added.
  int GetNumberOfMatchedSubscriptions() const;

  /// Publishes a typed message object exactly as it is (no stamping, no unit scaling): the way
  /// to send fields a mapping does not carry (header stamps, child_frame_id, covariances). Its
  /// type must be this node's ROS type. False (vtkErrorMacro) otherwise, as Publish.
  bool PublishMessageObject(vtkROS2Message* message);
  /// A default message of this node's type to fill in (nullptr until the type is known).
  /// The caller owns it (Python: an ordinary object).
  VTK_NEWINSTANCE vtkROS2Message* CreateMessageObject() const;
  /// Publishes `object` when it is of this node's VTK type (GetSlicerType(): vtkMatrix4x4,
  /// vtkPoints, vtkImageData, vtkTransformCollection, …), through the class's own Publish.
  /// A vtkROS2Message of this node's type goes to PublishMessageObject. Returns the messages
  /// sent: 0 when this node takes no such object (the reason in vtkErrorMacro and
  /// GetLastPublishError(); the call is counted).
  virtual int PublishObject(vtkObject* object);
  /// The same for nodes whose value is a bool, an integer, a double or a string (Bool, Int,
  /// Double, String): a vtkVariant of that kind (a string variant for String, a number for
  /// the others).
  virtual int PublishValue(const vtkVariant& value);
  /// Why the latest PublishObject / PublishValue / Publish failed ("" after a success).
  const char* GetLastPublishError() const { return this->LastPublishError.c_str(); }

  ///@{
  /// The stamp in the header of mapped messages that have one (PoseStamped, TransformStamped,
  /// PoseArray, WrenchStamped, Image, ...): the ROS node's clock at each Publish by default.
  /// SetHeaderStamp fixes it (data replayed with its recorded time, or SlicerROS2 code that set
  /// header.stamp itself) until UseNodeClockForHeaderStamp. `nanosec` must be < 1e9.
  void SetHeaderStamp(int sec, unsigned int nanosec);
  void UseNodeClockForHeaderStamp();
  bool GetHeaderStampIsFixed() const { return this->HeaderStampIsFixed; }
  ///@}

protected:
  vtkROS2PublisherNode();
  ~vtkROS2PublisherNode() override;

  /// Publishes a message struct of GetMessageTypeSupport()'s type. False (vtkErrorMacro) when
  /// the node is not added to a ROS node or DDS refused the sample. Counts the call.
  bool PublishMessage(const void* rosMessage);
  /// For subclasses whose conversion failed before a message existed: counts the call and
  /// reports `reason` with vtkErrorMacro.
  void RecordFailedPublish(const char* reason);
  /// The time a header published now carries, in nanoseconds: the stamp fixed by
  /// SetHeaderStamp, else the ROS node's clock (vtkROS2NodeNode::GetNodeTimeNanoseconds,
  /// simulated time when use_sim_time is on). 0 when not attached to a ROS node
  /// (PublishMessage refuses to send then anyway).
  vtkTypeInt64 GetStampTimeNanoseconds() const;

  bool CreateEndpoint(ros2vtk::wire::Participant& participant, const std::string& topic,
    const ros2vtk::wire::QoS& qos, std::string* error) override;
  void DestroyEndpoint() override;
  bool HasEndpoint() const override;
  const char* GetROS2NodeReferenceRole() const override;

  vtkTypeInt64 NumberOfCalls = 0;
  vtkTypeInt64 NumberOfMessagesSent = 0;
  std::string LastPublishError;
  bool HeaderStampIsFixed = false;
  vtkTypeInt64 FixedHeaderStampNanoseconds = 0;

private:
  vtkROS2PublisherNode(const vtkROS2PublisherNode&) = delete;
  void operator=(const vtkROS2PublisherNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
