// ros2vtk — one ROS 2 node as a Fast DDS 2.9 DomainParticipant, configured the way
// rmw_fastrtps configures its participants (WIRE_NOTES §2, §3).
#include "ParticipantImpl.hpp"

#include "GatedTransport.hpp"
#include "LoopbackTransport.hpp"
#include "PublisherImpl.hpp"
#include "ShippedTypes.hpp"
#include "SubscriptionImpl.hpp"
#include "TypeAdapter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Names.hpp"
#include "ros2vtk/wire/Publisher.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastrtps/attributes/LibrarySettingsAttributes.h>
#include <fastrtps/xmlparser/XMLProfileManager.h>
#include <fastdds/rtps/attributes/ServerAttributes.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>

namespace ros2vtk {
namespace wire {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

namespace {

// Fast DDS 2.9 may deliver a sample in-process to a reader of this process that is being (or
// was just) deleted: segfaults in StatefulWriter::deliver_sample_to_intraprocesses /
// intraprocess_delivery, seen on a loaded machine when two nodes of one process are destroyed one
// after the other (a discovery sample), and when a node publishes /clock while another switches
// use_sim_time (user data; eProsima/Fast-DDS#1235 fixed one path of it). Keeping in-process
// delivery for user data only turned the first into the second. So our participants of one
// process talk over the loopback like any other (one copy more, for a case users rarely have).
// Set once, before the first participant, after the default XML profiles (which may set it).
void use_no_intraprocess_delivery()
{
  static std::once_flag once;
  std::call_once(once, [] {
    dds::DomainParticipantFactory::get_instance()->load_profiles();
    eprosima::fastrtps::LibrarySettingsAttributes settings =
      eprosima::fastrtps::xmlparser::XMLProfileManager::library_settings();
    settings.intraprocess_delivery = eprosima::fastrtps::INTRAPROCESS_OFF;
    eprosima::fastrtps::xmlparser::XMLProfileManager::library_settings(settings);
  });
}

// RTPS well-known ports (spec 9.6.1.1, Fast DDS defaults): PB + DG * domain + offset + PG * id.
constexpr uint32_t kPortBase = 7400;
constexpr uint32_t kDomainGain = 250;
constexpr uint32_t kMetatrafficUnicastOffset = 10;
constexpr uint32_t kParticipantGain = 2;
constexpr int32_t kMaxParticipantId =
  119; // (DG - offset) / PG - 1: ids above reach the next domain
// LOCALHOST discovery sends to the ports of these participant ids (as rmw_fastrtps does); so do
// static peers.
constexpr uint32_t kLocalhostPeers = 32;
constexpr size_t kMaxStaticPeers = 32; // rmw's RMW_DISCOVERY_OPTIONS_STATIC_PEERS_MAX_LENGTH

uint32_t metatraffic_unicast_port(uint32_t domain_id, int32_t participant_id)
{
  return kPortBase + kDomainGain * domain_id + kMetatrafficUnicastOffset +
    kParticipantGain * static_cast<uint32_t>(participant_id);
}

// An IPv4 address as given, or the first one a host name resolves to ("" when none).
std::string ipv4_of(const std::string& host)
{
  using eprosima::fastrtps::rtps::IPLocator;
  if (IPLocator::isIPv4(host))
  {
    return host;
  }
  const std::set<std::string> addresses = IPLocator::resolveNameDNS(host).first;
  return addresses.empty() ? std::string() : *addresses.begin();
}

bool udp_port_is_free(uint32_t port, bool loopback_only)
{
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0)
  {
    return true; // cannot tell: let Fast DDS try
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  // A loopback-only participant probes on 127.0.0.1: it never binds elsewhere, even briefly.
  address.sin_addr.s_addr = htonl(loopback_only ? INADDR_LOOPBACK : INADDR_ANY);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool free = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  ::close(fd);
  return free;
}

// Fast DDS 2.9 numbers the participants of a process from a counter that never goes back, and a
// participant listens on the port of its number. Once a process had created 32 participants (a
// scene file reopened 32 times), its new ones listened outside the ports LOCALHOST discovery
// probes: two of them could no longer find each other, nor a peer numbered above 31 find them.
// Fast DDS cannot be asked for the lowest free number, so it is found here: the lowest id whose
// metatraffic port no participant (of any process) holds. -1 (Fast DDS's choice) when none is.
int32_t lowest_free_participant_id(uint32_t domain_id, bool loopback_only)
{
  for (int32_t id = 0; id <= kMaxParticipantId; ++id)
  {
    if (udp_port_is_free(metatraffic_unicast_port(domain_id, id), loopback_only))
    {
      return id;
    }
  }
  return -1;
}

bool set_error(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
  return false;
}

/// The `typehash=<hash>;` entry of an endpoint's USER_DATA (rmw's key=value; list), or "".
std::string type_hash_of(const dds::UserDataQosPolicy& user_data)
{
  const std::string text(user_data.data_vec().begin(), user_data.data_vec().end());
  const std::string key = "typehash=";
  size_t start = 0;
  while (start < text.size())
  {
    const size_t end = std::min(text.find(';', start), text.size());
    if (text.compare(start, key.size(), key) == 0)
    {
      return text.substr(start + key.size(), std::min<size_t>(end - start - key.size(), 80));
    }
    start = end + 1;
  }
  return std::string();
}

std::vector<rtps::octet> user_data_of(const std::string& text, bool with_nul)
{
  std::vector<rtps::octet> bytes(text.begin(), text.end());
  if (with_nul)
  {
    bytes.push_back(0);
  }
  return bytes;
}

void apply_common_endpoint_qos(const QoS& qos, dds::HistoryQosPolicy& history,
  dds::ReliabilityQosPolicy& reliability, dds::DurabilityQosPolicy& durability)
{
  history.kind =
    qos.history == QoS::History::KeepAll ? dds::KEEP_ALL_HISTORY_QOS : dds::KEEP_LAST_HISTORY_QOS;
  history.depth = static_cast<int32_t>(qos.depth == 0 ? 1 : qos.depth);
  reliability.kind = qos.reliability == QoS::Reliability::Reliable
    ? dds::RELIABLE_RELIABILITY_QOS
    : dds::BEST_EFFORT_RELIABILITY_QOS;
  durability.kind = qos.durability == QoS::Durability::TransientLocal
    ? dds::TRANSIENT_LOCAL_DURABILITY_QOS
    : dds::VOLATILE_DURABILITY_QOS;
}

} // namespace

dds::DataWriterQos make_writer_qos(const QoS& qos, const std::string& type_hash)
{
  dds::DataWriterQos writer_qos = dds::DATAWRITER_QOS_DEFAULT;
  apply_common_endpoint_qos(
    qos, writer_qos.history(), writer_qos.reliability(), writer_qos.durability());
  writer_qos.publish_mode().kind = dds::SYNCHRONOUS_PUBLISH_MODE;
  if (qos.reliability == QoS::Reliability::Reliable)
  {
    // A lost sample is repaired when the reader answers the writer's next heartbeat. Fast DDS's
    // default period (3 s, kept by rmw_fastrtps) holds every later sample of an in-order reliable
    // stream back for seconds after one loss (a Wi-Fi link); rmw_connextdds lowered its vendor's
    // 3 s to 100 ms for this reason (ros2/rmw_connextdds#26). One small message per 100 ms per
    // matched reader, and only while samples are unacknowledged.
    writer_qos.reliable_writer_qos().times.heartbeatPeriod =
      eprosima::fastrtps::Duration_t(0, 100000000);
    // With Fast DDS's default of 0, every write arms the reader proxy's NACK-suppression timer,
    // which wakes the participant's event thread before the sample is sent (strace of
    // bench_publish: one futex wake per write, ahead of its sendto); at 1 kHz that is ~15 us of
    // every sample's latency (docs/benchmarks.md, "pose_1khz"). While armed, the timer stays
    // armed, so later writes do not wake the thread. 5 ms ignores no NACK of a Fast DDS reader:
    // a reader asks for a sample only in answer to a heartbeat sent after it, and answers after
    // its heartbeatResponseDelay (5 ms by default, in Fast DDS 2.9 and 3).
    writer_qos.reliable_writer_qos().times.nackSupressionDuration =
      eprosima::fastrtps::Duration_t(0, 5000000);
  }
  writer_qos.data_sharing().off();
  writer_qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  writer_qos.representation().m_value.clear();
  writer_qos.representation().m_value.push_back(dds::XCDR_DATA_REPRESENTATION);
  if (!type_hash.empty())
  {
    writer_qos.user_data().data_vec(user_data_of("typehash=" + type_hash + ";", false));
  }
  return writer_qos;
}

std::string qos_policy_name(uint32_t policy_id)
{
  switch (policy_id)
  {
    case dds::DURABILITY_QOS_POLICY_ID:
      return "DURABILITY";
    case dds::DEADLINE_QOS_POLICY_ID:
      return "DEADLINE";
    case dds::LIVELINESS_QOS_POLICY_ID:
      return "LIVELINESS";
    case dds::RELIABILITY_QOS_POLICY_ID:
      return "RELIABILITY";
    case dds::OWNERSHIP_QOS_POLICY_ID:
      return "OWNERSHIP";
    case dds::DESTINATIONORDER_QOS_POLICY_ID:
      return "DESTINATION_ORDER";
    case dds::DATAREPRESENTATION_QOS_POLICY_ID:
      return "DATA_REPRESENTATION";
    case dds::TYPECONSISTENCYENFORCEMENT_QOS_POLICY_ID:
      return "TYPE_CONSISTENCY";
    default:
      return "policy " + std::to_string(policy_id);
  }
}

dds::DataReaderQos make_reader_qos(const QoS& qos, const std::string& type_hash)
{
  dds::DataReaderQos reader_qos = dds::DATAREADER_QOS_DEFAULT;
  apply_common_endpoint_qos(
    qos, reader_qos.history(), reader_qos.reliability(), reader_qos.durability());
  reader_qos.data_sharing().off();
  reader_qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  reader_qos.type_consistency().representation.m_value.clear();
  reader_qos.type_consistency().representation.m_value.push_back(dds::XCDR_DATA_REPRESENTATION);
  if (!type_hash.empty())
  {
    reader_qos.user_data().data_vec(user_data_of("typehash=" + type_hash + ";", false));
  }
  return reader_qos;
}

//------------------------------------------------------------------------------
ParticipantOptions ParticipantOptions::from_environment()
{
  ParticipantOptions options;
  if (const char* domain = std::getenv("ROS_DOMAIN_ID"))
  {
    char* end = nullptr;
    const long value = std::strtol(domain, &end, 10);
    if (end != domain && *end == '\0' && value >= 0 && value <= 232)
    {
      options.domain_id = static_cast<int>(value);
    }
  }
  const char* range = std::getenv("ROS_AUTOMATIC_DISCOVERY_RANGE");
  const char* localhost_only = std::getenv("ROS_LOCALHOST_ONLY");
  if (range && std::strcmp(range, "LOCALHOST") == 0)
  {
    options.range = DiscoveryRange::Localhost;
  }
  else if (range && std::strcmp(range, "OFF") == 0)
  {
    options.range = DiscoveryRange::Off;
  }
  else if ((!range || range[0] == '\0') && localhost_only && std::strcmp(localhost_only, "1") == 0)
  {
    options.range = DiscoveryRange::Localhost;
  }
  if (const char* bytes = std::getenv("ROS2VTK_SOCKET_BUFFER_BYTES"))
  {
    char* end = nullptr;
    const unsigned long value = std::strtoul(bytes, &end, 10);
    if (end != bytes && *end == '\0' && value <= (1ul << 30))
    {
      options.socket_buffer_bytes = static_cast<uint32_t>(value);
    }
    else
    {
      std::fprintf(stderr,
        "[ros2vtk] ROS2VTK_SOCKET_BUFFER_BYTES='%s' is not a byte count <= 1 GiB; ignored\n",
        bytes);
    }
  }
  if (const char* peers = std::getenv("ROS_STATIC_PEERS"))
  {
    std::string list(peers);
    for (size_t start = 0; start <= list.size() && options.static_peers.size() < kMaxStaticPeers;)
    {
      size_t end = list.find(';', start);
      end = end == std::string::npos ? list.size() : end;
      if (end > start)
      {
        options.static_peers.push_back(list.substr(start, end - start));
      }
      start = end + 1;
    }
  }
  if (const char* servers = std::getenv("ROS_DISCOVERY_SERVER"))
  {
    options.discovery_servers = servers;
  }
  if (const char* super_client = std::getenv("ROS_SUPER_CLIENT"))
  {
    const std::string value = super_client;
    options.super_client = value == "TRUE" || value == "true" || value == "True" || value == "1";
  }
  return options;
}

//------------------------------------------------------------------------------
Participant::Impl::Impl(std::string node_name, std::string node_namespace)
  : name(std::move(node_name))
  , ns(std::move(node_namespace))
{
}

Participant::Impl::~Impl()
{
  if (!participant)
  {
    return;
  }
  graph.shutdown();
  participant->set_listener(nullptr);
  participant->delete_contained_entities();
  dds::DomainParticipantFactory::get_instance()->delete_participant(participant);
}

bool Participant::Impl::init(const ParticipantOptions& options, std::string* error)
{
  dds::DomainParticipantQos qos = dds::PARTICIPANT_QOS_DEFAULT;
  qos.name("/");
  // rmw_fastrtps writes "enclave=/;" plus a NUL (WIRE_NOTES §3.1).
  qos.user_data().data_vec(user_data_of("enclave=/;", true));

  // UDPv4 only: shared memory between Fast DDS 2.9 and 3.x does not interoperate (segment
  // names changed), and peers would route same-host traffic there and lose it (§2.7.3).
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  qos.transport().use_builtin_transports = false;
  udp->sendBufferSize = options.socket_buffer_bytes;
  udp->receiveBufferSize = options.socket_buffer_bytes;
  qos.transport().send_socket_buffer_size = options.socket_buffer_bytes;
  qos.transport().listen_socket_buffer_size = options.socket_buffer_bytes;
  if (options.range != DiscoveryRange::Subnet)
  {
    udp->maxInitialPeersRange = 32;
    // A unicast metatraffic locator (port chosen by Fast DDS) stops the default multicast one.
    rtps::Locator_t unicast;
    unicast.kind = LOCATOR_KIND_UDPv4;
    qos.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(unicast);
    if (options.range == DiscoveryRange::Localhost)
    {
      // The well-known metatraffic unicast ports of participants 0..31 on this domain, as
      // rmw's LOCALHOST mode does.
      for (uint32_t participant_id = 0; participant_id < kLocalhostPeers; ++participant_id)
      {
        rtps::Locator_t peer;
        peer.kind = LOCATOR_KIND_UDPv4;
        eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, 127, 0, 0, 1);
        peer.port = metatraffic_unicast_port(
          static_cast<uint32_t>(options.domain_id), static_cast<int32_t>(participant_id));
        qos.wire_protocol().builtin.initialPeersList.push_back(peer);
      }
    }
  }
  // Static peers: their well-known metatraffic ports get our announcements by unicast, so two
  // hosts find each other where multicast is dropped (as rmw_fastrtps does with ROS_STATIC_PEERS).
  for (const std::string& host : options.static_peers)
  {
    const std::string address = ipv4_of(host);
    if (address.empty())
    {
      std::fprintf(
        stderr, "[ros2vtk] ROS_STATIC_PEERS: cannot resolve '%s'; ignored\n", host.c_str());
      continue;
    }
    for (uint32_t participant_id = 0; participant_id < kLocalhostPeers; ++participant_id)
    {
      rtps::Locator_t peer;
      peer.kind = LOCATOR_KIND_UDPv4;
      eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, address);
      peer.port = metatraffic_unicast_port(
        static_cast<uint32_t>(options.domain_id), static_cast<int32_t>(participant_id));
      qos.wire_protocol().builtin.initialPeersList.push_back(peer);
    }
  }
  if (!options.static_peers.empty() && options.range == DiscoveryRange::Subnet)
  {
    // Initial peers replace Fast DDS's default one (the SPDP multicast group): keep announcing
    // there too, so SUBNET discovery still finds the hosts that are not listed.
    rtps::Locator_t multicast;
    multicast.kind = LOCATOR_KIND_UDPv4;
    eprosima::fastrtps::rtps::IPLocator::setIPv4(multicast, 239, 255, 0, 1);
    multicast.port = kPortBase + kDomainGain * static_cast<uint32_t>(options.domain_id);
    qos.wire_protocol().builtin.initialPeersList.push_back(multicast);
  }
  if (options.discovery_servers.find("TCPv") != std::string::npos)
  {
    // Fast DDS 3 (and 2.13+) read "TCPv4:[host]:port" here; 2.9's parser has no TCP, and a TCP
    // discovery server would need TCP transports configured in code (docs/networking.md).
    return set_error(error,
      "ROS_DISCOVERY_SERVER '" + options.discovery_servers +
        "': TCP discovery servers are not supported with Fast DDS 2.9; run the server on "
        "UDP (fastdds discovery -i 0 -l HOST -p PORT) and list it as HOST:PORT");
  }
  if (!options.discovery_servers.empty())
  {
    // A discovery client: Fast DDS 2.9 reads ROS_DISCOVERY_SERVER itself when the participant
    // is SIMPLE (it becomes a CLIENT of those servers). A super client (ROS_SUPER_CLIENT, read
    // by rmw_fastrtps, not by Fast DDS 2.9) is set here from the same list.
    if (options.super_client)
    {
      auto& discovery = qos.wire_protocol().builtin.discovery_config;
      discovery.discoveryProtocol = rtps::DiscoveryProtocol_t::SUPER_CLIENT;
      if (!eprosima::fastdds::rtps::load_environment_server_info(
            options.discovery_servers, discovery.m_DiscoveryServers))
      {
        return set_error(error,
          "ROS_DISCOVERY_SERVER '" + options.discovery_servers +
            "' is not a list of host:port (';'-separated, position = server id)");
      }
    }
    else
    {
      std::list<eprosima::fastdds::rtps::RemoteServerAttributes> servers;
      if (!eprosima::fastdds::rtps::load_environment_server_info(
            options.discovery_servers, servers))
      {
        return set_error(error,
          "ROS_DISCOVERY_SERVER '" + options.discovery_servers +
            "' is not a list of host:port (';'-separated, position = server id)");
      }
    }
  }
  // Static peers and discovery servers name other hosts on purpose: they keep the plain transport.
  const bool loopback_only =
    (options.range == DiscoveryRange::Localhost || options.range == DiscoveryRange::Off) &&
    options.static_peers.empty() && options.discovery_servers.empty();
  // Either way reception waits behind a gate until the participant is enabled, so that a peer's
  // answer to our first announcement is not dropped (GatedTransport.hpp).
  std::shared_ptr<GatedTransportDescriptor> transport;
  if (loopback_only)
  {
    // Sockets bound to 127.0.0.1 only and only loopback locators announced; peers' same-host
    // locators are reached through 127.0.0.1 (LoopbackTransport.hpp). Static peers name other
    // hosts on purpose, so they keep the plain transport.
    transport = std::make_shared<LoopbackTransportDescriptor>(udp);
  }
  else
  {
    transport = std::make_shared<GatedTransportDescriptor>(udp);
  }
  qos.transport().user_transports.push_back(transport);
  qos.wire_protocol().participant_id =
    lowest_free_participant_id(static_cast<uint32_t>(options.domain_id), loopback_only);

