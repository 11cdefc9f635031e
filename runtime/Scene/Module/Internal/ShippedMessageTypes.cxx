// Registers the message types ros2vtk ships (ros2vtk::Messages) in the process registry when the
// Scene library loads, so generic nodes and type-name lookups work from Python with nothing but
// this module imported. The generated library registers only when asked (explicit function):
// static initializers in a static library are not linked unless referenced.
#include "ros2vtk/ros2vtkMessagesRegister.hpp" // ros2vtk_register_ros2vtkMessages_types()

namespace {
struct RegisterShippedMessageTypes
{
  RegisterShippedMessageTypes() { ros2vtk_register_ros2vtkMessages_types(); }
};
const RegisterShippedMessageTypes registerShippedMessageTypes;
} // namespace
