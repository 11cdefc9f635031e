// ros2vtk — a node's /rosout: its warnings and errors as rcl_interfaces/msg/Log, so that
// `ros2 topic echo /rosout` and rqt_console-style tools show them as they show an rclpy node's.
//
// Every Participant has one (rclpy and rclcpp nodes publish /rosout by default). log() fans a
// message out to every live node of the process whose level admits it: the VTK side reports
// through VTK's output window, which does not say which ROS node a message concerns.
#ifndef ros2vtk_wire_Rosout_hpp
#define ros2vtk_wire_Rosout_hpp

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

class Participant;
class Publisher;

/// ROS 2 log severities, with rcl_interfaces/msg/Log's values.
enum class LogSeverity : uint8_t
{
  Debug = 10,
  Info = 20,
  Warn = 30,
  Error = 40,
  Fatal = 50
};

class Rosout
{
public:
  /// A publisher on /rosout with rcl's rosout QoS (reliable, transient local, keep last 1000).
  /// nullptr (and `error`) when DDS refuses it.
  static std::unique_ptr<Rosout> create(Participant& participant, std::string* error);
  ~Rosout();
  Rosout(const Rosout&) = delete;
  Rosout& operator=(const Rosout&) = delete;

  /// Messages below this severity are not published (rcl's default: Info).
  void set_level(LogSeverity level);
  LogSeverity level() const;

  /// Publishes one Log message stamped now, when `severity` >= level(). False when filtered out
  /// or DDS refused it.
  bool publish(LogSeverity severity, const std::string& text, const std::string& file = "",
    const std::string& function = "", uint32_t line = 0);
  uint64_t published_count() const;

  /// Publishes on every live Rosout of this process; returns how many published it.
  static size_t log(LogSeverity severity, const std::string& text, const std::string& file = "",
    const std::string& function = "", uint32_t line = 0);

  /// rcl's logger name of a node: namespace and name joined by dots ("robot1.slicer").
  static std::string logger_name(const std::string& node_namespace, const std::string& node_name);

private:
  Rosout(std::unique_ptr<Publisher> publisher, std::string logger);
  std::unique_ptr<Publisher> publisher_;
  std::string logger_;
  std::atomic<LogSeverity> level_{ LogSeverity::Info };
  std::atomic<uint64_t> published_{ 0 };
};

} // namespace wire
} // namespace ros2vtk

#endif
