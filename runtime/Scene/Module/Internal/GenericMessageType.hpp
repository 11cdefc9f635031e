// ros2vtk — the ROS type a generic publisher/subscriber node carries, chosen at run time
// (private to the Scene module; generic nodes hold one).
#ifndef ros2vtk_scene_GenericMessageType_hpp
#define ros2vtk_scene_GenericMessageType_hpp

#include <string>

class vtkXMLDataElement;

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}
namespace scene {

/// Finds a registered message type by "pkg/msg/Type" or "pkg/Type". On failure returns nullptr
/// and sets `error` to a message listing the registered types.
const wire::MessageTypeSupport* find_generic_type(const char* ros_type, std::string& error);

/// SetROSType of both generic nodes: the type cannot change while the node is added to a ROS
/// node (its endpoint exists); otherwise `ros_type` is looked up and stored in `type`. Returns ""
/// on success (`changed` says whether `type` changed), else the reason.
std::string assign_generic_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, bool& changed);

/// A type name a generic subscriber may learn at run time (issue 13): "pkg/msg/Type" or
/// "pkg/Type" (made "pkg/msg/Type" in place), every part an identifier. False otherwise.
bool runtime_type_name(std::string& ros_type);

/// The `rosType` attribute a generic node saved, or nullptr when absent or empty.
const char* saved_generic_type(vtkXMLDataElement* element);

} // namespace scene
} // namespace ros2vtk

#endif
