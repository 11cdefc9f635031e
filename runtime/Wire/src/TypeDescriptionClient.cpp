// ros2vtk — RuntimeTypeResolver (TypeDescriptionClient.hpp): graph -> publisher's node ->
// ~/get_type_description -> DynamicType, one non-blocking step per poll().
#include "ros2vtk/wire/TypeDescriptionClient.hpp"

#include "ShippedTypes.hpp"
#include "ros2vtk/type_description_interfaces/srv/get_type_description.hpp"
#include "ros2vtk/wire/DynamicType.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Service.hpp"
#include "ros2vtk/wire/TypeDescriptionService.hpp"
#include "ros2vtk/wire/Utf8.hpp"

#include <cctype>
#include <vector>

namespace ros2vtk {
namespace wire {

namespace tdi = ::ros2vtk::type_description_interfaces;

namespace {

/// Keeps each described type's source the peer sent (so our node serves it on), and reads the
/// constants of the .msg ones (encoding "msg"; .srv and .action sources are not split into
/// their messages here, so those types get none). A source that does not parse leaves its type
/// without constants: the type is still usable.
void add_sources(const std::vector<tdi::msg::TypeSource>& sources, TypeDescriptionData& description)
{
  for (const tdi::msg::TypeSource& source : sources)
  {
    IndividualDescription* target =
      source.type_name == description.type.type_name ? &description.type : nullptr;
    for (IndividualDescription& referenced : description.referenced)
    {
      target = referenced.type_name == source.type_name ? &referenced : target;
    }
    if (!target)
    {
      continue;
    }
    target->source_encoding = source.encoding;
    target->source_contents = source.raw_file_contents;
    std::vector<DescriptionConstant> constants;
    std::string error;
    if (source.encoding == "msg" &&
      parse_msg_constants(source.raw_file_contents, &constants, &error))
    {
      target->constants = std::move(constants);
    }
  }
}

bool same_hash(const std::string& a, const std::string& b)
{
  if (a.size() != b.size())
    return false;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
      std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

std::string node_name_of(const EndpointInfo& info)
{
  if (info.node_namespace.empty() || info.node_namespace == "/")
    return "/" + info.node_name;
  return info.node_namespace + "/" + info.node_name;
}

/// The endpoints of `topic` that may be asked, in the order they are tried, each with the word
/// for its kind.
std::vector<std::pair<EndpointInfo, const char*>> candidates(
  const Participant& participant, const std::string& topic, RuntimeTypeResolver::Peers peers)
{
  std::vector<std::pair<EndpointInfo, const char*>> result;
  if (peers == RuntimeTypeResolver::Peers::SubscriptionsThenPublishers)
  {
    for (EndpointInfo& info : participant.subscribers_info(topic))
      result.emplace_back(std::move(info), "subscriber");
  }
  for (EndpointInfo& info : participant.publishers_info(topic))
    result.emplace_back(std::move(info), "publisher");
  return result;
}

} // namespace

RuntimeTypeResolver::RuntimeTypeResolver(Participant& participant, std::string topic,
  std::string ros_type, std::chrono::milliseconds service_wait, Peers peers)
  : participant_(participant)
  , topic_(std::move(topic))
  , ros_type_(std::move(ros_type))
  , service_wait_(service_wait)
  , peers_(peers)
{
  status_ = waiting_text();
}

std::string RuntimeTypeResolver::waiting_text() const
{
  return std::string("waiting for a ") +
    (peers_ == Peers::Publishers ? "publisher" : "subscriber or publisher") + " of " + ros_type_ +
    " on " + topic_ + " to learn the type from";
}

RuntimeTypeResolver::~RuntimeTypeResolver() = default;

void RuntimeTypeResolver::set_state(State state, std::string status)
{
  state_ = state;
  status_ = std::move(status);
}

bool RuntimeTypeResolver::pick_peer()
{
  const char* unnamed = nullptr;
  for (const auto& candidate : candidates(participant_, topic_, peers_))
  {
    const EndpointInfo& info = candidate.first;
    if (info.ros_type != ros_type_)
      continue;
    if (info.node_name.empty())
    {
      unnamed = unnamed ? unnamed : candidate.second; // its node's announcement is still to come
      continue;
    }
    node_ = node_name_of(info);
    type_hash_ = info.type_hash;
    role_ = candidate.second;
    return true;
  }
  set_state(State::WaitingForPublisher,
    unnamed ? std::string("waiting for the node name of the ") + unnamed + " of " + ros_type_ +
        " on " + topic_
            : waiting_text());
  return false;
}

RuntimeTypeResolver::State RuntimeTypeResolver::poll()
{
  if (state_ == State::Ready || state_ == State::Failed)
  {
    return state_;
  }
  if (node_.empty())
  {
    if (!pick_peer())
    {
      return state_;
    }
    if (type_hash_.empty())
    {
      set_state(State::NoService,
        "the " + std::string(role_) + " " + node_ + " announces no type hash for " + ros_type_ +
          " (ROS 2 before Jazzy): it cannot be asked for the type description");
      node_.clear(); // look again: another publisher may announce one
      return state_;
    }
    // Built already (another subscriber, or a library registered it meanwhile)?
    const MessageTypeSupport* known = find_message_type(ros_type_);
    if (known && known->type_hash && same_hash(known->type_hash, type_hash_))
    {
      type_ = known;
      set_state(State::Ready, "");
      return state_;
    }
    std::string error;
    client_ = participant_.create_service_client(
      shipped_service_type("type_description_interfaces/srv/GetTypeDescription"),
      node_ + "/get_type_description", QoS::services(), &error);
    if (!client_)
    {
      set_state(State::Failed,
        "cannot ask " + node_ + " for the type description of " + ros_type_ + ": " + error);
      return state_;
    }
    sequence_ = -1;
    asked_since_ = std::chrono::steady_clock::now();
    set_state(State::WaitingForDescription,
      "waiting for the type description of " + ros_type_ + " from " + node_);
  }
  // The asked endpoint left before answering: start over with whoever is there next.
  bool present = false;
  for (const auto& candidate : candidates(participant_, topic_, peers_))
  {
    present =
      present || (candidate.first.ros_type == ros_type_ && node_name_of(candidate.first) == node_);
  }
  if (!present)
  {
    client_.reset();
    node_.clear();
    pick_peer();
    return state_;
  }
  if (sequence_ < 0)
  {
    if (client_->is_server_available())
    {
      tdi::srv::GetTypeDescription_Request request;
      request.type_name = ros_type_;
      request.type_hash = type_hash_;
      // The .msg sources: a description has no constants, the source text does.
      request.include_type_sources = true;
      sequence_ = client_->send_request(&request);
      set_state(State::WaitingForDescription,
        "waiting for the type description of " + ros_type_ + " from " + node_);
    }
    else if (std::chrono::steady_clock::now() - asked_since_ > service_wait_)
    {
      set_state(State::NoService,
        "the " + std::string(role_) + " " + node_ + " does not serve type descriptions (no " +
          node_ + "/get_type_description after " +
          std::to_string(service_wait_.count() / 1000.0).substr(0, 3) +
          " s; nodes before Jazzy, or started with start_type_description_service false, have "
          "none)");
    }
    return state_;
  }
  std::vector<ServiceResponse> responses;
  client_->take(responses);
  for (const ServiceResponse& reply : responses)
  {
    if (reply.sequence_number != sequence_ || !reply.response)
    {
      continue;
    }
    const auto& response =
      *static_cast<const tdi::srv::GetTypeDescription_Response*>(reply.response.get());
    if (!response.successful)
    {
      set_state(State::Failed,
        "the " + std::string(role_) + " " + node_ + " did not give the type description of " +
          ros_type_ + ": " + clip_for_message(response.failure_reason));
      client_.reset();
      return state_;
    }
    std::string error;
    TypeDescriptionData description = from_message(response.type_description);
    add_sources(response.type_sources, description);
    const MessageTypeSupport* built = build_dynamic_message_type(description, type_hash_, &error);
    client_.reset();
    if (!built)
    {
      set_state(State::Failed,
        "the type description of " + ros_type_ + " from " + node_ + " is unusable: " + error);
      return state_;
    }
    if (built->ros_type != ros_type_)
    {
      set_state(
        State::Failed, node_ + " described " + built->ros_type + " when asked for " + ros_type_);
      return state_;
    }
    type_ = built;
    set_state(State::Ready, "");
    return state_;
  }
  return state_;
}

} // namespace wire
} // namespace ros2vtk
