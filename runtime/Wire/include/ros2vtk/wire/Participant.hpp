// ros2vtk — one ROS 2 node on the wire: a Fast DDS DomainParticipant that behaves as
// rmw_fastrtps does, so `ros2 node list`, rclpy and rclcpp see and talk to it.
#ifndef ros2vtk_wire_Participant_hpp
#define ros2vtk_wire_Participant_hpp

#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Rosout.hpp"
#include "ros2vtk/wire/WakeUp.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ros2vtk {
namespace wire {

struct MessageTypeSupport;
struct ServiceTypeSupport;
class NodeTypeCache;
class Publisher;
class ServiceClient;
class ServiceServer;
class Subscription;

/// Where discovery looks for peers (ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_LOCALHOST_ONLY).
enum class DiscoveryRange : uint8_t
{
  Subnet,
  Localhost,
  Off
};

struct ParticipantOptions
{
  int domain_id = 0;
  DiscoveryRange range = DiscoveryRange::Subnet;
  /// Hosts to discover by unicast besides the range (ROS_STATIC_PEERS, as ROS 2 Jazzy and later:
  /// IPv4 addresses or host names), for networks that drop multicast.
  std::vector<std::string> static_peers;
  /// UDP send and receive socket buffer size. A 640x480 rgb8 image (921 KB) is ~15 datagrams
  /// of 64 KB; the kernel's default 208 KB receive buffer drops the tail of a burst, and the
  /// reliable writer repairs it only after a NACK round (docs/benchmarks.md, "where the time
  /// goes"). The kernel caps it at net.core.rmem_max / wmem_max. 0 keeps the OS default.
  /// ROS2VTK_SOCKET_BUFFER_BYTES overrides it (the benchmarks' same-run baseline uses 0).
  uint32_t socket_buffer_bytes = 4u * 1024u * 1024u;
  /// Fast DDS discovery servers (ROS_DISCOVERY_SERVER: "host:port;host:port", the position in
  /// the list is the server id, as Fast DDS reads it; empty: no server). The participant is
  /// then a discovery client of them, with no multicast.
  std::string discovery_servers;
  /// ROS_SUPER_CLIENT=TRUE (as rmw_fastrtps): a super client, which the servers tell about the
  /// whole graph (node and topic lists), not only about the endpoints it matches.
  bool super_client = false;
  /// Reads ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_LOCALHOST_ONLY, ROS_STATIC_PEERS
  /// (';'-separated; rmw's limit of 32 peers), ROS_DISCOVERY_SERVER, ROS_SUPER_CLIENT
  /// and ROS2VTK_SOCKET_BUFFER_BYTES.
  static ParticipantOptions from_environment();
};

/// A remote or local endpoint as the ROS graph reports it.
struct TopicInfo
{
  std::string name;               ///< ROS name, "/chatter"
  std::vector<std::string> types; ///< ROS types, "std_msgs/msg/String"
};

/// One remote publisher or subscription of a topic (rclpy's get_publishers_info_by_topic and
/// get_subscriptions_info_by_topic, the parts we need).
struct EndpointInfo
{
  std::string node_name;      ///< "" while its node's ros_discovery_info has not arrived
  std::string node_namespace; ///< "/" or "/robot1"
  std::string ros_type;       ///< "pkg/msg/Type"
  std::string type_hash;      ///< USER_DATA typehash ("RIHS01_..."), "" when it sent none
};
using PublisherInfo = EndpointInfo;

/// One ROS 2 node. Creating it announces the node on `ros_discovery_info`; every publisher,
/// subscription, service and client it creates is added to that announcement.
class Participant
{
public:
  /// Returns nullptr and fills `error` when the name is not a valid ROS node name or DDS
  /// refuses to create the participant.
  static std::unique_ptr<Participant> create(const std::string& node_name,
    const std::string& node_namespace, const ParticipantOptions& options, std::string* error);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  const std::string& name() const;
  const std::string& node_namespace() const; ///< "/" or "/robot1"
  std::string fully_qualified_name() const;  ///< "/robot1/slicer"

