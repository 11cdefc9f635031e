// ros2vtk (private) — human-readable listings of the frames (tf2's allFramesAsString and
// allFramesAsYAML), shared by BufferCore and by the loop error message.
#ifndef ros2vtk_tf2_FrameListing_hpp
#define ros2vtk_tf2_FrameListing_hpp

#include "FrameTable.hpp"

#include <string>

namespace ros2vtk {
namespace tf2 {

std::string frames_as_string(const FrameTable& frames);
std::string frames_as_yaml(const FrameTable& frames, TimePoint current_time);

} // namespace tf2
} // namespace ros2vtk

#endif
