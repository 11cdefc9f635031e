// ros2vtk — finding a service type by any of the names scripts give it.
//
// ROS names a service type "std_srvs/srv/SetBool" (or "std_srvs/SetBool"). SlicerROS2 scripts
// name it by the class SlicerROS2 generates for its client or server
// ("vtkMRMLROS2ServiceClientSetBoolNode") or by its bare name ("SetBool"); both are accepted here
// so that such a script runs unchanged. A bare name must belong to one registered type.
#ifndef ros2vtk_scene_ServiceTypeName_hpp
#define ros2vtk_scene_ServiceTypeName_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <string>

namespace ros2vtk {
namespace scene {

/// The registered service type `name` stands for, or nullptr with `error` saying why (unknown,
/// with the known types listed; or a bare name two packages share, with both named).
const wire::ServiceTypeSupport* find_service_type_by_any_name(
  const std::string& name, std::string* error);

} // namespace scene
} // namespace ros2vtk

#endif
