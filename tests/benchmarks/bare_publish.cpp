// bare_publish — the floor of the throughput benchmarks' sender: a raw Fast DDS 2.9 DataWriter (no
// ROS layer, no ros2vtk runtime, no VTK → message conversion, no serialization) that writes one
// pre-serialized ROS message to `rt<topic>` as opaque bytes, beside bench_publish (our scene
// publisher node) and ros_publisher.py (rclpy). Per publish it only patches header.stamp and
// calls DataWriter::write, so bench_publish's publish_ms over bare_publish's is what our sender
// adds to Fast DDS's own write, and a receiver's latency from it has no sender-side conversion.
//
//   bare_publish --type PoseStamped|Image|PointCloud2|PoseArray --topic T --payload FILE
//                [--rate HZ] [--seconds S] [--wait S]
//
// FILE holds one message exactly as rclpy.serialization.serialize_message returns it (CDR_LE
// encapsulation header included; tests/benchmarks/rclpy_payload.py writes one). It is read once
// and checked against the type's CDR layout. Every publish writes header.stamp = now (system
// clock, as bench_publish) into the bytes: every one of the four types begins with
// std_msgs/Header, so sec is at byte 4 and nanosec at byte 8. Writer QoS and UDPv4 socket buffers
// as ros2vtk::wire's (ROS2VTK_SOCKET_BUFFER_BYTES honoured, 4 MiB by default); ROS_DOMAIN_ID and
// ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST as rmw. Waits up to --wait s for a matched reader, then
// publishes on an absolute schedule with sleeps only, as bench_publish.
//
// Prints {"sent": N, "seconds": S, "rate": achieved, "publish_ms": [...]} on stdout, as
// bench_publish; errors go to stderr with a non-zero exit code.
#include "BareFastDds.hpp"
#include "BenchCommon.hpp"

#include <fastdds/dds/core/status/PublicationMatchedStatus.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace fdds = bare::fdds;

namespace {

struct Options
{
  std::string type;
  std::string topic;
  std::string payload;
  double rate = 30.0;
  double seconds = 5.0;
  double wait = 20.0;
};

/// The DDS type name ROS 2 gives a benchmark type, nullptr for an unknown one.
const char* dds_type_name(const std::string& type)
{
  if (type == "PoseStamped")
    return "geometry_msgs::msg::dds_::PoseStamped_";
  if (type == "Image")
    return "sensor_msgs::msg::dds_::Image_";
  if (type == "PointCloud2")
    return "sensor_msgs::msg::dds_::PointCloud2_";
  if (type == "PoseArray")
    return "geometry_msgs::msg::dds_::PoseArray_";
  return nullptr;
}

/// Walks a CDR_LE (XCDR1) body the way Fast CDR lays it out: alignment relative to the end of the
/// 4-byte encapsulation header. Any read past the end clears ok.
class CdrWalker
{
public:
  explicit CdrWalker(const std::vector<uint8_t>& bytes)
    : bytes_(bytes)
  {
  }
  bool ok = true;
  size_t position() const { return pos_; }