  use_no_intraprocess_delivery();
  const dds::StatusMask mask = dds::StatusMask::none();
  participant = dds::DomainParticipantFactory::get_instance()->create_participant(
    options.domain_id, qos, this, mask);
  if (!participant)
  {
    return set_error(error,
      "Fast DDS could not create a participant on domain " + std::to_string(options.domain_id));
  }
  transport->gate->open(); // enabled: its receivers are registered (GatedTransport.hpp)
  reception_gate = transport->gate;
  publisher = participant->create_publisher(dds::PUBLISHER_QOS_DEFAULT);
  subscriber = participant->create_subscriber(dds::SUBSCRIBER_QOS_DEFAULT);
  if (!publisher || !subscriber)
  {
    return set_error(error, "Fast DDS could not create a publisher/subscriber");
  }
  const MessageTypeSupport& info_type =
    shipped_message_type("rmw_dds_common/msg/ParticipantEntitiesInfo");
  dds::Topic* graph_topic = acquire_topic("ros_discovery_info", info_type, error);
  if (!graph_topic)
  {
    return false;
  }
  return graph.init(participant, publisher, subscriber, graph_topic, ns, name, error);
}

dds::Topic* Participant::Impl::acquire_topic(
  const std::string& dds_name, const MessageTypeSupport& type, std::string* error)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto existing = topics_.find(dds_name);
  if (existing != topics_.end())
  {
    if (existing->second.topic->get_type_name() != type.dds_type_name)
    {
      set_error(error,
        "topic '" + dds_name + "' already has type " +
          dds_type_to_ros(existing->second.topic->get_type_name()) + " in this node, not " +
          type.ros_type);
      return nullptr;
    }
    ++existing->second.references;
    return existing->second.topic;
  }
  if (types_.find(type.dds_type_name) == types_.end())
  {
    dds::TypeSupport support(new TypeAdapter(type));
    if (support.register_type(participant) != ReturnCode_t::RETCODE_OK)
    {
      set_error(error, std::string("could not register type ") + type.ros_type);
      return nullptr;
    }
    types_.emplace(type.dds_type_name, support);
  }
  dds::Topic* topic =
    participant->create_topic(dds_name, type.dds_type_name, dds::TOPIC_QOS_DEFAULT);
  if (!topic)
  {
    set_error(error, "could not create DDS topic '" + dds_name + "'");
    return nullptr;
  }
  topics_[dds_name] = TopicEntry{ topic, 1 };
  return topic;
}

