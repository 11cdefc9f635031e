// ros2vtk — a node's ROS clock (rcl's RCL_ROS_TIME clock): the system clock, or, while
// simulated time is active, the last time the simulator announced on /clock.
//
// It holds no DDS: TimeSource feeds it from /clock and switches it with the use_sim_time
// parameter, as rclpy's TimeSource drives rclpy's Clock. Everything a node stamps (headers,
// tf broadcasts, parameter events) reads now() here, so one switch moves all of it.
#ifndef ros2vtk_wire_ROSClock_hpp
#define ros2vtk_wire_ROSClock_hpp

#include <cstdint>
#include <functional>

namespace ros2vtk {
namespace wire {

class ROSClock
{
public:
  /// Nanoseconds since the Unix epoch; replaceable so tests do not depend on the real clock.
  using SystemNow = std::function<int64_t()>;

  /// A clock on the system time (simulated time off, as rcl starts a ROS clock).
  ROSClock();
  explicit ROSClock(SystemNow system_now);

  /// ROS time in nanoseconds: the system time, or while simulated time is active the last
  /// set_sim_time() value, 0 before the first one (rcl: an enabled override starts at 0, so a
  /// node waiting for its simulator stamps 0, never a wall-clock time).
  int64_t now() const;

  /// Switches between system and simulated time. Switching counts as a jump (jump_count()):
  /// data stamped in the other time base is not comparable with the new one.
  void set_sim_time_active(bool active);
  bool is_sim_time_active() const { return sim_active_; }

  /// The latest /clock time. Kept while simulated time is off, and used again when it comes
  /// back on (rcl keeps its override value across disable/enable). A time earlier than the
  /// previous one counts as a jump when simulated time is active (a replayed bag looping).
  void set_sim_time(int64_t nanoseconds);
  /// Whether any simulated time arrived since construction (a status line says "waiting").
  bool has_sim_time() const { return has_sim_time_; }

  /// Times the clock went backwards or changed its source, since construction. A tf buffer
  /// compares this with the value it saw last and clears itself when it moved, as
  /// tf2_ros::Buffer does on rcl's jump callbacks ("Detected jump back in time").
  uint64_t jump_count() const { return jumps_; }

private:
  SystemNow system_now_;
  bool sim_active_ = false;
  bool has_sim_time_ = false;
  int64_t sim_time_ = 0;
  uint64_t jumps_ = 0;
};

} // namespace wire
} // namespace ros2vtk

#endif
