// ros2vtk (private) — tf2's validation of an incoming transform, before anything is stored:
// frame ids present, different, numbers finite, quaternion close enough to unit length.
#ifndef ros2vtk_tf2_TransformInputCheck_hpp
#define ros2vtk_tf2_TransformInputCheck_hpp

#include "ros2vtk/tf2/TransformStamped.hpp"

#include <string>
#include <string_view>

namespace ros2vtk {
namespace tf2 {

/// tf2's QUATERNION_NORMALIZATION_TOLERANCE (written 10e-3 there): accepted when
/// | x²+y²+z²+w² - 1 | < this.
constexpr double kQuaternionNormTolerance = 10e-3;

struct CheckedTransform
{
  bool ok = false;
  std::string message;     ///< one "TF_<ID>: ..." line per problem when not ok
  std::string_view parent; ///< frame_id without one leading '/' (a view of the input's)
  std::string_view child;  ///< child_frame_id without one leading '/' (a view of the input's)
  Transform transform;     ///< with the quaternion normalised
};

CheckedTransform check_transform_input(const TransformStamped& input, const std::string& authority);

/// `name` without one leading '/' (tf2's stripSlash); a view of `name`, not a copy.
std::string_view strip_leading_slash(std::string_view name);

} // namespace tf2
} // namespace ros2vtk

#endif
