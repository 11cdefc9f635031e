#include "ros2vtk/tf2/BufferCore.hpp"

#include "FrameListing.hpp"
#include "FrameTable.hpp"
#include "LatestPoses.hpp"
#include "TransformInputCheck.hpp"
#include "TreeWalker.hpp"

#include "ros2vtk/tf2/StaticCache.hpp"
#include "ros2vtk/tf2/TimeCache.hpp"

#include <algorithm>
#include <atomic>

namespace ros2vtk {
namespace tf2 {

namespace {

/// tf2's validateFrameId for lookups: empty or '/'-prefixed ids are invalid arguments, unknown
/// ids a lookup error. Returns kNoFrame and fills `result` on failure.
FrameId validate_frame_id(const FrameTable& frames, const char* function_name, const char* argument,
  const std::string& frame, LookupResult& result)
{
  // The "<function> argument <name>" wording is built only on failure: lookups run for every
  // link at every spin.
  auto where = [function_name, argument] {
    return std::string(function_name) + " argument " + argument;
  };
  if (frame.empty() || frame[0] == '/')
  {
    result.error = Tf2Error::InvalidArgument;
    result.message = "Invalid argument \"" + frame + "\" passed to " + where() +
      (frame.empty() ? " - in tf2 frame_ids cannot be empty"
                     : " - in tf2 frame_ids cannot start with a '/'");
    return kNoFrame;
  }
  const FrameId id = frames.ids.find(frame);
  if (id == kNoFrame)
  {
    result.error = Tf2Error::Lookup;
    result.message = "\"" + frame + "\" passed to " + where() + " does not exist.";
  }
  return id;
}

} // namespace

namespace {
std::atomic<std::uint64_t> next_buffer_serial{ 1 };
}

BufferCore::BufferCore(Duration cache_time)
  : serial_(next_buffer_serial.fetch_add(1))
  , cache_time_(std::max<Duration>(cache_time, 0))
  , frames_(std::make_unique<FrameTable>())
  , walk_scratch_(std::make_unique<WalkScratch>())
  , latest_poses_(std::make_unique<LatestPoses>())
{
}

BufferCore::~BufferCore() = default;

bool BufferCore::set_transform(const TransformStamped& transform, const std::string& authority,
  bool is_static, std::string* error)
{
  const CheckedTransform checked = check_transform_input(transform, authority);
  if (!checked.ok)
  {
    if (error)
    {
      *error = checked.message;
    }
    return false;
  }

  std::lock_guard<std::mutex> lock(mutex_);
  latest_poses_->invalidate(); // (a refused sample may still have replaced the frame's cache)
  const FrameId child = frames_->intern_child(checked.child);
  const FrameId parent = frames_->intern_parent(child, checked.parent);
  auto& cache = frames_->caches[child];
  if (!cache || cache->is_static() != is_static)
  {
    // First data, or data with the other static flag: tf2 starts the frame over with a cache of
    // the matching kind.
    if (is_static)
    {
      cache = std::make_unique<StaticCache>();
    }
    else
    {
      cache = std::make_unique<TimeCache>(cache_time_);
    }
  }
  if (!cache->insert(TransformRecord{ transform.stamp, checked.transform, parent, child }))
  {
    if (error)
    {
      *error = "TF_OLD_DATA ignoring data from the past for frame " + std::string(checked.child) +
        " at time " + display_time(transform.stamp) + " according to authority " + authority +
        "\nPossible reasons are listed at http://wiki.ros.org/tf/Errors%20explained";
    }
    return false;
  }
  std::string& stored_authority = frames_->authorities[child];
  if (stored_authority != authority)
  {
    stored_authority = authority; // usually the same one: no copy per transform
  }
  return true;
}

LookupResult BufferCore::lookup_locked(const std::string& target_frame,
  const std::string& source_frame, TimePoint time, const char* function_name) const
{
  LookupResult result;
  lookup_locked(target_frame, source_frame, time, function_name, result);
  return result;
}

void BufferCore::lookup_locked(const std::string& target_frame, const std::string& source_frame,
  TimePoint time, const char* function_name, LookupResult& result) const
{
  // Assigned field by field: the strings of a reused result keep their storage.
  result.ok = false;
  result.error = Tf2Error::NoError;
  result.message.clear();
  result.target_frame = target_frame;
  result.source_frame = source_frame;
  result.stamp = 0;
  result.transform = Transform();
  if (target_frame == source_frame)
  {
    // tf2 answers this before validating, so it works even for frames never seen.
    result.ok = true;
    result.stamp = time;
    if (time == kLatestTime)
    {
      const TimeCacheInterface* cache = frames_->cache(frames_->ids.find(target_frame));
      result.stamp = cache ? cache->newest_stamp() : kLatestTime;
    }
    return;
  }

  const FrameId target =
    validate_frame_id(*frames_, function_name, "target_frame", target_frame, result);
  if (target == kNoFrame)
  {
    return;
  }
  const FrameId source =
    validate_frame_id(*frames_, function_name, "source_frame", source_frame, result);
  if (source == kNoFrame)
  {
    return;
  }
  result.resolved_by = serial_;
  result.resolved_target = target;
  result.resolved_source = source;
  walk_locked(target, source, time, result);
}

void BufferCore::walk_locked(
  FrameId target, FrameId source, TimePoint time, LookupResult& result) const
{
  // Latest-time lookups (every link at every spin) share one walk per state of the buffer.
  WalkResult walk = time == kLatestTime
    ? latest_poses_->lookup(*frames_, *walk_scratch_, target, source)
    : TreeWalker(*frames_, *walk_scratch_).transform_between(target, source, time);
  result.error = walk.error;
  result.message = std::move(walk.message);
  result.ok = walk.error == Tf2Error::NoError;
  result.stamp = walk.time;
  if (result.ok)
  {
    result.transform = walk.transform;
  }
}

LookupResult BufferCore::lookup_transform(
  const std::string& target_frame, const std::string& source_frame, TimePoint time) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lookup_locked(target_frame, source_frame, time, "lookupTransform");
}

void BufferCore::lookup_transform(const std::string& target_frame, const std::string& source_frame,
  TimePoint time, LookupResult& result) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (result.resolved_by == serial_ && result.target_frame == target_frame &&
    result.source_frame == source_frame)
  {
    // The same names as last time into the same result: their ids, without the checks (the
    // names passed them then, and a name's id never changes).
    result.ok = false;
    result.error = Tf2Error::NoError;
    result.message.clear();
    result.stamp = 0;
    result.transform = Transform();
    walk_locked(result.resolved_target, result.resolved_source, time, result);
    return;
  }
  result.resolved_by = 0;
  lookup_locked(target_frame, source_frame, time, "lookupTransform", result);
}

