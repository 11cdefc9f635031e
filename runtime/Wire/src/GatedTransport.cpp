// ros2vtk — reception held until the participant is enabled (see GatedTransport.hpp).
#include "GatedTransport.hpp"

#include <fastdds/rtps/network/SenderResource.h>
#include <fastdds/rtps/transport/TransportReceiverInterface.h>

namespace ros2vtk {
namespace wire {

namespace rtps = eprosima::fastrtps::rtps;
namespace fdrtps = eprosima::fastdds::rtps;

bool ReceptionGate::hold(fdrtps::TransportReceiverInterface* receiver, const rtps::octet* data,
  uint32_t size, const rtps::Locator_t& local, const rtps::Locator_t& remote)
{
  if (open_.load(std::memory_order_acquire))
  {
    return false;
  }
  // Closed, or open() is handing the held datagrams on: wait for it, so this one follows them.
  std::lock_guard<std::mutex> lock(mutex_);
  if (open_.load(std::memory_order_relaxed))
  {
    return false;
  }
  if (held_bytes_ + size <= kMaxHeldBytes)
  {
    held_.push_back(
      Datagram{ receiver, std::vector<rtps::octet>(data, data + size), local, remote });
    held_bytes_ += size;
  }
  return true; // over the bound: dropped, as Fast DDS would have
}

size_t ReceptionGate::open()
{
  // Held under the lock: a datagram arriving meanwhile waits in hold() and follows the held ones.
  std::lock_guard<std::mutex> lock(mutex_);
  for (const Datagram& datagram : held_)
  {
    datagram.receiver->OnDataReceived(datagram.data.data(),
      static_cast<uint32_t>(datagram.data.size()), datagram.local, datagram.remote);
  }
  const size_t count = held_.size();
  held_.clear();
  held_.shrink_to_fit();
  held_bytes_ = 0;
  open_.store(true, std::memory_order_release);
  return count;
}

void ReceptionGate::observe(Observer observer)
{
  std::lock_guard<std::mutex> lock(observer_mutex_);
  observed_.store(static_cast<bool>(observer), std::memory_order_release);
  observer_ = std::move(observer);
}

void ReceptionGate::call_observer(const rtps::octet* data, uint32_t size)
{
  std::lock_guard<std::mutex> lock(observer_mutex_);
  if (observer_)
  {
    observer_(data, size);
  }
}

size_t ReceptionGate::held() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return held_.size();
}

GatedTransportDescriptor::GatedTransportDescriptor(
  std::shared_ptr<fdrtps::TransportDescriptorInterface> low)
  : ChainingTransportDescriptor(std::move(low))
{
}

fdrtps::TransportInterface* GatedTransportDescriptor::create_transport() const
{
  return new GatedTransport(*this);
}

GatedTransport::GatedTransport(const GatedTransportDescriptor& descriptor)
  : ChainingTransport(descriptor)
  , descriptor_(descriptor)
{
}

bool GatedTransport::send(rtps::SenderResource* low_sender_resource, const rtps::octet* send_buffer,
  uint32_t send_buffer_size, rtps::LocatorsIterator* destination_locators_begin,
  rtps::LocatorsIterator* destination_locators_end,
  const std::chrono::steady_clock::time_point& timeout)
{
  return low_sender_resource->send(
    send_buffer, send_buffer_size, destination_locators_begin, destination_locators_end, timeout);
}

void GatedTransport::receive(fdrtps::TransportReceiverInterface* next_receiver,
  const rtps::octet* receive_buffer, uint32_t receive_buffer_size,
  const rtps::Locator_t& local_locator, const rtps::Locator_t& remote_locator)
{
  descriptor_.gate->seen(receive_buffer, receive_buffer_size);
  if (!descriptor_.gate->hold(
        next_receiver, receive_buffer, receive_buffer_size, local_locator, remote_locator))
  {
    next_receiver->OnDataReceived(
      receive_buffer, receive_buffer_size, local_locator, remote_locator);
  }
}

fdrtps::TransportDescriptorInterface* GatedTransport::get_configuration()
{
  return &descriptor_;
}

} // namespace wire
} // namespace ros2vtk
