#include "ros2vtk/tf2/Transform.hpp"

namespace ros2vtk {
namespace tf2 {

Transform Transform::from_isometry(const Eigen::Isometry3d& isometry)
{
  Transform result;
  result.translation = isometry.translation();
  result.rotation = Eigen::Quaterniond(isometry.linear()).normalized();
  return result;
}

Eigen::Isometry3d Transform::to_isometry() const
{
  Eigen::Isometry3d isometry = Eigen::Isometry3d::Identity();
  isometry.linear() = rotation.toRotationMatrix();
  isometry.translation() = translation;
  return isometry;
}

Eigen::Vector3d Transform::apply(const Eigen::Vector3d& point) const
{
  return rotation * point + translation;
}

Transform Transform::inverse() const
{
  Transform result;
  result.rotation = rotation.conjugate();
  result.translation = -(result.rotation * translation);
  return result;
}

Transform Transform::operator*(const Transform& other) const
{
  Transform result;
  result.rotation = rotation * other.rotation;
  result.translation = rotation * other.translation + translation;
  return result;
}

bool Transform::operator==(const Transform& other) const
{
  return translation == other.translation && rotation.coeffs() == other.rotation.coeffs();
}

Transform interpolate(const Transform& a, const Transform& b, double ratio)
{
  Transform result;
  result.translation = (1.0 - ratio) * a.translation + ratio * b.translation;
  result.rotation = a.rotation.slerp(ratio, b.rotation);
  return result;
}

} // namespace tf2
} // namespace ros2vtk
