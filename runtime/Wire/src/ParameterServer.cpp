// ros2vtk — the rcl_interfaces parameter services and /parameter_events of one node.
#include "ros2vtk/wire/ParameterServer.hpp"

#include "ShippedTypes.hpp"
#include "ros2vtk/rcl_interfaces/srv/describe_parameters.hpp"
#include "ros2vtk/rcl_interfaces/srv/get_parameter_types.hpp"
#include "ros2vtk/rcl_interfaces/srv/get_parameters.hpp"
#include "ros2vtk/rcl_interfaces/srv/list_parameters.hpp"
#include "ros2vtk/rcl_interfaces/srv/set_parameters.hpp"
#include "ros2vtk/rcl_interfaces/srv/set_parameters_atomically.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"
#include "ros2vtk/wire/ROSClock.hpp"
#include "ros2vtk/wire/Service.hpp"

#include <chrono>
#include <functional>
#include <vector>

namespace ros2vtk {
namespace wire {

namespace srv = ::ros2vtk::rcl_interfaces::srv;

class ParameterServer::Impl
{
public:
  struct Endpoint
  {
    std::unique_ptr<ServiceServer> server;
    /// Fills the response for one request (both are structs of this service's types).
    std::function<void(const void* request, void* response)> answer;
  };

  ParameterStore store;
  std::string node_name;
  std::vector<Endpoint> endpoints;
  std::unique_ptr<Publisher> events;
  const ROSClock* clock = nullptr; // the node's clock for event stamps; system time without one
};

namespace {

template<typename Request, typename Response>
bool add_service(ParameterServer::Impl& impl, Participant& participant, const char* service,
  const char* ros_type, std::function<void(const Request&, Response&)> answer, std::string* error)
{
  ParameterServer::Impl::Endpoint endpoint;
  endpoint.server = participant.create_service_server(
    shipped_service_type(ros_type), "~/" + std::string(service), QoS::parameters(), error);
  if (!endpoint.server)
    return false;
  endpoint.answer = [answer](const void* request, void* response) {
    answer(*static_cast<const Request*>(request), *static_cast<Response*>(response));
  };
  impl.endpoints.push_back(std::move(endpoint));
  return true;
}

} // namespace

std::unique_ptr<ParameterServer> ParameterServer::create(
  Participant& participant, std::string* error)
{
  auto impl = std::make_unique<Impl>();
  impl->node_name = participant.fully_qualified_name();
  ParameterStore& store = impl->store;
  const bool ok = add_service<srv::GetParameters_Request, srv::GetParameters_Response>(
                    *impl, participant, "get_parameters", "rcl_interfaces/srv/GetParameters",
                    [&store](const auto& request, auto& response) {
                      response.values = store.get_parameters(request.names);
                    },
                    error) &&
    add_service<srv::GetParameterTypes_Request, srv::GetParameterTypes_Response>(
      *impl, participant, "get_parameter_types", "rcl_interfaces/srv/GetParameterTypes",
      [&store](const auto& request, auto& response) {
        response.types = store.get_parameter_types(request.names);
      },
      error) &&
    add_service<srv::SetParameters_Request, srv::SetParameters_Response>(
      *impl, participant, "set_parameters", "rcl_interfaces/srv/SetParameters",
      [&store](const auto& request, auto& response) {
        response.results = store.set_parameters(request.parameters);
      },
      error) &&
    add_service<srv::SetParametersAtomically_Request, srv::SetParametersAtomically_Response>(
      *impl, participant, "set_parameters_atomically", "rcl_interfaces/srv/SetParametersAtomically",
      [&store](const auto& request, auto& response) {
        response.result = store.set_parameters_atomically(request.parameters);
      },
      error) &&
    add_service<srv::DescribeParameters_Request, srv::DescribeParameters_Response>(
      *impl, participant, "describe_parameters", "rcl_interfaces/srv/DescribeParameters",
      [&store](const auto& request, auto& response) {
        response.descriptors = store.describe_parameters(request.names);
      },
      error) &&
    add_service<srv::ListParameters_Request, srv::ListParameters_Response>(
      *impl, participant, "list_parameters", "rcl_interfaces/srv/ListParameters",
      [&store](const auto& request, auto& response) {
        response.result = store.list_parameters(request.prefixes, request.depth);
      },
      error);
  if (!ok)
    return nullptr;
  impl->events =
    participant.create_publisher(shipped_message_type("rcl_interfaces/msg/ParameterEvent"),
      "/parameter_events", QoS::parameters(), error);
  if (!impl->events)
    return nullptr;
  return std::unique_ptr<ParameterServer>(new ParameterServer(std::move(impl)));
}

ParameterServer::ParameterServer(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

ParameterServer::~ParameterServer() = default;

ParameterStore& ParameterServer::store()
{
  return impl_->store;
}

void ParameterServer::set_clock(const ROSClock* clock)
{
  impl_->clock = clock;
}

size_t ParameterServer::process()
{
  size_t answered = 0;
  std::vector<ServiceRequest> requests;
  for (auto& endpoint : impl_->endpoints)
  {
    requests.clear();
    if (endpoint.server->take(requests) == 0)
    {
      continue;
    }
    const MessageTypeSupport& response_type = *endpoint.server->type().response();
    for (const auto& request : requests)
    {
      void* response = response_type.create();
      endpoint.answer(request.request.get(), response);
      endpoint.server->send_response(request.id, response);
      response_type.destroy(response);
      ++answered;
    }
  }
  publish_events();
  return answered;
}

size_t ParameterServer::publish_events()
{
  std::vector<rcl::ParameterEvent> events = impl_->store.take_events();
  if (events.empty())
  {
    return 0; // the usual spin: no clock read
  }
  // rclpy stamps parameter events with the node's clock (simulated time when it is on).
  const int64_t nanoseconds = impl_->clock ? impl_->clock->now()
                                           : std::chrono::duration_cast<std::chrono::nanoseconds>(
                                               std::chrono::system_clock::now().time_since_epoch())
                                               .count();
  for (auto& event : events)
  {
    event.stamp.sec = static_cast<int32_t>(nanoseconds / 1000000000);
    event.stamp.nanosec = static_cast<uint32_t>(nanoseconds % 1000000000);
    event.node = impl_->node_name;
    impl_->events->publish(&event);
  }
  return 0;
}

} // namespace wire
} // namespace ros2vtk
