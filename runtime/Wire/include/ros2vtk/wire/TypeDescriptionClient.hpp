// ros2vtk — learning a type nobody wrote a spec for from its publisher (issue 13).
//
// A topic's type may be one no library of this process registers. Its publisher knows it, and so
// does each of its subscriptions: since Jazzy every rclcpp/rclpy node serves
// `<node>/get_type_description` (REP 2011) for the types of all its endpoints. A
// RuntimeTypeResolver watches the graph for a publisher (or, for a publisher of ours, a
// subscription) of the topic with that type, takes that endpoint's node and type hash
// (ros_discovery_info and the endpoint's USER_DATA `typehash=`), asks that node for the
// description and builds the type (DynamicType.hpp), checked against the announced hash. It never
// blocks: poll() does what the graph and the replies allow and returns, so the scene's spin calls
// it each time; status() says in words what it waits for.
#ifndef ros2vtk_wire_TypeDescriptionClient_hpp
#define ros2vtk_wire_TypeDescriptionClient_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <chrono>
#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

class Participant;
class ServiceClient;

class RuntimeTypeResolver
{
public:
  /// Whose node is asked: a subscriber of ours learns from the topic's publishers; a publisher
  /// of ours from its subscriptions first, then its other publishers.
  enum class Peers
  {
    Publishers,
    SubscriptionsThenPublishers
  };
  enum class State
  {
    WaitingForPublisher,   ///< no endpoint of the type on the topic to ask yet
    WaitingForDescription, ///< asked (or about to ask) the publisher's node
    NoService,             ///< the publisher's node has no ~/get_type_description (still watched)
    Failed,                ///< the node refused, or the description was malformed (final)
    Ready                  ///< type() is the built type
  };

  /// `topic`: resolved ROS name; `ros_type`: "pkg/msg/Type". `service_wait`: how long a found
  /// publisher's node may take to show its type description service before status() says it
  /// has none (it is still used if it appears later).
  RuntimeTypeResolver(Participant& participant, std::string topic, std::string ros_type,
    std::chrono::milliseconds service_wait = std::chrono::milliseconds(3000),
    Peers peers = Peers::Publishers);
  ~RuntimeTypeResolver();
  RuntimeTypeResolver(const RuntimeTypeResolver&) = delete;
  RuntimeTypeResolver& operator=(const RuntimeTypeResolver&) = delete;

  /// Advances as far as possible without waiting. Call it from the spin.
  State poll();

  State state() const { return state_; }
  /// The built type once Ready, else nullptr.
  const MessageTypeSupport* type() const { return type_; }
  /// "waiting for the type description of pkg/msg/T from /node", "the publisher /node does not
  /// serve type descriptions (...)" ("the subscriber /node ..." when one was asked), the
  /// refusal's reason; "" once Ready.
  const std::string& status() const { return status_; }
  const std::string& ros_type() const { return ros_type_; }

private:
  bool pick_peer();
  void set_state(State state, std::string status);
  std::string waiting_text() const;

  Participant& participant_;
  std::string topic_;
  std::string ros_type_;
  std::chrono::milliseconds service_wait_;
  Peers peers_;
  State state_ = State::WaitingForPublisher;
  std::string status_;
  const MessageTypeSupport* type_ = nullptr;
  std::string node_;      ///< fully qualified name of the asked endpoint's node
  std::string type_hash_; ///< what that endpoint announces
  const char* role_ = ""; ///< "publisher" or "subscriber": what the asked endpoint is
  std::unique_ptr<ServiceClient> client_;
  int64_t sequence_ = -1;
  std::chrono::steady_clock::time_point asked_since_;
};

} // namespace wire
} // namespace ros2vtk

#endif
