// ros2vtk — the error classes of a tf2 lookup. Values are tf2's TF2Error numbers, so logs and
// scripts that know tf2's codes read ours the same way.
#ifndef ros2vtk_tf2_Tf2Error_hpp
#define ros2vtk_tf2_Tf2Error_hpp

#include <cstdint>

namespace ros2vtk {
namespace tf2 {

enum class Tf2Error : std::uint8_t
{
  NoError = 0,
  Lookup = 1,                 ///< unknown frame, or a loop in the tree
  Connectivity = 2,           ///< both frames exist but in different trees
  Extrapolation = 3,          ///< generic extrapolation (tf2's base class)
  InvalidArgument = 4,        ///< empty frame id or one with a leading '/'
  Timeout = 5,                ///< reserved for waiting callers (tf2_ros::Buffer)
  Transform = 6,              ///< reserved (tf2's base TransformException)
  BackwardExtrapolation = 7,  ///< requested time older than the oldest sample
  ForwardExtrapolation = 8,   ///< requested time newer than the newest sample
  NoDataForExtrapolation = 9, ///< a single sample (or none) that does not match the time
};

/// tf2's name for the code ("TF2_CONNECTIVITY_ERROR", ...).
const char* to_string(Tf2Error error);

/// True for the generic and the three specific extrapolation codes (tf2's
/// BackwardExtrapolationException and friends derive from ExtrapolationException).
bool is_extrapolation(Tf2Error error);

} // namespace tf2
} // namespace ros2vtk

#endif
