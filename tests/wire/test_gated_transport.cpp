// ros2vtk — unit tests of the reception gate (GatedTransport.hpp): what arrives before the
// participant is enabled is kept and handed on, in order and unchanged, once the gate opens; after
// that nothing is held. Without it Fast DDS 2.9 drops a peer's answer to our first announcement
// (the cause of the slow robot loads of issue 15, measured in tests/benchmarks).
#include "GatedTransport.hpp"

#include <fastdds/rtps/transport/TransportReceiverInterface.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace {

using namespace ros2vtk::wire;
namespace rtps = eprosima::fastrtps::rtps;

/// Records what a ReceiverResource would have been given.
class RecordingReceiver : public eprosima::fastdds::rtps::TransportReceiverInterface
{
public:
  void OnDataReceived(const rtps::octet* data, uint32_t size, const rtps::Locator_t& local,
    const rtps::Locator_t& remote) override
  {
    received.emplace_back(reinterpret_cast<const char*>(data), size);
    locals.push_back(local.port);
    remotes.push_back(remote.port);
  }
  std::vector<std::string> received;
  std::vector<uint32_t> locals;
  std::vector<uint32_t> remotes;
};

rtps::Locator_t udp(uint32_t port)
{
  rtps::Locator_t locator;
  locator.kind = LOCATOR_KIND_UDPv4;
  rtps::IPLocator::setIPv4(locator, 127, 0, 0, 1);
  locator.port = port;
  return locator;
}

bool hold(ReceptionGate& gate, RecordingReceiver& receiver, std::string bytes, uint32_t local,
  uint32_t remote)
{
  const bool held = gate.hold(&receiver, reinterpret_cast<const rtps::octet*>(bytes.data()),
    static_cast<uint32_t>(bytes.size()), udp(local), udp(remote));
  bytes.assign(bytes.size(), 'x'); // the transport's buffer is reused for the next datagram
  return held;
}

TEST(ReceptionGate, KeepsWhatArrivesBeforeItOpensAndHandsItOnInOrder)
{
  ReceptionGate gate;
  RecordingReceiver metatraffic, user;
  EXPECT_TRUE(hold(gate, metatraffic, "RTPS DATA(p) of a peer", 7410, 50001));
  EXPECT_TRUE(hold(gate, user, "RTPS HEARTBEAT", 7411, 50002));
  EXPECT_TRUE(hold(gate, metatraffic, "RTPS ACKNACK", 7410, 50001));
  EXPECT_EQ(gate.held(), 3u);
  EXPECT_TRUE(
    metatraffic.received.empty()); // nothing reaches a receiver that is not registered yet

  EXPECT_EQ(gate.open(), 3u);
  EXPECT_EQ(
    metatraffic.received, (std::vector<std::string>{ "RTPS DATA(p) of a peer", "RTPS ACKNACK" }));
  EXPECT_EQ(metatraffic.locals, (std::vector<uint32_t>{ 7410, 7410 }));
  EXPECT_EQ(metatraffic.remotes, (std::vector<uint32_t>{ 50001, 50001 }));
  EXPECT_EQ(user.received, (std::vector<std::string>{ "RTPS HEARTBEAT" }));
  EXPECT_EQ(user.locals, (std::vector<uint32_t>{ 7411 }));
  EXPECT_EQ(gate.held(), 0u);
}

TEST(ReceptionGate, PassesEverythingOnceOpen)
{
  ReceptionGate gate;
  RecordingReceiver receiver;
  EXPECT_EQ(gate.open(), 0u);
  EXPECT_FALSE(hold(gate, receiver, "RTPS DATA", 7410, 50001)); // the caller hands it on itself
  EXPECT_EQ(gate.held(), 0u);
  EXPECT_TRUE(receiver.received.empty());
  EXPECT_EQ(gate.open(), 0u); // opening twice is harmless
}

TEST(ReceptionGate, KeepsAtMostEightMebibytesWhileClosed)
{
  ReceptionGate gate;
  RecordingReceiver receiver;
  const std::string datagram(60000, 'd');
  size_t accepted = 0;
  for (int i = 0; i < 200; ++i) // 12 MB offered
  {
    EXPECT_TRUE(hold(gate, receiver, datagram, 7411, 50002)); // taken off the socket either way
    accepted = gate.held();
  }
  EXPECT_EQ(accepted, (8u << 20) / datagram.size());
  EXPECT_EQ(gate.open(), accepted);
  EXPECT_EQ(receiver.received.size(), accepted);
}

// Participant::set_datagram_observer: the benchmarks time a large sample's first and last
// fragment with it. The observer sees every datagram, held or passed, as it was read, before the
// receiver; removing it stops the calls.
TEST(ReceptionGate, ShowsEveryDatagramToItsObserverUntilTheObserverIsRemoved)
{
  GatedTransportDescriptor descriptor(
    std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>());
  GatedTransport transport(descriptor); // what Fast DDS creates; its receive() is the path
  ReceptionGate& gate = *descriptor.gate;
  RecordingReceiver receiver;
  std::vector<std::string> seen;
  size_t received_when_seen = 0;
  gate.observe([&](const uint8_t* data, size_t size) {
    seen.emplace_back(reinterpret_cast<const char*>(data), size);
    received_when_seen = receiver.received.size();
  });
  const auto arrive = [&](const std::string& bytes) {
    transport.receive(&receiver, reinterpret_cast<const rtps::octet*>(bytes.data()),
      static_cast<uint32_t>(bytes.size()), udp(7411), udp(50002));
  };
  arrive("RTPS DATA_FRAG 1"); // held: the gate is closed
  EXPECT_TRUE(receiver.received.empty());
  EXPECT_EQ(gate.open(), 1u);
  arrive("RTPS DATA_FRAG 2");
  EXPECT_EQ(seen, (std::vector<std::string>{ "RTPS DATA_FRAG 1", "RTPS DATA_FRAG 2" }));
  EXPECT_EQ(received_when_seen, 1u) << "the observer runs before the receiver";
  EXPECT_EQ(
    receiver.received, (std::vector<std::string>{ "RTPS DATA_FRAG 1", "RTPS DATA_FRAG 2" }));

  gate.observe(nullptr);
  arrive("RTPS HEARTBEAT");
  EXPECT_EQ(seen.size(), 2u);
  EXPECT_EQ(receiver.received.size(), 3u);
}

} // namespace
