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

void WakeUp::notify()
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

void WakeUp::clear()
{
  // Either flag or a notify() in progress: read. Whatever that notify wrote is then read here,
  // or its flag, set after its write, makes the next clear() read it.
  const bool flagged = pending_.exchange(false);
  if (!flagged && notifying_.load() == 0)
  {
    return;
  }
  uint64_t value = 0;
  const ssize_t count = read(fd_, &value, sizeof(value));
  (void)count;
}

bool WakeUp::wait_for(int timeout_ms) const
{
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
}

} // namespace wire
} // namespace ros2vtk
