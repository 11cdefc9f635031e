// ros2vtk — frame-id interning: every frame name seen by the buffer gets a small integer once, so
// caches, parents and tree walks compare integers instead of strings (tf2's CompactFrameID).
#ifndef ros2vtk_tf2_FrameIds_hpp
#define ros2vtk_tf2_FrameIds_hpp

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>

namespace ros2vtk {
namespace tf2 {

/// An interned frame name. 0 means "no frame" (tf2's NO_PARENT).
using FrameId = std::uint32_t;
constexpr FrameId kNoFrame = 0;

class FrameIds
{
public:
  FrameIds();
  // The map's keys point into names_: a copy would point into the original.
  FrameIds(const FrameIds&) = delete;
  FrameIds& operator=(const FrameIds&) = delete;

  /// The id of `name`, assigning the next free one the first time a name is seen.
  FrameId intern(std::string_view name);

  /// The id of `name`, or kNoFrame when it was never interned.
  FrameId find(std::string_view name) const;

  /// The name of an id; "NO_PARENT" for kNoFrame and for ids never handed out.
  const std::string& name(FrameId id) const;

  /// Number of ids handed out, plus one for kNoFrame: valid ids are 1 .. size() - 1.
  std::size_t size() const { return names_.size(); }

private:
  // Keyed by views of names_'s strings (a deque never moves them), so a name arriving on /tf is
  // looked up without first being copied into a std::string: every transform and every lookup
  // of every spin passes here.
  std::unordered_map<std::string_view, FrameId> ids_;
  std::deque<std::string> names_; ///< index = id; names_[0] is "NO_PARENT"
};

} // namespace tf2
} // namespace ros2vtk

#endif
