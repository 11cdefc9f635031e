// ros2vtk::igtl::Endpoint's per-peer queues (issue 16, "per-client queues that drop oldest rather
// than block the spin; several clients at once"), with plain POSIX sockets as peers: one peer that
// never reads (a stalled Slicer) loses its oldest queued messages and keeps the newest, in order,
// while a peer that reads gets every message. The peers parse what they read from the header
// layout of OpenIGTLink's header.md (58 bytes; device name at 14, body size at 42), not with our
// code.
#include "ros2vtk/igtl/Codec.hpp"
#include "ros2vtk/igtl/Endpoint.hpp"
#include "ros2vtk/igtl/Frame.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace igtl = ros2vtk::igtl;

namespace {

int free_port()
{
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
  socklen_t size = sizeof(address);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
  ::close(fd);
  return ntohs(address.sin_port);
}

// A loopback client; a small receive buffer makes a peer that does not read stall quickly.
int connect_to(int port, int receiveBuffer)
{
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (receiveBuffer > 0)
  {
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof(receiveBuffer));
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0)
  {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Reads what is there (waits up to `ms` for more) and cuts whole messages: their device names.
struct Reader
{
  explicit Reader(int socket)
    : fd(socket)
  {
  }
  int fd = -1;
  std::vector<std::uint8_t> buffer;
  std::vector<std::string> devices;

  bool read(int ms)
  {
    pollfd p{ fd, POLLIN, 0 };
    if (::poll(&p, 1, ms) <= 0)
    {
      return false;
    }
    std::uint8_t chunk[1 << 16];
    const ssize_t n = ::recv(fd, chunk, sizeof(chunk), MSG_DONTWAIT);
    if (n <= 0)
    {
      return false;
    }
    buffer.insert(buffer.end(), chunk, chunk + n);
    while (buffer.size() >= 58)
    {
      std::uint64_t body = 0;
      for (int i = 0; i < 8; ++i)
      {
        body = (body << 8) | buffer[42 + i];
      }
      if (buffer.size() < 58 + body)
      {
        break;
      }
      const char* name = reinterpret_cast<const char*>(buffer.data() + 14);
      devices.emplace_back(name, strnlen(name, 20));
      buffer.erase(buffer.begin(), buffer.begin() + static_cast<long>(58 + body));
    }
    return true;
  }
};

std::vector<std::uint8_t> message(int i, std::size_t bytes)
{
  return igtl::encode_frame(
    igtl::encode_string("k" + std::to_string(i), std::string(bytes, 'x'), 0));
}

bool wait_for_peers(igtl::Endpoint& endpoint, std::size_t count)
{
  std::vector<igtl::Endpoint::Received> received;
  for (int i = 0; i < 500 && endpoint.peer_count() < count; ++i)
  {
    endpoint.poll(received);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return endpoint.peer_count() == count;
}

// A server on a free loopback port whose peers may queue 8 messages each.
class IGTLEndpoint : public ::testing::Test
{
protected:
  void SetUp() override
  {
    options.port = free_port();
    options.max_queued_messages = 8;
    std::string error;
    ASSERT_TRUE(endpoint.start(options, error)) << error;
  }
  igtl::Endpoint endpoint;
  igtl::Endpoint::Options options;
};

} // namespace

TEST_F(IGTLEndpoint, AStalledPeerLosesItsOldestMessagesAndKeepsTheNewestInOrder)
{
  const int fd = connect_to(options.port, 4096);
  ASSERT_GE(fd, 0);
  ASSERT_TRUE(wait_for_peers(endpoint, 1));

  // 200 distinct devices of 32 KB, never read meanwhile: far beyond the socket buffers. No call
  // may block (the test would hang, not fail slowly: ctest's timeout then names it).
  const int total = 200;
  for (int i = 0; i < total; ++i)
  {
    endpoint.send("STRING:k" + std::to_string(i), message(i, 32 * 1024));
    endpoint.flush();
  }
  const std::uint64_t dropped = endpoint.messages_dropped();
  EXPECT_GT(dropped, 0u);

  // Now the peer reads everything that is left.
  Reader reader(fd);
  for (int idle = 0; idle < 20;)
  {
    endpoint.flush();
    idle = reader.read(50) ? 0 : idle + 1;
  }
  ::close(fd);
  endpoint.stop();
  ASSERT_FALSE(reader.devices.empty());
  EXPECT_EQ(reader.devices.size() + dropped, static_cast<std::size_t>(total));
  // In order, and what is missing is a block of older ones: the tail is the newest, contiguous.
  std::vector<int> numbers;
  for (const std::string& device : reader.devices)
  {
    numbers.push_back(std::stoi(device.substr(1)));
  }
  for (std::size_t i = 1; i < numbers.size(); ++i)
  {
    EXPECT_LT(numbers[i - 1], numbers[i]);
  }
  EXPECT_EQ(numbers.back(), total - 1);
  const std::size_t tail = options.max_queued_messages - 1; // the queue's newest, never dropped
  ASSERT_GE(numbers.size(), tail);
  for (std::size_t i = 0; i < tail; ++i)
  {
    EXPECT_EQ(numbers[numbers.size() - 1 - i], total - 1 - static_cast<int>(i));
  }
}

TEST_F(IGTLEndpoint, AStalledPeerDoesNotHoldBackAPeerThatReads)
{
  const int stalled = connect_to(options.port, 4096);
  ASSERT_TRUE(wait_for_peers(endpoint, 1));
  const int reading = connect_to(options.port, 0);
  ASSERT_GE(stalled, 0);
  ASSERT_GE(reading, 0);
  ASSERT_TRUE(wait_for_peers(endpoint, 2));

  Reader reader(reading);
  const int total = 200;
  for (int i = 0; i < total; ++i)
  {
    endpoint.send("STRING:k" + std::to_string(i), message(i, 32 * 1024));
    endpoint.flush();
    while (reader.read(0)) // the reading peer keeps up
    {
      endpoint.flush();
    }
  }
  for (int idle = 0; idle < 20;)
  {
    endpoint.flush();
    idle = reader.read(50) ? 0 : idle + 1;
  }
  EXPECT_GT(endpoint.messages_dropped(), 0u); // all of them the stalled peer's
  ASSERT_EQ(reader.devices.size(), static_cast<std::size_t>(total));
  for (int i = 0; i < total; ++i)
  {
    EXPECT_EQ(reader.devices[static_cast<std::size_t>(i)], "k" + std::to_string(i));
  }
  ::close(stalled);
  ::close(reading);
  endpoint.stop();
}
