// ros2vtk — follows parameters of a remote node through get_parameters + /parameter_events.
#include "ros2vtk/wire/ParameterClient.hpp"

#include "ShippedTypes.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_event.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/rcl_interfaces/srv/get_parameters.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Service.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

namespace ros2vtk {
namespace wire {

namespace rcl = ::ros2vtk::rcl_interfaces;

class ParameterClient::Impl
{
public:
  std::string remote_node;
  std::unique_ptr<ServiceClient> get_client;
  std::unique_ptr<Subscription> events;
  State state = State::WaitingForNode;
  std::set<std::string> watched;
  std::set<std::string> to_fetch; ///< names to ask for in the next request
  struct Request
  {
    std::vector<std::string> names;
    std::chrono::steady_clock::time_point sent;
    std::chrono::milliseconds patience; ///< asked again when unanswered this long
    bool asked_again = false;           ///< still answerable: a late answer is used too
  };
  /// The first wait for an answer; doubled on each retry up to kLongestPatience.
  static constexpr std::chrono::milliseconds kFirstPatience{ 150 };
  static constexpr std::chrono::milliseconds kLongestPatience{ 1000 };
  std::map<int64_t, Request> in_flight; ///< request sequence -> what was asked, when
  uint64_t servers_seen = 0; ///< servers_matched_total() when the values were last fetched

  /// Everything is fetched again: a (new) server is there.
  void refetch_all(uint64_t servers)
  {
    state = State::Ready;
    to_fetch = watched;
    in_flight.clear();
    servers_seen = servers;
  }

  /// Sends a get_parameters request; false when DDS refused it (asked again later).
  bool ask(
    const std::vector<std::string>& names, std::chrono::milliseconds patience = kFirstPatience)
  {
    rcl::srv::GetParameters_Request request;
    request.names = names;
    const int64_t sequence = get_client->send_request(&request);
    if (sequence < 0)
      return false;
    in_flight[sequence] = Request{ names, std::chrono::steady_clock::now(), patience };
    return true;
  }
  std::map<std::string, rcl::msg::ParameterValue> values;
  std::set<std::string> changed;

