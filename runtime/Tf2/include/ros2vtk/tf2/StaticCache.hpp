// ros2vtk — the value of one static frame (/tf_static): only the last sample is kept and it holds
// at every time, like tf2's StaticCache.
#ifndef ros2vtk_tf2_StaticCache_hpp
#define ros2vtk_tf2_StaticCache_hpp

#include "ros2vtk/tf2/TimeCacheInterface.hpp"

namespace ros2vtk {
namespace tf2 {

class StaticCache final : public TimeCacheInterface
{
public:
  /// Replaces the stored value; never refuses.
  bool insert(const TransformRecord& record) override;
  /// The stored value stamped with the requested time; fails only before the first insert.
  bool sample(TimePoint time, TransformRecord& out, SampleError* error = nullptr) const override;
  FrameId parent_at(TimePoint time) const override;
  /// (0, parent): a static frame never limits the latest common time.
  std::pair<TimePoint, FrameId> latest_time_and_parent() const override;
  TimePoint newest_stamp() const override { return 0; }
  TimePoint oldest_stamp() const override { return 0; }
  std::size_t size() const override { return 1; }
  /// Keeps the value: clearing a buffer (e.g. after a time jump) does not forget static frames.
  void clear() override {}
  bool is_static() const override { return true; }

private:
  TransformRecord record_;
  bool has_value_ = false;
};

} // namespace tf2
} // namespace ros2vtk

#endif
