// ros2vtk — a transport that sends nothing until its participant can hear the replies.
//
// Fast DDS 2.9 (and 3.x) enables a participant by announcing it first and registering its
// receivers second (RTPSParticipantImpl::enable). A peer that answers our first DATA(p) at once
// (on loopback it does, within a millisecond) can have its answer read from the socket and
// dropped in between. It then knows us and does not answer again: we learn of it only from its
// next periodic announcement, 0 to 3 s later, which made our discovery of a waiting rclpy node
// bimodal (10 ms or 1-3 s; docs/benchmarks.md, "scale"). This chaining transport drops what the
// participant sends before `open` is set (the first initial announcement), so the peer's answer
// comes to the next one, ~100 ms later, when the receivers are in place.
#ifndef ros2vtk_wire_StartGateTransport_hpp
#define ros2vtk_wire_StartGateTransport_hpp

#include <fastdds/rtps/transport/ChainingTransport.h>
#include <fastdds/rtps/transport/ChainingTransportDescriptor.h>

#include <atomic>
#include <memory>

namespace ros2vtk {
namespace wire {

/// Descriptor of the gate around `low_level` (UDPv4 or the loopback transport); `open` is set
/// by the participant once Fast DDS has enabled it.
struct StartGateTransportDescriptor : public eprosima::fastdds::rtps::ChainingTransportDescriptor
{
  StartGateTransportDescriptor(std::shared_ptr<eprosima::fastdds::rtps::TransportDescriptorInterface> low_level,
                               std::shared_ptr<std::atomic<bool>> open);

  eprosima::fastdds::rtps::TransportInterface* create_transport() const override;

  std::shared_ptr<std::atomic<bool>> open;
};

class StartGateTransport : public eprosima::fastdds::rtps::ChainingTransport
{
public:
  explicit StartGateTransport(const StartGateTransportDescriptor& descriptor);

  bool send(eprosima::fastrtps::rtps::SenderResource* low_sender_resource,
            const eprosima::fastrtps::rtps::octet* send_buffer, uint32_t send_buffer_size,
            eprosima::fastrtps::rtps::LocatorsIterator* destination_locators_begin,
            eprosima::fastrtps::rtps::LocatorsIterator* destination_locators_end,
            const std::chrono::steady_clock::time_point& timeout) override;

  void receive(eprosima::fastdds::rtps::TransportReceiverInterface* next_receiver,
               const eprosima::fastrtps::rtps::octet* receive_buffer, uint32_t receive_buffer_size,
               const eprosima::fastrtps::rtps::Locator_t& local_locator,
               const eprosima::fastrtps::rtps::Locator_t& remote_locator) override;

  eprosima::fastdds::rtps::TransportDescriptorInterface* get_configuration() override;

private:
  StartGateTransportDescriptor descriptor_;
};

} // namespace wire
} // namespace ros2vtk

#endif
