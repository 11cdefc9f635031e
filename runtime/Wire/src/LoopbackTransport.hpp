// ros2vtk — the UDPv4 transport of a participant that must stay on this host
// (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST or ROS_LOCALHOST_ONLY=1).
//
// Fast DDS 2.9 binds a loopback-only socket set when 127.0.0.1 is the transport's interface
// whitelist, and then announces only 127.0.0.1 locators. But it drops every locator a peer
// announces on one of this host's other addresses (what a Fast DDS 3 rclpy node in LOCALHOST
// mode announces), so it would never reach such a peer. This chaining transport keeps the
// whitelist and maps those same-host locators to 127.0.0.1 (same port; the peer listens on all
// interfaces); locators of other hosts and multicast are refused, so nothing leaves the host.
// Reception waits for the participant like every transport of ours (GatedTransport.hpp).
#ifndef ros2vtk_wire_LoopbackTransport_hpp
#define ros2vtk_wire_LoopbackTransport_hpp

#include "GatedTransport.hpp"

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>

#include <memory>

namespace ros2vtk {
namespace wire {

/// Descriptor of a loopback-only UDPv4 transport; `udp` is configured by the caller (its
/// whitelist is replaced by 127.0.0.1).
struct LoopbackTransportDescriptor : public GatedTransportDescriptor
{
  explicit LoopbackTransportDescriptor(
    std::shared_ptr<eprosima::fastdds::rtps::UDPv4TransportDescriptor> udp);

  eprosima::fastdds::rtps::TransportInterface* create_transport() const override;
};

/// Passes data through unchanged; only remote locators are rewritten (see the file comment).
class LoopbackTransport : public GatedTransport
{
public:
  explicit LoopbackTransport(const LoopbackTransportDescriptor& descriptor);

  bool transform_remote_locator(const eprosima::fastrtps::rtps::Locator_t& remote_locator,
    eprosima::fastrtps::rtps::Locator_t& result_locator) const override;

  eprosima::fastdds::rtps::TransportDescriptorInterface* get_configuration() override;

private:
  LoopbackTransportDescriptor descriptor_;
};

/// True when `address` (4 bytes, network order) is one of this host's IPv4 addresses.
bool is_address_of_this_host(const eprosima::fastrtps::rtps::Locator_t& locator);

} // namespace wire
} // namespace ros2vtk

#endif
