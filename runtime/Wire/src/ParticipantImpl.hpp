// ros2vtk — internals of Participant: the DDS entities and the bookkeeping shared by the
// publishers and subscriptions of one ROS node. Not installed; never seen by VTK wrapping.
#ifndef ros2vtk_wire_ParticipantImpl_hpp
#define ros2vtk_wire_ParticipantImpl_hpp

#include "GraphCache.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/QoS.hpp"

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>

namespace ros2vtk {
namespace wire {

class ReceptionGate; // GatedTransport.hpp

/// Translates our QoS into Fast DDS entity QoS the way rmw_fastrtps does (WIRE_NOTES §2.2).
eprosima::fastdds::dds::DataWriterQos make_writer_qos(const QoS& qos, const std::string& type_hash);
eprosima::fastdds::dds::DataReaderQos make_reader_qos(const QoS& qos, const std::string& type_hash);
/// "RELIABILITY", "DURABILITY", ... as ROS tools name the policy that kept endpoints apart.
std::string qos_policy_name(uint32_t policy_id);

class Participant::Impl : public eprosima::fastdds::dds::DomainParticipantListener
{
public:
  Impl(std::string name, std::string ns);
  ~Impl() override;

  bool init(const ParticipantOptions& options, std::string* error);

  /// Topics are shared by the writers and readers of one participant (Fast DDS refuses two
  /// Topic objects with the same name), so they are reference counted here.
  eprosima::fastdds::dds::Topic* acquire_topic(
    const std::string& dds_name, const MessageTypeSupport& type, std::string* error);
  void release_topic(eprosima::fastdds::dds::Topic* topic);

  /// Local endpoints, announced on ros_discovery_info.
  void add_local_endpoint(const eprosima::fastrtps::rtps::GUID_t& guid, bool is_writer,
    const std::string& dds_topic, const std::string& dds_type);
  void remove_local_endpoint(const eprosima::fastrtps::rtps::GUID_t& guid);

  // DomainParticipantListener: remote participants and endpoints, for the graph.
  void on_participant_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
    eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override;
  void on_subscriber_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
    eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override;
  void on_publisher_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
    eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override;

  std::string name;
  std::string ns;
  eprosima::fastdds::dds::DomainParticipant* participant = nullptr;
  eprosima::fastdds::dds::Publisher* publisher = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber = nullptr;
  WakeUp wake_up;
  /// The reception gate of this participant's transport (GatedTransport.hpp), kept for
  /// set_datagram_observer.
  std::shared_ptr<ReceptionGate> reception_gate;
  GraphCache graph;
  NodeTypeCache types; // what ~/get_type_description serves (every endpoint registers)
  // Link status (on_participant_discovery): remote participants alive, and lease expiries.
  mutable std::mutex peers_mutex;
  std::set<Gid> remote_participants;
  uint64_t dropped_participants = 0;

private:
  struct TopicEntry
  {
    eprosima::fastdds::dds::Topic* topic = nullptr;
    int references = 0;
  };
  std::mutex mutex_;
  std::map<std::string, TopicEntry> topics_;
  std::map<std::string, eprosima::fastdds::dds::TypeSupport> types_;
};

} // namespace wire
} // namespace ros2vtk

#endif
