// ros2vtk — drives a node's ROSClock from the ROS graph, as rclpy's TimeSource does: the
// node's `use_sim_time` parameter (bool, default false) switches simulated time on and off, and
// while it is on the clock follows rosgraph_msgs/msg/Clock samples on /clock.
//
// The /clock subscription exists only while use_sim_time is true (rclpy creates and destroys
// it the same way), with rclpy's QoS for it: keep last 1, best effort, volatile, so that a
// simulator publishing best effort or reliable is heard. DDS threads only queue; process()
// moves the newest sample into the clock on the owner's thread (the spin).
#ifndef ros2vtk_wire_TimeSource_hpp
#define ros2vtk_wire_TimeSource_hpp

#include <cstdint>
#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

class Participant;
class ParameterStore;
class ROSClock;
class Subscription;

class TimeSource
{
public:
  /// The parameter's name, as every rclpy and rclcpp node declares it.
  static constexpr const char* kUseSimTimeParameter = "use_sim_time";
  /// The topic (absolute: a node's namespace does not move it).
  static constexpr const char* kClockTopic = "/clock";

  /// Declares use_sim_time (false) in `store` unless declared already, in which case its value
  /// is followed, and follows every later set of it. `participant`, `store` and `clock` must
  /// outlive the time source. nullptr (and `error`) when the parameter has another type or
  /// DDS refused the /clock subscription.
  static std::unique_ptr<TimeSource> create(
    Participant& participant, ParameterStore& store, ROSClock& clock, std::string* error);
  ~TimeSource();
  TimeSource(const TimeSource&) = delete;
  TimeSource& operator=(const TimeSource&) = delete;

  /// Moves the queued /clock samples into the clock (each in arrival order, so a jump back is
  /// seen). Returns how many were taken; 0 while simulated time is off.
  size_t process();

  /// Whether the /clock subscription exists (use_sim_time is true), for tests and status.
  bool subscribed() const { return subscription_ != nullptr; }
  /// Why the last switch failed ("" when it did not): a set of use_sim_time succeeds before
  /// the subscription is made, so a DDS refusal can only be reported afterwards.
  const std::string& last_error() const { return last_error_; }

private:
  TimeSource(Participant& participant, ParameterStore& store, ROSClock& clock);
  /// Turns simulated time on or off: the clock's source and the /clock subscription.
  bool set_active(bool active, std::string* error);

  Participant& participant_;
  ParameterStore& store_;
  ROSClock& clock_;
  std::unique_ptr<Subscription> subscription_;
  size_t callback_id_ = 0;
  std::string last_error_;
};

} // namespace wire
} // namespace ros2vtk

#endif
