// ros2vtk (private) — tf2's validation of an incoming transform, before anything is stored:
// frame ids present, different, numbers finite, quaternion close enough to unit length.
#ifndef ros2vtk_tf2_TransformInputCheck_hpp
#define ros2vtk_tf2_TransformInputCheck_hpp

#include "ros2vtk/tf2/TransformStamped.hpp"

#include <string>

namespace ros2vtk {
namespace tf2 {

/// tf2's QUATERNION_NORMALIZATION_TOLERANCE (written 10e-3 there): accepted when
/// | x²+y²+z²+w² - 1 | < this.
constexpr double kQuaternionNormTolerance = 10e-3;

struct CheckedTransform
{
  bool ok = false;
  std::string message; ///< one "TF_<ID>: ..." line per problem when not ok
  std::string parent;  ///< frame_id without one leading '/'
  std::string child;   ///< child_frame_id without one leading '/'
  Transform transform; ///< with the quaternion normalised
};

CheckedTransform check_transform_input(const TransformStamped& input, const std::string& authority);

/// `name` without one leading '/' (tf2's stripSlash).
std::string strip_leading_slash(const std::string& name);

} // namespace tf2
} // namespace ros2vtk

#endif
