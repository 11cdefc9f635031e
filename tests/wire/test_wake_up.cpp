// WakeUp: the eventfd a DDS thread raises and the spinner clears. A notify() interrupted between
// its write and its flag (a DDS thread descheduled there on a loaded machine) must not leave
// the descriptor readable after clear(): every poll would wake the spinner and every spin would
// skip the read, a busy loop until that thread runs again.
#include "ros2vtk/wire/WakeUp.hpp"

#include <gtest/gtest.h>

#include <poll.h>

#include <condition_variable>
#include <fstream>
#include <string>
#include <mutex>
#include <thread>

namespace ros2vtk {
namespace wire {

// Pauses notify() right after its write (the friend of WakeUp).
struct WakeUpTestProbe
{
  static void PauseAfterWrite(WakeUp& wake, std::function<void()> pause)
  {
    wake.after_write_for_test_ = std::move(pause);
  }
  // The descriptor without asking for it (which would arm it).
  static int RawFd(const WakeUp& wake) { return wake.fd_; }
};

} // namespace wire
} // namespace ros2vtk

namespace {
using ros2vtk::wire::WakeUp;

bool Readable(WakeUp& wake)
{
  pollfd descriptor{ wake.fd(), POLLIN, 0 };
  return ::poll(&descriptor, 1, 0) == 1 && (descriptor.revents & POLLIN);
}

TEST(WakeUp, NotifyMakesReadableAndClearDrains)
{
  WakeUp wake;
  ASSERT_GE(wake.fd(), 0);
  EXPECT_FALSE(Readable(wake));
  wake.notify();
  wake.notify();
  EXPECT_TRUE(Readable(wake));
  wake.clear();
  EXPECT_FALSE(Readable(wake));
  wake.clear(); // nothing pending: nothing to read, still not readable
  EXPECT_FALSE(Readable(wake));
}

TEST(WakeUp, AClearDuringANotifysWindowLeavesNothingReadable)
{
  WakeUp wake;
  ASSERT_GE(wake.fd(), 0); // armed, as by a poller: notify() writes the descriptor
  std::mutex mutex;
  std::condition_variable changed;
  bool written = false, resume = false;
  ros2vtk::wire::WakeUpTestProbe::PauseAfterWrite(wake, [&] {
    std::unique_lock<std::mutex> lock(mutex);
    written = true;
    changed.notify_all();
    changed.wait(lock, [&] { return resume; });
  });
  std::thread notifier([&] { wake.notify(); });
  {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return written; });
  }
  // The notifier has written but not flagged yet: the spinner wakes and clears.
  EXPECT_TRUE(Readable(wake));
  wake.clear();
  EXPECT_FALSE(Readable(wake)) << "readable after clear(): the spinner would wake again at once";
  {
    std::lock_guard<std::mutex> lock(mutex);
    resume = true;
  }
  changed.notify_all();
  notifier.join();
  // The late flag costs one read at most; the descriptor stays quiet.
  wake.clear();
  EXPECT_FALSE(Readable(wake));
  wake.notify();
  EXPECT_TRUE(Readable(wake)) << "a later notify still wakes";
}

// The eventfd's counter as the kernel reports it: how many notifications were written.
long EventCount(int fd)
{
  std::ifstream info("/proc/self/fdinfo/" + std::to_string(fd));
  std::string line;
  while (std::getline(info, line))
  {
    if (line.rfind("eventfd-count:", 0) == 0)
    {
      return std::stol(line.substr(line.find(':') + 1), nullptr, 16);
    }
  }
  return -1;
}

TEST(WakeUp, NobodyPollsNothingIsWrittenUntilTheDescriptorIsAskedFor)
{
  WakeUp wake;
  const int raw = ros2vtk::wire::WakeUpTestProbe::RawFd(wake);
  ASSERT_GE(raw, 0);
  ASSERT_EQ(EventCount(raw), 0) << "no eventfd-count in /proc/self/fdinfo";
  // A timer-driven spinner: messages arrive, spins clear, nobody asks for the descriptor.
  for (int i = 0; i < 5; ++i)
  {
    wake.notify();
  }
  wake.clear();
  wake.notify(); // pending when the host loop starts polling
  EXPECT_EQ(EventCount(raw), 0) << "a notify wrote the eventfd although nobody polls it";
  // Asking for the descriptor arms it, and what is pending makes it readable at once.
  EXPECT_TRUE(Readable(wake));
  wake.clear();
  EXPECT_FALSE(Readable(wake));
  wake.notify();
  EXPECT_TRUE(Readable(wake)) << "armed: a notify wakes the poller";
  wake.clear();
  EXPECT_FALSE(Readable(wake));
  // wait_for arms too (a fresh wake-up, nothing pending: it times out, then sees a notify).
  WakeUp other;
  EXPECT_FALSE(other.wait_for(0));
  other.clear(); // the write of arming
  EXPECT_FALSE(other.wait_for(0));
  other.notify();
  EXPECT_TRUE(other.wait_for(0));
}

} // namespace

namespace {

// The spin asks clear() whether anything was queued: data handed to a sink (tf into the
// buffer) wakes the spinner but leaves the queues empty, so the spin may skip them.
TEST(WakeUp, ClearSaysWhetherAnythingWasQueuedSinceTheLastClear)
{
  WakeUp wake;
  EXPECT_TRUE(wake.clear()) << "a first spin looks at every queue";
  EXPECT_FALSE(wake.clear());
  wake.notify(false); // sunk
  EXPECT_FALSE(wake.clear());
  wake.notify(false);
  wake.notify(); // queued
  wake.notify(false);
  EXPECT_TRUE(wake.clear());
  EXPECT_FALSE(wake.clear());
  // The same when a poller armed the descriptor; a sunk notify still wakes it.
  EXPECT_FALSE(Readable(wake)); // arms it; nothing pending
  wake.notify(false);
  EXPECT_TRUE(Readable(wake)) << "sunk data must still wake the spinner (the lookups use it)";
  EXPECT_FALSE(wake.clear());
  EXPECT_FALSE(Readable(wake));
}

} // namespace
