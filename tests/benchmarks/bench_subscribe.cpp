// bench_subscribe — throughput and latency of a scene subscriber node (event-driven spin).
//
// A ROS 2 peer (tests/benchmarks/ros_publisher.py, rclpy) publishes stamped messages; this
// program owns a vtkROS2Logic whose default node subscribes through the generated subscriber
// node of the type, spins on wake-up, and in the ModifiedEvent observer converts the newest
// message to its VTK type (vtkMatrix4x4, vtkImageData, vtkPolyData, vtkTransformCollection).
// Per message it records the end-to-end latency: wall clock once the VTK value is ready minus the
// header stamp the publisher wrote just before publishing (same host, same clock). Per spin it
// records the conversion time (the GetLastMessage() call) and the spin time. Each latency is also
// split at the wake-up the DDS thread raised once it had taken and deserialized the message: the
// first wake-up at or after the message's stamp. `queued_ms` = that wake-up − stamp (the
// sender's write, the transport, Fast DDS and our deserialization), `wake_to_ready_ms` = VTK value
// ready − that wake-up (the spinner's wake-up, the spin and the conversion).
//
// Before that wake-up, every datagram the participant reads is shown to an observer
// (Participant::set_datagram_observer), which reads the RTPS submessage headers of the sample's
// DATA or DATA_FRAG submessages: `first_fragment_ms` = first datagram of the sample − stamp (the
// sender's write and the loopback), `fragments_ms` = last − first datagram (the rest of the
// sample on the wire: one datagram, 0, for small messages), `last_fragment_to_wake_ms` = the
// wake-up − last datagram (Fast DDS's reassembly and delivery, our take and deserialization).
//
//   bench_subscribe --type PoseStamped|Image|PointCloud2|PoseArray --topic T [--seconds S]
//                   [--idle S] [--depth N]
//
// Ends --idle seconds after the last message (or at --seconds); prints one JSON object.
#include "BenchCommon.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberImageNode.h"
#include "vtkROS2SubscriberPointCloud2Node.h"
#include "vtkROS2SubscriberPoseArrayNode.h"
#include "vtkROS2SubscriberPoseStampedNode.h"

#include "ros2vtk/geometry_msgs/msg/pose_array.hpp"
#include "ros2vtk/geometry_msgs/msg/pose_stamped.hpp"
#include "ros2vtk/sensor_msgs/msg/image.hpp"
#include "ros2vtk/sensor_msgs/msg/point_cloud2.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/WakeUp.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "ros2vtkNodesRegister.hpp" // ros2vtk_register_ros2vtkNodes_nodes()

namespace {

/// The generated subscriber node of a type, with the raw messages of a spin reachable (they are
/// protected in the node's API): the benchmark needs every message's header stamp, not only the
/// newest one's.
template<typename Base>
class StampedProbe : public Base
{
public:
  static StampedProbe* New()
  {
    auto* probe = new StampedProbe;
    probe->InitializeObjectBase();
    return probe;
  }
  const void* Raw(int i) const { return this->GetNewRawMessage(i); }
  int NewCount() const { return this->Base::GetNumberOfNewMessages(); }
};

/// When the datagrams of one sample arrived, from their RTPS submessage headers.
struct SampleArrival
{
  double first = 0; ///< wall seconds of the first datagram carrying part of the sample
  double last = 0;  ///< ... and of the last one
  int datagrams = 0;
};

/// Reads the RTPS submessages of each datagram (RTPS 2.3, 8.3.3 and 9.4.5) far enough to know
/// which sample of which user writer a DATA or DATA_FRAG carries, and that sample's header stamp
/// (the first 8 bytes after the CDR encapsulation of fragment 1: every benchmarked type begins
/// with std_msgs/Header). Hand-written because Fast DDS reports a sample only once it is whole:
/// no API of it says when its first or last fragment arrived.
class FragmentClock
{
public:
  /// On Fast DDS's receive thread, with every datagram.
  void on_datagram(const uint8_t* data, size_t size, double now)
  {
    if (size < 20 || std::memcmp(data, "RTPS", 4) != 0)
      return;
    std::array<uint8_t, 12> prefix{};
    std::memcpy(prefix.data(), data + 8, 12);
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t at = 20; at + 4 <= size;)
    {
      const uint8_t id = data[at];
      const uint8_t flags = data[at + 1];
      const bool little = (flags & 0x01) != 0;
      const size_t length = read16(data + at + 2, little);
      const size_t body = at + 4;
      const size_t end = length == 0 ? size : std::min(size, body + length);
      if (id == kData || id == kDataFrag)
        on_data(id, flags, data + body, end - body, prefix, now, little);
      if (length == 0)
        break;
      at = body + length;
    }
  }

