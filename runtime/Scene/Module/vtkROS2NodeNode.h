// ros2vtk — one ROS 2 node (one DDS participant) in the scene, with its publishers and
// subscribers (SlicerROS2's vtkMRMLROS2NodeNode).
//
//   node = vtkROS2NodeNode::New(); scene->AddNode(node); node->Create("slicer");
//   pub = node->CreateAndAddPublisherNode("String", "/pub");
//   node->Spin(); // on the thread that owns the scene
//
// Publishers, subscribers, tf2 lookups, parameters, services and robots are scene nodes of their
// own (children): the ROS node references them by the role of their kind ("publisher",
// "tf2Lookup", ...) and they reference it (vtkROS2SceneNode::ROS2NodeReferenceRole). Spin order,
// roles and the child index: docs/architecture.md.
#ifndef vtkROS2NodeNode_h
#define vtkROS2NodeNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SceneNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkDataArray;
class vtkROS2PublisherNode;
class vtkROS2SubscriberNode;
class vtkStringArray;

namespace ros2vtk {
namespace wire {
class Participant;
}
}

class vtkROS2ParameterNode;
class vtkROS2RobotNode;
class vtkROS2ActionClientNode;
class vtkROS2ActionServerNode;
class vtkROS2ServiceClientNode;
class vtkROS2ServiceServerNode;
class vtkROS2Tf2BroadcasterNode;
class vtkROS2Tf2LookupNode;
class vtkROS2TopicNode;
namespace ros2vtk {
namespace tf2 {
class BufferCore;
}
namespace tf2_ros {
class TransformBroadcaster;
}
namespace wire {
class ParameterServer;
}
}
#ifndef __VTK_WRAP__
#include <functional> // for std::function (spin callbacks)
#endif

