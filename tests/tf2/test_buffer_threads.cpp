// One thread inserts (as a DDS listener would) while another looks up (as Spin() would).
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

#include <atomic>
#include <thread>

using namespace tf2test;
using namespace ros2vtk::tf2;

TEST(BufferThreads, InsertWhileLookingUp)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(0.001), { 1, 0, 0 }), "x"));
  constexpr int kSamples = 20000;
  std::atomic<bool> done{ false };
  std::atomic<int> failed_inserts{ 0 };
  std::thread writer([&] {
    for (int i = 2; i <= kSamples; ++i)
    {
      // x grows with the stamp in milliseconds, so every interpolated x equals the lookup time.
      const double ms = i;
      if (!buffer.set_transform(make_stamped("world", "base", sec(ms / 1000), { ms, 0, 0 }), "x"))
      {
        ++failed_inserts;
      }
    }
    done = true;
  });
  int inconsistent = 0;
  int lookups = 0;
  while (!done)
  {
    const LookupResult r = buffer.lookup_transform("world", "base", kLatestTime);
    ++lookups;
    if (!r.ok || std::abs(r.transform.translation.x() - time_to_seconds(r.stamp) * 1000) > 1e-6)
    {
      ++inconsistent;
    }
  }
  writer.join();
  EXPECT_EQ(failed_inserts, 0);
  EXPECT_EQ(inconsistent, 0) << "out of " << lookups << " lookups";
  const LookupResult last = buffer.lookup_transform("world", "base", kLatestTime);
  ASSERT_TRUE(last.ok) << last.message;
  EXPECT_EQ(last.stamp, sec(kSamples / 1000.0));
  EXPECT_DOUBLE_EQ(last.transform.translation.x(), kSamples);
}
