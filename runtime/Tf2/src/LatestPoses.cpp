#include "LatestPoses.hpp"

#include <algorithm>

namespace ros2vtk {
namespace tf2 {

namespace {

/// tf2's latest common time of a chain: static links (stamp 0) do not constrain it.
TimePoint chain_time(TimePoint stamp, TimePoint parent_time)
{
  if (stamp == kLatestTime)
  {
    return parent_time;
  }
  return parent_time == kLatestTime ? stamp : std::min(stamp, parent_time);
}

} // namespace

WalkResult LatestPoses::lookup(
  const FrameTable& frames, WalkScratch& scratch, FrameId target, FrameId source)
{
  if (poses_.size() < frames.ids.size())
  {
    poses_.resize(frames.ids.size());
  }
  // Up from the source along the newest parents until the target or a pose known in this state.
  chain_.clear();
  for (FrameId frame = source; frame != target && !known(frame, target);)
  {
    const TimeCacheInterface* cache = frames.cache(frame);
    const FrameId parent = cache ? cache->latest_time_and_parent().second : kNoFrame;
    if (parent == kNoFrame || chain_.size() > kMaxGraphDepth)
    {
      // A root without meeting the target (it is not an ancestor), or a loop: the walker's way.
      return TreeWalker(frames, scratch).transform_between(target, source, kLatestTime);
    }
    chain_.push_back(frame);
    frame = parent;
  }
  // Down again, each frame from its parent.
  for (auto frame = chain_.rbegin(); frame != chain_.rend(); ++frame)
  {
    if (!compose(frames, scratch, target, *frame))
    {
      return TreeWalker(frames, scratch).transform_between(target, source, kLatestTime);
    }
  }
  const Pose& pose = poses_[source];
  WalkResult result;
  result.time = pose.time;
  result.transform = pose.transform;
  return result;
}

bool LatestPoses::compose(
  const FrameTable& frames, WalkScratch& scratch, FrameId target, FrameId frame)
{
  const TimeCacheInterface& cache = *frames.cache(frame); // the upward walk found data here
  const auto [stamp, parent] = cache.latest_time_and_parent();
  static const Pose kTarget{ 0, kNoFrame, true, true, 0, kLatestTime, Transform::identity() };
  const Pose& above = parent == target ? kTarget : poses_[parent];
  Pose& pose = poses_[frame];
  pose.state = state_;
  pose.target = target;
  pose.time = chain_time(stamp, above.time);
  pose.depth = above.depth + 1;
  // The parent's pose was sampled at its own chain time: reusable when this frame's chain time
  // is the same, or when nothing above moves.
  TransformRecord link;
  if (above.composable && (pose.time == above.time || above.all_static) &&
    pose.depth <= kMaxGraphDepth && cache.sample(pose.time, link) && link.parent == parent)
  {
    pose.composable = true;
    pose.all_static = above.all_static && cache.is_static();
    pose.transform = parent == target ? link.transform : above.transform * link.transform;
    return true;
  }
  // Older than the chain above, or re-parented within the history: the walker, for this frame.
  const WalkResult walk = TreeWalker(frames, scratch).transform_between(target, frame, kLatestTime);
  if (walk.error != Tf2Error::NoError)
  {
    pose.state = 0;
    return false;
  }
  // Its children may start from it when the walk met the target on this frame's own path.
  pose.composable = !scratch.path.empty() && scratch.path.back() == target;
  pose.depth = scratch.path.size() - 1;
  pose.all_static = false;
  pose.time = walk.time;
  pose.transform = walk.transform;
  return true;
}

} // namespace tf2
} // namespace ros2vtk
