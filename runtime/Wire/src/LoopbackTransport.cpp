// ros2vtk — loopback-only UDPv4 transport for LOCALHOST discovery (see LoopbackTransport.hpp).
#include "LoopbackTransport.hpp"

#include <fastrtps/utils/IPFinder.h>
#include <fastrtps/utils/IPLocator.h>

#include <vector>

namespace ros2vtk {
namespace wire {

namespace rtps = eprosima::fastrtps::rtps;
namespace fdrtps = eprosima::fastdds::rtps;

namespace {

std::shared_ptr<fdrtps::UDPv4TransportDescriptor> loopback_only(
  std::shared_ptr<fdrtps::UDPv4TransportDescriptor> udp)
{
  udp->interfaceWhiteList = { "127.0.0.1" };
  return udp;
}

} // namespace

bool is_address_of_this_host(const rtps::Locator_t& locator)
{
  std::vector<rtps::IPFinder::info_IP> addresses;
  if (!rtps::IPFinder::getIPs(&addresses, true))
  {
    return false;
  }
  for (const auto& address : addresses)
  {
    if ((address.type == rtps::IPFinder::IP4 || address.type == rtps::IPFinder::IP4_LOCAL) &&
      rtps::IPLocator::compareAddress(address.locator, locator))
    {
      return true;
    }
  }
  return false;
}

LoopbackTransportDescriptor::LoopbackTransportDescriptor(
  std::shared_ptr<fdrtps::UDPv4TransportDescriptor> udp)
  : GatedTransportDescriptor(loopback_only(std::move(udp)))
{
}

fdrtps::TransportInterface* LoopbackTransportDescriptor::create_transport() const
{
  return new LoopbackTransport(*this);
}

LoopbackTransport::LoopbackTransport(const LoopbackTransportDescriptor& descriptor)
  : GatedTransport(descriptor)
  , descriptor_(descriptor)
{
}

bool LoopbackTransport::transform_remote_locator(
  const rtps::Locator_t& remote_locator, rtps::Locator_t& result_locator) const
{
  if (remote_locator.kind != LOCATOR_KIND_UDPv4 || rtps::IPLocator::isMulticast(remote_locator))
  {
    return false;
  }
  if (rtps::IPLocator::isLocal(remote_locator))
  {
    return low_level_transport_->transform_remote_locator(remote_locator, result_locator);
  }
  if (!is_address_of_this_host(remote_locator))
  {
    return false; // another host: never reached in LOCALHOST mode
  }
  rtps::Locator_t loopback = remote_locator;
  rtps::IPLocator::setIPv4(loopback, 127, 0, 0, 1);
  return low_level_transport_->transform_remote_locator(loopback, result_locator);
}

fdrtps::TransportDescriptorInterface* LoopbackTransport::get_configuration()
{
  return &descriptor_;
}

} // namespace wire
} // namespace ros2vtk
