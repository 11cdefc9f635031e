#include "ros2vtk/convert/Stamp.hpp"

#include <limits>

namespace ros2vtk {
namespace convert {

Stamp to_stamp(std::chrono::system_clock::time_point time)
{
  return stamp_from_nanoseconds(
    std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count());
}

Stamp stamp_from_nanoseconds(int64_t nanoseconds)
{
  Stamp stamp;
  if (nanoseconds < 0)
  {
    return stamp;
  }
  const int64_t seconds = nanoseconds / 1000000000;
  if (seconds > std::numeric_limits<int32_t>::max())
  {
    stamp.sec = std::numeric_limits<int32_t>::max();
    stamp.nanosec = 999999999u;
    return stamp;
  }
  stamp.sec = static_cast<int32_t>(seconds);
  stamp.nanosec = static_cast<uint32_t>(nanoseconds % 1000000000);
  return stamp;
}

Stamp now_stamp()
{
  return to_stamp(std::chrono::system_clock::now());
}

} // namespace convert
} // namespace ros2vtk
