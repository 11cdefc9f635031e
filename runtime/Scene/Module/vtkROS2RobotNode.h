// ros2vtk — a robot in the scene, built from its URDF robot_description (SlicerROS2's
// vtkMRMLROS2RobotNode, RViz 2's RobotModel display).
//
//   robot = rosNode->CreateAndAddRobotNode("PSM1", "/PSM1/robot_state_publisher",
//   "robot_description"); robot = rosNode->CreateAndAddRobotNodeFromTopic("arm",
//   "/robot_description"); // RViz 2's way robot = rosNode->CreateAndAddRobotNodeFromFile("arm",
//   "/path/to/arm.urdf");   // and RViz 2's other
//
// The description comes from a parameter of a robot_state_publisher (through a parameter node),
// from its transient-local robot_description topic (through a subscriber node) or from a file
// (read on the next spin, and again on Reload()). When it
// arrives (on a spin of the ROS node), the robot node builds, in the scene:
//   * a base transform node "<robot>:base" (identity; edit it to place the whole robot),
//   * one transform node per link under it: a tf2 lookup node (fixed frame <- prefix + link),
//     or a plain identity node for the fixed frame's own link,
//   * one model node per URDF <visual> under its link's node: meshes (STL, OBJ, PLY, DAE, glTF)
//     and primitives, placed by the visual origin and mesh scale, coloured from the URDF material
//     or the mesh file.
// Links that tf does not place (no robot_state_publisher: a robot from a file) are placed by the
// robot's own forward kinematics: the zero configuration, or joint positions from a JointState
// topic or SetJointPosition (docs/robot-state.md).
// Lengths follow the toolkit's units policy: the scene is in millimetres. A new description
// (robot_state_publisher restarted with another URDF) reloads the robot; a missing mesh is a
// warning and a placeholder; a broken URDF is a state (GetRobotState) and one error message.
#ifndef vtkROS2RobotNode_h
#define vtkROS2RobotNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SceneNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2ModelNode;
class vtkROS2NodeNode;
class vtkROS2TransformNode;

