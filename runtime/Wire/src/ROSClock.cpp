// ros2vtk — the ROS clock (rcl/src/rcl/time.c semantics for RCL_ROS_TIME with an override).
#include "ros2vtk/wire/ROSClock.hpp"

#include <chrono>
#include <utility>

namespace ros2vtk {
namespace wire {

namespace {
int64_t system_nanoseconds()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
    .count();
}
} // namespace

ROSClock::ROSClock()
  : system_now_(&system_nanoseconds)
{
}

ROSClock::ROSClock(SystemNow system_now)
  : system_now_(system_now ? std::move(system_now) : SystemNow(&system_nanoseconds))
{
}

int64_t ROSClock::now() const
{
  return sim_active_ ? sim_time_ : system_now_();
}

void ROSClock::set_sim_time_active(bool active)
{
  if (active == sim_active_)
  {
    return;
  }
  sim_active_ = active;
  ++jumps_;
}

void ROSClock::set_sim_time(int64_t nanoseconds)
{
  if (sim_active_ && nanoseconds < sim_time_)
  {
    ++jumps_;
  }
  sim_time_ = nanoseconds;
  has_sim_time_ = true;
}

} // namespace wire
} // namespace ros2vtk
