// ros2vtk — ROS 2 services over Fast DDS the way rmw_fastrtps correlates them: a request
// topic `rq/<name>Request` and a reply topic `rr/<name>Reply`, matched by the related sample
// identity (WIRE_NOTES §4). Both sides queue from DDS threads; the owner drains them.
#ifndef ros2vtk_wire_Service_hpp
#define ros2vtk_wire_Service_hpp

#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {

struct ServiceTypeSupport;

/// Identifies one request: the GUID the client wants replies for, and the request's sequence.
struct RequestId
{
  std::array<uint8_t, 16> writer_guid{};
  int64_t sequence_number = 0;
};

/// A request as the server receives it.
struct ServiceRequest
{
  RequestId id;
  MessagePtr request;
};

/// A response as the client receives it.
struct ServiceResponse
{
  int64_t sequence_number = 0;
  MessagePtr response;
};

class ServiceServer
{
public:
  ~ServiceServer();
  ServiceServer(const ServiceServer&) = delete;
  ServiceServer& operator=(const ServiceServer&) = delete;

  /// Moves queued requests into `out`; returns how many.
  size_t take(std::vector<ServiceRequest>& out);
  /// Sends the response for `id`. Waits up to 100 ms for the client's reply reader to match
  /// (as rmw_fastrtps does) so the first reply to a new client is not lost.
  bool send_response(const RequestId& id, const void* response);

  const std::string& service_name() const;
  const ServiceTypeSupport& type() const;
  /// Requests rejected as malformed since creation, and the reason of the latest one.
  uint64_t rejected_count() const;
  std::string last_rejection() const;

  class Impl;

private:
  friend class Participant;
  explicit ServiceServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class ServiceClient
{
public:
  ~ServiceClient();
  ServiceClient(const ServiceClient&) = delete;
  ServiceClient& operator=(const ServiceClient&) = delete;

  /// True when a server's request reader and reply writer are both matched.
  bool is_server_available() const;
  /// How many server request readers this client has matched since it was created. It grows
  /// when a new server appears (a restarted node: new GUID) even while the old one is still
  /// matched because its lease has not expired.
  uint64_t servers_matched_total() const;
  /// Sends a request; returns its sequence number, or -1 when DDS refused it.
  int64_t send_request(const void* request);
  /// Moves the responses addressed to this client into `out`; returns how many.
  size_t take(std::vector<ServiceResponse>& out);

  const std::string& service_name() const;
  const ServiceTypeSupport& type() const;

  class Impl;

private:
  friend class Participant;
  explicit ServiceClient(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace wire
} // namespace ros2vtk

#endif
