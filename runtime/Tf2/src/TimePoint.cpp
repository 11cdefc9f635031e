#include "ros2vtk/tf2/TimePoint.hpp"

#include <cmath>
#include <cstdio>

namespace ros2vtk {
namespace tf2 {

TimePoint time_from_seconds(double seconds)
{
  return static_cast<TimePoint>(std::llround(seconds * 1e9));
}

double time_to_seconds(TimePoint time)
{
  return static_cast<double>(time) * 1e-9;
}

std::string display_time(TimePoint time)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", time_to_seconds(time));
  return text;
}

} // namespace tf2
} // namespace ros2vtk
