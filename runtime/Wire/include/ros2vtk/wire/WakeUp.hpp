// ros2vtk — the signal DDS threads raise when data is pending, for event-driven spinning.
#ifndef ros2vtk_wire_WakeUp_hpp
#define ros2vtk_wire_WakeUp_hpp

#include <atomic>
#include <functional>
#include <mutex>

namespace ros2vtk {
namespace wire {

/// An eventfd that becomes readable when any subscription of a participant has queued data,
/// plus an optional callback (called on the DDS thread: it must only schedule work, e.g. post
/// to a Qt or VTK event loop). A host loop polls fd() or calls wait_for().
///
/// The descriptor is written only once somebody asked for it (fd() or wait_for() arm it): a
/// timer-driven spinner (Slicer's 50 Hz QTimer, SpinFor) never polls, so until then notify()
/// and clear() are a flag each, not a write per message on the DDS thread and a read per spin.
class WakeUp
{
public:
  WakeUp();
  ~WakeUp();
  WakeUp(const WakeUp&) = delete;
  WakeUp& operator=(const WakeUp&) = delete;

  /// Readable (POLLIN) while a notification is pending; never closed before destruction.
  /// Arms the descriptor (see above); a notification already pending makes it readable at once.
  int fd()
  {
    arm();
    return fd_;
  }
  /// Called by DDS threads after enqueuing; `queued` false when the data went to a sink instead
  /// of a queue (the tf buffer: the spin only looks up, it has nothing to take).
  void notify(bool queued = true);
  /// Clears pending notifications (the spinner calls this before draining queues). True when
  /// anything was queued since the last clear: a spin that gets false may skip taking from the
  /// queues it knows were quiet (a later enqueue's flag is seen by the next clear).
  bool clear();
  /// Blocks up to `timeout_ms` (-1: forever) for a notification; true when one is pending.
  bool wait_for(int timeout_ms);
  /// Replaces the callback run on each notify (nullptr to remove).
  void set_callback(std::function<void()> callback);

private:
  friend struct WakeUpTestProbe; // tests pause a notify() between its write and its flag

  void arm();
  /// Writes the eventfd, then sets the flag (the order clear() relies on).
  void write_and_flag();

  int fd_ = -1;
  std::atomic<bool> armed_{ false };
  std::atomic<bool> queued_{ true }; // a first spin looks at every queue
  // Whether a callback is set, so notify() takes the callback's lock only when there is one.
  std::atomic<bool> has_callback_{ false };
  // Set after each write, so clear() reads the eventfd only when something was written: the
  // spinner calls clear() on every spin, and a syscall per spin per node is most of an idle spin.
  std::atomic<bool> pending_{ false };
  // notify() calls between their start and their flag: clear() reads then too. Without it, a
  // notifier descheduled after its write left the eventfd readable and unflagged, so every poll
  // woke the spinner and every spin skipped the read: ~2500 empty spins/s on a loaded machine.
  std::atomic<int> notifying_{ 0 };
  std::function<void()> after_write_for_test_;
  std::mutex callback_mutex_;
  std::function<void()> callback_;
};

} // namespace wire
} // namespace ros2vtk

#endif
