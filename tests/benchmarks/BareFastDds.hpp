// The raw Fast DDS 2.9 pieces of the "bare" benchmark programs (bare_echo, bare_publish): a ROS
// type seen as opaque CDR bytes, the participant of rmw / ros2vtk::wire on UDPv4 (ROS_DOMAIN_ID
// and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST honoured the way rmw does), the endpoint QoS of the
// benchmark clients and SIGINT/SIGTERM handling. Nothing of ros2vtk's runtime: only fastrtps and
// fastcdr, so these programs are the floor our stack is compared with.
#ifndef ros2vtk_bench_BareFastDds_hpp
#define ros2vtk_bench_BareFastDds_hpp

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bare {

namespace fdds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

/// Set by SIGINT / SIGTERM once install_signal_handlers() ran.
inline std::atomic<bool> interrupted{ false };

inline void on_signal(int)
{
  interrupted = true;
}

inline void install_signal_handlers()
{
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

/// A ROS type seen as opaque CDR bytes (encapsulation header included): what arrives is what
/// leaves, so the echo costs no conversion at all.
class OpaqueType : public fdds::TopicDataType
{
public:
  explicit OpaqueType(const std::string& dds_name)
  {
    setName(dds_name.c_str());
    m_typeSize = 512; // pool payload size; PREALLOCATED_WITH_REALLOC grows it when needed
    m_isGetKeyDefined = false;
    // Fast DDS 3 (Kilted's rmw) refuses to match 2.x type objects; names alone must match.
    auto_fill_type_object(false);
    auto_fill_type_information(false);
  }
  bool serialize(void* data, rtps::SerializedPayload_t* payload) override
  {
    const auto& bytes = *static_cast<std::vector<uint8_t>*>(data);
    if (bytes.size() < 4 || bytes.size() > payload->max_size)
      return false;
    std::memcpy(payload->data, bytes.data(), bytes.size());
    payload->length = static_cast<uint32_t>(bytes.size());
    // The first two bytes are the encapsulation id (CDR_LE = 0x0001 on the wire).
    payload->encapsulation = bytes[1] == 1 ? CDR_LE : CDR_BE;
    return true;
  }
  bool deserialize(rtps::SerializedPayload_t* payload, void* data) override
  {
    static_cast<std::vector<uint8_t>*>(data)->assign(
      payload->data, payload->data + payload->length);
    return true;
  }
  std::function<uint32_t()> getSerializedSizeProvider(void* data) override
  {
    return [data]() {
      return static_cast<uint32_t>(static_cast<std::vector<uint8_t>*>(data)->size());
    };
  }
  void* createData() override { return new std::vector<uint8_t>(); }
  void deleteData(void* data) override { delete static_cast<std::vector<uint8_t>*>(data); }
  bool getKey(void*, rtps::InstanceHandle_t*, bool) override { return false; }
};

inline int env_int(const char* name, int fallback)
{
  const char* value = std::getenv(name);
  return value && *value ? std::atoi(value) : fallback;
}

/// ROS2VTK_SOCKET_BUFFER_BYTES as ros2vtk::wire reads it (a byte count <= 1 GiB), else `fallback`
/// (ros2vtk's default is 4 MiB).
inline uint32_t socket_buffer_bytes(const char* program, uint32_t fallback = 4u * 1024u * 1024u)
{
  const char* bytes = std::getenv("ROS2VTK_SOCKET_BUFFER_BYTES");
  if (!bytes)
    return fallback;
  char* end = nullptr;
  const unsigned long value = std::strtoul(bytes, &end, 10);
  if (end != bytes && *end == '\0' && value <= (1ul << 30))
    return static_cast<uint32_t>(value);
  std::fprintf(stderr,
    "%s: ROS2VTK_SOCKET_BUFFER_BYTES='%s' is not a byte count <= 1 GiB; ignored\n", program, bytes);
  return fallback;
}

/// The participant QoS of rmw / ros2vtk::wire on LOCALHOST: UDPv4 only (Fast DDS 2.9 and 3 do
/// not share memory segments), unicast discovery to the loopback well-known ports. A non-zero
/// `buffer_bytes` sets the UDP send/receive socket buffers as ros2vtk::wire does (0: Fast DDS's
/// defaults).
inline fdds::DomainParticipantQos participant_qos(
  const std::string& name, int domain, bool localhost, uint32_t buffer_bytes = 0)
{
  fdds::DomainParticipantQos qos = fdds::PARTICIPANT_QOS_DEFAULT;
  qos.name(name);
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  qos.transport().use_builtin_transports = false;
  if (buffer_bytes)
  {
    udp->sendBufferSize = buffer_bytes;
    udp->receiveBufferSize = buffer_bytes;
    qos.transport().send_socket_buffer_size = buffer_bytes;
    qos.transport().listen_socket_buffer_size = buffer_bytes;
  }
  if (localhost)
  {
    udp->maxInitialPeersRange = 32;
    rtps::Locator_t unicast;
    unicast.kind = LOCATOR_KIND_UDPv4;
    qos.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(unicast);
    for (uint32_t id = 0; id < 32; ++id)
    {
      rtps::Locator_t peer;
      peer.kind = LOCATOR_KIND_UDPv4;
      eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, 127, 0, 0, 1);
      peer.port = 7400 + 250 * static_cast<uint32_t>(domain) + 10 + 2 * id;
      qos.wire_protocol().builtin.initialPeersList.push_back(peer);
    }
  }
  qos.transport().user_transports.push_back(udp);
  return qos;
}

/// A participant named `program` on ROS_DOMAIN_ID (LOCALHOST discovery when
/// ROS_AUTOMATIC_DISCOVERY_RANGE says so); nullptr, with a message on stderr, when it cannot be
/// created. Free it with delete_participant().
inline fdds::DomainParticipant* create_participant(const char* program, uint32_t buffer_bytes = 0)
{
  const int domain = env_int("ROS_DOMAIN_ID", 0);
  const char* range = std::getenv("ROS_AUTOMATIC_DISCOVERY_RANGE");
  const bool localhost = range && std::strcmp(range, "LOCALHOST") == 0;
  fdds::DomainParticipant* participant =
    fdds::DomainParticipantFactory::get_instance()->create_participant(
      domain, participant_qos(program, domain, localhost, buffer_bytes));
  if (!participant)
    std::fprintf(stderr, "%s: cannot create a participant on domain %d\n", program, domain);
  return participant;
}

inline void delete_participant(fdds::DomainParticipant* participant)
{
  participant->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant);
}

/// The benchmark clients' writer QoS (reliable, volatile, keep last 1000), XCDR1 as rmw_fastrtps
/// writes, synchronous, no data sharing.
inline fdds::DataWriterQos writer_qos()
{
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1000;
  qos.publish_mode().kind = fdds::SYNCHRONOUS_PUBLISH_MODE;
  qos.data_sharing().off();
  qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  qos.representation().m_value = { fdds::XCDR_DATA_REPRESENTATION };
  return qos;
}

} // namespace bare

#endif
