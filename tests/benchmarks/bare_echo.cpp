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
#include "BareFastDds.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace fdds = bare::fdds;
namespace rtps = bare::rtps;

namespace {

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
  bare::install_signal_handlers();

  fdds::DomainParticipant* participant = bare::create_participant("bare_echo");
  if (!participant)
    return 1;
  fdds::TypeSupport opaque(new bare::OpaqueType(type));
  opaque.register_type(participant);
  fdds::Topic* in_topic = participant->create_topic("rt" + in, type, fdds::TOPIC_QOS_DEFAULT);
  fdds::Topic* out_topic = participant->create_topic("rt" + out, type, fdds::TOPIC_QOS_DEFAULT);
  fdds::Publisher* publisher = participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::Subscriber* subscriber = participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);

  // The client's QoS (reliable, volatile, keep last 1000), XCDR1 as rmw_fastrtps writes; the
  // writer's is bare::writer_qos().
  fdds::DataReaderQos reader_qos = fdds::DATAREADER_QOS_DEFAULT;
  reader_qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  reader_qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  reader_qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  reader_qos.history().depth = 1000;
  reader_qos.data_sharing().off();
  reader_qos.endpoint().history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  reader_qos.type_consistency().representation.m_value = { fdds::XCDR_DATA_REPRESENTATION };

  EchoListener listener;
  listener.writer = publisher->create_datawriter(out_topic, bare::writer_qos());
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
  while (!bare::interrupted && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::printf("{\"echoed\": %ld}\n", listener.echoed.load());
  std::fflush(stdout);
  reader->set_listener(nullptr);
  bare::delete_participant(participant);
  return 0;
}
