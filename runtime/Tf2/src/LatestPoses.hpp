// ros2vtk (private) — latest-time lookups of many frames in one target frame (a robot's links in
// its fixed frame, at every spin) with one walk of the tree: a frame's pose in the target is its
// parent's pose, computed once per state of the buffer, composed with the frame's own transform.
// A robot of N links costs N samples and N compositions, not N walks to its base.
//
// Same answers as TreeWalker::transform_between(target, source, kLatestTime): the latest common
// time of a frame's chain is the minimum of its own newest stamp and its parent's chain time, and
// the parent's remembered pose is used only when it was sampled at that same time (or its chain
// is static, valid at every time). Anything else — the target is not an ancestor, a parent that
// changed within the history, a sample that fails, a chain as long as tf2's loop bound — goes
// through the tree walker, so errors and their wording stay the walker's. Compositions run from
// the target down instead of from the source up: the same transform to rounding (~1e-16).
#ifndef ros2vtk_tf2_LatestPoses_hpp
#define ros2vtk_tf2_LatestPoses_hpp

#include "FrameTable.hpp"
#include "TreeWalker.hpp"

#include <cstdint>
#include <vector>

namespace ros2vtk {
namespace tf2 {

class LatestPoses
{
public:
  /// Forgets every remembered pose; the buffer calls it (under its lock) whenever its frames
  /// change.
  void invalidate() { ++state_; }

  /// transform_between(target, source, kLatestTime) for source != target. `scratch` serves the
  /// tree walker when a frame cannot be composed from its parent.
  WalkResult lookup(const FrameTable& frames, WalkScratch& scratch, FrameId target, FrameId source);

private:
  /// A frame's pose in `target`, valid while the buffer is in state `state`.
  struct Pose
  {
    std::uint64_t state = 0; ///< 0: never computed
    FrameId target = kNoFrame;
    bool composable = false; ///< children may be composed from it (its chain reaches target)
    bool all_static = false; ///< every link up to the target is a /tf_static one
    std::size_t depth = 0;   ///< links between the frame and the target
    TimePoint time = 0;      ///< latest common time of the chain (0: not constrained)
    Transform transform;     ///< maps the frame into the target
  };

  bool known(FrameId frame, FrameId target) const
  {
    const Pose& pose = poses_[frame];
    return pose.state == state_ && pose.target == target && pose.composable;
  }
  /// Computes poses_[frame] from its newest parent's pose (known, or the target itself).
  bool compose(const FrameTable& frames, WalkScratch& scratch, FrameId target, FrameId frame);

  std::uint64_t state_ = 1;
  std::vector<Pose> poses_;    ///< index: FrameId
  std::vector<FrameId> chain_; ///< frames between a source and a known pose, source first
};

} // namespace tf2
} // namespace ros2vtk

#endif
