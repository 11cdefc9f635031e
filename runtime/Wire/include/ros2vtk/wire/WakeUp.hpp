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
class WakeUp
{
public:
  WakeUp();
  ~WakeUp();
  WakeUp(const WakeUp&) = delete;
  WakeUp& operator=(const WakeUp&) = delete;

  /// Readable (POLLIN) while a notification is pending; never closed before destruction.
  int fd() const { return fd_; }
  /// Called by DDS threads after enqueuing.
  void notify();
  /// Clears pending notifications (the spinner calls this before draining queues).
  void clear();
  /// Blocks up to `timeout_ms` (-1: forever) for a notification; true when one is pending.
  bool wait_for(int timeout_ms) const;
  /// Replaces the callback run on each notify (nullptr to remove).
  void set_callback(std::function<void()> callback);

private:
  friend struct WakeUpTestProbe; // tests pause a notify() between its write and its flag

  int fd_ = -1;
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
