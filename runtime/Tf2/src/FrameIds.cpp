#include "ros2vtk/tf2/FrameIds.hpp"

namespace ros2vtk {
namespace tf2 {

FrameIds::FrameIds()
  : names_{ "NO_PARENT" }
{
}

FrameId FrameIds::intern(std::string_view name)
{
  auto found = ids_.find(name);
  if (found != ids_.end())
  {
    return found->second;
  }
  const auto id = static_cast<FrameId>(names_.size());
  names_.emplace_back(name);
  ids_.emplace(names_.back(), id);
  return id;
}

FrameId FrameIds::find(std::string_view name) const
{
  auto found = ids_.find(name);
  return found == ids_.end() ? kNoFrame : found->second;
}

const std::string& FrameIds::name(FrameId id) const
{
  return id < names_.size() ? names_[id] : names_[kNoFrame];
}

} // namespace tf2
} // namespace ros2vtk
