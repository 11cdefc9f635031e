// ros2vtk — QoS profile and policy names: the one table of the names ROS 2 users type
// ("sensor_data", "transient_local", …), used by the scene's setters, scene files and the app.
#include "ros2vtk/wire/QoS.hpp"

#include <cstring>

namespace ros2vtk {
namespace wire {

namespace {

struct NamedProfile
{
  const char* name;
  QoS qos;
};

// rmw's profile names first, then the aliases users also type.
const NamedProfile kProfiles[] = {
  { "default", QoS::default_profile() },
  { "sensor_data", QoS::sensor_data() },
  { "services_default", QoS::services() },
  { "parameters", QoS::parameters() },
  { "parameter_events", QoS::parameters() },
  { "transient_local", QoS::transient_local() },
  { "keep_all",
    QoS{ QoS::History::KeepAll, 1000, QoS::Reliability::Reliable, QoS::Durability::Volatile } },
  { "system_default", QoS::default_profile() },
  { "best_effort", QoS::sensor_data() },
  { "services", QoS::services() },
  { "latched", QoS::transient_local() },
};

template<typename Enum>
struct NamedValue
{
  const char* name;
  Enum value;
};

const NamedValue<QoS::Reliability> kReliability[] = { { "reliable", QoS::Reliability::Reliable },
  { "best_effort", QoS::Reliability::BestEffort } };
const NamedValue<QoS::Durability> kDurability[] = { { "volatile", QoS::Durability::Volatile },
  { "transient_local", QoS::Durability::TransientLocal } };
const NamedValue<QoS::History> kHistory[] = { { "keep_last", QoS::History::KeepLast },
  { "keep_all", QoS::History::KeepAll } };

template<typename Enum, size_t N>
const char* name_in(const NamedValue<Enum> (&table)[N], Enum value)
{
  for (const auto& entry : table)
  {
    if (entry.value == value)
    {
      return entry.name;
    }
  }
  return "unknown";
}

template<typename Enum, size_t N>
bool parse_in(const NamedValue<Enum> (&table)[N], const char* name, Enum& value)
{
  for (const auto& entry : table)
  {
    if (name && std::strcmp(entry.name, name) == 0)
    {
      value = entry.value;
      return true;
    }
  }
  return false;
}

} // namespace

bool QoS::from_name(const std::string& name, QoS& qos)
{
  for (const auto& profile : kProfiles)
  {
    if (name == profile.name)
    {
      qos = profile.qos;
      return true;
    }
  }
  return false;
}

std::string QoS::profile_names()
{
  std::string text;
  for (const auto& profile : kProfiles)
  {
    text += (text.empty() ? "" : ", ") + std::string(profile.name);
  }
  return text;
}

const char* QoS::name_of(Reliability value)
{
  return name_in(kReliability, value);
}
const char* QoS::name_of(Durability value)
{
  return name_in(kDurability, value);
}
const char* QoS::name_of(History value)
{
  return name_in(kHistory, value);
}
bool QoS::parse(const char* name, Reliability& value)
{
  return parse_in(kReliability, name, value);
}
bool QoS::parse(const char* name, Durability& value)
{
  return parse_in(kDurability, name, value);
}
bool QoS::parse(const char* name, History& value)
{
  return parse_in(kHistory, name, value);
}

std::string QoS::to_string() const
{
  std::string text =
    std::string(name_of(reliability)) + ", " + name_of(durability) + ", " + name_of(history);
  if (history == History::KeepLast)
  {
    text += "(" + std::to_string(depth) + ")";
  }
  return text;
}

} // namespace wire
} // namespace ros2vtk