class ROS2VTKSCENE_EXPORT vtkROS2RobotNode : public vtkROS2SceneNode
{
public:
  static vtkROS2RobotNode* New();
  vtkTypeMacro(vtkROS2RobotNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Fired (with ModifiedEvent) on the spin that finished (re)building the robot's nodes.
  enum
  {
    RobotLoadedEvent = vtkCommand::UserEvent + 60
  };

  /// The name given at creation ("PSM1"); also the prefix of the names of the nodes it builds.
  void SetRobotName(const char* robotName);
  const char* GetRobotName() const;
  /// "parameter" (SlicerROS2's way), "topic" or "file" (RViz 2's ways).
  const char* GetDescriptionSource() const;
  /// The parameter source: remote node and parameter ("/robot_state_publisher",
  /// "robot_description").
  const char* GetParameterNodeName() const;
  const char* GetParameterName() const;
  /// The topic source ("/PSM1/robot_description").
  const char* GetDescriptionTopic() const;
  /// The file source (absolute path).
  const char* GetDescriptionFile() const;
  /// Builds the robot again on the next spin even if the description did not change (the file
  /// is read again, meshes too: e.g. after editing them).
  void Reload();

  /// The frame links are looked up from. Empty (default): the scene's fixed frame
  /// (vtkROS2Scene::SetFixedFrame, as RViz's global Fixed Frame places a RobotModel), or the
  /// root link with the tf prefix when the scene has none. Changing it (or the scene's, when
  /// used) after a load rebuilds the lookups on the next spin.
  void SetFixedFrame(const char* frame);
  const char* GetFixedFrame() const;
  /// Prepended to every link name to form its tf frame (robot_state_publisher's frame_prefix,
  /// e.g. "robot1/"). Changing it after a load rebuilds the lookups on the next spin.
  void SetTfPrefix(const char* prefix);
  const char* GetTfPrefix() const;
  /// A folder searched first for package:// (before the package above the URDF file,
  /// AMENT_PREFIX_PATH and ROS_PACKAGE_PATH): a package, a folder holding packages, an install
  /// prefix, or a folder named like the package / holding one (no package.xml needed). Relative
  /// mesh paths are looked for in it after the mesh base folder ("meshes/x.stl" as
  /// <folder>/meshes/x.stl; "../meshes/x.STL" also as <folder>/meshes/x.STL). Applies to the
  /// next load.
  void AddMeshSearchPath(const char* folder);
  /// The folder relative mesh paths ("../meshes/arm.stl") are taken from when the description
  /// comes over the network and so has no folder of its own: usually the URDF file's folder.
  /// Empty (default): the mesh search paths, then the current folder. Applies to the next load.
  void SetMeshBaseFolder(const char* folder);
  const char* GetMeshBaseFolder() const;
  /// Arguments for a `.xacro` description file, as on xacro's command line ("prefix:=left_
  /// use_gripper:=true"). The file is expanded by the xacro program (pip install xacro; found
  /// as $ROS2VTK_XACRO, on PATH or in the venv), `$(find pkg)` through AMENT_PREFIX_PATH. False
  /// (and an error) for an item that is not name:=value. A robot loaded from a file reloads.
  bool SetXacroArguments(const char* arguments);
  const char* GetXacroArguments() const;
  /// On (default): meshes are read only inside package roots, the URDF file's folder (or the
  /// mesh base folder) and the mesh search paths, after `..` and symlinks are resolved, so a
  /// description from the network cannot make us read other files. Off is the explicit opt-out.
  void SetRestrictMeshesToRoots(bool on);
  bool GetRestrictMeshesToRoots() const;

  /// "waiting for robot_description", "loaded" or "failed: <why>".
  const char* GetRobotState() const;
  bool IsLoaded() const;
  /// Why the latest description was refused (empty when it loaded).
  const char* GetLastError() const;
  /// Warnings of the latest load (missing meshes, urdfdom complaints), one per line.
  std::string GetWarnings() const;
  /// The latest load in one line, as it is logged once per load: "7 visuals, 2 of 5 meshes
  /// missing (2 warnings, 1 cause); first: link 'a': could not load mesh '…': …", or "7 visuals,
  /// all 5 meshes loaded". Empty before the first load.
  std::string GetLoadSummary() const;
  /// A link's status after the latest load: "ok", "<k> of <n> visuals are placeholders: <first
  /// warning>", or "" when there is no such link.
  std::string GetLinkStatus(const char* link) const;
  /// Descriptions loaded so far (a reload counts again).
  int GetNumberOfLoads() const;
  /// Seconds from taking the description to every node being in the scene (latest load).
  double GetLastLoadDuration() const;

  int GetNumberOfLinks() const;
  /// Link names in URDF tree order (parents first), space-separated.
  std::string GetLinkNames() const;
  /// The transform node of a link (a vtkROS2Tf2LookupNode, or the identity node of the fixed
  /// frame's link); nullptr when there is no such link.
  vtkROS2TransformNode* GetLinkTransformNode(const char* link);
  /// Links whose tf lookup currently succeeds (the fixed frame's own link counts).
  int GetNumberOfLinksTracked();
  /// The transform node every link hangs under; edit its matrix to place the robot.
  vtkROS2TransformNode* GetBaseTransformNode();

  /// One model node per URDF visual, in link order.
  int GetNumberOfModelNodes() const;
  vtkROS2ModelNode* GetNthModelNode(int n);
  /// Visuals whose mesh could not be loaded (a placeholder cube stands in for each).
  int GetNumberOfPlaceholders() const;

  ///@{
  /// Joint positions without a robot_state_publisher (docs/robot-state.md). Links whose tf lookup
  /// does not succeed are placed by forward kinematics from these positions: the zero
  /// configuration (0 clamped into each joint's limits) until positions arrive from the joint
  /// states topic or SetJointPosition. Where tf for a link arrives, tf wins.
  ///
  /// Follows sensor_msgs/JointState on `topic` (e.g. "/joint_states"), applied on the ROS node's
  /// spin; "" (default) stops. False (and an error) when it cannot subscribe.
  bool SetJointStatesTopic(const char* topic);
  const char* GetJointStatesTopic() const;
  /// Sets an actuated joint (radians or metres; revolute and prismatic joints are clamped into
  /// their limits, continuous ones are not). False (and an error) for an unknown, fixed or mimic
  /// joint or a non-finite value. Before the robot is loaded the value is kept for the load.
  bool SetJointPosition(const char* joint, double value);
  /// The joint's position (mimic joints: multiplier * leader + offset); NaN for no such joint.
  double GetJointPosition(const char* joint) const;
  /// Joints that take a position (moving, not mimic), URDF tree order, space-separated.
  std::string GetJointNames() const;
  /// Every joint back to the zero configuration.
  void ResetJointPositions();
  /// Off (default): the computed poses only move our scene. On: they are also broadcast as
  /// robot_state_publisher would (moving joints on /tf stamped with the joint state's stamp, or
  /// the node clock; fixed joints on /tf_static; frames prefixed with the tf prefix), so other
  /// ROS nodes see the robot.
  void SetPublishTf(bool on);
  bool GetPublishTf() const;
  /// Where a link's pose comes from: "tf" (its tf lookup succeeds), "fixed frame" (the link is
  /// the fixed frame), "zero configuration (no tf)", "joint positions (no tf)"; "" for no such
  /// link or before the first spin after a load.
  std::string GetLinkPoseStatus(const char* link) const;
  /// Where the links' poses come from, in one line, e.g. "6 links: 1 fixed frame, 5 zero
  /// configuration (no tf)" (counts per GetLinkPoseStatus word, in the table's order); "" before
  /// the first spin after a load. What a panel shows next to "loaded".
  std::string GetLinkPoseSummary() const;
  /// Joint state messages applied so far, and refused ones with the latest reason.
  vtkTypeInt64 GetNumberOfJointStatesApplied() const;
  vtkTypeInt64 GetNumberOfJointStatesRefused() const;
  const char* GetLastJointStateError() const;
  ///@}

  /// The robot's workspace: a sphere (centre x, y, z and radius, world mm) that holds every
  /// visual of the robot in every joint position within the limits, centred on its root link's
  /// origin where it is now (what a view frames to keep the whole robot in sight while it moves).
  /// The radius is each link's reach (KinematicTree::link_reach: the joint origins' lengths along
  /// its chain plus prismatic travel) plus the furthest point of its visuals from the link's
  /// origin. False (sphere unchanged) before the robot is loaded.
  bool GetWorkspaceSphere(double sphere[4]);

  /// Builds the robot from URDF text right away (besides the automatic load from the source),
  /// with relative mesh paths taken from `baseFolder`. False (state "failed") on a broken URDF.
  bool LoadRobotDescription(const char* urdfXml, const char* baseFolder = "");

  /// The ROS node that spins this robot.
  vtkROS2NodeNode* GetROS2Node() const;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: takes the description from `parameterName` of `remoteNode`.
  bool AttachToParameter(
    vtkROS2NodeNode* rosNode, const std::string& remoteNode, const std::string& parameterName);
  /// Used by vtkROS2NodeNode: takes the description from a std_msgs/String `topic`.
  bool AttachToTopic(vtkROS2NodeNode* rosNode, const std::string& topic);
  /// Used by vtkROS2NodeNode: takes the description from a URDF file.
  bool AttachToFile(vtkROS2NodeNode* rosNode, const std::string& urdfFile);
#endif

  /// Saved: the source, frames and mesh folders; the base and link transform nodes are saved as
  /// nodes of their own. The models are not: on restore the robot loads again when its source
  /// delivers the description (robot_state_publisher's parameter or latched topic).
  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  void OnSceneRestored() override;

  /// Spin hook (vtkROS2SceneNode::OnROS2NodeSpin): loads a new description, then places the
  /// links tf does not place from the joint positions.
  int OnROS2NodeSpin(vtkROS2NodeNode*) override;
  /// Index key among the ROS node's robots.
  std::string GetROS2NodeChildKey() const override
  {
    return this->GetRobotName();
  }

protected:
  vtkROS2RobotNode();
  ~vtkROS2RobotNode() override;

  void OnRemovedFromScene() override;

private:
  vtkROS2RobotNode(const vtkROS2RobotNode&) = delete;
  void operator=(const vtkROS2RobotNode&) = delete;

  /// Observes the description source (parameter node or subscriber) and spins with `rosNode`.
  void FollowSource(vtkROS2NodeNode* rosNode, vtkROS2SceneNode* source);
  /// Spins with `rosNode`, reading the description file on the next spin.
  void FollowFile(vtkROS2NodeNode* rosNode);
  /// The file source's text; false (state "failed") when it cannot be read.
  bool ReadDescriptionFile(std::string& description);
  /// Spin callback: loads a new description when the source brought one.
  int CheckForNewDescription();
  /// Spin callback: joint states in, link poses out (RobotJointStateDriver). `rosNode`: the
  /// spinning node (this robot's), passed in so a spin does not look it up again.
  int UpdateLinkPoses(vtkROS2NodeNode* rosNode);
  /// Removes everything this robot built (models, its own link nodes, the base).
  void Unload();
  void RemoveModels();
  /// Removes one of its link nodes (through the ROS node when it is a tf2 lookup).
  void RemoveLinkNode(vtkROS2TransformNode* node);
  void ReleaseSource();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
