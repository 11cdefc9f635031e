// ros2vtk — base class of every subscriber node (vtkROS2Subscriber<Short>Node, generic).
//
// Abstract. DDS threads only queue samples; when the owning vtkROS2NodeNode spins (on the
// caller's thread), ProcessIncomingMessages() takes the queue, keeps the newest raw message and
// the raw messages of this spin, calls OnNewMessages() so subclasses can drop their converted
// cache, and fires ONE ModifiedEvent with the number of new messages (int*) as call data.
// Malformed samples are counted and reported, at most once per few seconds.
#ifndef vtkROS2SubscriberNode_h
#define vtkROS2SubscriberNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2TopicNode.h"

class vtkROS2Message;

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class ROS2VTKSCENE_EXPORT vtkROS2SubscriberNode : public vtkROS2TopicNode
{
public:
  vtkTypeMacro(vtkROS2SubscriberNode, vtkROS2TopicNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Messages received (taken by spins) since the node was created.
  vtkTypeInt64 GetNumberOfMessages() const { return this->NumberOfMessages; }
  /// Samples rejected as malformed (bad CDR) and the reason of the latest one.
  vtkTypeInt64 GetNumberOfRejectedMessages() const { return this->NumberOfRejectedMessages; }
  const char* GetLastRejectionReason() const;
  /// Publishers (local or remote) currently matched; 0 when not added.
  int GetNumberOfMatchedPublications() const;
  /// Seconds (wall clock) since a spin last brought a message; -1 before the first. With the
  /// matched publications, what a panel shows of a link outage while it lasts.
  double GetSecondsSinceLastMessage() const;
  /// Publishers found on the topic whose QoS cannot match this subscriber (they send nothing
  /// here; each is reported once, as rclpy's "requesting incompatible QoS"), and the policy that
  /// kept the latest apart ("RELIABILITY", "DURABILITY", ...; empty when none).
  vtkTypeInt64 GetNumberOfIncompatibleQoSPublishers() const
  {
    return this->NumberOfIncompatibleQoSPublishers;
  }
  const char* GetLastIncompatibleQoSPolicy() const;

  /// The newest message as YAML, as `ros2 topic echo` prints it; empty before the first one.
  std::string GetLastMessageYAML() const;

  /// A top-level string field of the newest message, read through the type's introspection
  /// (e.g. "data" of a std_msgs/String, as robot_description is). False (and `value` untouched)
  /// before the first message or when the type has no string field of that name.
  bool GetLastMessageStringField(const char* fieldName, std::string& value) const;

  /// The newest message, every field, as a typed message object (header stamps, frame ids and
  /// whatever a mapping leaves out; values as on the wire, SI units). False before the first.
  bool GetLastMessageObject(vtkROS2Message* message) const;
  /// Message i of those the latest spin brought (0 = oldest; see GetNumberOfNewMessages in
  /// subclasses); false for an index out of range.
  bool GetNewMessageObject(int i, vtkROS2Message* message) const;

  /// SlicerROS2's target node: after every spin that brought messages, the newest one is copied
  /// into this scene node before ModifiedEvent fires (a model node takes a vtkPolyData, a
  /// transform node a vtkMatrix4x4; vtkROS2SceneNode::CopyContentFrom). nullptr/"" = none.
  /// A target that cannot take this subscriber's type is reported once per reason.
  void SetTargetNodeID(const char* nodeID);
  const char* GetTargetNodeID() const;
  /// The reference role of the target node in scene files.
  static const char* const TargetNodeReferenceRole;

  /// Takes the queued messages; returns how many were new. Called by vtkROS2NodeNode::Spin on
  /// the spinning thread; fires ModifiedEvent (call data int*: the count) when there were any.
  int ProcessIncomingMessages();

  /// Spin hook (vtkROS2SceneNode::OnROS2NodeSpin): takes the queued messages.
  int OnROS2NodeSpin(vtkROS2NodeNode*) override { return this->ProcessIncomingMessages(); }

protected:
  vtkROS2SubscriberNode();
  ~vtkROS2SubscriberNode() override;

  /// A script that reads messages while its ROS node has never spun receives nothing: says so
  /// once per subscriber, naming the fix (SlicerROS2 spins on a 50 Hz timer, so scripts ported
  /// from it have no spin of their own).
  void WarnIfNeverSpun(const char* call) const;
  /// Copies the newest message into the target node, if there is one (SetTargetNodeID).
  void UpdateTargetNode();

  /// The newest message as the VTK object a target node takes (generated subscribers whose
  /// conversion gives a VTK object return it); nullptr by default and before the first message.
  virtual vtkObject* GetLastMessageAsObject() { return nullptr; }

  /// Newest message received (struct of GetMessageTypeSupport()'s type); nullptr before the
  /// first. Valid until a later spin brings new messages.
  const void* GetLastRawMessage() const;
  /// Messages brought by the latest spin (0 when it brought none), oldest first; the last one is
  /// GetLastRawMessage(). nullptr for an index out of range.
  int GetNumberOfNewMessages() const;
  const void* GetNewRawMessage(int i) const;

  /// Called by ProcessIncomingMessages when a spin brought messages, before ModifiedEvent.
  /// Subclasses invalidate their converted value here (convert lazily on Get).
  virtual void OnNewMessages() {}

  /// Called on every spin, with or without messages, before OnNewMessages: a subclass that keeps
  /// state across messages drops what has expired at `nowNanoseconds` (the ROS node's clock,
  /// simulated time included) and returns true when that changed what it shows; the spin then
  /// fires the ModifiedEvent (count 0 when it brought no message).
  virtual bool ExpireKeptState(vtkTypeInt64 vtkNotUsed(nowNanoseconds)) { return false; }
  /// The ROS node's clock at the latest spin (0 before the first): when OnNewMessages' messages
  /// were taken.
  vtkTypeInt64 SpinTimeNanoseconds = 0;

  bool CreateEndpoint(ros2vtk::wire::Participant& participant, const std::string& topic,
    const ros2vtk::wire::QoS& qos, std::string* error) override;
  void DestroyEndpoint() override;
  bool HasEndpoint() const override;
  const char* GetROS2NodeReferenceRole() const override;

  vtkTypeInt64 NumberOfMessages = 0;
  vtkTypeInt64 NumberOfRejectedMessages = 0;
  vtkTypeInt64 NumberOfIncompatibleQoSPublishers = 0;
  mutable bool WarnedNeverSpun = false; // WarnIfNeverSpun said it once

private:
  vtkROS2SubscriberNode(const vtkROS2SubscriberNode&) = delete;
  void operator=(const vtkROS2SubscriberNode&) = delete;

  void ReportRejections();
  void ReportIncompatibleQoS();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
