// ros2vtk — lookup of the shipped generated types used by the wire protocol itself.
#include "ShippedTypes.hpp"

#include <cstdio>
#include <cstdlib>

// Exported by the generated shipped-type library (ros2vtk::Messages).
#include "ros2vtk/ros2vtkMessagesRegister.hpp" // ros2vtk_register_ros2vtkMessages_types()

namespace ros2vtk {
namespace wire {

namespace {

void ensure_registered()
{
  static const bool registered = [] {
    ros2vtk_register_ros2vtkMessages_types();
    return true;
  }();
  (void)registered;
}

} // namespace

const MessageTypeSupport& shipped_message_type(const std::string& ros_type)
{
  ensure_registered();
  const MessageTypeSupport* type = find_message_type(ros_type);
  if (!type)
  {
    std::fprintf(stderr, "ros2vtk: shipped message type %s is not registered\n", ros_type.c_str());
    std::abort();
  }
  return *type;
}

const ServiceTypeSupport& shipped_service_type(const std::string& ros_type)
{
  ensure_registered();
  const ServiceTypeSupport* type = find_service_type(ros_type);
  if (!type)
  {
    std::fprintf(stderr, "ros2vtk: shipped service type %s is not registered\n", ros_type.c_str());
    std::abort();
  }
  return *type;
}

} // namespace wire
} // namespace ros2vtk
