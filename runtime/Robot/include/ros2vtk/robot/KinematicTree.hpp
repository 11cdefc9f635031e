// ros2vtk — a robot's joint tree from its URDF, and the transforms robot_state_publisher
// would broadcast for a set of joint positions. Plain C++ (urdfdom + Eigen): used by the
// simulated robot and by tests that check where our scene puts each link.
#ifndef ros2vtk_robot_KinematicTree_hpp
#define ros2vtk_robot_KinematicTree_hpp

#include <Eigen/Geometry>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// One URDF joint, reduced to what kinematics needs.
struct JointInfo
{
  enum class Type
  {
    Fixed,
    Revolute,
    Continuous,
    Prismatic,
    Floating,
    Planar
  };
  std::string name;
  Type type = Type::Fixed;
  std::string parent_link;
  std::string child_link;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity(); ///< parent link -> joint frame (m)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  double lower = 0.0; ///< limits (rad or m); equal for joints without limits
  double upper = 0.0;
  bool has_limits = false;
  std::string mimic_joint; ///< non-empty: position = multiplier * mimic + offset
  double mimic_multiplier = 1.0;
  double mimic_offset = 0.0;

  /// True for joints robot_state_publisher puts on /tf (everything but fixed joints).
  bool is_moving() const { return type != Type::Fixed; }
};

/// A transform as robot_state_publisher broadcasts it: parent link -> child link.
struct LinkTransform
{
  std::string parent;
  std::string child;
  Eigen::Isometry3d transform; ///< pose of child in parent (metres)
  bool is_static = false;
};

/// Where a link's origin can be: within `radius` of `centre` (root link frame, metres).
struct LinkReach
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

class KinematicTree
{
public:
  /// Parses URDF XML with urdfdom. Returns nullptr and a message naming the problem when the
  /// XML does not parse or describes no tree (urdfdom's own checks: one root, no loops).
  static std::unique_ptr<KinematicTree> from_urdf(const std::string& urdf_xml, std::string* error);

  const std::string& robot_name() const { return robot_name_; }
  const std::string& root_link() const { return root_link_; }
  const std::vector<JointInfo>& joints() const { return joints_; }
  std::vector<std::string> link_names() const;
  /// Joints that take a position (moving, not mimic), in URDF order.
  std::vector<std::string> actuated_joints() const;
  const JointInfo* joint(const std::string& name) const;

  /// Transforms of every joint for the given positions (missing joints at 0, mimic joints
  /// from their leader). Static transforms (fixed joints) are flagged.
  std::vector<LinkTransform> joint_transforms(const std::map<std::string, double>& positions) const;

  /// Pose of every link in the root link's frame.
  std::map<std::string, Eigen::Isometry3d> link_poses(
    const std::map<std::string, double>& positions) const;

  /// For every link, a ball in the root link's frame (metres) that holds its origin in every
  /// joint position within the limits: centred on the deepest point of its chain that no joint
  /// moves (a joint turning about an axis that the next joint's origin lies on leaves that origin
  /// in place), with radius the lengths of the joint origins below that point plus each
  /// prismatic joint's largest travel (a mimic one's: |multiplier| x its leader's plus |offset|).
  /// An upper bound (rotations only turn these segments); floating and planar joints count as at
  /// their origin (robot_state_publisher does not move them either).
  std::map<std::string, LinkReach> link_reach() const;

private:
  std::string robot_name_;
  std::string root_link_;
  std::vector<JointInfo> joints_;
  std::map<std::string, size_t> joint_index_;
  std::vector<std::string> links_;
};

/// The motion of one joint for a position q: rotation about the axis (revolute/continuous),
/// translation along it (prismatic), identity otherwise.
Eigen::Isometry3d joint_motion(const JointInfo& joint, double q);

} // namespace robot
} // namespace ros2vtk

#endif
