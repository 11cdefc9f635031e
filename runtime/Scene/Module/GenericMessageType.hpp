// ros2vtk — the ROS type a generic publisher/subscriber node carries, chosen at run time
// (private to the Scene module; generic nodes hold one).
#ifndef ros2vtk_scene_GenericMessageType_hpp
#define ros2vtk_scene_GenericMessageType_hpp

#include <string>

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}
namespace scene {

/// Finds a registered message type by "pkg/msg/Type" or "pkg/Type". On failure returns nullptr
/// and sets `error` to a message listing the registered types.
const wire::MessageTypeSupport* find_generic_type(const char* ros_type, std::string& error);

} // namespace scene
} // namespace ros2vtk

#endif
