#include "GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

namespace ros2vtk {
namespace scene {

const wire::MessageTypeSupport* find_generic_type(const char* ros_type, std::string& error)
{
  const wire::MessageTypeSupport* type = ros_type ? wire::find_message_type(ros_type) : nullptr;
  if (!type)
  {
    error = std::string("unknown ROS message type '") + (ros_type ? ros_type : "(null)") +
      "'; registered types:";
    const auto known = wire::registered_message_types();
    for (const auto& name : known)
    {
      error += " " + name;
    }
    if (known.empty())
    {
      error += " (none: is the generated message library loaded?)";
    }
  }
  return type;
}

} // namespace scene
} // namespace ros2vtk
