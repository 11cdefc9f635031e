// ros2vtk — a robot's joint positions and the link poses they give (forward kinematics), so a
// robot loaded from a file can be shown and driven without a robot_state_publisher. Holds one
// value per actuated joint (zero configuration until told otherwise), applies
// sensor_msgs/JointState contents with robot_state_publisher's checks, clamps into the URDF
// limits and derives mimic joints. Plain C++ (Eigen), metres and radians; not thread-safe.
#ifndef ros2vtk_robot_JointStateKinematics_hpp
#define ros2vtk_robot_JointStateKinematics_hpp

#include "ros2vtk/robot/KinematicTree.hpp"

#include <Eigen/Geometry>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// What happened to the contents of one JointState message (apply_joint_state).
struct JointStateReport
{
  bool accepted = false;               ///< false: the whole message was refused (see error)
  std::string error;                   ///< why it was refused ("" when accepted)
  size_t applied = 0;                  ///< positions taken (clamped ones included)
  std::vector<std::string> unknown;    ///< names that are no actuated joint of this robot (ignored)
  std::vector<std::string> not_finite; ///< joints whose position was NaN or infinite (ignored)
  std::vector<std::string> clamped;    ///< joints whose position was out of limits (clamped)
};

class JointStateKinematics
{
public:
  /// Why a position was not taken by set_position.
  enum class SetResult
  {
    Applied,
    Clamped,
    UnknownJoint,
    NotActuated,
    NotFinite
  };

  /// Parses the URDF (KinematicTree::from_urdf); nullptr and why when it does not parse.
  static std::unique_ptr<JointStateKinematics> from_urdf(
    const std::string& urdf_xml, std::string* error);
  explicit JointStateKinematics(std::unique_ptr<KinematicTree> tree);

  const KinematicTree& tree() const { return *tree_; }

  /// Joints that take a position (moving, not mimic; floating and planar joints are not
  /// supported and stay at their origin), in URDF tree order.
  const std::vector<std::string>& joint_names() const { return actuated_; }

  /// Sets one actuated joint. Revolute and prismatic joints are clamped into [lower, upper]
  /// (when lower < upper: a URDF limit without a range does not freeze the joint); continuous
  /// joints are unbounded. Mimic, fixed and unknown joints and non-finite values are refused.
  SetResult set_position(const std::string& joint, double value);
  /// The position of any joint: actuated (as set, after clamping), mimic (multiplier * leader +
  /// offset) or fixed (0). NaN for a joint this robot does not have.
  double position(const std::string& joint) const;
  /// Every actuated joint back to the zero configuration (0 clamped into its limits).
  void reset();
  /// True once a position was set (by set_position or a joint state) since the last reset.
  bool has_positions() const { return has_positions_; }

  /// The contents of a sensor_msgs/JointState, checked as robot_state_publisher does: name and
  /// position arrays of different lengths refuse the whole message; names that are no actuated
  /// joint and non-finite positions are ignored (and listed), the rest applied.
  JointStateReport apply_joint_state(
    const std::vector<std::string>& names, const std::vector<double>& positions);

  /// Pose of every link in the root link's frame, metres, for the current positions. Mimic
  /// joints follow their leader exactly (not clamped, as robot_state_publisher does).
  std::map<std::string, Eigen::Isometry3d> link_poses() const;
  /// The transforms robot_state_publisher would broadcast (parent link -> child link, one per
  /// joint, fixed joints flagged static) for the current positions.
  std::vector<LinkTransform> joint_transforms() const;

private:
  double clamp_into_limits(const JointInfo& joint, double value, bool* clamped) const;
  /// Joint position used for kinematics: actuated as set, mimic from its leader (chains of
  /// mimic joints followed, a loop or an unknown leader gives 0).
  double effective_position(const JointInfo& joint) const;

  std::unique_ptr<KinematicTree> tree_;
  std::vector<std::string> actuated_;
  std::map<std::string, double> positions_; ///< actuated joints only
  bool has_positions_ = false;
};

} // namespace robot
} // namespace ros2vtk

#endif
