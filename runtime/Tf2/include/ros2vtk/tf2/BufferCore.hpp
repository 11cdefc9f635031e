// ros2vtk — the tf2 buffer core: stores the transforms received on /tf and /tf_static and answers
// "where is frame S in frame T at time t" with tf2's semantics (10 s history, interpolation,
// latest-common-time lookups for time 0, static frames valid forever, tf2's error classes and
// wording). Independent of any transport: the tf listener feeds set_transform(), scene nodes call
// lookup_transform(). Nothing here throws; failures come back as values with a message.
// Thread-safe: one mutex guards the frames, so a DDS thread may insert while another looks up.
#ifndef ros2vtk_tf2_BufferCore_hpp
#define ros2vtk_tf2_BufferCore_hpp

#include "ros2vtk/tf2/FrameIds.hpp"
#include "ros2vtk/tf2/LookupResult.hpp"
#include "ros2vtk/tf2/TimePoint.hpp"
#include "ros2vtk/tf2/TransformStamped.hpp"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ros2vtk {
namespace tf2 {

struct FrameTable;
struct WalkScratch;
class LatestPoses;

class BufferCore
{
public:
  /// `cache_time`: how much history each dynamic frame keeps (negative values count as 0).
  explicit BufferCore(Duration cache_time = kDefaultCacheTime);
  ~BufferCore();
  BufferCore(const BufferCore&) = delete;
  BufferCore& operator=(const BufferCore&) = delete;

  /// Validates and stores one transform (tf2's setTransform). One leading '/' is stripped from
  /// both frame ids. Rejected with a message that starts with tf2's stable id:
  ///   TF_SELF_TRANSFORM, TF_NO_CHILD_FRAME_ID, TF_NO_FRAME_ID, TF_NAN_INPUT (NaN or infinite
  ///   numbers), TF_DENORMALIZED_QUATERNION (| |q|^2 - 1 | >= 0.01; inside the tolerance the
  ///   quaternion is normalised), TF_OLD_DATA (older than the frame's history window).
  /// Several problems in one transform give one line each. `is_static` selects the frame's cache
  /// kind; data with the other flag replaces the frame's cache (as tf2 does).
  bool set_transform(const TransformStamped& transform, const std::string& authority,
    bool is_static = false, std::string* error = nullptr);

  /// Transform that maps points in `source_frame` into `target_frame` at `time`
  /// (kLatestTime: the latest time at which the whole chain has data). Equal names give the
  /// identity without any check (even for unknown frames). Errors: InvalidArgument (empty or
  /// leading '/'), Lookup (unknown frame, loop), Connectivity (different trees), and the three
  /// specific extrapolation codes (see LookupResult::message for tf2's text).
  LookupResult lookup_transform(
    const std::string& target_frame, const std::string& source_frame, TimePoint time) const;
  /// The same into `result`, for callers that look the same frames up at every spin: a reused
  /// result keeps its strings' storage, so the lookup allocates nothing for them, and the frame
  /// ids its names resolved to, so the names are not hashed and checked again.
  void lookup_transform(const std::string& target_frame, const std::string& source_frame,
    TimePoint time, LookupResult& result) const;

  /// Time-travel form: source at `source_time` and target at `target_time`, linked through a
  /// `fixed_frame` that does not move between the two times. Stamp of the result: target_time
  /// (or the latest common time used for the target half).
  LookupResult lookup_transform(const std::string& target_frame, TimePoint target_time,
    const std::string& source_frame, TimePoint source_time, const std::string& fixed_frame) const;

  /// Whether lookup_transform would succeed; `error` receives its message when not.
  bool can_transform(const std::string& target_frame, const std::string& source_frame,
    TimePoint time, std::string* error = nullptr) const;
  bool can_transform(const std::string& target_frame, TimePoint target_time,
    const std::string& source_frame, TimePoint source_time, const std::string& fixed_frame,
    std::string* error = nullptr) const;

  /// True when the name was ever seen, as a child or as a parent.
  bool frame_exists(const std::string& frame) const;

  /// Names the authority of `frame`'s newest transform `to` when it is still `from` (a listener
  /// that learnt the sender's node only after inserting; a later sender's authority stays).
  void replace_authority(const std::string& frame, const std::string& from, const std::string& to);

  /// Parent of `frame` at `time` (kLatestTime: newest). False for unknown frames, roots and
  /// times the frame's history does not cover.
  bool get_frame_parent(const std::string& frame, TimePoint time, std::string& parent) const;

  /// Every frame name seen (children and parents), in order of first appearance.
  std::vector<std::string> all_frame_names() const;

  /// One line per frame that has data: "Frame <child> exists with parent <parent>." (tf2).
  std::string all_frames_as_string() const;

  /// tf2's allFramesAsYAML: per frame its parent, broadcaster (authority), rate, newest and
  /// oldest stamp, buffer length and — when `current_time` is not 0 — the delay to it.
  std::string all_frames_as_yaml(TimePoint current_time = kLatestTime) const;

  /// Forgets the history of dynamic frames (static frames and frame names stay), e.g. after
  /// ROS time jumped backwards.
  void clear();

  Duration cache_time() const { return cache_time_; }

private:
  LookupResult lookup_locked(const std::string& target_frame, const std::string& source_frame,
    TimePoint time, const char* function_name) const;
  void lookup_locked(const std::string& target_frame, const std::string& source_frame,
    TimePoint time, const char* function_name, LookupResult& result) const;
  /// The walk of lookup_locked once both frames are known ids.
  void walk_locked(FrameId target, FrameId source, TimePoint time, LookupResult& result) const;

  const std::uint64_t serial_; ///< this buffer among all of the process (LookupResult::resolved_by)

  Duration cache_time_;
  mutable std::mutex mutex_;
  std::unique_ptr<FrameTable> frames_;
  std::unique_ptr<WalkScratch> walk_scratch_; ///< reused by every lookup; guarded by mutex_
  std::unique_ptr<LatestPoses> latest_poses_; ///< latest-time poses of this state; mutex_ too
};

} // namespace tf2
} // namespace ros2vtk

#endif
