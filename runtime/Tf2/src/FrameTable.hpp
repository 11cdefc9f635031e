// ros2vtk (private) — everything the buffer knows about its frames, in one place so that the tree
// walker and the listings read the same data: interned names, one cache per child frame (none
// for frames only ever seen as a parent) and who last broadcast each frame.
#ifndef ros2vtk_tf2_FrameTable_hpp
#define ros2vtk_tf2_FrameTable_hpp

#include "ros2vtk/tf2/FrameIds.hpp"
#include "ros2vtk/tf2/TimeCacheInterface.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ros2vtk {
namespace tf2 {

struct FrameTable
{
  FrameIds ids;
  std::vector<std::unique_ptr<TimeCacheInterface>> caches; ///< index = FrameId
  std::vector<std::string> authorities;                    ///< index = FrameId

  /// The cache of a frame, nullptr for roots and unknown ids.
  const TimeCacheInterface* cache(FrameId id) const
  {
    return id < caches.size() ? caches[id].get() : nullptr;
  }

  /// Interns a name and keeps the per-frame vectors as long as the id table.
  FrameId intern(std::string_view name)
  {
    const FrameId id = ids.intern(name);
    if (caches.size() < ids.size())
    {
      caches.resize(ids.size());
      authorities.resize(ids.size());
      next_child.resize(ids.size(), kNoFrame);
    }
    return id;
  }

  /// intern() for the child of an incoming transform. A broadcaster sends its frames in the same
  /// order in every message: the frame that followed the previous child last time is checked
  /// first, by comparing names, which costs less than hashing the name.
  FrameId intern_child(std::string_view name)
  {
    FrameId id = next_child.empty() ? kNoFrame : next_child[last_child];
    if (id == kNoFrame || ids.name(id) != name)
    {
      id = intern(name);
      next_child[last_child] = id;
    }
    last_child = id;
    return id;
  }

  /// intern() for the parent of an incoming transform: usually the child's current parent.
  FrameId intern_parent(FrameId child, std::string_view name)
  {
    const TimeCacheInterface* known = cache(child);
    const FrameId id = known ? known->latest_time_and_parent().second : kNoFrame;
    return id != kNoFrame && ids.name(id) == name ? id : intern(name);
  }

private:
  std::vector<FrameId> next_child; ///< index = FrameId (kNoFrame: before the first child)
  FrameId last_child = kNoFrame;
};

} // namespace tf2
} // namespace ros2vtk

#endif
