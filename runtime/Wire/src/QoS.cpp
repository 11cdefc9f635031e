// ros2vtk — QoS profile names.
#include "ros2vtk/wire/QoS.hpp"

namespace ros2vtk {
namespace wire {

bool QoS::from_name(const std::string& name, QoS& qos)
{
  if (name == "default" || name == "system_default")
  {
    qos = default_profile();
  }
  else if (name == "sensor_data" || name == "best_effort")
  {
    qos = sensor_data();
  }
  else if (name == "services_default" || name == "services")
  {
    qos = services();
  }
  else if (name == "parameters" || name == "parameter_events")
  {
    qos = parameters();
  }
  else if (name == "transient_local" || name == "latched")
  {
    qos = transient_local();
  }
  else if (name == "keep_all")
  {
    qos = QoS{ History::KeepAll, 1000, Reliability::Reliable, Durability::Volatile };
  }
  else
  {
    return false;
  }
  return true;
}

std::string QoS::to_string() const
{
  std::string text = reliability == Reliability::Reliable ? "reliable" : "best_effort";
  text += durability == Durability::Volatile ? ", volatile" : ", transient_local";
  text += history == History::KeepAll ? ", keep_all" : ", keep_last(" + std::to_string(depth) + ")";
  return text;
}

} // namespace wire
} // namespace ros2vtk
