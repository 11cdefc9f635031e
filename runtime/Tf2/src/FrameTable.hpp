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
    }
    return id;
  }
};

} // namespace tf2
} // namespace ros2vtk

#endif
