// ros2vtk — serves a ParameterStore the way rclcpp nodes do: the six rcl_interfaces parameter
// services under `<node>/…` (QoS "parameters") and ParameterEvent messages on
// /parameter_events, so rclpy's parameter client and `ros2 param` work against our nodes.
#ifndef ros2vtk_wire_ParameterServer_hpp
#define ros2vtk_wire_ParameterServer_hpp

#include "ros2vtk/wire/ParameterStore.hpp"

#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

class Participant;
class ROSClock;

class ParameterServer
{
public:
  /// nullptr (and `error`) when DDS refused one of the endpoints.
  static std::unique_ptr<ParameterServer> create(Participant& participant, std::string* error);
  ~ParameterServer();
  ParameterServer(const ParameterServer&) = delete;
  ParameterServer& operator=(const ParameterServer&) = delete;

  ParameterStore& store();

  /// The clock that stamps parameter events (the node's, so they follow simulated time as
  /// rclpy's do); nullptr: the system clock. It must outlive the server or be unset first.
  void set_clock(const ROSClock* clock);

  /// Answers every queued request and publishes pending parameter events. Call it from the
  /// thread that owns the store (the spin). Returns the number of requests answered.
  size_t process();
  /// Publishes pending parameter events only (a spin with no request queued; see
  /// WakeUp::clear). Returns 0: no request was answered.
  size_t publish_events();

  class Impl;

private:
  explicit ParameterServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace wire
} // namespace ros2vtk

#endif
