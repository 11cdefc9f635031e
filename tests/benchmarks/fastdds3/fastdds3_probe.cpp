// ros2vtk benchmarks — a sensor_msgs/Image reader and writer on the wheels' Fast DDS 3, to measure
// what a Fast DDS 3 build of ros2vtk's Wire would gain (issue 17): shared memory with rclpy's
// nodes (impossible from Debian's Fast DDS 2.9: the segment formats differ) and between two
// ros2vtk processes. Payloads are opaque CDR bytes: only header.stamp is read (latency = receipt
// − stamp, as tests/benchmarks/ros_subscriber.py measures) and written.
//
//     fastdds3_probe sub TOPIC --seconds S [--idle I]      prints {"ready": true}, then
//                                                           {"received": N, "latency_ms": [...]}
//     fastdds3_probe pub TOPIC --rate HZ --seconds S [--width W --height H]   rgb8 images,
//                                                           prints {"sent": N, "rate": achieved}
//
// Transports: Fast DDS 3's defaults (shared memory + UDPv4) unless FASTDDS_BUILTIN_TRANSPORTS
// says otherwise; with PROBE_TUNED=1 the transports are set as ros2vtk sets its own (4 MiB UDP
// socket buffers) plus a 4 MiB shared-memory segment (Fast DDS's default of 512 KiB is smaller
// than one VGA image), UDPv4 only when FASTDDS_BUILTIN_TRANSPORTS=UDPv4. ROS_DOMAIN_ID picks the
// domain. QoS: reliable, volatile, keep last 1000, as the
// other benchmark endpoints. Hand-written because the measured thing is the transport alone.
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/rtps/common/SerializedPayload.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.hpp>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace fdds = eprosima::fastdds::dds;
namespace frtps = eprosima::fastdds::rtps;

namespace {

using Bytes = std::vector<uint8_t>;

/// Any ROS message as its CDR bytes (encapsulation header included).
class OpaqueType : public fdds::TopicDataType
{
public:
  explicit OpaqueType(const std::string& dds_name)
  {
    set_name(dds_name);
    max_serialized_type_size = 16 * 1024 * 1024;
    is_compute_key_provided = false;
  }
  bool serialize(const void* const data, frtps::SerializedPayload_t& payload,
    fdds::DataRepresentationId_t) override
  {
    const Bytes& bytes = *static_cast<const Bytes*>(data);
    if (payload.max_size < bytes.size())
      return false;
    std::memcpy(payload.data, bytes.data(), bytes.size());
    payload.length = static_cast<uint32_t>(bytes.size());
    return true;
  }
  bool deserialize(frtps::SerializedPayload_t& payload, void* data) override
  {
    static_cast<Bytes*>(data)->assign(payload.data, payload.data + payload.length);
    return true;
  }
  uint32_t calculate_serialized_size(const void* const data, fdds::DataRepresentationId_t) override
  {
    return static_cast<uint32_t>(static_cast<const Bytes*>(data)->size());
  }
  void* create_data() override { return new Bytes(); }
  void delete_data(void* data) override { delete static_cast<Bytes*>(data); }
  bool compute_key(frtps::SerializedPayload_t&, frtps::InstanceHandle_t&, bool) override
  {
    return false;
  }
  bool compute_key(const void* const, frtps::InstanceHandle_t&, bool) override { return false; }
};

double now_seconds()
{
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

double arg(int argc, char** argv, const char* name, double fallback)
{
  for (int i = 3; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], name) == 0)
      return std::atof(argv[i + 1]);
  return fallback;
}

struct Endpoints
{
  fdds::DomainParticipant* participant = nullptr;
  fdds::Topic* topic = nullptr;
};

