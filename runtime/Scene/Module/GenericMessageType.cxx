#include "GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkXMLDataElement.h"

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

std::string assign_generic_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, bool& changed)
{
  changed = false;
  if (added_to_ros_node)
  {
    return "cannot change the type while added to a ROS node";
  }
  std::string error;
  const wire::MessageTypeSupport* found = find_generic_type(ros_type, error);
  if (!found)
  {
    return error;
  }
  changed = found != type;
  type = found;
  return std::string();
}

const char* saved_generic_type(vtkXMLDataElement* element)
{
  const char* ros_type = element ? element->GetAttribute("rosType") : nullptr;
  return ros_type && *ros_type ? ros_type : nullptr;
}

} // namespace scene
} // namespace ros2vtk
