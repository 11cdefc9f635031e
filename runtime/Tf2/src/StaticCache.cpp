#include "ros2vtk/tf2/StaticCache.hpp"

namespace ros2vtk {
namespace tf2 {

bool StaticCache::insert(const TransformRecord& record)
{
  record_ = record;
  has_value_ = true;
  return true;
}

bool StaticCache::sample(TimePoint time, TransformRecord& out, SampleError* error) const
{
  if (!has_value_)
  {
    if (error)
    {
      error->code = Tf2Error::NoDataForExtrapolation;
      error->message = "Lookup would require extrapolation at time " + display_time(time) +
        ", but no static transform is in the buffer";
    }
    return false;
  }
  out = record_;
  out.stamp = time;
  return true;
}

FrameId StaticCache::parent_at(TimePoint /*time*/) const
{
  return has_value_ ? record_.parent : kNoFrame;
}

std::pair<TimePoint, FrameId> StaticCache::latest_time_and_parent() const
{
  return { 0, parent_at(0) };
}

} // namespace tf2
} // namespace ros2vtk
