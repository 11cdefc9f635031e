// ros2vtk — internals of Publisher (a DataWriter on `rt/<topic>`).
#ifndef ros2vtk_wire_PublisherImpl_hpp
#define ros2vtk_wire_PublisherImpl_hpp

#include "ParticipantImpl.hpp"
#include "ros2vtk/wire/Publisher.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>

#include <atomic>
#include <memory>

namespace ros2vtk {
namespace wire {

class Publisher::Impl
{
public:
  static std::unique_ptr<Impl> create(Participant::Impl& owner, const MessageTypeSupport& type,
    const std::string& topic, const QoS& qos, std::string* error);
  Impl(Participant::Impl& owner, const MessageTypeSupport& type, std::string topic, QoS qos);
  ~Impl();

  Participant::Impl& owner;
  const MessageTypeSupport& type;
  std::string topic;
  QoS qos;
  eprosima::fastdds::dds::Topic* dds_topic = nullptr;
  eprosima::fastdds::dds::DataWriter* writer = nullptr;
  std::atomic<uint64_t> published{ 0 };
  NodeTypeCache::Registration type_registration; // the type, served while this exists
};

} // namespace wire
} // namespace ros2vtk

#endif
