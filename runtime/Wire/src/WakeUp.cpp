// ros2vtk — eventfd-based wake-up for event-driven spinning.
#include "ros2vtk/wire/WakeUp.hpp"

#include <cerrno>
#include <cstdint>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

namespace ros2vtk {
namespace wire {

WakeUp::WakeUp()
  : fd_(eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC))
{
}

WakeUp::~WakeUp()
{
  if (fd_ >= 0)
  {
    close(fd_);
  }
}

void WakeUp::arm()
{
  // Whatever was notified before is pending now: one write makes the descriptor say so. Either
  // this load sees the flag of a notify() that found the descriptor unarmed, or that notify's
  // second look sees armed_ and writes itself (both: one extra read, harmless).
  if (!armed_.load() && !armed_.exchange(true) && pending_.load())
  {
    write_and_flag();
  }
}

void WakeUp::notify(bool queued)
{
  if (queued)
  {
    queued_.store(true); // after the enqueue, before the wake: see clear()
  }
  if (!armed_.load())
  {
    pending_.store(true); // nobody polls: the spinner just finds the queues full
    if (armed_.load())
    {
      write_and_flag(); // armed meanwhile: see arm()
    }
  }
  else
  {
    write_and_flag();
  }
  if (!has_callback_.load())
  {
    return;
  }
  std::function<void()> callback;
  {
    std::lock_guard<std::mutex> lock(callback_mutex_);
    callback = callback_;
  }
  if (callback)
  {
    callback();
  }
}

void WakeUp::write_and_flag()
{
  notifying_.fetch_add(1);
  const uint64_t one = 1;
  // A full counter (EAGAIN) still leaves the fd readable, which is all we need.
  const ssize_t written = write(fd_, &one, sizeof(one));
  (void)written;
  if (after_write_for_test_)
  {
    after_write_for_test_();
  }
  // After the write: a clear() that misses this flag sees notifying_ and reads anyway.
  pending_.store(true);
  notifying_.fetch_sub(1);
}

bool WakeUp::clear()
{
  const bool queued = queued_.exchange(false);
  // Either flag or a notify() in progress: read. Whatever that notify wrote is then read here,
  // or its flag, set after its write, makes the next clear() read it.
  const bool flagged = pending_.exchange(false);
  if (!armed_.load() || (!flagged && notifying_.load() == 0))
  {
    return queued;
  }
  uint64_t value = 0;
  const ssize_t count = read(fd_, &value, sizeof(value));
  (void)count;
  return queued;
}

bool WakeUp::wait_for(int timeout_ms)
{
  arm();
  pollfd descriptor{ fd_, POLLIN, 0 };
  int result = 0;
  do
  {
    result = poll(&descriptor, 1, timeout_ms);
  } while (result < 0 && errno == EINTR);
  return result > 0 && (descriptor.revents & POLLIN);
}

void WakeUp::set_callback(std::function<void()> callback)
{
  std::lock_guard<std::mutex> lock(callback_mutex_);
  callback_ = std::move(callback);
  has_callback_.store(static_cast<bool>(callback_));
}

} // namespace wire
} // namespace ros2vtk
