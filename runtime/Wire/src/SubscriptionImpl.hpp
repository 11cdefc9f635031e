// ros2vtk — internals of Subscription: a DataReader whose listener deserializes and queues.
#ifndef ros2vtk_wire_SubscriptionImpl_hpp
#define ros2vtk_wire_SubscriptionImpl_hpp

#include "ParticipantImpl.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>

namespace ros2vtk {
namespace wire {

class Subscription::Impl : public eprosima::fastdds::dds::DataReaderListener
{
public:
  static std::unique_ptr<Impl> create(Participant::Impl& owner, const MessageTypeSupport& type,
    const std::string& topic, const QoS& qos, std::string* error);
  Impl(Participant::Impl& owner, const MessageTypeSupport& type, std::string topic, QoS qos);
  ~Impl() override;

  /// Runs on a Fast DDS thread: take, deserialize (already done by TypeAdapter), enqueue.
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override;
  /// Runs on a Fast DDS thread when a publisher on the topic cannot match (rclpy's "requesting
  /// incompatible QoS"): counted, and the policy remembered for the report.
  void on_requested_incompatible_qos(eprosima::fastdds::dds::DataReader* reader,
    const eprosima::fastdds::dds::RequestedIncompatibleQosStatus& status) override;

  Participant::Impl& owner;
  const MessageTypeSupport& type;
  NodeTypeCache::Registration type_registration; // the type, served while this exists
  std::string topic;
  QoS qos;
  eprosima::fastdds::dds::Topic* dds_topic = nullptr;
  eprosima::fastdds::dds::DataReader* reader = nullptr;

  mutable std::mutex mutex;
  std::deque<MessagePtr> queue;
  /// set_sink()'s consumer; copied under the mutex and called outside it, so replacing it never
  /// races a call in progress.
  std::shared_ptr<const Subscription::Sink> sink;
  size_t queue_limit = 1000;
  std::string last_rejection;
  std::atomic<uint64_t> received{ 0 };
  std::atomic<uint64_t> rejected{ 0 };
  std::atomic<uint64_t> dropped{ 0 };
  std::atomic<uint64_t> incompatible{ 0 };
  std::string last_incompatible_policy; // guarded by mutex
};

} // namespace wire
} // namespace ros2vtk

#endif