  void store(const std::string& name, const rcl::msg::ParameterValue& value)
  {
    auto it = values.find(name);
    if (value.type == rcl::msg::ParameterType::PARAMETER_NOT_SET) // deleted, or never set
    {
      if (it != values.end())
      {
        values.erase(it);
        changed.insert(name);
      }
      return;
    }
    if (it == values.end() || !(it->second == value))
    {
      values[name] = value;
      changed.insert(name);
    }
  }
};

std::unique_ptr<ParameterClient> ParameterClient::create(
  Participant& participant, const std::string& remote_node, std::string* error)
{
  auto impl = std::make_unique<Impl>();
  impl->remote_node =
    remote_node.empty() || remote_node[0] == '/' ? remote_node : "/" + remote_node;
  impl->get_client =
    participant.create_service_client(shipped_service_type("rcl_interfaces/srv/GetParameters"),
      impl->remote_node + "/get_parameters", QoS::services(), error);
  if (!impl->get_client)
    return nullptr;
  impl->events =
    participant.create_subscription(shipped_message_type("rcl_interfaces/msg/ParameterEvent"),
      "/parameter_events", QoS::parameters(), error);
  if (!impl->events)
    return nullptr;
  return std::unique_ptr<ParameterClient>(new ParameterClient(std::move(impl)));
}

ParameterClient::ParameterClient(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}

ParameterClient::~ParameterClient() = default;

const std::string& ParameterClient::remote_node() const
{
  return impl_->remote_node;
}

ParameterClient::State ParameterClient::state() const
{
  return impl_->state;
}

void ParameterClient::add(const std::string& name)
{
  if (impl_->watched.insert(name).second)
    impl_->to_fetch.insert(name);
}

void ParameterClient::remove(const std::string& name)
{
  impl_->watched.erase(name);
  impl_->to_fetch.erase(name);
  if (impl_->values.erase(name))
    impl_->changed.insert(name);
}

std::vector<std::string> ParameterClient::watched() const
{
  return std::vector<std::string>(impl_->watched.begin(), impl_->watched.end());
}

const rcl::msg::ParameterValue* ParameterClient::value(const std::string& name) const
{
  auto it = impl_->values.find(name);
  return it == impl_->values.end() ? nullptr : &it->second;
}

std::set<std::string> ParameterClient::process()
{
  Impl& d = *impl_;
  // Availability: losing the server forgets nothing yet, but everything is fetched again when it
  // returns (the node may have restarted with other values). A node restarted within its lease
  // time never looks unavailable (the dead server stays matched), but its new server is a new
  // match: fetch again then too. Its declarations went out on /parameter_events before our
  // subscription matched its new writer, so the fetch is what brings the new values.
  const bool available = d.get_client->is_server_available();
  const uint64_t servers = d.get_client->servers_matched_total();
  if (!available && d.state == State::Ready)
  {
    d.state = State::WaitingForNode;
    d.in_flight.clear();
  }
  else if (available && (d.state == State::WaitingForNode || servers != d.servers_seen))
  {
    d.refetch_all(servers);
  }

  // Discovery is not symmetric: our endpoints may match the server's before the server's reply
  // writer matched our reply reader, and rmw servers drop a reply to an unmatched client after
  // 100 ms. So an unanswered request is asked again, after 150 ms, then twice as long each time
  // up to 1 s (get_parameters has no side effect). A slow server's late answer to an earlier
  // request is still used (kept for 30 s); the first answer settles the others of the same names.
  // It used to wait 300 ms before every first request: a third of a second on every robot load
  // from a parameter, although almost every first answer arrives (issue 15).
  const auto now = std::chrono::steady_clock::now();
  if (d.state == State::Ready)
  {
    std::vector<std::pair<std::vector<std::string>, std::chrono::milliseconds>> retries;
    for (auto it = d.in_flight.begin(); it != d.in_flight.end();)
    {
      Impl::Request& request = it->second;
      if (now - request.sent > std::chrono::seconds(30))
      {
        it = d.in_flight.erase(it);
        continue;
      }
      if (!request.asked_again && now - request.sent > request.patience)
      {
        request.asked_again = true;
        retries.emplace_back(request.names, std::min(2 * request.patience, Impl::kLongestPatience));
      }
      ++it;
    }
    for (const auto& [names, patience] : retries)
    {
      if (!d.ask(names, patience))
        d.to_fetch.insert(names.begin(), names.end()); // DDS refused: asked with the next ones
    }
    if (!d.to_fetch.empty() &&
      d.ask(std::vector<std::string>(d.to_fetch.begin(), d.to_fetch.end())))
      d.to_fetch.clear();
  }

  std::vector<ServiceResponse> responses;
  d.get_client->take(responses);
  for (const auto& response : responses)
  {
    auto it = d.in_flight.find(response.sequence_number);
    if (it == d.in_flight.end())
      continue;
    const auto* values =
      static_cast<const rcl::srv::GetParameters_Response*>(response.response.get());
    const std::vector<std::string> names = it->second.names;
    d.in_flight.erase(it);
    for (auto other = d.in_flight.begin(); other != d.in_flight.end();) // asked again: answered now
      other = other->second.names == names ? d.in_flight.erase(other) : std::next(other);
    // rclcpp and rclpy answer an empty list when any name is undeclared: ask for each name
    // alone then, so one missing parameter does not hide the others.
    if (values->values.size() != names.size())
    {
      if (names.size() > 1)
      {
        for (const auto& name : names)
          d.ask({ name });
      }
      else if (names.size() == 1)
      {
        d.store(names.front(), rcl::msg::ParameterValue());
      }
    }
    else
    {
      for (size_t i = 0; i < values->values.size(); ++i)
      {
        if (d.watched.count(names[i]))
          d.store(names[i], values->values[i]);
      }
    }
  }

  std::vector<MessagePtr> events;
  d.events->take(events);
  for (const auto& message : events)
  {
    const auto* event = static_cast<const rcl::msg::ParameterEvent*>(message.get());
    if (event->node != d.remote_node)
      continue;
    // Every parameter an event reports is kept, added or not: SlicerROS2's parameter node
    // stores them too, and its scripts wait for a parameter they never added to be set.
    for (const auto* list : { &event->new_parameters, &event->changed_parameters })
    {
      for (const auto& parameter : *list)
        d.store(parameter.name, parameter.value);
    }
    for (const auto& parameter : event->deleted_parameters)
    {
      if (d.watched.count(parameter.name) || d.values.count(parameter.name))
        d.store(parameter.name, rcl::msg::ParameterValue());
    }
  }
  std::set<std::string> changed;
  changed.swap(d.changed);
  return changed;
}

} // namespace wire
} // namespace ros2vtk