LookupResult BufferCore::lookup_transform(const std::string& target_frame, TimePoint target_time,
  const std::string& source_frame, TimePoint source_time, const std::string& fixed_frame) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  LookupResult result;
  result.target_frame = target_frame;
  result.source_frame = source_frame;
  // tf2 validates all three names before looking anything up.
  const std::pair<const char*, const std::string*> arguments[] = {
    { "target_frame", &target_frame },
    { "source_frame", &source_frame },
    { "fixed_frame", &fixed_frame },
  };
  for (const auto& [argument, frame] : arguments)
  {
    if (validate_frame_id(*frames_, "lookupTransform", argument, *frame, result) == kNoFrame)
    {
      return result;
    }
  }

  LookupResult fixed_from_source =
    lookup_locked(fixed_frame, source_frame, source_time, "lookupTransform");
  if (!fixed_from_source.ok)
  {
    fixed_from_source.target_frame = target_frame;
    return fixed_from_source;
  }
  LookupResult target_from_fixed =
    lookup_locked(target_frame, fixed_frame, target_time, "lookupTransform");
  if (!target_from_fixed.ok)
  {
    target_from_fixed.source_frame = source_frame;
    return target_from_fixed;
  }
  result.ok = true;
  result.stamp = target_from_fixed.stamp;
  result.transform = target_from_fixed.transform * fixed_from_source.transform;
  return result;
}

bool BufferCore::can_transform(const std::string& target_frame, const std::string& source_frame,
  TimePoint time, std::string* error) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const LookupResult result = lookup_locked(target_frame, source_frame, time, "canTransform");
  if (!result.ok && error)
  {
    *error = result.message;
  }
  return result.ok;
}

bool BufferCore::can_transform(const std::string& target_frame, TimePoint target_time,
  const std::string& source_frame, TimePoint source_time, const std::string& fixed_frame,
  std::string* error) const
{
  const LookupResult result =
    lookup_transform(target_frame, target_time, source_frame, source_time, fixed_frame);
  if (!result.ok && error)
  {
    *error = result.message;
  }
  return result.ok;
}

bool BufferCore::frame_exists(const std::string& frame) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_->ids.find(frame) != kNoFrame;
}

void BufferCore::replace_authority(
  const std::string& frame, const std::string& from, const std::string& to)
{
  std::lock_guard<std::mutex> lock(mutex_);
  const FrameId id = frames_->ids.find(frame);
  if (id != kNoFrame && id < frames_->authorities.size() && frames_->authorities[id] == from)
  {
    frames_->authorities[id] = to;
  }
}

bool BufferCore::get_frame_parent(
  const std::string& frame, TimePoint time, std::string& parent) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimeCacheInterface* cache = frames_->cache(frames_->ids.find(frame));
  if (!cache)
  {
    return false;
  }
  const FrameId parent_id = cache->parent_at(time);
  if (parent_id == kNoFrame)
  {
    return false;
  }
  parent = frames_->ids.name(parent_id);
  return true;
}

std::vector<std::string> BufferCore::all_frame_names() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names;
  for (FrameId id = 1; id < frames_->ids.size(); ++id)
  {
    names.push_back(frames_->ids.name(id));
  }
  return names;
}

std::string BufferCore::all_frames_as_string() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_as_string(*frames_);
}

std::string BufferCore::all_frames_as_yaml(TimePoint current_time) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_as_yaml(*frames_, current_time);
}

void BufferCore::clear()
{
  std::lock_guard<std::mutex> lock(mutex_);
  latest_poses_->invalidate();
  for (auto& cache : frames_->caches)
  {
    if (cache)
    {
      cache->clear();
    }
  }
}

} // namespace tf2
} // namespace ros2vtk
