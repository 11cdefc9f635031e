#include "FrameListing.hpp"

#include <cstdint>
#include <sstream>

namespace ros2vtk {
namespace tf2 {

namespace {

/// Parent of the newest sample, kNoFrame when there is none.
FrameId newest_parent(const TimeCacheInterface& cache)
{
  TransformRecord newest;
  return cache.sample(kLatestTime, newest) ? newest.parent : kNoFrame;
}

} // namespace

std::string frames_as_string(const FrameTable& frames)
{
  std::ostringstream out;
  for (FrameId id = 1; id < frames.ids.size(); ++id)
  {
    const TimeCacheInterface* cache = frames.cache(id);
    if (!cache)
    {
      continue;
    }
    out << "Frame " << frames.ids.name(id) << " exists with parent "
        << frames.ids.name(newest_parent(*cache)) << ".\n";
  }
  return out.str();
}

std::string frames_as_yaml(const FrameTable& frames, TimePoint current_time)
{
  std::ostringstream out;
  out.setf(std::ios::fixed, std::ios::floatfield);
  out.precision(3);
  bool any = false;
  for (FrameId id = 1; id < frames.ids.size(); ++id)
  {
    const TimeCacheInterface* cache = frames.cache(id);
    TransformRecord newest;
    if (!cache || !cache->sample(kLatestTime, newest))
    {
      continue;
    }
    any = true;
    const std::string& authority = frames.authorities[id];
    // Unsigned: exact even for stamps at the ends of the int64 range (newest >= oldest).
    const auto span = static_cast<std::uint64_t>(cache->newest_stamp()) -
      static_cast<std::uint64_t>(cache->oldest_stamp());
    // tf2's rate: samples per second over the stored span, with a 0.1 ms floor on the span.
    const std::uint64_t rate_span = span > 100'000u ? span : 100'000u;
    const double rate = static_cast<double>(cache->size()) * 1e9 / static_cast<double>(rate_span);
    out << frames.ids.name(id) << ":\n"
        << "  parent: '" << frames.ids.name(newest.parent) << "'\n"
        << "  broadcaster: '" << (authority.empty() ? "no recorded authority" : authority) << "'\n"
        << "  rate: " << rate << "\n"
        << "  most_recent_transform: " << display_time(cache->newest_stamp()) << "\n"
        << "  oldest_transform: " << display_time(cache->oldest_stamp()) << "\n";
    if (current_time != kLatestTime)
    {
      out << "  transform_delay: "
          << time_to_seconds(current_time) - time_to_seconds(cache->newest_stamp()) << "\n";
    }
    out << "  buffer_length: " << static_cast<double>(span) * 1e-9 << "\n";
  }
  return any ? out.str() : std::string("[]");
}

} // namespace tf2
} // namespace ros2vtk
