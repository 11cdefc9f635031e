// ros2vtk — a ROS 2 subscription (DataReader on `rt/<topic>`).
#include "SubscriptionImpl.hpp"

#include "TypeAdapter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Names.hpp"

#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include <algorithm>
#include <chrono>

namespace ros2vtk {
namespace wire {

namespace dds = eprosima::fastdds::dds;

//------------------------------------------------------------------------------
MessagePtr::MessagePtr(const MessageTypeSupport* type, void* message)
  : type_(type)
  , message_(message)
{
}

MessagePtr::~MessagePtr()
{
  if (message_)
  {
    type_->destroy(message_);
  }
}

MessagePtr::MessagePtr(MessagePtr&& other) noexcept
  : source_timestamp_ns(other.source_timestamp_ns)
  , reception_timestamp_ns(other.reception_timestamp_ns)
  , publisher_gid(other.publisher_gid)
  , type_(other.type_)
  , message_(other.message_)
{
  other.message_ = nullptr;
}

MessagePtr& MessagePtr::operator=(MessagePtr&& other) noexcept
{
  if (this != &other)
  {
    if (message_)
    {
      type_->destroy(message_);
    }
    type_ = other.type_;
    message_ = other.message_;
    source_timestamp_ns = other.source_timestamp_ns;
    reception_timestamp_ns = other.reception_timestamp_ns;
    publisher_gid = other.publisher_gid;
    other.message_ = nullptr;
  }
  return *this;
}

//------------------------------------------------------------------------------
std::unique_ptr<Subscription::Impl> Subscription::Impl::create(Participant::Impl& owner,
  const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error)
{
  auto impl = std::make_unique<Impl>(owner, type, topic, qos);
  impl->dds_topic = owner.acquire_topic(topic_to_dds(topic), type, error);
  if (!impl->dds_topic)
  {
    return nullptr;
  }
  impl->queue_limit = std::max<size_t>(qos.depth, 1000);
  impl->reader = owner.subscriber->create_datareader(impl->dds_topic,
    make_reader_qos(qos, type.type_hash), impl.get(),
    dds::StatusMask::data_available() << dds::StatusMask::requested_incompatible_qos());
  if (!impl->reader)
  {
    if (error)
    {
      *error = "Fast DDS refused a reader on " + topic + " with QoS " + qos.to_string();
    }
    return nullptr;
  }
  owner.add_local_endpoint(impl->reader->guid(), false, topic_to_dds(topic), type.dds_type_name);
  return impl;
}

Subscription::Impl::Impl(
  Participant::Impl& owner_, const MessageTypeSupport& type_, std::string topic_, QoS qos_)
  : owner(owner_)
  , type(type_)
  , topic(std::move(topic_))
  , qos(qos_)
{
}

Subscription::Impl::~Impl()
{
  if (reader)
  {
    reader->set_listener(nullptr);
    owner.remove_local_endpoint(reader->guid());
    owner.subscriber->delete_datareader(reader);
  }
  if (dds_topic)
  {
    owner.release_topic(dds_topic);
  }
}

void Subscription::Impl::on_data_available(dds::DataReader* data_reader)
{
  ReceivedSample sample;
  dds::SampleInfo info;
  bool queued = false;
  bool to_queue = false; // some sample went to the queue (not to a sink)
  bool rejected_any = false;
  while (data_reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK)
  {
    if (!info.valid_data)
    {
      continue;
    }
    if (!sample.valid)
    {
      ++rejected;
      rejected_any = true;
      std::lock_guard<std::mutex> lock(mutex);
      last_rejection = sample.error;
      continue;
    }
    MessagePtr message(&type, sample.message);
    sample.message = nullptr;
    message.source_timestamp_ns = info.source_timestamp.to_ns();
    message.publisher_gid = to_gid(info.sample_identity.writer_guid());
    message.reception_timestamp_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::system_clock::now().time_since_epoch())
                                       .count();
    ++received;
    std::shared_ptr<const Subscription::Sink> consumer;
    {
      std::lock_guard<std::mutex> lock(mutex);
      consumer = sink;
      if (!consumer)
      {
        to_queue = true;
        queue.push_back(std::move(message));
        while (queue.size() > queue_limit)
        {
          queue.pop_front();
          ++dropped;
        }
      }
    }
    if (consumer)
    {
      (*consumer)(std::move(message));
    }
    queued = true;
  }
  if (sample.message)
  {
    type.destroy(sample.message);
  }
  if (queued || rejected_any)
  {
    // Handed to a sink: the spin has nothing to take from this subscription's queue.
    owner.wake_up.notify(to_queue || rejected_any);
  }
}

//------------------------------------------------------------------------------
Subscription::Subscription(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

Subscription::~Subscription() = default;

size_t Subscription::take(std::vector<MessagePtr>& out)
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const size_t count = impl_->queue.size();
  for (auto& message : impl_->queue)
  {
    out.push_back(std::move(message));
  }
  impl_->queue.clear();
  return count;
}

void Subscription::set_sink(Sink sink)
{
  std::shared_ptr<const Sink> consumer;
  if (sink)
  {
    consumer = std::make_shared<const Sink>(std::move(sink));
  }
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->sink = std::move(consumer);
}

size_t Subscription::pending() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->queue.size();
}

void Subscription::Impl::on_requested_incompatible_qos(
  dds::DataReader*, const dds::RequestedIncompatibleQosStatus& status)
{
  {
    std::lock_guard<std::mutex> lock(mutex);
    last_incompatible_policy = qos_policy_name(status.last_policy_id);
  }
  incompatible = status.total_count;
}

uint64_t Subscription::incompatible_qos_count() const
{
  return impl_->incompatible;
}

std::string Subscription::last_incompatible_qos_policy() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->last_incompatible_policy;
}

uint64_t Subscription::rejected_count() const
{
  return impl_->rejected.load();
}

std::string Subscription::last_rejection() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->last_rejection;
}

uint64_t Subscription::dropped_count() const
{
  return impl_->dropped.load();
}

uint64_t Subscription::received_count() const
{
  return impl_->received.load();
}

void Subscription::set_queue_limit(size_t limit)
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->queue_limit = std::max<size_t>(limit, 1);
}

const std::string& Subscription::topic() const
{
  return impl_->topic;
}

const MessageTypeSupport& Subscription::type() const
{
  return impl_->type;
}

const QoS& Subscription::qos() const
{
  return impl_->qos;
}

size_t Subscription::matched_publications() const
{
  dds::SubscriptionMatchedStatus status;
  impl_->reader->get_subscription_matched_status(status);
  return static_cast<size_t>(status.current_count);
}

} // namespace wire
} // namespace ros2vtk
