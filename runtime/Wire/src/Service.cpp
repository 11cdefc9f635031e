// ros2vtk — ROS 2 services with rmw_fastrtps's request/reply correlation (WIRE_NOTES §4.2).
#include "ServiceImpl.hpp"

#include "TypeAdapter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Names.hpp"

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/rtps/common/WriteParams.h>

#include <chrono>
#include <cstring>
#include <thread>

namespace ros2vtk {
namespace wire {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

namespace {

std::array<uint8_t, 16> guid_bytes(const rtps::GUID_t& guid)
{
  std::array<uint8_t, 16> bytes{};
  std::memcpy(bytes.data(), guid.guidPrefix.value, 12);
  std::memcpy(bytes.data() + 12, guid.entityId.value, 4);
  return bytes;
}

rtps::GUID_t guid_from_bytes(const std::array<uint8_t, 16>& bytes)
{
  rtps::GUID_t guid;
  std::memcpy(guid.guidPrefix.value, bytes.data(), 12);
  std::memcpy(guid.entityId.value, bytes.data() + 12, 4);
  return guid;
}

int64_t to_int64(const rtps::SequenceNumber_t& sequence)
{
  return (static_cast<int64_t>(sequence.high) << 32) | sequence.low;
}

rtps::SequenceNumber_t to_sequence(int64_t value)
{
  rtps::SequenceNumber_t sequence;
  sequence.high = static_cast<int32_t>(value >> 32);
  sequence.low = static_cast<uint32_t>(value & 0xffffffff);
  return sequence;
}

} // namespace

//------------------------------------------------------------------------------
ServiceEndpoints::ServiceEndpoints(Participant::Impl& owner_)
  : owner(owner_)
{
}

ServiceEndpoints::~ServiceEndpoints()
{
  if (reader)
  {
    reader->set_listener(nullptr);
    owner.remove_local_endpoint(reader->guid());
    owner.subscriber->delete_datareader(reader);
  }
  if (writer)
  {
    writer->set_listener(nullptr);
    owner.remove_local_endpoint(writer->guid());
    owner.publisher->delete_datawriter(writer);
  }
  if (read_topic)
  {
    owner.release_topic(read_topic);
  }
  if (write_topic)
  {
    owner.release_topic(write_topic);
  }
}

bool ServiceEndpoints::create(const MessageTypeSupport& write_type, const std::string& write_name,
  const MessageTypeSupport& read_type, const std::string& read_name, const QoS& qos,
  dds::DataReaderListener* reader_listener, std::string* error)
{
  write_topic = owner.acquire_topic(write_name, write_type, error);
  read_topic = owner.acquire_topic(read_name, read_type, error);
  if (!write_topic || !read_topic)
  {
    return false;
  }
  writer = owner.publisher->create_datawriter(write_topic,
    make_writer_qos(qos, write_type.type_hash), this, dds::StatusMask::publication_matched());
  reader = owner.subscriber->create_datareader(read_topic,
    make_reader_qos(qos, read_type.type_hash), reader_listener, dds::StatusMask::data_available());
  if (!writer || !reader)
  {
    if (error)
    {
      *error = "Fast DDS refused the endpoints of service topics " + write_name + " / " + read_name;
    }
    return false;
  }
  owner.add_local_endpoint(writer->guid(), true, write_name, write_type.dds_type_name);
  owner.add_local_endpoint(reader->guid(), false, read_name, read_type.dds_type_name);
  return true;
}

void ServiceEndpoints::on_publication_matched(
  dds::DataWriter*, const dds::PublicationMatchedStatus& info)
{
  std::array<uint8_t, 16> reader_guid{};
  std::memcpy(reader_guid.data(), info.last_subscription_handle.value, 16);
  std::lock_guard<std::mutex> lock(match_mutex_);
  if (info.current_count_change > 0)
  {
    matched_readers_.insert(reader_guid);
    ++readers_matched_total_;
  }
  else if (info.current_count_change < 0)
  {
    matched_readers_.erase(reader_guid);
  }
}

uint64_t ServiceEndpoints::readers_matched_total()
{
  std::lock_guard<std::mutex> lock(match_mutex_);
  return readers_matched_total_;
}

bool ServiceEndpoints::wait_for_matched_reader(
  const std::array<uint8_t, 16>& reader_guid, int timeout_ms)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (true)
  {
    {
      std::lock_guard<std::mutex> lock(match_mutex_);
      if (matched_readers_.count(reader_guid) > 0)
      {
        return true;
      }
    }
    if (std::chrono::steady_clock::now() >= deadline)
    {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

//------------------------------------------------------------------------------
ServiceServer::Impl::Impl(
  Participant::Impl& owner, const ServiceTypeSupport& type_, std::string name_)
  : type(type_)
  , name(std::move(name_))
  , endpoints(owner)
{
}

void ServiceServer::Impl::on_data_available(dds::DataReader* data_reader)
{
  const MessageTypeSupport& request_type = *type.request();
  ReceivedSample sample;
  dds::SampleInfo info;
  bool queued = false;
  while (data_reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK)
  {
    if (!info.valid_data)
    {
      continue;
    }
    if (!sample.valid)
    {
      ++rejected;
      {
        std::lock_guard<std::mutex> lock(mutex);
        last_rejection = sample.error;
      }
      queued = true; // wake the owner so it can report the rejection
      continue;
    }
    ServiceRequest request;
    // Replies go to the client's reply reader when it told us (related identity), else to the
    // request writer (older clients).
    const rtps::GUID_t& related = info.related_sample_identity.writer_guid();
    request.id.writer_guid =
      guid_bytes(related != rtps::GUID_t::unknown() ? related : info.sample_identity.writer_guid());
    request.id.sequence_number = to_int64(info.sample_identity.sequence_number());
    request.request = MessagePtr(&request_type, sample.message);
    sample.message = nullptr;
    {
      std::lock_guard<std::mutex> lock(mutex);
      queue.push_back(std::move(request));
      has_requests.store(true, std::memory_order_release);
    }
    queued = true;
  }
  if (sample.message)
  {
    request_type.destroy(sample.message);
  }
  if (queued)
  {
    endpoints.owner.wake_up.notify();
  }
}

ServiceServer::ServiceServer(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

ServiceServer::~ServiceServer() = default;

size_t ServiceServer::take(std::vector<ServiceRequest>& out)
{
  if (!impl_->has_requests.load(std::memory_order_acquire))
  {
    return 0; // a request queued meanwhile wakes the next spin
  }
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->has_requests.store(false, std::memory_order_relaxed);
  const size_t count = impl_->queue.size();
  for (auto& request : impl_->queue)
  {
    out.push_back(std::move(request));
  }
  impl_->queue.clear();
  return count;
}

bool ServiceServer::send_response(const RequestId& id, const void* response)
{
  // A reader GUID (entity kind bit 0x04) means the client named its reply reader: wait until
  // our reply writer matched it, or the reply would go nowhere.
  if (id.writer_guid[15] & 0x04)
  {
    if (!impl_->endpoints.wait_for_matched_reader(id.writer_guid, 100))
    {
      return false;
    }
  }
  rtps::WriteParams params;
  params.related_sample_identity().writer_guid(guid_from_bytes(id.writer_guid));
  params.related_sample_identity().sequence_number(to_sequence(id.sequence_number));
  return impl_->endpoints.writer->write(const_cast<void*>(response), params);
}

const std::string& ServiceServer::service_name() const
{
  return impl_->name;
}

const ServiceTypeSupport& ServiceServer::type() const
{
  return impl_->type;
}

uint64_t ServiceServer::rejected_count() const
{
  return impl_->rejected.load();
}

std::string ServiceServer::last_rejection() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->last_rejection;
}

//------------------------------------------------------------------------------
ServiceClient::Impl::Impl(
  Participant::Impl& owner, const ServiceTypeSupport& type_, std::string name_)
  : type(type_)
  , name(std::move(name_))
  , endpoints(owner)
{
}

void ServiceClient::Impl::on_data_available(dds::DataReader* data_reader)
{
  const MessageTypeSupport& response_type = *type.response();
  const rtps::GUID_t reader_guid = endpoints.reader->guid();
  const rtps::GUID_t writer_guid = endpoints.writer->guid();
  ReceivedSample sample;
  dds::SampleInfo info;
  bool queued = false;
  while (data_reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK)
  {
    if (!info.valid_data || !sample.valid)
    {
      continue;
    }
    // Replies reach every client of the service: keep only ours.
    const rtps::GUID_t& related = info.related_sample_identity.writer_guid();
    if (related != reader_guid && related != writer_guid)
    {
      continue;
    }
    ServiceResponse response;
    response.sequence_number = to_int64(info.related_sample_identity.sequence_number());
    response.response = MessagePtr(&response_type, sample.message);
    sample.message = nullptr;
    {
      std::lock_guard<std::mutex> lock(mutex);
      queue.push_back(std::move(response));
    }
    queued = true;
  }
  if (sample.message)
  {
    response_type.destroy(sample.message);
  }
  if (queued)
  {
    endpoints.owner.wake_up.notify();
  }
}

ServiceClient::ServiceClient(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

ServiceClient::~ServiceClient() = default;

bool ServiceClient::is_server_available() const
{
  dds::PublicationMatchedStatus publication;
  impl_->endpoints.writer->get_publication_matched_status(publication);
  dds::SubscriptionMatchedStatus subscription;
  impl_->endpoints.reader->get_subscription_matched_status(subscription);
  return publication.current_count > 0 && subscription.current_count > 0;
}

uint64_t ServiceClient::servers_matched_total() const
{
  return impl_->endpoints.readers_matched_total();
}

int64_t ServiceClient::send_request(const void* request)
{
  rtps::WriteParams params;
  params.related_sample_identity().writer_guid(impl_->endpoints.reader->guid());
  if (!impl_->endpoints.writer->write(const_cast<void*>(request), params))
  {
    return -1;
  }
  return to_int64(params.sample_identity().sequence_number());
}

size_t ServiceClient::take(std::vector<ServiceResponse>& out)
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const size_t count = impl_->queue.size();
  for (auto& response : impl_->queue)
  {
    out.push_back(std::move(response));
  }
  impl_->queue.clear();
  return count;
}

const std::string& ServiceClient::service_name() const
{
  return impl_->name;
}

const ServiceTypeSupport& ServiceClient::type() const
{
  return impl_->type;
}

//------------------------------------------------------------------------------
std::unique_ptr<ServiceServer> Participant::create_service_server(const ServiceTypeSupport& type,
  const std::string& service_name, const QoS& qos, std::string* error)
{
  std::string resolved;
  if (!resolve_name(service_name, resolved, error))
  {
    return nullptr;
  }
  auto impl = std::make_unique<ServiceServer::Impl>(*impl_, type, resolved);
  if (!impl->endpoints.create(*type.response(), service_reply_to_dds(resolved), *type.request(),
        service_request_to_dds(resolved), qos, impl.get(), error))
  {
    return nullptr;
  }
  impl->type_registration = impl_->types.add(type.type_hash, type.description);
  return std::unique_ptr<ServiceServer>(new ServiceServer(std::move(impl)));
}

std::unique_ptr<ServiceClient> Participant::create_service_client(const ServiceTypeSupport& type,
  const std::string& service_name, const QoS& qos, std::string* error)
{
  std::string resolved;
  if (!resolve_name(service_name, resolved, error))
  {
    return nullptr;
  }
  auto impl = std::make_unique<ServiceClient::Impl>(*impl_, type, resolved);
  if (!impl->endpoints.create(*type.request(), service_request_to_dds(resolved), *type.response(),
        service_reply_to_dds(resolved), qos, impl.get(), error))
  {
    return nullptr;
  }
  impl->type_registration = impl_->types.add(type.type_hash, type.description);
  return std::unique_ptr<ServiceClient>(new ServiceClient(std::move(impl)));
}

} // namespace wire
} // namespace ros2vtk
