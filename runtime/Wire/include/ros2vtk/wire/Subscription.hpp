// ros2vtk — a typed-by-table ROS 2 subscription (DDS DataReader on `rt/<topic>`).
//
// DDS listener threads deserialize each sample and enqueue it here; they never touch the
// scene. The owner drains the queue from its own thread with take().
#ifndef ros2vtk_wire_Subscription_hpp
#define ros2vtk_wire_Subscription_hpp

#include "ros2vtk/wire/QoS.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {

struct MessageTypeSupport;

/// A received message owned by whoever took it (destroyed with its type's destroy()).
class MessagePtr
{
public:
  MessagePtr() = default;
  MessagePtr(const MessageTypeSupport* type, void* message);
  ~MessagePtr();
  MessagePtr(MessagePtr&& other) noexcept;
  MessagePtr& operator=(MessagePtr&& other) noexcept;
  MessagePtr(const MessagePtr&) = delete;
  MessagePtr& operator=(const MessagePtr&) = delete;

  void* get() const { return message_; }
  const MessageTypeSupport* type() const { return type_; }
  explicit operator bool() const { return message_ != nullptr; }
  int64_t source_timestamp_ns = 0; ///< writer's time stamp of the sample
  int64_t reception_timestamp_ns = 0;
  /// The DDS GUID of the writer that sent it (the rmw gid; Participant::node_of_writer names
  /// its node).
  std::array<uint8_t, 16> publisher_gid{};

private:
  const MessageTypeSupport* type_ = nullptr;
  void* message_ = nullptr;
};

class Subscription
{
public:
  ~Subscription();
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;

  /// Moves every queued message into `out` (appended, oldest first); returns how many.
  size_t take(std::vector<MessagePtr>& out);

  /// Receives each later message on the DDS thread that deserialized it, instead of the queue
  /// (messages queued before stay there for take()); the participant's wake-up is raised as for a
  /// queued one. For thread-safe consumers that should not wait for a spin: the tf listener
  /// inserts into its locked buffer as tf2_ros's listener thread does, so a spin only looks up.
  /// A sink must be quick and must never touch the scene. An empty function queues again.
  using Sink = std::function<void(MessagePtr&&)>;
  void set_sink(Sink sink);
  /// Messages waiting in the queue.
  size_t pending() const;

  /// Samples rejected as malformed since creation, and the reason of the latest one.
  uint64_t rejected_count() const;
  std::string last_rejection() const;
  /// Messages dropped because the queue was full (oldest dropped first).
  uint64_t dropped_count() const;
  uint64_t received_count() const;
  /// Publishers found on the topic whose QoS cannot match this subscription (each one counted
  /// once; they send nothing here), and the policy that failed last ("RELIABILITY", ...).
  uint64_t incompatible_qos_count() const;
  std::string last_incompatible_qos_policy() const;

  /// Upper bound of the queue between DDS and take() (default max(depth, 1000)).
  void set_queue_limit(size_t limit);

  const std::string& topic() const;
  const MessageTypeSupport& type() const;
  const QoS& qos() const;
  size_t matched_publications() const;

  class Impl;

private:
  friend class Participant;
  explicit Subscription(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace wire
} // namespace ros2vtk

#endif