void Participant::Impl::release_topic(dds::Topic* topic)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = topics_.find(topic->get_name());
  if (it != topics_.end() && --it->second.references == 0)
  {
    participant->delete_topic(topic);
    topics_.erase(it);
  }
}

void Participant::Impl::add_local_endpoint(const rtps::GUID_t& guid, bool is_writer,
  const std::string& dds_topic, const std::string& dds_type)
{
  graph.add_local_endpoint(to_gid(guid), is_writer, dds_topic, dds_type);
}

void Participant::Impl::remove_local_endpoint(const rtps::GUID_t& guid)
{
  graph.remove_local_endpoint(to_gid(guid));
}

void Participant::Impl::on_participant_discovery(
  dds::DomainParticipant*, rtps::ParticipantDiscoveryInfo&& info)
{
  const Gid gid = to_gid(info.info.m_guid);
  if (info.status == rtps::ParticipantDiscoveryInfo::DISCOVERED_PARTICIPANT)
  {
    std::lock_guard<std::mutex> lock(peers_mutex);
    remote_participants.insert(gid);
  }
  if (info.status == rtps::ParticipantDiscoveryInfo::REMOVED_PARTICIPANT ||
    info.status == rtps::ParticipantDiscoveryInfo::DROPPED_PARTICIPANT)
  {
    {
      std::lock_guard<std::mutex> lock(peers_mutex);
      if (remote_participants.erase(gid) > 0 &&
        info.status == rtps::ParticipantDiscoveryInfo::DROPPED_PARTICIPANT)
      {
        ++dropped_participants;
      }
    }
    graph.remove_remote_participant(gid);
  }
  if (info.status == rtps::ParticipantDiscoveryInfo::DISCOVERED_PARTICIPANT ||
    info.status == rtps::ParticipantDiscoveryInfo::REMOVED_PARTICIPANT ||
    info.status == rtps::ParticipantDiscoveryInfo::DROPPED_PARTICIPANT)
  {
    // A peer found or lost: the spinner's next Spin reports the new link state (the node fires
    // its LinkStateChangedEvent there, on the spinning thread, never here on a DDS thread).
    wake_up.notify();
  }
}