Endpoints open(const std::string& ros_topic)
{
  const char* domain = std::getenv("ROS_DOMAIN_ID");
  fdds::DomainParticipantQos qos = fdds::PARTICIPANT_QOS_DEFAULT;
  qos.name("fastdds3_probe");
  const char* tuned = std::getenv("PROBE_TUNED");
  if (tuned && std::strcmp(tuned, "1") == 0)
  {
    constexpr uint32_t kBuffer = 4 * 1024 * 1024;
    const char* builtin = std::getenv("FASTDDS_BUILTIN_TRANSPORTS");
    qos.transport().use_builtin_transports = false;
    if (!builtin || std::strcmp(builtin, "UDPv4") != 0)
    {
      auto shm = std::make_shared<frtps::SharedMemTransportDescriptor>();
      shm->segment_size(kBuffer);
      shm->max_message_size(kBuffer);
      qos.transport().user_transports.push_back(shm);
    }
    auto udp = std::make_shared<frtps::UDPv4TransportDescriptor>();
    udp->sendBufferSize = kBuffer;
    udp->receiveBufferSize = kBuffer;
    qos.transport().user_transports.push_back(udp);
    qos.transport().send_socket_buffer_size = kBuffer;
    qos.transport().listen_socket_buffer_size = kBuffer;
  }
  Endpoints e;
  e.participant = fdds::DomainParticipantFactory::get_instance()->create_participant(
    domain ? std::atoi(domain) : 0, qos);
  fdds::TypeSupport type(new OpaqueType("sensor_msgs::msg::dds_::Image_"));
  type.register_type(e.participant);
  e.topic =
    e.participant->create_topic("rt" + ros_topic, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  return e;
}

template<typename Qos>
void ros_qos(Qos& qos)
{
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1000;
  qos.data_sharing().off(); // rmw_fastrtps keeps data sharing off for unbounded types too
}

class Reader : public fdds::DataReaderListener
{
public:
  void on_data_available(fdds::DataReader* reader) override
  {
    Bytes bytes;
    fdds::SampleInfo info;
    while (reader->take_next_sample(&bytes, &info) == fdds::RETCODE_OK)
    {
      if (!info.valid_data || bytes.size() < 12)
        continue;
      const double received = now_seconds();
      int32_t sec = 0;
      uint32_t nanosec = 0;
      std::memcpy(
        &sec, bytes.data() + 4, 4); // after the 4-byte encapsulation header, little endian
      std::memcpy(&nanosec, bytes.data() + 8, 4);
      std::lock_guard<std::mutex> lock(mutex);
      latencies.push_back(1000.0 * (received - (sec + 1e-9 * nanosec)));
      last = received;
    }
  }
  std::mutex mutex;
  std::vector<double> latencies;
  double last = 0;
};

int run_sub(const std::string& topic, double seconds, double idle)
{
  Endpoints e = open(topic);
  fdds::Subscriber* subscriber = e.participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  ros_qos(qos);
  Reader listener;
  subscriber->create_datareader(e.topic, qos, &listener);
  std::printf("{\"ready\": true}\n");
  std::fflush(stdout);
  const double end = now_seconds() + seconds;
  while (now_seconds() < end)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::lock_guard<std::mutex> lock(listener.mutex);
    if (listener.last > 0 && now_seconds() - listener.last > idle)
      break;
  }
  e.participant->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(e.participant);
  std::lock_guard<std::mutex> lock(listener.mutex);
  std::printf("{\"received\": %zu, \"latency_ms\": [", listener.latencies.size());
  for (size_t i = 0; i < listener.latencies.size(); ++i)
    std::printf("%s%.4f", i ? ", " : "", listener.latencies[i]);
  std::printf("]}\n");
  return 0;
}

/// sensor_msgs/Image rgb8 in CDR: header (stamp, frame_id "camera"), height, width, encoding,
/// is_bigendian, step, data.
Bytes image_cdr(uint32_t width, uint32_t height)
{
  Bytes b = { 0x00, 0x01, 0x00, 0x00 };
  auto align = [&](size_t n) {
    while ((b.size() - 4) % n)
      b.push_back(0);
  };
  auto u32 = [&](uint32_t v) {
    align(4);
    const uint8_t* p = reinterpret_cast<const uint8_t*>(&v);
    b.insert(b.end(), p, p + 4);
  };
  auto text = [&](const char* s) {
    u32(static_cast<uint32_t>(std::strlen(s) + 1));
    b.insert(b.end(), s, s + std::strlen(s) + 1);
  };
  u32(0);
  u32(0);
  text("camera");
  u32(height);
  u32(width);
  text("rgb8");
  b.push_back(0); // is_bigendian
  u32(width * 3);
  u32(width * 3 * height);
  b.resize(b.size() + static_cast<size_t>(width) * 3 * height, 0x5a);
  return b;
}

int run_pub(const std::string& topic, double rate, double seconds, uint32_t width, uint32_t height)
{
  Endpoints e = open(topic);
  fdds::Publisher* publisher = e.participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  ros_qos(qos);
  fdds::DataWriter* writer = publisher->create_datawriter(e.topic, qos);
  fdds::PublicationMatchedStatus matched;
  for (int i = 0;
       i < 200 && (writer->get_publication_matched_status(matched), matched.current_count == 0);
       ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(500)); // the reader's side of discovery
  Bytes image = image_cdr(width, height);
  const auto start = std::chrono::steady_clock::now();
  auto next = start;
  const auto period = std::chrono::duration<double>(1.0 / rate);
  size_t sent = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::duration<double>(seconds))
  {
    const double stamp = now_seconds();
    const int32_t sec = static_cast<int32_t>(stamp);
    const uint32_t nanosec = static_cast<uint32_t>((stamp - sec) * 1e9);
    std::memcpy(image.data() + 4, &sec, 4);
    std::memcpy(image.data() + 8, &nanosec, 4);
    writer->write(&image);
    ++sent;
    next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
    std::this_thread::sleep_until(next);
  }
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::this_thread::sleep_for(std::chrono::seconds(1)); // let the last ones arrive
  std::printf("{\"sent\": %zu, \"rate\": %.2f}\n", sent, sent / elapsed);
  e.participant->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(e.participant);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::fprintf(stderr,
      "usage: fastdds3_probe sub|pub TOPIC [--seconds S] [--idle I] [--rate HZ] [--width W "
      "--height H]\n");
    return 2;
  }
  const std::string mode = argv[1];
  const std::string topic = argv[2];
  if (mode == "sub")
    return run_sub(topic, arg(argc, argv, "--seconds", 30), arg(argc, argv, "--idle", 3));
  if (mode == "pub")
    return run_pub(topic, arg(argc, argv, "--rate", 30), arg(argc, argv, "--seconds", 5),
      static_cast<uint32_t>(arg(argc, argv, "--width", 640)),
      static_cast<uint32_t>(arg(argc, argv, "--height", 480)));
  std::fprintf(stderr, "unknown mode '%s'\n", mode.c_str());
  return 2;
}
