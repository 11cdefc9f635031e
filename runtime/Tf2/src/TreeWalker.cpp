#include "TreeWalker.hpp"

#include "FrameListing.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace ros2vtk {
namespace tf2 {

namespace {

using NewestLink = WalkScratch::NewestLink;

constexpr TimePoint kNoTimeYet = std::numeric_limits<TimePoint>::max();

// Frames met on a walk. A vector, not a hash set: chains are a handful of frames long and a
// lookup per link runs at every spin, so node allocations cost more than a linear search. The
// walks keep their vectors in a WalkScratch (cleared, not freed) for the same reason.
using FramePath = std::vector<FrameId>;

/// Adds `frame` to `path`; false when it was there already (the tree has a loop) or the path
/// is longer than tf2 allows.
bool visit(FramePath& path, FrameId frame)
{
  if (path.size() > kMaxGraphDepth || std::find(path.begin(), path.end(), frame) != path.end())
  {
    return false;
  }
  path.push_back(frame);
  return true;
}

void take_min(TimePoint& common, TimePoint stamp)
{
  if (stamp != kLatestTime)
  { // static frames report 0 and do not constrain the time
    common = std::min(common, stamp);
  }
}

TimePoint finish(TimePoint common)
{
  return common == kNoTimeYet ? kLatestTime : common;
}

} // namespace

WalkResult TreeWalker::loop_error() const
{
  WalkResult result;
  result.error = Tf2Error::Lookup;
  result.message =
    "The tf tree is invalid because it contains a loop.\n" + frames_as_string(frames_) + "\n";
  return result;
}

WalkResult TreeWalker::connectivity_error(FrameId target, FrameId source) const
{
  WalkResult result;
  result.error = Tf2Error::Connectivity;
  // tf2's text, including the missing space after "tree.".
  result.message = "Could not find a connection between '" + frames_.ids.name(target) + "' and '" +
    frames_.ids.name(source) +
    "' because they are not part of the same tree.Tf has two or more unconnected trees.";
  return result;
}

std::string TreeWalker::direction(FrameId source, FrameId target) const
{
  return ", when looking up transform from frame [" + frames_.ids.name(source) + "] to frame [" +
    frames_.ids.name(target) + "]";
}

WalkResult TreeWalker::latest_common_time(FrameId target, FrameId source) const
{
  WalkResult result;
  if (source == target)
  {
    const TimeCacheInterface* cache = frames_.cache(source);
    result.time = cache ? cache->newest_stamp() : kLatestTime;
    return result;
  }

  // Source towards its root, remembering each frame's newest link.
  std::vector<NewestLink>& source_path = scratch_.source_links;
  FramePath& seen = scratch_.path;
  source_path.clear();
  seen.assign(1, source);
  TimePoint common = kNoTimeYet;
  for (FrameId frame = source;;)
  {
    const TimeCacheInterface* cache = frames_.cache(frame);
    if (!cache)
    {
      break; // a root: known only as somebody's parent
    }
    const auto [stamp, parent] = cache->latest_time_and_parent();
    if (parent == kNoFrame)
    {
      break; // no data (cleared); a path from the target may still reach us
    }
    take_min(common, stamp);
    source_path.push_back({ stamp, parent });
    if (parent == target)
    {
      result.time = finish(common);
      return result;
    }
    if (!visit(seen, parent))
    {
      return loop_error();
    }
    frame = parent;
  }

  // Target upwards until its parent lies on the source's path (or is the source).
  common = kNoTimeYet;
  FrameId common_parent = kNoFrame;
  FramePath& seen_from_target = scratch_.from_target;
  seen_from_target.assign(1, target);
  for (FrameId frame = target;;)
  {
    const TimeCacheInterface* cache = frames_.cache(frame);
    if (!cache)
    {
      break;
    }
    const auto [stamp, parent] = cache->latest_time_and_parent();
    if (parent == kNoFrame)
    {
      break;
    }
    take_min(common, stamp);
    if (parent == source)
    {
      result.time = finish(common);
      return result;
    }
    auto on_path = std::find_if(source_path.begin(), source_path.end(),
      [parent = parent](const NewestLink& link) { return link.parent == parent; });
    if (on_path != source_path.end())
    {
      common_parent = parent;
      break;
    }
    if (!visit(seen_from_target, parent))
    {
      return loop_error();
    }
    frame = parent;
  }

  if (common_parent == kNoFrame)
  {
    return connectivity_error(target, source);
  }
  // The source's links up to (and including) the one into the common parent.
  for (const NewestLink& link : source_path)
  {
    take_min(common, link.stamp);
    if (link.parent == common_parent)
    {
      break;
    }
  }
  result.time = finish(common);
  return result;
}

WalkResult TreeWalker::transform_between(FrameId target, FrameId source, TimePoint time) const
{
  WalkResult result;
  result.time = time;
  if (source == target)
  {
    return result;
  }
  if (time == kLatestTime)
  {
    result = latest_common_time(target, source);
    if (result.error != Tf2Error::NoError)
    {
      return result;
    }
  }

  // Source towards its root: source_to[i] maps source into path[i].
  std::vector<Transform>& source_to = scratch_.source_to;
  FramePath& path = scratch_.path; // latest_common_time's use of it is over
  source_to.assign(1, Transform::identity());
  path.assign(1, source);
  SampleError source_stop; // why the source walk ended early, if it did
  for (FrameId frame = source; frame != target;)
  {
    const TimeCacheInterface* cache = frames_.cache(frame);
    if (!cache)
    {
      break;
    }
    TransformRecord link;
    if (!cache->sample(result.time, link, &source_stop))
    {
      break; // the target may still reach this frame from below
    }
    if (!visit(path, link.parent))
    {
      return loop_error();
    }
    // The first link is the source's own transform: composing it with the identity would cost
    // a product for the same numbers.
    source_to.push_back(source_to.size() == 1 ? link.transform : link.transform * source_to.back());
    frame = link.parent;
  }

  // Target upwards until it meets the source's path; target_to maps target into `frame`.
  Transform target_to = Transform::identity();
  FramePath& seen_from_target = scratch_.from_target;
  seen_from_target.assign(1, target);
  for (FrameId frame = target;;)
  {
    auto met = std::find(path.begin(), path.end(), frame);
    if (met != path.end())
    {
      const Transform& source_to_met = source_to[static_cast<std::size_t>(met - path.begin())];
      // Usually the target is on the source's path (a link looked up in its robot's base): then
      // target_to is still the identity and the answer is the source's chain as composed.
      result.transform = frame == target ? source_to_met : target_to.inverse() * source_to_met;
      return result;
    }
    const TimeCacheInterface* cache = frames_.cache(frame);
    if (!cache)
    {
      break;
    }
    TransformRecord link;
    SampleError target_stop;
    if (!cache->sample(result.time, link, &target_stop))
    {
      result.error = target_stop.code;
      result.message = target_stop.message + direction(source, target);
      return result;
    }
    if (!visit(seen_from_target, link.parent))
    {
      return loop_error();
    }
    target_to = link.transform * target_to;
    frame = link.parent;
  }

  if (source_stop.code != Tf2Error::NoError)
  {
    result.error = source_stop.code;
    result.message = source_stop.message + direction(source, target);
    return result;
  }
  return connectivity_error(target, source);
}

} // namespace tf2
} // namespace ros2vtk
