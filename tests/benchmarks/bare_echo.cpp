// bare_echo — the floor of the round-trip benchmark: a raw Fast DDS 2.9 DomainParticipant (no
// ROS layer, no ros2vtk runtime, no (de)serialization) that reads `rt/<in>` samples of a ROS type
// as opaque bytes and writes the same bytes to `rt/<out>` from the DDS listener thread.
// Nothing can echo faster over the same transport, so ours/bare-echo is the cost of our stack.
//
//   bare_echo [--in /round_trip/out] [--out /round_trip/back]
//             [--type std_msgs::msg::dds_::Float64_] [--seconds S]
//
// ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST are honoured the way rmw does (and
// ros2vtk::wire does): unicast discovery with loopback initial peers. Prints {"ready": true}
// once created and {"echoed": N} at the end.
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace fdds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

namespace {

std::atomic<bool> interrupted{ false };
void on_signal(int)
{
  interrupted = true;
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

/// Writes every sample it reads straight back, on the listener thread (no queue, no hop).
class EchoListener : public fdds::DataReaderListener
{
public:
  fdds::DataWriter* writer = nullptr;
  std::atomic<long> echoed{ 0 };
  void on_data_available(fdds::DataReader* reader) override
  {
    std::vector<uint8_t> bytes;
    fdds::SampleInfo info;
    while (reader->take_next_sample(&bytes, &info) ==
      eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK)
    {
      if (info.valid_data && writer->write(&bytes))
        ++echoed;
    }
  }
};

int env_int(const char* name, int fallback)
{
  const char* value = std::getenv(name);
  return value && *value ? std::atoi(value) : fallback;
}

/// The participant QoS of rmw / ros2vtk::wire on LOCALHOST: UDPv4 only (Fast DDS 2.9 and 3 do
/// not share memory segments), unicast discovery to the loopback well-known ports.
fdds::DomainParticipantQos participant_qos(int domain, bool localhost)
{
  fdds::DomainParticipantQos qos = fdds::PARTICIPANT_QOS_DEFAULT;
  qos.name("bare_echo");
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  qos.transport().use_builtin_transports = false;
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

} // namespace

int main(int argc, char** argv)
{
  std::string in = "/round_trip/out";
  std::string out = "/round_trip/back";
  std::string type = "std_msgs::msg::dds_::Float64_";
  double seconds = 60.0;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if (arg == "--in")
      in = argv[i + 1];
    else if (arg == "--out")
      out = argv[i + 1];
    else if (arg == "--type")
      type = argv[i + 1];
    else if (arg == "--seconds")
      seconds = std::atof(argv[i + 1]);
    else
    {
      std::fprintf(stderr, "usage: bare_echo [--in T] [--out T] [--type DDS_TYPE] [--seconds S]\n");
      return 2;
    }
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  const int domain = env_int("ROS_DOMAIN_ID", 0);
  const char* range = std::getenv("ROS_AUTOMATIC_DISCOVERY_RANGE");
  const bool localhost = range && std::strcmp(range, "LOCALHOST") == 0;
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipant* participant =
    factory->create_participant(domain, participant_qos(domain, localhost));
  if (!participant)
  {
    std::fprintf(stderr, "bare_echo: cannot create a participant on domain %d\n", domain);
    return 1;
  }
  fdds::TypeSupport opaque(new OpaqueType(type));
  opaque.register_type(participant);
  fdds::Topic* in_topic = participant->create_topic("rt" + in, type, fdds::TOPIC_QOS_DEFAULT);
  fdds::Topic* out_topic = participant->create_topic("rt" + out, type, fdds::TOPIC_QOS_DEFAULT);
  fdds::Publisher* publisher = participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::Subscriber* subscriber = participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);

  // The client's QoS (reliable, volatile, keep last 1000), XCDR1 as rmw_fastrtps writes.
  fdds::DataWriterQos writer_qos = fdds::DATAWRITER_QOS_DEFAULT;
  writer_qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  writer_qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  writer_qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  writer_qos.history().depth = 1000;
  writer_qos.publish_mode().kind = fdds::SYNCHRONOUS_PUBLISH_MODE;
  writer_qos.data_sharing().off();
  writer_qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  writer_qos.representation().m_value = { fdds::XCDR_DATA_REPRESENTATION };
  fdds::DataReaderQos reader_qos = fdds::DATAREADER_QOS_DEFAULT;
  reader_qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  reader_qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  reader_qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  reader_qos.history().depth = 1000;
  reader_qos.data_sharing().off();
  reader_qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  reader_qos.type_consistency().representation.m_value = { fdds::XCDR_DATA_REPRESENTATION };

  EchoListener listener;
  listener.writer = publisher->create_datawriter(out_topic, writer_qos);
  fdds::DataReader* reader =
    listener.writer ? subscriber->create_datareader(in_topic, reader_qos, &listener) : nullptr;
  if (!reader)
  {
    std::fprintf(stderr, "bare_echo: cannot create the reader/writer\n");
    return 1;
  }
  std::printf("{\"ready\": true}\n");
  std::fflush(stdout);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!interrupted && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::printf("{\"echoed\": %ld}\n", listener.echoed.load());
  std::fflush(stdout);
  reader->set_listener(nullptr);
  participant->delete_contained_entities();
  factory->delete_participant(participant);
  return 0;
}