  /// The arrival of the sample with this header stamp, taken out of the clock (false: unknown).
  bool take(int32_t sec, uint32_t nanosec, SampleArrival& arrival)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto stamp = by_stamp_.find({ sec, nanosec });
    if (stamp == by_stamp_.end())
      return false;
    const auto sample = samples_.find(stamp->second);
    by_stamp_.erase(stamp);
    if (sample == samples_.end())
      return false;
    arrival = sample->second;
    samples_.erase(sample);
    return true;
  }

private:
  static constexpr uint8_t kData = 0x15;
  static constexpr uint8_t kDataFrag = 0x16;
  using Key = std::pair<std::array<uint8_t, 16>, uint64_t>; // writer GUID, sequence number

  static uint32_t read16(const uint8_t* p, bool little)
  {
    return little ? uint32_t(p[0]) | uint32_t(p[1]) << 8 : uint32_t(p[1]) | uint32_t(p[0]) << 8;
  }
  static uint32_t read32(const uint8_t* p, bool little)
  {
    return little
      ? uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24
      : uint32_t(p[3]) | uint32_t(p[2]) << 8 | uint32_t(p[1]) << 16 | uint32_t(p[0]) << 24;
  }

  void on_data(uint8_t id, uint8_t flags, const uint8_t* body, size_t size,
    const std::array<uint8_t, 12>& prefix, double now, bool little)
  {
    // extraFlags(2) octetsToInlineQos(2) readerId(4) writerId(4) writerSN(8) [DATA_FRAG:
    // fragmentStartingNum(4) fragmentsInSubmessage(2) fragmentSize(2) sampleSize(4)]
    if (size < 20)
      return;
    const uint8_t writer_kind = body[11];
    if ((writer_kind & 0xc0) != 0)
      return; // a built-in writer (discovery, liveliness), not a topic's
    Key key;
    std::memcpy(key.first.data(), prefix.data(), 12);
    std::memcpy(key.first.data() + 12, body + 8, 4);
    key.second = uint64_t(read32(body + 12, little)) << 32 | read32(body + 16, little);
    SampleArrival& arrival = samples_[key];
    if (arrival.datagrams == 0)
      arrival.first = now;
    arrival.last = now;
    ++arrival.datagrams;
    const bool first_part = id == kData || (size >= 24 && read32(body + 20, little) == 1);
    if (!first_part)
      return;
    // The serialized payload follows the inline QoS (flag Q), which ends at PID_SENTINEL.
    size_t payload = 4 + read16(body + 2, little);
    if ((flags & 0x02) != 0)
    {
      while (payload + 4 <= size && read16(body + payload, little) != 0x0001)
        payload += 4 + read16(body + payload + 2, little);
      payload += 4;
    }
    if (payload + 12 > size || body[payload] != 0x00 || body[payload + 1] != 0x01)
      return; // not CDR little-endian: the stamp cannot be read here
    const auto sec = static_cast<int32_t>(read32(body + payload + 4, true));
    by_stamp_[{ sec, read32(body + payload + 8, true) }] = key;
  }

  std::mutex mutex_;
  std::map<Key, SampleArrival> samples_;
  std::map<std::pair<int32_t, uint32_t>, Key> by_stamp_;
};

struct Options
{
  std::string type;
  std::string topic;
  double seconds = 60.0;
  double idle = 2.0;
  int depth = 1000;
};