  void skip(uint64_t size, size_t alignment)
  {
    pos_ = 4 + (pos_ - 4 + alignment - 1) / alignment * alignment;
    if (!ok || pos_ > bytes_.size() || size > bytes_.size() - pos_)
    {
      ok = false;
      pos_ = bytes_.size();
      return;
    }
    pos_ += static_cast<size_t>(size);
  }
  uint32_t u32()
  {
    skip(4, 4);
    if (!ok)
      return 0;
    const uint8_t* p = bytes_.data() + pos_ - 4;
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  }
  /// A string: length (NUL included), then the characters and the NUL.
  void string()
  {
    const uint32_t length = u32();
    ok = ok && length > 0;
    skip(length, 1);
    ok = ok && bytes_[pos_ - 1] == '\0';
  }
  void header()
  {
    skip(8, 4); // builtin_interfaces/Time stamp
    string();   // frame_id
  }
  /// A sequence of `element`-byte items aligned to `alignment`.
  void sequence(uint64_t element, size_t alignment)
  {
    const uint32_t count = u32();
    if (count > 0)
      skip(count * element, alignment);
  }

private:
  const std::vector<uint8_t>& bytes_;
  size_t pos_ = 4;
};

/// Checks that `bytes` is one serialized `type` (header, layout, total size); empty when it is,
/// else what is wrong.
std::string check_payload(const std::string& type, const std::vector<uint8_t>& bytes)
{
  if (bytes.size() < 16)
    return "too short for a CDR message with a std_msgs/Header (" + std::to_string(bytes.size()) +
      " bytes)";
  if (bytes[0] != 0x00 || bytes[1] != 0x01)
    return "encapsulation is not CDR_LE (00 01)";
  CdrWalker cdr(bytes);
  cdr.header();
  if (type == "PoseStamped")
    cdr.skip(7 * 8, 8); // geometry_msgs/Pose: 7 float64
  else if (type == "Image")
  {
    cdr.skip(8, 4);     // height, width
    cdr.string();       // encoding
    cdr.skip(1, 1);     // is_bigendian
    cdr.skip(4, 4);     // step
    cdr.sequence(1, 1); // data
  }
  else if (type == "PointCloud2")
  {
    cdr.skip(8, 4); // height, width
    for (uint32_t i = 0, fields = cdr.u32(); cdr.ok && i < fields; ++i)
    {
      cdr.string();   // name
      cdr.skip(4, 4); // offset
      cdr.skip(1, 1); // datatype
      cdr.skip(4, 4); // count
    }
    cdr.skip(1, 1);     // is_bigendian
    cdr.skip(8, 4);     // point_step, row_step
    cdr.sequence(1, 1); // data
    cdr.skip(1, 1);     // is_dense
  }
  else if (type == "PoseArray")
    cdr.sequence(7 * 8, 8); // geometry_msgs/Pose[]
  // serialize_message may pad the end to a multiple of 4 (the encapsulation options say so).
  if (!cdr.ok || bytes.size() - cdr.position() > 3)
    return "not one serialized " + type + " (its CDR layout ends at byte " +
      std::to_string(cdr.position()) + " of " + std::to_string(bytes.size()) + ")";
  return {};
}

void put_le32(std::vector<uint8_t>& bytes, size_t offset, uint32_t value)
{
  for (size_t i = 0; i < 4; ++i)
    bytes[offset + i] = static_cast<uint8_t>(value >> (8 * i));
}

/// header.stamp = now (system clock): sec (int32) at byte 4, nanosec (uint32) at byte 8.
void stamp_now(std::vector<uint8_t>& bytes)
{
  const int64_t ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
                       .count();
  put_le32(bytes, 4, static_cast<uint32_t>(static_cast<int32_t>(ns / 1000000000)));
  put_le32(bytes, 8, static_cast<uint32_t>(ns % 1000000000));
}

/// The whole file into `bytes`; false (errno set) when it cannot be read.
bool read_file(const std::string& path, std::vector<uint8_t>& bytes)
{
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
    return false;
  uint8_t chunk[1 << 16];
  for (size_t n; (n = std::fread(chunk, 1, sizeof chunk, file)) > 0;)
    bytes.insert(bytes.end(), chunk, chunk + n);
  const bool ok = !std::ferror(file);
  std::fclose(file);
  return ok;
}

int usage()
{
  std::fprintf(stderr,
    "usage: bare_publish --type PoseStamped|Image|PointCloud2|PoseArray --topic T --payload FILE\n"
    "                    [--rate HZ] [--seconds S] [--wait S]\n");
  return 2;
}

int run(const Options& options, std::vector<uint8_t> bytes)
{
  const char* type_name = dds_type_name(options.type);
  fdds::DomainParticipant* participant =
    bare::create_participant("bare_publish", bare::socket_buffer_bytes("bare_publish"));
  if (!participant)
    return 1;
  fdds::TypeSupport opaque(new bare::OpaqueType(type_name));
  opaque.register_type(participant);
  fdds::Topic* topic =
    participant->create_topic("rt" + options.topic, type_name, fdds::TOPIC_QOS_DEFAULT);
  fdds::Publisher* publisher =
    topic ? participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT) : nullptr;
  // ros2vtk::wire's reliable writer (make_writer_qos): heartbeats every 100 ms, NACKs suppressed
  // for 5 ms after a send.
  fdds::DataWriterQos writer_qos = bare::writer_qos();
  writer_qos.reliable_writer_qos().times.heartbeatPeriod =
    eprosima::fastrtps::Duration_t(0, 100000000);
  writer_qos.reliable_writer_qos().times.nackSupressionDuration =
    eprosima::fastrtps::Duration_t(0, 5000000);
  fdds::DataWriter* writer = publisher ? publisher->create_datawriter(topic, writer_qos) : nullptr;
  if (!writer)
  {
    std::fprintf(stderr, "bare_publish: cannot publish on %s\n", options.topic.c_str());
    bare::delete_participant(participant);
    return 1;
  }

  const auto matched_readers = [writer] {
    fdds::PublicationMatchedStatus status;
    writer->get_publication_matched_status(status);
    return status.current_count;
  };
  const auto wait_end = bench::Clock::now() + std::chrono::duration<double>(options.wait);
  while (!bare::interrupted && matched_readers() < 1 && bench::Clock::now() < wait_end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (matched_readers() < 1)
    std::fprintf(stderr, "bare_publish: no reader matched on %s within %g s; publishing anyway\n",
      options.topic.c_str(), options.wait);
  std::this_thread::sleep_for(
    std::chrono::milliseconds(500)); // as ros_publisher.py: let matching settle

  bench::publish_paced(
    options.rate, options.seconds,
    [&] {
      stamp_now(bytes);
      return writer->write(&bytes);
    },
    [] { return !bare::interrupted; });
  bare::delete_participant(participant);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  const bool parsed = bench::OptionParser()
                        .add("--type", &o.type)
                        .add("--topic", &o.topic)
                        .add("--payload", &o.payload)
                        .add("--rate", &o.rate)
                        .add("--seconds", &o.seconds)
                        .add("--wait", &o.wait)
                        .parse(argc, argv);
  if (!parsed)
    return usage();
  if (!dds_type_name(o.type))
  {
    std::fprintf(stderr, "bare_publish: unknown --type '%s'\n", o.type.c_str());
    return usage();
  }
  if (o.rate <= 0 || o.seconds <= 0 || o.topic.empty() || o.payload.empty())
  {
    std::fprintf(
      stderr, "bare_publish: --topic, --payload, --rate > 0 and --seconds > 0 are required\n");
    return 2;
  }
  std::vector<uint8_t> bytes;
  if (!read_file(o.payload, bytes))
  {
    std::fprintf(
      stderr, "bare_publish: cannot read %s: %s\n", o.payload.c_str(), std::strerror(errno));
    return 1;
  }
  const std::string problem = check_payload(o.type, bytes);
  if (!problem.empty())
  {
    std::fprintf(stderr, "bare_publish: %s: %s\n", o.payload.c_str(), problem.c_str());
    return 1;
  }
  bare::install_signal_handlers();
  return run(o, std::move(bytes));
}
