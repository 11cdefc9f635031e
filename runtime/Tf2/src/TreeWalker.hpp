// ros2vtk (private) — the two tree walks of a lookup: finding the latest time at which a chain
// of frames has data (for time 0), and composing the transforms along the chain from source up
// to the first frame the target also reaches.
#ifndef ros2vtk_tf2_TreeWalker_hpp
#define ros2vtk_tf2_TreeWalker_hpp

#include "FrameTable.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace ros2vtk {
namespace tf2 {

/// tf2's BufferCore::MAX_GRAPH_DEPTH: a walk longer than this is reported as a loop, as tf2
/// does. Frames come from the network; without the bound a 10 000-frame chain costs 10^8 steps
/// per lookup per spin (the loop check is linear in the path) (issue 11.5).
constexpr std::size_t kMaxGraphDepth = 1000;

/// The vectors a walk fills, kept by the buffer between lookups (cleared, not freed): a lookup
/// per link runs at every spin, and these allocations cost more than the walk itself. A
/// per-thread copy would go through __tls_get_addr at every use in a shared library.
struct WalkScratch
{
  /// One step of the time walk: a frame's newest stamp and the parent that sample names.
  struct NewestLink
  {
    TimePoint stamp;
    FrameId parent;
  };
  std::vector<NewestLink> source_links; ///< latest_common_time: the source's chain
  std::vector<Transform> source_to;     ///< transform_between: source into path[i]
  std::vector<FrameId> path;            ///< frames met walking from the source
  std::vector<FrameId> from_target;     ///< frames met walking from the target
};

struct WalkResult
{
  Tf2Error error = Tf2Error::NoError;
  std::string message;
  TimePoint time = 0;  ///< the time used (resolved from kLatestTime when asked for it)
  Transform transform; ///< maps source into target when error == NoError
};

class TreeWalker
{
public:
  /// `scratch` is only used during a call; one walk at a time per scratch.
  TreeWalker(const FrameTable& frames, WalkScratch& scratch)
    : frames_(frames)
    , scratch_(scratch)
  {
  }

  /// tf2's getLatestCommonTime: the minimum over the newest stamps of every dynamic frame on the
  /// path between the two frames (static frames do not count; 0 when all are static).
  /// Connectivity error when the frames share no ancestor; Lookup error on a loop.
  WalkResult latest_common_time(FrameId target, FrameId source) const;

  /// The transform from `source` into `target` at `time` (kLatestTime: latest common time).
  /// Walks source towards its root, then target upwards until it meets the source's path.
  /// Frames above the meeting point are not sampled, so a lookup inside a subtree does not
  /// depend on how fresh the transforms above it are.
  WalkResult transform_between(FrameId target, FrameId source, TimePoint time) const;

private:
  WalkResult loop_error() const;
  WalkResult connectivity_error(FrameId target, FrameId source) const;
  std::string direction(FrameId source, FrameId target) const;

  const FrameTable& frames_;
  WalkScratch& scratch_;
};

} // namespace tf2
} // namespace ros2vtk

#endif