struct Record
{
  std::vector<double> latency_ms;    // per message
  std::vector<double> conversion_ms; // per spin that brought messages
  std::vector<double> per_spin_messages;
  std::vector<double> queued_ms;                // per message: stamp -> the DDS thread's wake-up
  std::vector<double> wake_to_ready_ms;         // per message: that wake-up -> VTK value ready
  std::vector<double> first_fragment_ms;        // per message: stamp -> its first datagram
  std::vector<double> fragments_ms;             // per message: first -> last datagram
  std::vector<double> last_fragment_to_wake_ms; // per message: last datagram -> the wake-up
  std::vector<double> datagrams;                // per message: datagrams carrying it
  FragmentClock fragments;
  std::mutex wake_mutex;
  std::vector<double> wake_ups; // wall seconds of the DDS thread's wake-ups since the last spin
  std::string conversion_error;
  size_t converted_size = 0; // points, pixels or poses of the newest conversion
};

template<typename Message>
double stamp_seconds(const void* raw)
{
  const auto& stamp = static_cast<const Message*>(raw)->header.stamp;
  return stamp.sec + 1e-9 * stamp.nanosec;
}

template<typename Message>
bool take_arrival(FragmentClock& fragments, const void* raw, SampleArrival& arrival)
{
  const auto& stamp = static_cast<const Message*>(raw)->header.stamp;
  return fragments.take(stamp.sec, stamp.nanosec, arrival);
}

size_t size_of(vtkMatrix4x4* m)
{
  return m ? 1 : 0;
}
size_t size_of(vtkImageData* image)
{
  return image ? static_cast<size_t>(image->GetNumberOfPoints()) : 0;
}
size_t size_of(vtkPolyData* cloud)
{
  return cloud ? static_cast<size_t>(cloud->GetNumberOfPoints()) : 0;
}
size_t size_of(vtkTransformCollection* poses)
{
  return poses ? static_cast<size_t>(poses->GetNumberOfItems()) : 0;
}

