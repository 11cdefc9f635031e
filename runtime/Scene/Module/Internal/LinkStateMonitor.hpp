// ros2vtk — watches a ROS node's link state from spin to spin (private to Scene).
//
// The node reads its peer count on each Spin and gives it here; this says whether the link
// state changed since the previous Spin (the node then fires LinkStateChangedEvent on the
// spinning thread) and whether the node has found nobody long enough to say so (the first time
// after `quiet_after`, then at most once per `repeat_every` while it lasts; finding a peer
// starts over).
#ifndef ros2vtk_scene_LinkStateMonitor_hpp
#define ros2vtk_scene_LinkStateMonitor_hpp

#include <chrono>

namespace ros2vtk {
namespace scene {

class LinkStateMonitor
{
public:
  using Clock = std::chrono::steady_clock;

  LinkStateMonitor(Clock::duration quiet_after, Clock::duration repeat_every)
    : quiet_after_(quiet_after)
    , repeat_every_(repeat_every)
  {
  }

  /// A new participant at `now`: nobody found yet, nothing reported.
  void start(Clock::time_point now)
  {
    participants_ = 0;
    alone_since_ = now;
    reported_alone_ = false;
  }

  /// The participant count seen on this Spin. True when it differs from the previous Spin's
  /// (a peer found or lost: the link state or its count changed).
  bool update(int participants, Clock::time_point now)
  {
    if (participants == participants_)
    {
      return false;
    }
    if (participants == 0)
    {
      alone_since_ = now;
      reported_alone_ = false;
    }
    participants_ = participants;
    return true;
  }

  /// Seconds without any peer to report now, or a negative number when there is nothing to
  /// say (peers seen, not alone long enough yet, or reported within `repeat_every`).
  double alone_report_due(Clock::time_point now) const
  {
    if (participants_ > 0 || now - alone_since_ < quiet_after_ ||
      (reported_alone_ && now - last_report_ < repeat_every_))
    {
      return -1.0;
    }
    return std::chrono::duration<double>(now - alone_since_).count();
  }

  /// The report due at `now` was made (or skipped): the next one waits `repeat_every`.
  void alone_reported(Clock::time_point now)
  {
    reported_alone_ = true;
    last_report_ = now;
  }

private:
  Clock::duration quiet_after_;
  Clock::duration repeat_every_;
  int participants_ = 0;
  Clock::time_point alone_since_{};
  Clock::time_point last_report_{};
  bool reported_alone_ = false;
};

} // namespace scene
} // namespace ros2vtk

#endif
