// Helpers shared by the tf2 tests: building inputs and comparing rotations. Expected values in
// the tests are computed by hand (or with Eigen directly), never by the code under test.
#ifndef ros2vtk_tests_Tf2TestUtil_hpp
#define ros2vtk_tests_Tf2TestUtil_hpp

#include "ros2vtk/tf2/TransformStamped.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tf2test {

using ros2vtk::tf2::TimePoint;
using ros2vtk::tf2::Transform;
using ros2vtk::tf2::TransformStamped;

constexpr double kPi = 3.14159265358979323846;

/// Whole and fractional seconds to nanoseconds, written out so no library code is involved.
constexpr TimePoint sec(double seconds)
{
  return static_cast<TimePoint>(seconds * 1e9 + (seconds >= 0 ? 0.5 : -0.5));
}

/// Rotation of `degrees` about a unit axis, from the half-angle formula.
inline Eigen::Quaterniond about(double x, double y, double z, double degrees)
{
  const double half = degrees * kPi / 360.0;
  return Eigen::Quaterniond(
    std::cos(half), x * std::sin(half), y * std::sin(half), z * std::sin(half));
}

inline Transform make_transform(
  const Eigen::Vector3d& t, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity())
{
  Transform transform;
  transform.translation = t;
  transform.rotation = q;
  return transform;
}

inline TransformStamped make_stamped(const std::string& parent, const std::string& child,
  TimePoint stamp, const Eigen::Vector3d& t,
  const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity())
{
  TransformStamped stamped;
  stamped.frame_id = parent;
  stamped.child_frame_id = child;
  stamped.stamp = stamp;
  stamped.transform = make_transform(t, q);
  return stamped;
}

/// Same rotation: q and -q are the same rotation, so compare |dot| with 1.
inline ::testing::AssertionResult same_rotation(
  const Eigen::Quaterniond& actual, const Eigen::Quaterniond& expected, double tolerance = 1e-9)
{
  const double dot = std::abs(actual.normalized().dot(expected.normalized()));
  if (std::abs(dot - 1.0) <= tolerance)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
    << "rotation (" << actual.coeffs().transpose() << ") [x y z w] differs from ("
    << expected.coeffs().transpose() << "), |dot| = " << dot;
}

inline ::testing::AssertionResult same_vector(
  const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance = 1e-9)
{
  if ((actual - expected).norm() <= tolerance)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
    << "vector (" << actual.transpose() << ") differs from (" << expected.transpose() << ")";
}

} // namespace tf2test

#endif