void Participant::Impl::on_subscriber_discovery(
  dds::DomainParticipant*, rtps::ReaderDiscoveryInfo&& info)
{
  if (info.status == rtps::ReaderDiscoveryInfo::DISCOVERED_READER)
  {
    graph.add_remote_endpoint(to_gid(info.info.guid()), false, info.info.topicName().to_string(),
      info.info.typeName().to_string(), type_hash_of(info.info.m_qos.m_userData));
  }
  else if (info.status == rtps::ReaderDiscoveryInfo::REMOVED_READER)
  {
    graph.remove_remote_endpoint(to_gid(info.info.guid()));
  }
}

void Participant::Impl::on_publisher_discovery(
  dds::DomainParticipant*, rtps::WriterDiscoveryInfo&& info)
{
  if (info.status == rtps::WriterDiscoveryInfo::DISCOVERED_WRITER)
  {
    graph.add_remote_endpoint(to_gid(info.info.guid()), true, info.info.topicName().to_string(),
      info.info.typeName().to_string(), type_hash_of(info.info.m_qos.m_userData));
  }
  else if (info.status == rtps::WriterDiscoveryInfo::REMOVED_WRITER)
  {
    graph.remove_remote_endpoint(to_gid(info.info.guid()));
  }
}

//------------------------------------------------------------------------------
std::unique_ptr<Participant> Participant::create(const std::string& node_name,
  const std::string& node_namespace, const ParticipantOptions& options, std::string* error)
{
  std::string ns;
  if (!validate_node_name(node_name, error) || !normalize_namespace(node_namespace, ns, error))
  {
    return nullptr;
  }
  auto impl = std::make_unique<Impl>(node_name, ns);
  if (!impl->init(options, error))
  {
    return nullptr;
  }
  std::unique_ptr<Participant> participant(new Participant(std::move(impl)));
  std::string rosout_error;
  participant->rosout_ = Rosout::create(*participant, &rosout_error);
  if (!participant->rosout_)
  {
    std::fprintf(
      stderr, "[ros2vtk] node '%s' has no /rosout: %s\n", node_name.c_str(), rosout_error.c_str());
  }
  return participant;
}