class ROS2VTKSCENE_EXPORT vtkROS2NodeNode : public vtkROS2SceneNode
{
public:
  static vtkROS2NodeNode* New();
  vtkTypeMacro(vtkROS2NodeNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Creates the ROS node (DDS participant; ROS_DOMAIN_ID and discovery range from the
  /// environment). The scene node's Name becomes the ROS node name when it has none.
  /// False (vtkErrorMacro) for an invalid name/namespace, a DDS failure, or when already created.
  bool Create(const char* nodeName, const char* nodeNamespace = "");

#ifndef __VTK_WRAP__
  ///@{
  /// The reference roles under which this node holds its children, one per kind (saved in scene
  /// files: these spellings are the file format). A kind added outside the runtime picks its own.
  static constexpr const char* PublisherRole = "publisher";
  static constexpr const char* SubscriberRole = "subscriber";
  static constexpr const char* Tf2LookupRole = "tf2Lookup";
  static constexpr const char* Tf2BroadcasterRole = "tf2Broadcaster";
  static constexpr const char* ParameterRole = "parameter";
  static constexpr const char* RobotRole = "robot";
  static constexpr const char* ServiceClientRole = "serviceClient";
  static constexpr const char* ServiceServerRole = "serviceServer";
  static constexpr const char* ActionClientRole = "actionClient";
  static constexpr const char* ActionServerRole = "actionServer";
  ///@}
#endif
  /// Removes every publisher and subscriber from DDS (they stay in the scene) and destroys the
  /// participant. False when not created.
  bool Destroy();
  bool IsCreated() const;

  /// As given to Create ("slicer", "/" or "/robot1"); empty before Create.
  const char* GetROS2NodeName() const;
  const char* GetROS2NodeNamespace() const;

  /// Creates a publisher/subscriber node of `type`, adds it to this node's scene and to this
  /// ROS node on `topic`. `type` is a short name ("String"), a class name
  /// ("vtkROS2PublisherStringNode", "vtkMRMLROS2PublisherStringNode") or a ROS type
  /// ("geometry_msgs/msg/Point", "geometry_msgs/Point"; a generic node when no single mapped
  /// class exists). A full ROS type no library registers makes a generic node that learns the
  /// type from a peer on the topic (REP 2011 type descriptions). Returns the new node (owned by
  /// the scene) or nullptr with vtkErrorMacro (unknown short name: the message lists the known
  /// names; topic already used by this node).
  vtkROS2PublisherNode* CreateAndAddPublisherNode(const char* type, const char* topic);
  vtkROS2SubscriberNode* CreateAndAddSubscriberNode(const char* type, const char* topic);
  /// Removes the publisher/subscriber of this node on `topic` from DDS and from the scene.
  bool RemoveAndDeletePublisherNode(const char* topic);
  bool RemoveAndDeleteSubscriberNode(const char* topic);
  /// nullptr when this node has none on `topic` (name as given or resolved).
  vtkROS2PublisherNode* GetPublisherNodeByTopic(const char* topic);
  vtkROS2SubscriberNode* GetSubscriberNodeByTopic(const char* topic);
  int GetNumberOfPublisherNodes();
  int GetNumberOfSubscriberNodes();

  /// Space-separated class names of the publisher / subscriber classes that can be created.
  std::string GetRegisteredROS2PublisherNodes() const;
  std::string GetRegisteredROS2SubscriberNodes() const;
  /// SlicerROS2's spelling of the two above.
  std::string RegisteredROS2PublisherNodes() const
  {
    return this->GetRegisteredROS2PublisherNodes();
  }
  std::string RegisteredROS2SubscriberNodes() const
  {
    return this->GetRegisteredROS2SubscriberNodes();
  }

  /// Processes what DDS queued for this node's subscribers, on the calling thread (each
  /// subscriber with new messages fires one ModifiedEvent). Returns the number of messages.
  int Spin();
  /// SlicerROS2's names: true once this created node has been spun, and a warning naming
  /// `context` ("Node slicer is not spinning (yet) when ...") while it has not.
  bool GetSpinning() const;
  void WarnIfNotSpinning(const char* context) const;
  /// Readable (poll POLLIN) while this node has queued data; -1 before Create. Stays open
  /// until Destroy.
  int GetWakeUpFileDescriptor();

  ///@{
  /// tf2 (SlicerROS2's names). A lookup node is a transform node kept equal to the latest
  /// parent <- child transform on every Spin (frames from /tf and /tf_static); a broadcaster
  /// node publishes matrices as transforms (dynamic, or static with SetStatic). Frame pairs are
  /// unique per ROS node. Remove* return false (vtkErrorMacro) when there is no such node.
  vtkROS2Tf2LookupNode* CreateAndAddTf2LookupNode(const char* parentFrame, const char* childFrame);
  vtkROS2Tf2LookupNode* GetTf2LookupNodeByParentChild(
    const char* parentFrame, const char* childFrame);
  /// By scene node ID (SlicerROS2 scripts keep IDs); nullptr unless it is this node's lookup.
  vtkROS2Tf2LookupNode* GetTf2LookupNodeByID(const char* nodeID);
  bool RemoveAndDeleteTf2LookupNode(const char* parentFrame, const char* childFrame);
  /// By scene node ID (SlicerROS2's one-argument form).
  bool RemoveAndDeleteTf2LookupNode(const char* nodeID);
  vtkROS2Tf2BroadcasterNode* CreateAndAddTf2BroadcasterNode(
    const char* parentFrame, const char* childFrame);
  vtkROS2Tf2BroadcasterNode* GetTf2BroadcasterNodeByParentChild(
    const char* parentFrame, const char* childFrame);
  /// By scene node ID; nullptr unless it is this node's broadcaster.
  vtkROS2Tf2BroadcasterNode* GetTf2BroadcasterNodeByID(const char* nodeID);
  bool RemoveAndDeleteTf2BroadcasterNode(const char* parentFrame, const char* childFrame);
  /// By scene node ID (SlicerROS2's one-argument form).
  bool RemoveAndDeleteTf2BroadcasterNode(const char* nodeID);
  ///@}

  ///@{
  /// Parameters of another ROS node (SlicerROS2's parameter node), one scene node per
  /// monitored node ("/robot_state_publisher"; a name without '/' is taken as absolute).
  vtkROS2ParameterNode* CreateAndAddParameterNode(const char* monitoredNodeName);
  vtkROS2ParameterNode* GetParameterNodeByNode(const char* monitoredNodeName);
  /// By scene node ID; nullptr unless it is this node's parameter node.
  vtkROS2ParameterNode* GetParameterNodeByNodeID(const char* nodeID);
  bool RemoveAndDeleteParameterNode(const char* monitoredNodeName);
  /// By scene node ID (SlicerROS2's name); false unless it is this node's parameter node.
  bool RemoveAndDeleteParameterNodeByNodeID(const char* nodeID);
  ///@}

  ///@{
  /// Services of any generated .srv type (`type` as "std_srvs/srv/SetBool" or "std_srvs/SetBool"):
  /// a client sends requests and gets responses or timeouts on Spin; a server fires an event per
  /// request for an observer to answer. One client and one server per service name and ROS
  /// node; nullptr / false (vtkErrorMacro listing the known types) otherwise.
  vtkROS2ServiceClientNode* CreateAndAddServiceClientNode(const char* type, const char* service);
  vtkROS2ServiceClientNode* GetServiceClientNodeByService(const char* service);
  bool RemoveAndDeleteServiceClientNode(const char* service);
  vtkROS2ServiceServerNode* CreateAndAddServiceServerNode(const char* type, const char* service);
  vtkROS2ServiceServerNode* GetServiceServerNodeByService(const char* service);
  bool RemoveAndDeleteServiceServerNode(const char* service);
  /// Space-separated ROS names of the service types that can be used.
  std::string GetRegisteredServiceTypes() const;
  /// SlicerROS2's name for the same list (its service clients are one class per type; ours is
  /// one class for every type, so the list names the types).
  std::string RegisteredROS2ServiceClientNodes() const
  {
    return this->GetRegisteredServiceTypes();
  }
  ///@}

  ///@{
  /// Actions of any generated .action type (`type` as "test_msgs/action/Fibonacci" or
  /// "test_msgs/Fibonacci"; docs/actions.md): a client sends goals and gets feedback, results and
  /// cancels on Spin; a server fires an event per goal and cancel request for a script to answer.
  /// One client and one server per action name and ROS node; nullptr / false (vtkErrorMacro
  /// listing the known types) otherwise.
  vtkROS2ActionClientNode* CreateAndAddActionClientNode(const char* type, const char* action);
  vtkROS2ActionClientNode* GetActionClientNodeByAction(const char* action);
  bool RemoveAndDeleteActionClientNode(const char* action);
  vtkROS2ActionServerNode* CreateAndAddActionServerNode(const char* type, const char* action);
  vtkROS2ActionServerNode* GetActionServerNodeByAction(const char* action);
  bool RemoveAndDeleteActionServerNode(const char* action);
  /// Space-separated ROS names of the action types that can be used.
  std::string GetRegisteredActionTypes() const;
  ///@}

  ///@{
  /// Robots (SlicerROS2's robot node). The description is the `parameterName` parameter of the
  /// remote `parameterNodeName` (a robot_state_publisher), a std_msgs/String topic (transient
  /// local, like RViz 2's RobotModel) or a file. Links are looked up from `fixedFrame` (empty: the
  /// root link) with `tfPrefix` prepended to link names. The robot appears on the spin that brings
  /// its description. Names are unique per ROS node; nullptr / false (vtkErrorMacro) otherwise.
  vtkROS2RobotNode* CreateAndAddRobotNode(const char* robotName, const char* parameterNodeName,
    const char* parameterName = "robot_description", const char* fixedFrame = "",
    const char* tfPrefix = "");
  vtkROS2RobotNode* CreateAndAddRobotNodeFromTopic(const char* robotName,
    const char* topic = "/robot_description", const char* fixedFrame = "",
    const char* tfPrefix = "");
  /// RViz 2's third source: a URDF file on this machine (re-read with vtkROS2RobotNode::Reload).
  /// `package://` URIs of the package holding the file resolve without any set-up.
  vtkROS2RobotNode* CreateAndAddRobotNodeFromFile(const char* robotName, const char* urdfFile,
    const char* fixedFrame = "", const char* tfPrefix = "");
  vtkROS2RobotNode* GetRobotNodeByName(const char* robotName);
  /// Removes the robot and every node it created (links, models, and its description source
  /// when it created that).
  bool RemoveAndDeleteRobotNode(const char* robotName);
  ///@}

  ///@{
  /// The ROS graph as this node sees it (like `ros2 node list` / `ros2 topic list -t`): one
  /// entry per line, "/ns/name" and "/topic type1 type2". Discovery takes about a second.
  std::string GetNodeNamesAndNamespaces();
  std::string GetTopicNamesAndTypes();
  /// The nodes publishing `topic` (like `ros2 topic info -v`), one "/ns/name" a line, sorted;
  /// "?" for writers that no node's ros_discovery_info announcement lists (yet).
  std::string GetPublisherNodeNames(const char* topic);
  ///@}

  /// Every frame of this node's tf buffer that has a transform, as tf2's allFramesAsYAML
  /// (`ros2 run tf2_tools view_frames`): per frame its parent, broadcaster (the node that sent
  /// its newest transform, from the writer's ros_discovery_info announcement), rate,
  /// newest and oldest stamp, buffer length, and the delay of the newest transform to the
  /// node's current time. Static frames have stamp 0. "[]" when the buffer holds nothing,
  /// "" before Create. Subscribes to /tf and /tf_static on first use, as lookups do.
  std::string GetTf2FramesAsYAML();

  ///@{
  /// Link status, for a panel: other ROS processes' participants this node currently sees (on
  /// any host), how many were dropped because they fell silent beyond the DDS lease (20 s: a
  /// cut network), and a word for it: "not created" (no participant), "no peers" (nobody
  /// found, or everybody dropped) or "peers". A short outage, within the lease, shows instead
  /// on the subscribers (vtkROS2SubscriberNode::GetSecondsSinceLastMessage) and recovers by itself.
  int GetNumberOfDiscoveredParticipants() const;
  vtkTypeInt64 GetNumberOfDroppedParticipants() const;
  const char* GetLinkState() const;
  /// What to check when this node finds nobody: the discovery settings it uses (domain, range,
  /// static peers, discovery server) and the usual causes (docs/networking.md). "" while it sees
  /// peers or before Create. A created node with children that still finds nobody after 5 s of
  /// Spin warns with it (vtkWarningMacro, repeated at most once a minute while it lasts).
  std::string GetNoPeersAdvice() const;
  ///@}

  /// Fired by Spin (on the spinning thread, never on a DDS thread) when the link state changed
  /// since the previous Spin: a peer participant found or lost, so GetLinkState() or
  /// GetNumberOfDiscoveredParticipants() differ. Call data: the new GetLinkState() (const char*).
  /// The participant wakes the spinner when it finds or drops a peer (GetWakeUpFileDescriptor),
  /// so a loop waiting on it sees the change at once. A cut within the 20 s lease changes no
  /// link state: it shows on subscribers (vtkROS2SubscriberNode::GetSecondsSinceLastMessage).
  enum
  {
    LinkStateChangedEvent = vtkCommand::UserEvent + 50
  };

  ///@{
  /// This ROS node's own parameters, served to `ros2 param` and rclpy clients (declared on
  /// first set; a later set must keep the type). False with vtkErrorMacro otherwise.
  bool SetParameterAsBool(const char* name, bool value);
  bool SetParameterAsInteger(const char* name, vtkTypeInt64 value);
  bool SetParameterAsDouble(const char* name, double value);
  bool SetParameterAsString(const char* name, const char* value);
  /// Array parameters (bool[], integer[], double[], byte[], string[]) from one-component arrays:
  /// bools are non-zero values; integers must be whole (a 64-bit integer array is taken
  /// exactly); bytes must be whole and within 0..255. A refused element names its index.
  bool SetParameterAsBoolArray(const char* name, vtkDataArray* values);
  bool SetParameterAsIntegerArray(const char* name, vtkDataArray* values);
  bool SetParameterAsDoubleArray(const char* name, vtkDataArray* values);
  bool SetParameterAsByteArray(const char* name, vtkDataArray* values);
  bool SetParameterAsStringArray(const char* name, vtkStringArray* values);
  /// "name (type): value", or "name (not set): not set".
  std::string PrintOwnParameter(const char* name);
  /// Largest value (bytes of a string or array) other nodes may set on these parameters; a
  /// bigger one is refused with a reason (default 4 MiB). False before Create.
  bool SetParameterValueSizeLimit(vtkTypeInt64 bytes);
  vtkTypeInt64 GetParameterValueSizeLimit();
  ///@}

  ///@{
  /// Simulated time (rclpy's `use_sim_time` parameter, declared on every created node, default
  /// false; ros2 param and rclpy's SetParameters switch it too). While it is on, the node's
  /// clock follows rosgraph_msgs/msg/Clock on /clock (taken on Spin) instead of the system
  /// clock, and everything the node stamps uses it: publishers' headers, tf broadcasts,
  /// parameter events. Before the first /clock message the time is 0, as in rclpy. Switching
  /// it, or /clock going backwards, clears the tf buffer (tf2_ros does the same).
  /// SetUseSimTime before Create applies at Create (and is saved in scene files). False
  /// (vtkErrorMacro) when the set was refused.
  bool SetUseSimTime(bool useSimTime);
  /// Whether the node's time is simulated (the parameter's value once created).
  bool GetUseSimTime() const;
  /// Whether a /clock time has arrived since Create (a status line shows "waiting for /clock").
  bool GetSimTimeReceived() const;
  /// The node's current ROS time: seconds since the epoch of its source (the Unix epoch, or the
  /// simulator's), and the same in nanoseconds, what header stamps carry.
  double GetNodeTime() const;
  vtkTypeInt64 GetNodeTimeNanoseconds() const;
  ///@}

  ///@{
  /// The REP 2011 type description service `~/get_type_description` that rclpy and rclcpp
  /// nodes serve (tools learn the types our endpoints use from it), switched by the read-only
  /// parameter `start_type_description_service` (default true), declared at Create with the
  /// value set here. Set it before Create; after Create the set is refused (vtkErrorMacro, false).
  /// Saved in scene files (attribute startTypeDescriptionService="0", written only when off).
  /// Get: whether the node serves it (once created), or will at Create.
  bool SetStartTypeDescriptionService(bool start);
  bool GetStartTypeDescriptionService() const;
  ///@}

  ///@{
  /// Severity from which this node's warnings and errors are published on /rosout, with
  /// rcl_interfaces/msg/Log's values (10 debug, 20 info (rcl's default), 30 warn, 40 error,
  /// 50 fatal). False (vtkErrorMacro) before Create or for another value.
  bool SetLogLevel(int severity);
  int GetLogLevel();
  ///@}

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  /// Re-creates the ROS node saved in the scene file.
  void OnSceneRestored() override;

#ifndef __VTK_WRAP__
  /// The participant (nullptr before Create), for publishers/subscribers and C++ users.
  ros2vtk::wire::Participant* GetParticipant() const;
  /// The node's tf2 buffer, fed from /tf and /tf_static on each Spin (subscribed on first use).
  /// nullptr before Create.
  ros2vtk::tf2::BufferCore* GetTf2Buffer();
  /// Where `frame` is in `targetFrame` at `stampNanoseconds` (0: the latest transform), from
  /// this node's tf buffer: a translation (metres) and a unit quaternion x, y, z, w that map
  /// points of `frame` into `targetFrame`. False and tf2's reason when it cannot be looked up;
  /// `olderThanHistory` (when given) then says whether the stamp is older than the oldest
  /// transform the buffer holds on the way (tf2's backward extrapolation: waiting cannot help).
  /// For code that places data by its header (markers), with std types only.
  bool LookupFramePose(const std::string& targetFrame, const std::string& frame,
    vtkTypeInt64 stampNanoseconds, double translation[3], double rotation[4], std::string* error,
    bool* olderThanHistory = nullptr);
  /// The node's /tf (or /tf_static) broadcaster, created on first use; nullptr before Create.
  ros2vtk::tf2_ros::TransformBroadcaster* GetTf2Broadcaster(bool isStatic);
  /// The server of this node's own parameters (nullptr before Create).
  ros2vtk::wire::ParameterServer* GetParameterServer() const;
  /// Work done on every Spin after all children (the "connectors" step of the spin order), for
  /// objects that are not children of this node (the OpenIGTLink connector while it runs).
  /// Children override vtkROS2SceneNode::OnROS2NodeSpin instead.
  void AddSpinCallback(vtkROS2SceneNode* owner, std::function<int()> callback);
  void RemoveSpinCallbacks(vtkROS2SceneNode* owner);
  ///@{
  /// The one create/find/remove path of every child kind. A child is referenced under its
  /// kind's `role` and found by its GetROS2NodeChildKey() through an index (rebuilt only when
  /// the references change), so N children cost O(N) to create, not O(N^2).
  /// AddChild sets the child's ROS2NodeReferenceRole reference and this node's `role` one.
  vtkROS2SceneNode* FindChild(const char* role, const std::string& key);
  void AddChild(const char* role, vtkROS2SceneNode* child);
  /// Drops the reference and removes the child from the scene.
  bool RemoveChild(const char* role, vtkROS2SceneNode* child);
  /// Children visited by FindChild (index rebuilds and lookups), for tests of its scaling.
  vtkTypeUInt64 GetNumberOfChildVisits() const;
  ///@}
#endif

protected:
  vtkROS2NodeNode();
  ~vtkROS2NodeNode() override;

  void OnRemovedFromScene() override;

private:
  vtkROS2NodeNode(const vtkROS2NodeNode&) = delete;
  void operator=(const vtkROS2NodeNode&) = delete;

  // Used by the SlicerROS2 methods of each child kind, which are defined in the kind's own
  // .cxx file so that this class's file includes no child kind.
  bool CheckReadyFor(const char* what);
#ifndef __VTK_WRAP__
  /// A child by a name as given or as resolved against this node's namespace (topics,
  /// services), or by its frame pair.
  vtkROS2SceneNode* FindChildByName(const char* role, const char* name);
  vtkROS2SceneNode* FindChildByFrames(
    const char* role, const char* parentFrame, const char* childFrame);
  /// The scene node `nodeID` when this node references it under `role`.
  vtkROS2SceneNode* FindChildByID(const char* role, const char* nodeID);
  /// Names `child`, adds it to the scene and runs `attach`; on success references it under
  /// `role`, on failure removes it from the scene again.
  bool AdoptChild(const char* role, vtkROS2SceneNode* child, const char* name,
    const std::function<bool()>& attach);
  /// The create and remove paths of the kinds keyed by one ROS name (service and action clients
  /// and servers), for their SlicerROS2 methods: `what` names the method in errors, `argument`
  /// the key ("service"), `duplicate` / `missing` start the refusals ("this node serves ",
  /// "no server of "). Create checks readiness and arguments, refuses a second child of the same
  /// name, then adopts `child` named `namePrefix` + key.
  bool AdoptKeyedChild(const char* what, const char* role, vtkROS2SceneNode* child,
    const char* type, const char* key, const char* argument, const char* duplicate,
    const char* namePrefix, const std::function<bool()>& attach);
  bool RemoveKeyedChild(const char* what, const char* role, const char* key, const char* missing);
  /// CreateAndAddPublisherNode / SubscriberNode: the class mapped to `type`, or `newGeneric`'s
  /// node (a new reference) for a registered type without a mapping rule.
  vtkROS2SceneNode* CreateAndAddTopicNode(bool publisher, const char* type, const char* topic,
    vtkROS2TopicNode* (*newGeneric)(const char* rosType));
  /// "name" -> "/name" (monitored nodes are named absolutely).
  static std::string AbsoluteNodeName(const char* name);
  /// Adds a robot node and attaches it to its description source with `attach`; removes it again
  /// (nullptr) when that fails.
  vtkROS2RobotNode* AddRobotNode(const char* what, const char* robotName, const char* fixedFrame,
    const char* tfPrefix, const std::function<bool(vtkROS2RobotNode*)>& attach);
#endif
  int SpinTf2Listener();
  /// Makes the time source (declares use_sim_time) once the parameter server exists.
  void StartTimeSource();
  /// Declares start_type_description_service and, when it is true, serves ~/get_type_description.
  void StartTypeDescriptionService();
  /// Clears the tf buffer when the clock changed source or went back since the last spin.
  void ClearTf2BufferOnClockJump();
  void CollectSpinChildren();
  /// End of Spin: fires LinkStateChangedEvent on a change, warns when nobody was found.
  void UpdateLinkState();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
