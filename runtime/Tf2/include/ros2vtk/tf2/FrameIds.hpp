// ros2vtk — frame-id interning: every frame name seen by the buffer gets a small integer once, so
// caches, parents and tree walks compare integers instead of strings (tf2's CompactFrameID).
#ifndef ros2vtk_tf2_FrameIds_hpp
#define ros2vtk_tf2_FrameIds_hpp

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace ros2vtk {
namespace tf2 {

/// An interned frame name. 0 means "no frame" (tf2's NO_PARENT).
using FrameId = std::uint32_t;
constexpr FrameId kNoFrame = 0;

class FrameIds
{
public:
  FrameIds();

  /// The id of `name`, assigning the next free one the first time a name is seen.
  FrameId intern(const std::string& name);

  /// The id of `name`, or kNoFrame when it was never interned.
  FrameId find(const std::string& name) const;

  /// The name of an id; "NO_PARENT" for kNoFrame and for ids never handed out.
  const std::string& name(FrameId id) const;

  /// Number of ids handed out, plus one for kNoFrame: valid ids are 1 .. size() - 1.
  std::size_t size() const { return names_.size(); }

private:
  std::unordered_map<std::string, FrameId> ids_;
  std::vector<std::string> names_; ///< index = id; names_[0] is "NO_PARENT"
};

} // namespace tf2
} // namespace ros2vtk

#endif
