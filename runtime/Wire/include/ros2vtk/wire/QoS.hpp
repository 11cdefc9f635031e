// ros2vtk — ROS 2 quality-of-service profiles, with the names and values rmw uses.
#ifndef ros2vtk_wire_QoS_hpp
#define ros2vtk_wire_QoS_hpp

#include <cstdint>
#include <string>

namespace ros2vtk {
namespace wire {

/// The QoS policies ROS 2 exposes for topics and services (docs/wire-notes.md §2.1).
struct QoS
{
  enum class History : uint8_t
  {
    KeepLast,
    KeepAll
  };
  enum class Reliability : uint8_t
  {
    Reliable,
    BestEffort
  };
  enum class Durability : uint8_t
  {
    Volatile,
    TransientLocal
  };

  History history = History::KeepLast;
  uint32_t depth = 10;
  Reliability reliability = Reliability::Reliable;
  Durability durability = Durability::Volatile;

  /// rmw_qos_profile_default: keep last 10, reliable, volatile.
  static QoS default_profile() { return QoS{}; }
  /// rmw_qos_profile_sensor_data: keep last 5, best effort, volatile.
  static QoS sensor_data()
  {
    return QoS{ History::KeepLast, 5, Reliability::BestEffort, Durability::Volatile };
  }
  /// Latched topics (/robot_description, /tf_static publisher side): keep last `depth`, reliable,
  /// transient local.
  static QoS transient_local(uint32_t depth = 1)
  {
    return QoS{ History::KeepLast, depth, Reliability::Reliable, Durability::TransientLocal };
  }
  /// rmw_qos_profile_services_default.
  static QoS services() { return QoS{}; }
  /// rmw_qos_profile_parameters / parameter_events: keep last 1000, reliable, volatile.
  static QoS parameters()
  {
    return QoS{ History::KeepLast, 1000, Reliability::Reliable, Durability::Volatile };
  }

  /// Profiles by their ROS names: "default" (alias "system_default"), "sensor_data" (alias
  /// "best_effort"), "services_default" (alias "services"), "parameters", "parameter_events",
  /// "transient_local" (alias "latched"), "keep_all" (reliable, nothing dropped by history).
  /// False for unknown names. This table is the only list of profile names (QoS.cpp).
  static bool from_name(const std::string& name, QoS& qos);
  /// Every name from_name accepts, comma-separated, for error messages.
  static std::string profile_names();

  /// Policy values as ROS 2 spells them ("reliable", "best_effort", "volatile",
  /// "transient_local", "keep_last", "keep_all"), for setters, scene files and logs. Each parse
  /// returns false (leaving `value` alone) for a null or unknown name.
  static const char* name_of(Reliability value);
  static const char* name_of(Durability value);
  static const char* name_of(History value);
  static bool parse(const char* name, Reliability& value);
  static bool parse(const char* name, Durability& value);
  static bool parse(const char* name, History& value);

  /// "reliable, volatile, keep_last(10)" — for logs and scene files.
  std::string to_string() const;

  bool operator==(const QoS& o) const
  {
    return history == o.history && depth == o.depth && reliability == o.reliability &&
      durability == o.durability;
  }
};

} // namespace wire
} // namespace ros2vtk

#endif
