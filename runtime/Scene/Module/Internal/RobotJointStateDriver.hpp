// ros2vtk — places a robot's links from joint positions wherever tf does not (issue 15), private
// to the Scene module and used by vtkROS2RobotNode only.
//
// Without a robot_state_publisher, a robot loaded from a file had every link at the origin. This
// keeps the robot's joint positions (zero configuration until told otherwise), takes
// sensor_msgs/JointState from a topic on the ROS node's spin, computes forward kinematics
// (ros2vtk::robot::JointStateKinematics) and sets the matrix of every link node whose tf lookup
// does not succeed. Optionally it broadcasts the transforms on /tf and /tf_static as
// robot_state_publisher would. Runs on the spinning thread only.
#ifndef ros2vtk_scene_RobotJointStateDriver_hpp
#define ros2vtk_scene_RobotJointStateDriver_hpp

#include "RateLimitedReport.hpp"

#include "vtkNew.h"
#include "vtkWeakPointer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

class vtkMatrix4x4;
class vtkROS2Message;
class vtkROS2NodeNode;
class vtkROS2SubscriberNode;
class vtkROS2TransformNode;
class vtkROS2Tf2LookupNode;

namespace ros2vtk {
namespace robot {
class JointStateKinematics;
struct LinkReach;
}
namespace scene {

/// The link-pose status words (GetLinkPoseStatus), in one place.
struct LinkPoseStatus
{
  static constexpr const char* Tf = "tf";
  static constexpr const char* FixedFrame = "fixed frame";
  static constexpr const char* ZeroConfiguration = "zero configuration (no tf)";
  static constexpr const char* JointPositions = "joint positions (no tf)";
};

class RobotJointStateDriver
{
public:
  /// A link and the transform node that places it (a tf2 lookup, or the fixed frame's identity).
  using LinkNodes = std::vector<std::pair<std::string, vtkWeakPointer<vtkROS2TransformNode>>>;

  RobotJointStateDriver();
  ~RobotJointStateDriver();

  /// Kinematics for a newly loaded description. Joint positions set before carry over to joints
  /// of the same name. False (and why) when the URDF has no kinematic tree.
  bool Load(const std::string& urdfXml, std::string* error);
  void Unload();
  bool IsLoaded() const { return static_cast<bool>(this->Kinematics); }
  /// For every link, a ball holding its origin in every joint position (root link frame,
  /// metres; KinematicTree::link_reach), and the root link's name; empty before a load.
  std::map<std::string, ros2vtk::robot::LinkReach> GetLinkReach() const;
  std::string GetRootLink() const;

  /// Actuated joints (moving, not mimic), URDF tree order; empty before a load.
  std::vector<std::string> GetJointNames() const;
  /// False, and why, for a joint that takes no position (unknown, fixed or mimic) or a
  /// non-finite value; out-of-limit values are clamped. Before a load the value is kept and
  /// applied when the robot loads (a joint it does not have is then reported).
  bool SetJointPosition(const std::string& joint, double value, std::string* why);
  /// Any joint's position (mimic joints computed); NaN when unknown or before a load.
  double GetJointPosition(const std::string& joint) const;
  /// Back to the zero configuration.
  void ResetJointPositions();

  /// Follows sensor_msgs/JointState on `topic` ("" stops). The subscriber is the ROS node's
  /// own (shared with a script's subscriber of the same topic, created when there is none and
  /// then tagged with `owner`, so that it is still known as ours after a scene is restored).
  bool SetJointStatesTopic(vtkROS2NodeNode* rosNode, const std::string& topic,
    const std::string& owner, std::string* error);
  const std::string& GetJointStatesTopic() const { return this->Topic; }
  /// Drops the subscriber this driver created (the robot leaves the scene).
  void ReleaseJointStatesTopic(vtkROS2NodeNode* rosNode);
  /// JointState messages applied (accepted, even partly) and refused so far; why the latest
  /// refusal.
  std::int64_t GetNumberOfJointStatesApplied() const { return this->JointStatesApplied; }
  std::int64_t GetNumberOfJointStatesRefused() const { return this->JointStatesRefused; }
  const std::string& GetLastJointStateError() const { return this->LastJointStateError; }

  void SetPublishTf(bool on);
  bool GetPublishTf() const { return this->PublishTf; }

  /// The spin's work: takes new joint states, places every link whose lookup is not "ok"
  /// (relative to `fixedFrame` when it is one of the links, else with the root link at the fixed
  /// frame), broadcasts tf when asked. Returns whether anything changed.
  bool Update(vtkROS2NodeNode* rosNode, const LinkNodes& links, const std::string& fixedFrame,
    const std::string& tfPrefix);

  /// The latest status of a link's pose (LinkPoseStatus words); "" for an unknown link.
  std::string GetLinkPoseStatus(const std::string& link) const;

  /// Messages for the log, collected since the last call (the robot node logs them as its own).
  std::vector<std::string> TakeWarnings();

private:
  void ReadJointStates(vtkROS2NodeNode* rosNode);
  void PlaceLinks(const LinkNodes& links, const std::string& fixedFrame,
    const std::string& tfPrefix, bool* changed);
  void Broadcast(vtkROS2NodeNode* rosNode, const std::string& tfPrefix);

  std::unique_ptr<ros2vtk::robot::JointStateKinematics> Kinematics;
  std::map<std::string, double> PendingPositions; // set before the first load
  bool PosesDirty = true; // joint positions changed since the poses were computed
  std::map<std::string, std::vector<double>> LinkMatricesMillimetres; // cached, per fixed frame
  std::string PosesFixedFrame;
  std::map<std::string, std::string> LinkStatus;
  // Per entry of the last `links`: the node, its lookup (downcast once) and the status last
  // written, so a spin where nothing changed touches no map and no attribute.
  struct PlacedLink
  {
    vtkROS2TransformNode* Node = nullptr;
    vtkROS2Tf2LookupNode* Lookup = nullptr;
    const char* Status = nullptr;
  };
  std::vector<PlacedLink> Placed;
  vtkNew<vtkMatrix4x4> Scratch;

  std::string Topic;
  std::string Owner; // tag of the subscriber this driver created
  vtkWeakPointer<vtkROS2SubscriberNode> Subscriber;
  bool OwnsSubscriber = false;
  std::int64_t MessagesSeen = 0;
  vtkNew<vtkROS2Message> Message;
  std::int64_t JointStatesApplied = 0;
  std::int64_t JointStatesRefused = 0;
  std::string LastJointStateError;
  std::set<std::string> ReportedUnknownJoints;
  RateLimitedReport NonFiniteReport{ std::chrono::seconds(5) };
  RateLimitedReport RefusedReport{ std::chrono::seconds(5) };

  bool PublishTf = false;
  bool PublishDue = false; // positions changed (or a joint state came) since the last broadcast
  bool StaticPublished = false; // fixed joints went to /tf_static for this load
  std::int64_t LatestStamp =
    0; // header stamp of the latest joint state (ns), 0: use the node clock

  std::vector<std::string> Warnings;
};

} // namespace scene
} // namespace ros2vtk

#endif