template<typename Node, typename Message>
int run(const Options& options)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  auto probe = vtkSmartPointer<StampedProbe<Node>>::New();
  probe->SetName(options.topic.c_str());
  // Reliable, volatile, keep last `depth`: what a ROS 2 peer uses for "no loss" streams.
  probe->SetReliability("reliable");
  probe->SetHistory("keep_last");
  probe->SetHistoryDepth(options.depth);
  logic->GetScene()->AddNode(probe);
  if (!node || !probe->AddToROS2Node(node->GetID(), options.topic.c_str()))
  {
    std::fprintf(stderr, "bench_subscribe: cannot subscribe to %s\n", options.topic.c_str());
    return 1;
  }
  Record record;
  struct Context
  {
    StampedProbe<Node>* probe;
    Record* record;
  } context{ probe, &record };
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&context);
  observer->SetCallback([](vtkObject*, unsigned long, void* client_data, void*) {
    auto* c = static_cast<Context*>(client_data);
    const auto start = bench::Clock::now();
    auto* value = c->probe->GetLastMessage();
    const auto end = bench::Clock::now();
    const double ready = bench::wall_seconds();
    c->record->conversion_ms.push_back(bench::ms_between(start, end));
    if (!value)
      c->record->conversion_error = c->probe->GetLastConversionError();
    c->record->converted_size = size_of(value);
    const int count = c->probe->NewCount();
    c->record->per_spin_messages.push_back(count);
    std::vector<double> wake_ups;
    {
      std::lock_guard<std::mutex> lock(c->record->wake_mutex);
      wake_ups.swap(c->record->wake_ups);
    }
    for (int i = 0; i < count; ++i)
    {
      const double stamp = stamp_seconds<Message>(c->probe->Raw(i));
      c->record->latency_ms.push_back(1000.0 * (ready - stamp));
      auto wake = std::lower_bound(wake_ups.begin(), wake_ups.end(), stamp);
      if (wake != wake_ups.end())
      {
        c->record->queued_ms.push_back(1000.0 * (*wake - stamp));
        c->record->wake_to_ready_ms.push_back(1000.0 * (ready - *wake));
      }
      SampleArrival arrival;
      if (take_arrival<Message>(c->record->fragments, c->probe->Raw(i), arrival))
      {
        c->record->first_fragment_ms.push_back(1000.0 * (arrival.first - stamp));
        c->record->fragments_ms.push_back(1000.0 * (arrival.last - arrival.first));
        c->record->datagrams.push_back(arrival.datagrams);
        // The first wake-up after the last datagram is the one this sample raised.
        auto raised = std::lower_bound(wake_ups.begin(), wake_ups.end(), arrival.last);
        if (raised != wake_ups.end())
          c->record->last_fragment_to_wake_ms.push_back(1000.0 * (*raised - arrival.last));
      }
    }
  });
  probe->AddObserver(vtkCommand::ModifiedEvent, observer);
  // On the DDS thread, after a message was taken, deserialized and queued.
  node->GetParticipant()->wake_up().set_callback([&record] {
    const double now = bench::wall_seconds();
    std::lock_guard<std::mutex> lock(record.wake_mutex);
    record.wake_ups.push_back(now);
  });
  node->GetParticipant()->set_datagram_observer([&record](const uint8_t* data, size_t size) {
    record.fragments.on_datagram(data, size, bench::wall_seconds());
  });

  std::printf("{\"ready\": true}\n");
  std::fflush(stdout);
  std::vector<double> spin_ms;
  const auto end = bench::Clock::now() + std::chrono::duration<double>(options.seconds);
  auto last_message = bench::Clock::now();
  bool any = false;
  while (bench::Clock::now() < end)
  {
    // Event-driven: SpinOnWakeUp blocks until data is queued, then spins once. Its own
    // duration is the spin; the wait is not.
    const int handled = logic->SpinOnWakeUp(0.1);
    if (handled > 0)
    {
      spin_ms.push_back(logic->GetLastSpinDuration());
      last_message = bench::Clock::now();
      any = true;
    }
    else if (any && bench::ms_between(last_message, bench::Clock::now()) > 1000.0 * options.idle)
      break;
  }
  bench::JsonObject()
    .text("type", options.type)
    .number("received", static_cast<double>(probe->GetNumberOfMessages()))
    .number("rejected", static_cast<double>(probe->GetNumberOfRejectedMessages()))
    .number("converted_size", static_cast<double>(record.converted_size))
    .text("conversion_error", record.conversion_error)
    .numbers("latency_ms", record.latency_ms)
    .numbers("conversion_ms", record.conversion_ms)
    .numbers("spin_ms", spin_ms)
    .numbers("messages_per_spin", record.per_spin_messages)
    .numbers("queued_ms", record.queued_ms)
    .numbers("wake_to_ready_ms", record.wake_to_ready_ms)
    .numbers("first_fragment_ms", record.first_fragment_ms)
    .numbers("fragments_ms", record.fragments_ms)
    .numbers("last_fragment_to_wake_ms", record.last_fragment_to_wake_ms)
    .numbers("datagrams", record.datagrams)
    .print();
  // Nothing may reach `record` or `context` once they are gone (they live on this stack).
  node->GetParticipant()->set_datagram_observer(nullptr);
  node->GetParticipant()->wake_up().set_callback(nullptr);
  probe->RemoveObserver(observer);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  ros2vtk_register_ros2vtkNodes_nodes();
  Options options;
  const bool parsed = bench::OptionParser()
                        .add("--type", &options.type)
                        .add("--topic", &options.topic)
                        .add("--seconds", &options.seconds)
                        .add("--idle", &options.idle)
                        .add("--depth", &options.depth)
                        .parse(argc, argv);
  if (!parsed)
    return 2;
  namespace gm = ros2vtk::geometry_msgs::msg;
  namespace sm = ros2vtk::sensor_msgs::msg;
  if (options.type == "PoseStamped")
    return run<vtkROS2SubscriberPoseStampedNode, gm::PoseStamped>(options);
  if (options.type == "Image")
    return run<vtkROS2SubscriberImageNode, sm::Image>(options);
  if (options.type == "PointCloud2")
    return run<vtkROS2SubscriberPointCloud2Node, sm::PointCloud2>(options);
  if (options.type == "PoseArray")
    return run<vtkROS2SubscriberPoseArrayNode, gm::PoseArray>(options);
  std::fprintf(
    stderr, "usage: bench_subscribe --type PoseStamped|Image|PointCloud2|PoseArray --topic T\n");
  return 2;
}
