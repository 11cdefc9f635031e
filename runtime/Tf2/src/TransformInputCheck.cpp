#include "TransformInputCheck.hpp"

#include <cmath>
#include <cstdio>

namespace ros2vtk {
namespace tf2 {

namespace {

std::string format_numbers(const Transform& t, bool with_translation)
{
  char text[256];
  const auto& q = t.rotation;
  if (with_translation)
  {
    std::snprintf(text, sizeof(text), "(%f %f %f) (%f %f %f %f)", t.translation.x(),
      t.translation.y(), t.translation.z(), q.x(), q.y(), q.z(), q.w());
  }
  else
  {
    std::snprintf(text, sizeof(text), "(%f %f %f %f)", q.x(), q.y(), q.z(), q.w());
  }
  return text;
}

void add_line(std::string& message, const std::string& line)
{
  if (!message.empty())
  {
    message += '\n';
  }
  message += line;
}

} // namespace

std::string_view strip_leading_slash(std::string_view name)
{
  return !name.empty() && name[0] == '/' ? name.substr(1) : name;
}

CheckedTransform check_transform_input(const TransformStamped& input, const std::string& authority)
{
  CheckedTransform result;
  result.parent = strip_leading_slash(input.frame_id);
  result.child = strip_leading_slash(input.child_frame_id);
  result.transform = input.transform;
  // Quoted names only for a message: every /tf transform passes here.
  const auto quoted_authority = [&authority] {
    return "\"" + authority + "\"";
  };
  const auto quoted_child = [&result] {
    return "\"" + std::string(result.child) + "\"";
  };

  std::string& message = result.message;
  if (result.child == result.parent)
  {
    add_line(message,
      "TF_SELF_TRANSFORM: Ignoring transform from authority " + quoted_authority() +
        " with frame_id and child_frame_id " + quoted_child() + " because they are the same");
  }
  if (result.child.empty())
  {
    add_line(message,
      "TF_NO_CHILD_FRAME_ID: Ignoring transform from authority " + quoted_authority() +
        " because child_frame_id not set");
  }
  if (result.parent.empty())
  {
    add_line(message,
      "TF_NO_FRAME_ID: Ignoring transform with child_frame_id " + quoted_child() +
        " from authority " + quoted_authority() + " because frame_id not set");
  }

  const Eigen::Vector3d& t = input.transform.translation;
  const Eigen::Vector4d& q = input.transform.rotation.coeffs();
  const bool has_nan = t.hasNaN() || q.hasNaN();
  if (has_nan || !t.allFinite() || !q.allFinite())
  {
    // tf2 checks NaN only; an infinite value would poison every lookup through this frame just
    // the same, so it is refused under the same id.
    add_line(message,
      std::string("TF_NAN_INPUT: Ignoring transform for child_frame_id ") + quoted_child() +
        " from authority " + quoted_authority() + " because of " +
        (has_nan ? "a nan" : "an infinite") + " value in the transform " +
        format_numbers(input.transform, true));
  }

  const double squared_norm = q.squaredNorm();
  if (!(std::abs(squared_norm - 1.0) < kQuaternionNormTolerance))
  {
    add_line(message,
      "TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id " + quoted_child() +
        " from authority " + quoted_authority() +
        " because of an invalid quaternion in the transform " +
        format_numbers(input.transform, false));
  }

  result.ok = message.empty();
  if (result.ok)
  {
    result.transform.rotation.normalize();
  }
  return result;
}

} // namespace tf2
} // namespace ros2vtk