Rosout* Participant::rosout() const
{
  return rosout_.get();
}

Participant::Participant(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

Participant::~Participant() = default;

const std::string& Participant::name() const
{
  return impl_->name;
}

const std::string& Participant::node_namespace() const
{
  return impl_->ns;
}

std::string Participant::fully_qualified_name() const
{
  return fully_qualified_node_name(impl_->ns, impl_->name);
}

bool Participant::resolve_name(
  const std::string& name, std::string& resolved, std::string* error) const
{
  return expand_topic_name(name, impl_->name, impl_->ns, resolved, error);
}

std::unique_ptr<Publisher> Participant::create_publisher(
  const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error)
{
  std::string resolved;
  if (!resolve_name(topic, resolved, error))
  {
    return nullptr;
  }
  auto impl = Publisher::Impl::create(*impl_, type, resolved, qos, error);
  if (!impl)
  {
    return nullptr;
  }
  impl->type_registration = impl_->types.add(type.type_hash, type.description);
  return std::unique_ptr<Publisher>(new Publisher(std::move(impl)));
}

std::unique_ptr<Subscription> Participant::create_subscription(
  const MessageTypeSupport& type, const std::string& topic, const QoS& qos, std::string* error)
{
  std::string resolved;
  if (!resolve_name(topic, resolved, error))
  {
    return nullptr;
  }
  auto impl = Subscription::Impl::create(*impl_, type, resolved, qos, error);
  if (!impl)
  {
    return nullptr;
  }
  impl->type_registration = impl_->types.add(type.type_hash, type.description);
  return std::unique_ptr<Subscription>(new Subscription(std::move(impl)));
}

const NodeTypeCache& Participant::type_cache() const
{
  return impl_->types;
}

NodeTypeCache& Participant::type_cache()
{
  return impl_->types;
}

WakeUp& Participant::wake_up()
{
  return impl_->wake_up;
}

void Participant::set_datagram_observer(DatagramObserver observer)
{
  if (impl_->reception_gate)
  {
    impl_->reception_gate->observe(std::move(observer));
  }
}

std::vector<std::pair<std::string, std::string>> Participant::node_names_and_namespaces() const
{
  return impl_->graph.node_names_and_namespaces();
}

std::vector<TopicInfo> Participant::topic_names_and_types() const
{
  return impl_->graph.topic_names_and_types();
}

size_t Participant::count_publishers(const std::string& topic) const
{
  std::string resolved;
  return resolve_name(topic, resolved, nullptr)
    ? impl_->graph.count_endpoints(topic_to_dds(resolved), true)
    : 0;
}

std::vector<PublisherInfo> Participant::publishers_info(const std::string& topic) const
{
  std::string resolved;
  return resolve_name(topic, resolved, nullptr)
    ? impl_->graph.remote_endpoints(topic_to_dds(resolved), true)
    : std::vector<PublisherInfo>();
}

std::vector<EndpointInfo> Participant::subscribers_info(const std::string& topic) const
{
  std::string resolved;
  return resolve_name(topic, resolved, nullptr)
    ? impl_->graph.remote_endpoints(topic_to_dds(resolved), false)
    : std::vector<EndpointInfo>();
}

size_t Participant::count_subscribers(const std::string& topic) const
{
  std::string resolved;
  return resolve_name(topic, resolved, nullptr)
    ? impl_->graph.count_endpoints(topic_to_dds(resolved), false)
    : 0;
}

std::vector<std::string> Participant::publisher_node_names(const std::string& topic) const
{
  std::string resolved;
  return resolve_name(topic, resolved, nullptr)
    ? impl_->graph.publisher_nodes(topic_to_dds(resolved))
    : std::vector<std::string>();
}

std::string Participant::node_of_writer(const std::array<uint8_t, 16>& gid) const
{
  return impl_->graph.node_of_writer(gid);
}

size_t Participant::remote_participant_count() const
{
  std::lock_guard<std::mutex> lock(impl_->peers_mutex);
  return impl_->remote_participants.size();
}

uint64_t Participant::dropped_participant_count() const
{
  std::lock_guard<std::mutex> lock(impl_->peers_mutex);
  return impl_->dropped_participants;
}

std::vector<uint8_t> Participant::gid() const
{
  const Gid gid = to_gid(impl_->participant->guid());
  return std::vector<uint8_t>(gid.begin(), gid.end());
}

} // namespace wire
} // namespace ros2vtk
