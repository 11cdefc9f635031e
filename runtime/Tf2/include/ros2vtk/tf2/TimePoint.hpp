// ros2vtk — time in the tf2 buffer: ROS time as signed 64-bit nanoseconds, the unit that
// builtin_interfaces/Time (sec, nanosec) reduces to without loss.
#ifndef ros2vtk_tf2_TimePoint_hpp
#define ros2vtk_tf2_TimePoint_hpp

#include <cstdint>
#include <string>

namespace ros2vtk {
namespace tf2 {

/// A ROS time stamp in nanoseconds. 0 is special in lookups: "the latest data available"
/// (tf2's TimePointZero), exactly as tf2 treats it.
using TimePoint = std::int64_t;
/// A span of ROS time in nanoseconds.
using Duration = std::int64_t;

/// tf2's TimePointZero: ask for the latest common time.
constexpr TimePoint kLatestTime = 0;
/// How long a dynamic frame keeps its history (tf2's BUFFER_CORE_DEFAULT_CACHE_TIME, 10 s).
constexpr Duration kDefaultCacheTime = 10'000'000'000;

/// builtin_interfaces/Time fields to nanoseconds.
constexpr TimePoint time_from_sec_nanosec(std::int32_t sec, std::uint32_t nanosec)
{
  return static_cast<TimePoint>(sec) * 1'000'000'000 + static_cast<TimePoint>(nanosec);
}

/// Seconds (rounded to the nearest nanosecond) to a TimePoint.
TimePoint time_from_seconds(double seconds);

/// A TimePoint in seconds.
double time_to_seconds(TimePoint time);

/// Seconds with six decimals ("12.500000"): tf2's displayTimePoint, used in every message that
/// names a time so our errors read like tf2's.
std::string display_time(TimePoint time);

} // namespace tf2
} // namespace ros2vtk

#endif
