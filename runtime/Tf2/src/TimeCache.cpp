#include "ros2vtk/tf2/TimeCache.hpp"

#include <algorithm>
#include <cstdint>

namespace ros2vtk {
namespace tf2 {

namespace {

/// newer - older for newer >= older, exact for every pair of int64 stamps (the signed difference
/// could overflow at the extremes; stamps arrive from the network, so any value is possible).
std::uint64_t span(TimePoint newer, TimePoint older)
{
  return static_cast<std::uint64_t>(newer) - static_cast<std::uint64_t>(older);
}

void fail(SampleError* error, Tf2Error code, std::string message)
{
  if (error)
  {
    error->code = code;
    error->message = std::move(message);
  }
}

} // namespace

TimeCache::TimeCache(Duration cache_time)
  : cache_time_(std::max<Duration>(cache_time, 0))
{
}

bool TimeCache::insert(const TransformRecord& record)
{
  if (!records_.empty() && record.stamp < records_.back().stamp &&
    span(records_.back().stamp, record.stamp) > static_cast<std::uint64_t>(cache_time_))
  {
    return false; // older than (newest - cache_time)
  }
  if (records_.empty() || record.stamp > records_.back().stamp)
  {
    records_.push_back(record); // the usual case: newer than everything held
    prune();
    return true;
  }
  // After every sample with a stamp <= the new one: equal stamps stay in arrival order.
  auto position = std::upper_bound(records_.begin(), records_.end(), record.stamp,
    [](TimePoint stamp, const TransformRecord& stored) { return stamp < stored.stamp; });
  for (auto same = position; same != records_.begin();)
  {
    --same;
    if (same->stamp != record.stamp)
    {
      break;
    }
    if (*same == record)
    {
      return true; // received twice (e.g. a relayed /tf): keep one copy
    }
  }
  records_.insert(position, record);
  prune();
  return true;
}

void TimeCache::prune()
{
  // tf2 (ROS 2) prunes before inserting, which lets stale samples survive until the next
  // insert; pruning after keeps the window exactly cache_time long.
  const TimePoint newest = records_.back().stamp;
  while (!records_.empty() &&
    span(newest, records_.front().stamp) > static_cast<std::uint64_t>(cache_time_))
  {
    records_.pop_front();
  }
}

int TimeCache::find_closest(
  TimePoint time, std::size_t& older, std::size_t& newer, SampleError* error) const
{
  if (records_.empty())
  {
    fail(error, Tf2Error::NoDataForExtrapolation,
      "Lookup would require extrapolation at time " + display_time(time) +
        ", but no data is in the buffer");
    return 0;
  }
  const std::size_t last = records_.size() - 1;
  if (time == kLatestTime)
  {
    older = last;
    return 1;
  }
  if (records_.size() == 1)
  {
    if (records_.front().stamp == time)
    {
      older = 0;
      return 1;
    }
    fail(error, Tf2Error::NoDataForExtrapolation,
      "Lookup would require extrapolation at time " + display_time(time) + ", but only time " +
        display_time(records_.front().stamp) + " is in the buffer");
    return 0;
  }
  const TimePoint newest = records_.back().stamp;
  if (time == newest)
  {
    older = last; // the usual latest-time lookup: the oldest record (a cold line) is not read
    return 1;
  }
  const TimePoint oldest = records_.front().stamp;
  if (time == oldest)
  {
    older = 0;
    return 1;
  }
  if (time > newest)
  {
    fail(error, Tf2Error::ForwardExtrapolation,
      "Lookup would require extrapolation into the future.  Requested time " + display_time(time) +
        " but the latest data is at time " + display_time(newest));
    return 0;
  }
  if (time < oldest)
  {
    fail(error, Tf2Error::BackwardExtrapolation,
      "Lookup would require extrapolation into the past.  Requested time " + display_time(time) +
        " but the earliest data is at time " + display_time(oldest));
    return 0;
  }
  // oldest < time < newest: the last sample at or before `time` and the one after it.
  auto after = std::upper_bound(records_.begin(), records_.end(), time,
    [](TimePoint stamp, const TransformRecord& stored) { return stamp < stored.stamp; });
  newer = static_cast<std::size_t>(after - records_.begin());
  older = newer - 1;
  return 2;
}

bool TimeCache::sample(TimePoint time, TransformRecord& out, SampleError* error) const
{
  std::size_t older = 0;
  std::size_t newer = 0;
  const int found = find_closest(time, older, newer, error);
  if (found == 0)
  {
    return false;
  }
  const TransformRecord& a = records_[older];
  out = a;
  if (found == 2 && a.parent == records_[newer].parent)
  {
    const TransformRecord& b = records_[newer];
    if (b.stamp == a.stamp)
    {
      out = b;
    }
    else
    {
      const double ratio =
        static_cast<double>(span(time, a.stamp)) / static_cast<double>(span(b.stamp, a.stamp));
      out.transform = interpolate(a.transform, b.transform, ratio);
    }
  }
  // found == 2 with different parents: the older sample as it is (no interpolation across a
  // parent change).
  out.stamp = time == kLatestTime ? a.stamp : time;
  return true;
}

FrameId TimeCache::parent_at(TimePoint time) const
{
  std::size_t older = 0;
  std::size_t newer = 0;
  if (find_closest(time, older, newer, nullptr) == 0)
  {
    return kNoFrame;
  }
  return records_[older].parent;
}

std::pair<TimePoint, FrameId> TimeCache::latest_time_and_parent() const
{
  if (records_.empty())
  {
    return { 0, kNoFrame };
  }
  return { records_.back().stamp, records_.back().parent };
}

TimePoint TimeCache::newest_stamp() const
{
  return records_.empty() ? 0 : records_.back().stamp;
}

TimePoint TimeCache::oldest_stamp() const
{
  return records_.empty() ? 0 : records_.front().stamp;
}

} // namespace tf2
} // namespace ros2vtk
