// ros2vtk — a ROS 2 publisher (DataWriter on `rt/<topic>`).
#include "PublisherImpl.hpp"

#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Names.hpp"

namespace ros2vtk {
namespace wire {

namespace dds = eprosima::fastdds::dds;

std::unique_ptr<Publisher::Impl> Publisher::Impl::create(Participant::Impl& owner,
  const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error)
{
  auto impl = std::make_unique<Impl>(owner, type, topic, qos);
  impl->dds_topic = owner.acquire_topic(topic_to_dds(topic), type, error);
  if (!impl->dds_topic)
  {
    return nullptr;
  }
  impl->writer =
    owner.publisher->create_datawriter(impl->dds_topic, make_writer_qos(qos, type.type_hash));
  if (!impl->writer)
  {
    if (error)
    {
      *error = "Fast DDS refused a writer on " + topic + " with QoS " + qos.to_string();
    }
    return nullptr;
  }
  owner.add_local_endpoint(impl->writer->guid(), true, topic_to_dds(topic), type.dds_type_name);
  return impl;
}

Publisher::Impl::Impl(
  Participant::Impl& owner_, const MessageTypeSupport& type_, std::string topic_, QoS qos_)
  : owner(owner_)
  , type(type_)
  , topic(std::move(topic_))
  , qos(qos_)
{
}

Publisher::Impl::~Impl()
{
  if (writer)
  {
    owner.remove_local_endpoint(writer->guid());
    owner.publisher->delete_datawriter(writer);
  }
  if (dds_topic)
  {
    owner.release_topic(dds_topic);
  }
}

//------------------------------------------------------------------------------
Publisher::Publisher(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

Publisher::~Publisher() = default;

bool Publisher::publish(const void* message)
{
  const bool ok = impl_->writer->write(const_cast<void*>(message));
  if (ok)
  {
    ++impl_->published;
  }
  return ok;
}

bool Publisher::publish_serialized(const uint8_t* data, size_t size)
{
  // Validate and go through the struct so the writer keeps one data type.
  void* message = impl_->type.create();
  const bool ok =
    deserialize_message(impl_->type, data, size, message, nullptr) && publish(message);
  impl_->type.destroy(message);
  return ok;
}

const std::string& Publisher::topic() const
{
  return impl_->topic;
}

const MessageTypeSupport& Publisher::type() const
{
  return impl_->type;
}

const QoS& Publisher::qos() const
{
  return impl_->qos;
}

size_t Publisher::matched_subscriptions() const
{
  dds::PublicationMatchedStatus status;
  impl_->writer->get_publication_matched_status(status);
  return static_cast<size_t>(status.current_count);
}

uint64_t Publisher::published_count() const
{
  return impl_->published.load();
}

} // namespace wire
} // namespace ros2vtk
