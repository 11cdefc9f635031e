// ros2vtk — a transport that sends nothing until its participant can hear the replies
// (see StartGateTransport.hpp).
#include "StartGateTransport.hpp"

#include <fastdds/rtps/network/SenderResource.h>
#include <fastdds/rtps/transport/TransportReceiverInterface.h>

namespace ros2vtk {
namespace wire {

namespace rtps = eprosima::fastrtps::rtps;
namespace fdrtps = eprosima::fastdds::rtps;

StartGateTransportDescriptor::StartGateTransportDescriptor(
  std::shared_ptr<fdrtps::TransportDescriptorInterface> low_level, std::shared_ptr<std::atomic<bool>> gate)
  : ChainingTransportDescriptor(std::move(low_level))
  , open(std::move(gate))
{
}

fdrtps::TransportInterface* StartGateTransportDescriptor::create_transport() const
{
  return new StartGateTransport(*this);
}

StartGateTransport::StartGateTransport(const StartGateTransportDescriptor& descriptor)
  : ChainingTransport(descriptor)
  , descriptor_(descriptor)
{
}

bool StartGateTransport::send(rtps::SenderResource* low_sender_resource, const rtps::octet* send_buffer,
                              uint32_t send_buffer_size, rtps::LocatorsIterator* destination_locators_begin,
                              rtps::LocatorsIterator* destination_locators_end,
                              const std::chrono::steady_clock::time_point& timeout)
{
  if (!descriptor_.open->load(std::memory_order_acquire))
  {
    return true; // as if lost on the way: announcements repeat, and nothing else is sent yet
  }
  return low_sender_resource->send(send_buffer, send_buffer_size, destination_locators_begin,
                                   destination_locators_end, timeout);
}

void StartGateTransport::receive(fdrtps::TransportReceiverInterface* next_receiver,
                                 const rtps::octet* receive_buffer, uint32_t receive_buffer_size,
                                 const rtps::Locator_t& local_locator, const rtps::Locator_t& remote_locator)
{
  next_receiver->OnDataReceived(receive_buffer, receive_buffer_size, local_locator, remote_locator);
}

fdrtps::TransportDescriptorInterface* StartGateTransport::get_configuration()
{
  return &descriptor_;
}

} // namespace wire
} // namespace ros2vtk
