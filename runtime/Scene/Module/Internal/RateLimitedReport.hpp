// ros2vtk — decides when a recurring problem is worth another log line (private to Scene).
//
// A subscriber can receive hundreds of malformed samples a second; logging each one drowns the
// console (SlicerROS2 logs a failing lookup 50 times a second). The first occurrence is
// reported at once; later ones are summed and reported at most once per interval.
#ifndef ros2vtk_scene_RateLimitedReport_hpp
#define ros2vtk_scene_RateLimitedReport_hpp

#include <chrono>
#include <cstdint>

namespace ros2vtk {
namespace scene {

class RateLimitedReport
{
public:
  using Clock = std::chrono::steady_clock;

  explicit RateLimitedReport(Clock::duration interval)
    : interval_(interval)
  {
  }

  /// Adds `count` new occurrences at `now` (count may be 0, to flush a pending sum). Returns
  /// the number of occurrences to report now (everything since the last report), or 0 when
  /// the report must wait.
  uint64_t record(uint64_t count, Clock::time_point now)
  {
    pending_ += count;
    if (pending_ == 0 || (reported_once_ && now - last_report_ < interval_))
    {
      return 0;
    }
    const uint64_t due = pending_;
    pending_ = 0;
    last_report_ = now;
    reported_once_ = true;
    return due;
  }

private:
  Clock::duration interval_;
  Clock::time_point last_report_{};
  bool reported_once_ = false;
  uint64_t pending_ = 0;
};

} // namespace scene
} // namespace ros2vtk

#endif
