#include "QoSNames.hpp"

#include <string>

namespace ros2vtk {
namespace scene {

bool parse_reliability(const char* name, wire::QoS::Reliability& value)
{
  const std::string text = name ? name : "";
  if (text == "reliable")
  {
    value = wire::QoS::Reliability::Reliable;
    return true;
  }
  if (text == "best_effort")
  {
    value = wire::QoS::Reliability::BestEffort;
    return true;
  }
  return false;
}

bool parse_durability(const char* name, wire::QoS::Durability& value)
{
  const std::string text = name ? name : "";
  if (text == "volatile")
  {
    value = wire::QoS::Durability::Volatile;
    return true;
  }
  if (text == "transient_local")
  {
    value = wire::QoS::Durability::TransientLocal;
    return true;
  }
  return false;
}

bool parse_history(const char* name, wire::QoS::History& value)
{
  const std::string text = name ? name : "";
  if (text == "keep_last")
  {
    value = wire::QoS::History::KeepLast;
    return true;
  }
  if (text == "keep_all")
  {
    value = wire::QoS::History::KeepAll;
    return true;
  }
  return false;
}

const char* to_name(wire::QoS::Reliability value)
{
  return value == wire::QoS::Reliability::Reliable ? "reliable" : "best_effort";
}

const char* to_name(wire::QoS::Durability value)
{
  return value == wire::QoS::Durability::Volatile ? "volatile" : "transient_local";
}

const char* to_name(wire::QoS::History value)
{
  return value == wire::QoS::History::KeepLast ? "keep_last" : "keep_all";
}

} // namespace scene
} // namespace ros2vtk
