// ros2vtk — a chaining transport that holds what arrives until its participant can read it.
//
// Fast DDS 2.9 (and 3.x) sends a new participant's first SPDP announcement (DATA(p)) from
// RTPSParticipantImpl::enable() *before* it registers the participant's message receivers on
// its sockets. A peer on the same host answers that announcement within a millisecond, and
// its answer (its own DATA(p), sent once, to the new participant only) reaches sockets whose
// receive threads run but hand the datagram to no receiver: it is dropped. The peer knows us
// from then on and does not answer our later announcements, so we learn of it only at its next
// periodic announcement (rmw_fastrtps: every 3 s; more when that one is lost too). Every
// endpoint of that peer waits as long: a robot loading from a robot_state_publisher's parameter
// took 0.1 s or 0.6-2.8 s by this race alone (issue 15's load-time investigation; figures in
// docs/robot-state.md).
//
// The gate closes that window: datagrams received before `open()` are kept (copied) and handed
// on by `open()`, which Participant::Impl calls once create_participant has returned (the
// participant is enabled and its receivers are registered). ReceiverResource::OnDataReceived
// serialises on its own mutex, so handing them on from the creating thread is safe.
#ifndef ros2vtk_wire_GatedTransport_hpp
#define ros2vtk_wire_GatedTransport_hpp

#include <fastdds/rtps/transport/ChainingTransport.h>
#include <fastdds/rtps/transport/ChainingTransportDescriptor.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace ros2vtk {
namespace wire {

/// Shared by a descriptor, the transport Fast DDS creates from it, and the participant's owner.
class ReceptionGate
{
public:
  using Observer = std::function<void(const uint8_t* data, size_t size)>;

  /// Shows every datagram to `observer` (on the receiving thread, before Fast DDS parses it);
  /// an empty function stops it. See Participant::set_datagram_observer.
  void observe(Observer observer);
  /// Called by the transport with each datagram it read; costs one atomic load when unobserved.
  void seen(const eprosima::fastrtps::rtps::octet* data, uint32_t size)
  {
    if (observed_.load(std::memory_order_acquire))
    {
      call_observer(data, size);
    }
  }

  /// Keeps a copy of the datagram while the gate is closed (true), else false: pass it on.
  bool hold(eprosima::fastdds::rtps::TransportReceiverInterface* receiver,
    const eprosima::fastrtps::rtps::octet* data, uint32_t size,
    const eprosima::fastrtps::rtps::Locator_t& local,
    const eprosima::fastrtps::rtps::Locator_t& remote);
  /// Hands the held datagrams on, in arrival order, and lets later ones pass. Returns how many.
  size_t open();
  size_t held() const;

private:
  struct Datagram
  {
    eprosima::fastdds::rtps::TransportReceiverInterface* receiver;
    std::vector<eprosima::fastrtps::rtps::octet> data;
    eprosima::fastrtps::rtps::Locator_t local;
    eprosima::fastrtps::rtps::Locator_t remote;
  };
  void call_observer(const eprosima::fastrtps::rtps::octet* data, uint32_t size);

  /// Bounds what a closed gate keeps (a participant is enabled within milliseconds).
  static constexpr size_t kMaxHeldBytes = 8u << 20;
  mutable std::mutex mutex_;
  /// Set by open() once the held datagrams were handed on: read without the lock by every
  /// datagram after that, so an open gate costs no mutex per datagram.
  std::atomic<bool> open_{ false };
  std::atomic<bool> observed_{ false };
  std::mutex observer_mutex_;
  Observer observer_;
  size_t held_bytes_ = 0;
  std::vector<Datagram> held_;
};

struct GatedTransportDescriptor : public eprosima::fastdds::rtps::ChainingTransportDescriptor
{
  explicit GatedTransportDescriptor(
    std::shared_ptr<eprosima::fastdds::rtps::TransportDescriptorInterface> low);

  eprosima::fastdds::rtps::TransportInterface* create_transport() const override;

  std::shared_ptr<ReceptionGate> gate = std::make_shared<ReceptionGate>();
};

/// Passes everything through, except that reception waits for the gate (see the file comment).
class GatedTransport : public eprosima::fastdds::rtps::ChainingTransport
{
public:
  explicit GatedTransport(const GatedTransportDescriptor& descriptor);

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
  GatedTransportDescriptor descriptor_;
};

} // namespace wire
} // namespace ros2vtk

#endif
