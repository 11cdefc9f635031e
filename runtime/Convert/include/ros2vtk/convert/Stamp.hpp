// ros2vtk — header stamps for publishers.
//
// Broadcast transforms (and anything else we publish with a header) carry the current time, not
// zero (tf2 treats a zero stamp as "latest"). builtin_interfaces/Time is int32 sec + uint32 nanosec
// since the Unix epoch.
#ifndef ros2vtk_convert_Stamp_hpp
#define ros2vtk_convert_Stamp_hpp

#include <chrono>
#include <cstdint>

namespace ros2vtk {
namespace convert {

/// builtin_interfaces/Time.
struct Stamp
{
  int32_t sec = 0;
  uint32_t nanosec = 0; ///< always < 1e9
};

/// The system clock now (what rclcpp's default ROS clock gives when sim time is off).
/// Nodes stamp with their own clock instead (vtkROS2NodeNode::GetNodeTimeNanoseconds), which
/// follows simulated time.
Stamp now_stamp();

/// ROS time in nanoseconds (a node clock's reading) as a stamp, clamped like to_stamp.
Stamp stamp_from_nanoseconds(int64_t nanoseconds);

/// A system-clock time point as a stamp; times before the epoch or after 2038 (int32 seconds)
/// are clamped to the representable range.
Stamp to_stamp(std::chrono::system_clock::time_point time);

} // namespace convert
} // namespace ros2vtk

#endif
