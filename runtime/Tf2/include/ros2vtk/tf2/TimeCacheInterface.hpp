// ros2vtk — what the buffer needs from the history of one frame. Two implementations, as in tf2:
// TimeCache (dynamic frames, /tf: a time window with interpolation) and StaticCache (/tf_static:
// one value, valid at every time). The buffer walks the tree through this interface only.
#ifndef ros2vtk_tf2_TimeCacheInterface_hpp
#define ros2vtk_tf2_TimeCacheInterface_hpp

#include "ros2vtk/tf2/Tf2Error.hpp"
#include "ros2vtk/tf2/TransformRecord.hpp"

#include <cstddef>
#include <string>
#include <utility>

namespace ros2vtk {
namespace tf2 {

/// Why a cache could not give a sample at the requested time (tf2's wording in `message`).
struct SampleError
{
  Tf2Error code = Tf2Error::NoError;
  std::string message;
};

class TimeCacheInterface
{
public:
  virtual ~TimeCacheInterface() = default;

  /// Stores a sample. False when the cache refuses it because it is older than the cache keeps
  /// (the caller reports TF_OLD_DATA).
  virtual bool insert(const TransformRecord& record) = 0;

  /// The sample at `time` (kLatestTime: the newest one), interpolated between neighbours when
  /// that is allowed. On failure returns false and, when `error` is given, says why.
  virtual bool sample(TimePoint time, TransformRecord& out, SampleError* error = nullptr) const = 0;

  /// Parent of the frame at `time` without interpolating; kNoFrame when no sample fits.
  virtual FrameId parent_at(TimePoint time) const = 0;

  /// Stamp and parent of the newest sample; (0, kNoFrame) when empty. Static caches report
  /// stamp 0 so that they never constrain the latest common time.
  virtual std::pair<TimePoint, FrameId> latest_time_and_parent() const = 0;

  virtual TimePoint newest_stamp() const = 0; ///< 0 when empty or static
  virtual TimePoint oldest_stamp() const = 0; ///< 0 when empty or static
  virtual std::size_t size() const = 0;       ///< samples held (1 for a static cache)
  virtual void clear() = 0;                   ///< drops history (static values survive, as in tf2)
  virtual bool is_static() const = 0;

protected:
  TimeCacheInterface() = default;
  TimeCacheInterface(const TimeCacheInterface&) = default;
  TimeCacheInterface& operator=(const TimeCacheInterface&) = default;
};

} // namespace tf2
} // namespace ros2vtk

#endif
