// ros2vtk — a rigid transform as tf2 stores it: a translation and a unit quaternion. Kept as a
// value type separate from Eigen::Isometry3d so that interpolation works on the quaternion
// (SLERP) and the stored rotation is exactly what was received.
#ifndef ros2vtk_tf2_Transform_hpp
#define ros2vtk_tf2_Transform_hpp

#include <Eigen/Geometry>

namespace ros2vtk {
namespace tf2 {

/// Pose of a child frame in its parent: p_parent = rotation * p_child + translation
/// (geometry_msgs/Transform semantics).
struct Transform
{
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();

  static Transform identity() { return Transform(); }
  static Transform from_isometry(const Eigen::Isometry3d& isometry);
  Eigen::Isometry3d to_isometry() const;

  /// Maps a point given in the child frame into the parent frame.
  Eigen::Vector3d apply(const Eigen::Vector3d& point) const;

  /// The transform that undoes this one (parent -> child).
  Transform inverse() const;

  /// this ∘ other: first `other`, then this. If other maps C into B and this maps B into A,
  /// the result maps C into A.
  Transform operator*(const Transform& other) const;

  /// Exact equality of all seven numbers (tf2 compares stored records this way).
  bool operator==(const Transform& other) const;
  bool operator!=(const Transform& other) const { return !(*this == other); }
};

/// tf2's interpolation between two samples: translation (1 - ratio) * a + ratio * b, rotation by
/// SLERP along the shorter arc (Eigen's slerp flips the second quaternion when dot < 0).
Transform interpolate(const Transform& a, const Transform& b, double ratio);

} // namespace tf2
} // namespace ros2vtk

#endif