  /// Expands a topic or service name as rcl does (absolute, relative, `~`).
  bool resolve_name(const std::string& name, std::string& resolved, std::string* error) const;

  /// nullptr (and `error`) on an invalid topic name or a DDS failure.
  std::unique_ptr<Publisher> create_publisher(
    const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error);
  std::unique_ptr<Subscription> create_subscription(
    const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error);

  /// Services: the server uses `qos` for its request reader and reply writer; the parameter
  /// services of rclcpp use QoS::parameters(), everything else QoS::services().
  std::unique_ptr<ServiceServer> create_service_server(const ServiceTypeSupport& type,
    const std::string& service_name, const QoS& qos, std::string* error);
  std::unique_ptr<ServiceClient> create_service_client(const ServiceTypeSupport& type,
    const std::string& service_name, const QoS& qos, std::string* error);

  /// The types this node's endpoints use, with their REP 2011 descriptions (what its
  /// ~/get_type_description serves, TypeDescriptionService).
  const NodeTypeCache& type_cache() const;
  /// For types no single endpoint carries: an action client or server registers its action
  /// type (pkg/action/X) here while it exists, as rcl_action_client_init and
  /// rcl_action_server_init do (rcl_node_type_cache_register_type). A registration must not
  /// outlive this participant.
  NodeTypeCache& type_cache();

  /// Raised whenever any subscription, server or client of this node queued data.
  WakeUp& wake_up();

  /// Shows `observer` every datagram this participant's transports read, on Fast DDS's
  /// receiving thread, before Fast DDS parses it; an empty function stops it. For measurement:
  /// Fast DDS reports a sample only once it is whole, so a benchmark times a large sample's
  /// first and last fragment here. The observer must return quickly and must not call back into
  /// this participant.
  using DatagramObserver = std::function<void(const uint8_t* data, size_t size)>;
  void set_datagram_observer(DatagramObserver observer);

  /// The ROS graph as seen from here (from DDS discovery and ros_discovery_info).
  std::vector<std::pair<std::string, std::string>> node_names_and_namespaces() const;
  std::vector<TopicInfo> topic_names_and_types() const;
  size_t count_publishers(const std::string& topic) const;
  /// The publishers of other participants on `topic` (a name this node resolves).
  std::vector<PublisherInfo> publishers_info(const std::string& topic) const;
  size_t count_subscribers(const std::string& topic) const;
  /// The subscriptions of other participants on `topic` (a name this node resolves).
  std::vector<EndpointInfo> subscribers_info(const std::string& topic) const;
  /// The nodes ("/ns/name") publishing `topic`, sorted; "?" stands for writers that no node's
  /// ros_discovery_info announcement lists (yet).
  std::vector<std::string> publisher_node_names(const std::string& topic) const;
  /// The node ("/ns/name") whose ros_discovery_info announcement lists the writer `gid` (this
  /// node for its own writers); "" when none does (yet).
  std::string node_of_writer(const std::array<uint8_t, 16>& gid) const;

  /// Link status: remote participants (other processes' nodes, on any host) discovered and not
  /// yet removed, and how many of them were dropped because their lease expired (silence
  /// beyond the lease duration, e.g. a cut network) since this participant was created.
  size_t remote_participant_count() const;
  uint64_t dropped_participant_count() const;

  /// 16-byte DDS GUID of the participant (the rmw gid).
  std::vector<uint8_t> gid() const;

  /// This node's /rosout (nullptr when DDS refused the publisher: the node works without it).
  Rosout* rosout() const;

  class Impl;
  Impl& impl() { return *impl_; }

private:
  explicit Participant(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<Rosout> rosout_; // after impl_: destroyed first, before the DDS entities
};

} // namespace wire
} // namespace ros2vtk

#endif
