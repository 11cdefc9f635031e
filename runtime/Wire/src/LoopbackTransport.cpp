// ros2vtk — loopback-only UDPv4 transport for LOCALHOST discovery (see LoopbackTransport.hpp).
#include "LoopbackTransport.hpp"

#include <fastdds/rtps/transport/TransportReceiverInterface.h>
#include <fastdds/rtps/network/SenderResource.h>
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
  : ChainingTransportDescriptor(loopback_only(std::move(udp)))
{
}

fdrtps::TransportInterface* LoopbackTransportDescriptor::create_transport() const
{
  return new LoopbackTransport(*this);
}

LoopbackTransport::LoopbackTransport(const LoopbackTransportDescriptor& descriptor)
  : ChainingTransport(descriptor)
  , descriptor_(descriptor)
{
}

bool LoopbackTransport::transform_remote_locator(const rtps::Locator_t& remote_locator,
                                                 rtps::Locator_t& result_locator) const
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

bool LoopbackTransport::send(rtps::SenderResource* low_sender_resource, const rtps::octet* send_buffer,
                             uint32_t send_buffer_size, rtps::LocatorsIterator* destination_locators_begin,
                             rtps::LocatorsIterator* destination_locators_end,
                             const std::chrono::steady_clock::time_point& timeout)
{
  return low_sender_resource->send(send_buffer, send_buffer_size, destination_locators_begin,
                                   destination_locators_end, timeout);
}

void LoopbackTransport::receive(fdrtps::TransportReceiverInterface* next_receiver,
                                const rtps::octet* receive_buffer, uint32_t receive_buffer_size,
                                const rtps::Locator_t& local_locator, const rtps::Locator_t& remote_locator)
{
  next_receiver->OnDataReceived(receive_buffer, receive_buffer_size, local_locator, remote_locator);
}

fdrtps::TransportDescriptorInterface* LoopbackTransport::get_configuration()
{
  return &descriptor_;
}

} // namespace wire
} // namespace ros2vtk
