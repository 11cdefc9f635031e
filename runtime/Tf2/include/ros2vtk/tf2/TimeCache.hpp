// ros2vtk — the history of one dynamic frame (/tf): samples sorted by stamp over a sliding window
// (10 s by default), looked up with linear + SLERP interpolation like tf2's TimeCache.
#ifndef ros2vtk_tf2_TimeCache_hpp
#define ros2vtk_tf2_TimeCache_hpp

#include "ros2vtk/tf2/TimeCacheInterface.hpp"

#include <deque>

namespace ros2vtk {
namespace tf2 {

class TimeCache final : public TimeCacheInterface
{
public:
  explicit TimeCache(Duration cache_time = kDefaultCacheTime);

  /// Rejects a sample older than (newest - cache_time); skips an exact duplicate; otherwise
  /// inserts it in stamp order (after earlier samples with the same stamp) and drops samples
  /// older than (newest - cache_time).
  bool insert(const TransformRecord& record) override;

  /// tf2's findClosest + interpolate:
  ///  - empty: NoDataForExtrapolation;
  ///  - time 0: the newest sample;
  ///  - one sample: only an exact stamp match, else NoDataForExtrapolation;
  ///  - after the newest / before the oldest: Forward / BackwardExtrapolation;
  ///  - otherwise the bracketing pair, interpolated when both have the same parent (when the
  ///    parent changes in between, the older sample is returned unchanged).
  /// The returned record carries the requested stamp (the newest stamp for time 0).
  bool sample(TimePoint time, TransformRecord& out, SampleError* error = nullptr) const override;

  FrameId parent_at(TimePoint time) const override;
  std::pair<TimePoint, FrameId> latest_time_and_parent() const override;
  TimePoint newest_stamp() const override;
  TimePoint oldest_stamp() const override;
  std::size_t size() const override { return records_.size(); }
  void clear() override { records_.clear(); }
  bool is_static() const override { return false; }

  Duration cache_time() const { return cache_time_; }
  /// Stored samples, oldest first (for listings and tests).
  const std::deque<TransformRecord>& records() const { return records_; }

private:
  /// Indices of the samples that answer `time`: one (exact or newest) or a bracketing pair
  /// (older, newer). Returns how many were found (0 on failure, with `error` filled).
  int find_closest(
    TimePoint time, std::size_t& older, std::size_t& newer, SampleError* error) const;
  void prune();

  Duration cache_time_;
  std::deque<TransformRecord> records_; ///< ascending stamps; equal stamps in arrival order
};

} // namespace tf2
} // namespace ros2vtk

#endif
