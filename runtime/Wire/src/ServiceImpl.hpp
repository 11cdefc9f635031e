// ros2vtk — internals of ServiceServer and ServiceClient.
#ifndef ros2vtk_wire_ServiceImpl_hpp
#define ros2vtk_wire_ServiceImpl_hpp

#include "ParticipantImpl.hpp"
#include "ros2vtk/wire/Service.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <set>

namespace ros2vtk {
namespace wire {

/// The writer + reader pair of one side of a service, with match tracking. The server
/// writes replies and reads requests; the client the other way round.
class ServiceEndpoints : public eprosima::fastdds::dds::DataWriterListener
{
public:
  ServiceEndpoints(Participant::Impl& owner);
  ~ServiceEndpoints() override;

  bool create(const MessageTypeSupport& write_type, const std::string& write_topic,
    const MessageTypeSupport& read_type, const std::string& read_topic, const QoS& qos,
    eprosima::fastdds::dds::DataReaderListener* reader_listener, std::string* error);

  void on_publication_matched(eprosima::fastdds::dds::DataWriter* writer,
    const eprosima::fastdds::dds::PublicationMatchedStatus& info) override;
  /// Waits until the writer matched the reader with this GUID (bytes), up to `timeout_ms`.
  bool wait_for_matched_reader(const std::array<uint8_t, 16>& reader_guid, int timeout_ms);
  /// How many readers the writer has matched since it was created (never decreases).
  uint64_t readers_matched_total();

  Participant::Impl& owner;
  eprosima::fastdds::dds::Topic* write_topic = nullptr;
  eprosima::fastdds::dds::Topic* read_topic = nullptr;
  eprosima::fastdds::dds::DataWriter* writer = nullptr;
  eprosima::fastdds::dds::DataReader* reader = nullptr;

private:
  std::mutex match_mutex_;
  std::set<std::array<uint8_t, 16>> matched_readers_;
  uint64_t readers_matched_total_ = 0;
};

class ServiceServer::Impl : public eprosima::fastdds::dds::DataReaderListener
{
public:
  Impl(Participant::Impl& owner, const ServiceTypeSupport& type, std::string name);
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override;

  const ServiceTypeSupport& type;
  std::string name;
  ServiceEndpoints endpoints;
  NodeTypeCache::Registration type_registration; // the service type, served while this exists
  std::mutex mutex;
  std::deque<ServiceRequest> queue;
  // Set with the queue under `mutex`; read without it so a spin with nothing queued takes no lock.
  std::atomic<bool> has_requests{ false };
  std::atomic<uint64_t> rejected{ 0 };
  std::string last_rejection; // guarded by mutex
};

class ServiceClient::Impl : public eprosima::fastdds::dds::DataReaderListener
{
public:
  Impl(Participant::Impl& owner, const ServiceTypeSupport& type, std::string name);
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override;

  const ServiceTypeSupport& type;
  std::string name;
  ServiceEndpoints endpoints;
  NodeTypeCache::Registration type_registration; // the service type, served while this exists
  std::mutex mutex;
  std::deque<ServiceResponse> queue;
};

} // namespace wire
} // namespace ros2vtk

#endif
