// ros2vtk — /tf and /tf_static into a tf2 buffer (tf2_ros/src/transform_listener.cpp semantics).
#include "ros2vtk/tf2_ros/TransformListener.hpp"

#include "ros2vtk/tf2_msgs/msg/tf_message.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <vector>

namespace ros2vtk {
namespace tf2_ros {

std::unique_ptr<TransformListener> TransformListener::create(
  wire::Participant& participant, tf2::BufferCore& buffer, std::string* error)
{
  std::unique_ptr<TransformListener> listener(new TransformListener(participant, buffer));
  const wire::MessageTypeSupport& type = tf2_msgs::msg::TFMessage::type_support();
  wire::QoS dynamic_qos{ wire::QoS::History::KeepLast, 100, wire::QoS::Reliability::Reliable,
    wire::QoS::Durability::Volatile };
  wire::QoS static_qos{ wire::QoS::History::KeepLast, 100, wire::QoS::Reliability::Reliable,
    wire::QoS::Durability::TransientLocal };
  listener->dynamic_ = participant.create_subscription(type, "/tf", dynamic_qos, error);
  listener->static_ = participant.create_subscription(type, "/tf_static", static_qos, error);
  if (!listener->dynamic_ || !listener->static_)
    return nullptr;
  TransformListener* self = listener.get(); // the sinks go with the subscriptions it owns
  listener->static_->set_sink([self](wire::MessagePtr&& message) { self->insert(message, true); });
  listener->dynamic_->set_sink(
    [self](wire::MessagePtr&& message) { self->insert(message, false); });
  return listener;
}

const std::string TransformListener::kUnknownAuthority = "ros2vtk_tf_listener";

TransformListener::TransformListener(wire::Participant& participant, tf2::BufferCore& buffer)
  : participant_(participant)
  , buffer_(buffer)
{
}

const std::string& TransformListener::authority_of(const std::array<uint8_t, 16>& writer)
{
  const auto known = authorities_.find(writer);
  if (known != authorities_.end())
    return known->second;
  std::string node = participant_.node_of_writer(writer);
  if (node.empty())
    return kUnknownAuthority; // asked again with its next message: announcements come late
  return authorities_.emplace(writer, std::move(node)).first->second;
}

void TransformListener::resolve_authorities()
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto writer = unresolved_.begin(); writer != unresolved_.end();)
  {
    const std::string& node = authority_of(writer->first);
    if (&node == &kUnknownAuthority)
    {
      ++writer;
      continue;
    }
    for (const std::string& frame : writer->second)
    {
      buffer_.replace_authority(frame, kUnknownAuthority, node);
    }
    writer = unresolved_.erase(writer);
  }
  has_unresolved_ = !unresolved_.empty();
}

TransformListener::~TransformListener()
{
  // Stop the DDS threads' inserts before any member they use goes.
  dynamic_.reset();
  static_.reset();
}

std::string TransformListener::last_rejection() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_rejection_;
}

void TransformListener::insert(const wire::MessagePtr& message, bool is_static)
{
  const auto* tf = static_cast<const tf2_msgs::msg::TFMessage*>(message.get());
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string& authority = authority_of(message.publisher_gid);
  tf2::TransformStamped& transform = scratch_;
  for (const auto& t : tf->transforms)
  {
    transform.frame_id = t.header.frame_id;
    transform.child_frame_id = t.child_frame_id;
    transform.stamp = tf2::time_from_sec_nanosec(t.header.stamp.sec, t.header.stamp.nanosec);
    transform.transform.translation = Eigen::Vector3d(
      t.transform.translation.x, t.transform.translation.y, t.transform.translation.z);
    // Eigen's constructor order is (w, x, y, z).
    transform.transform.rotation = Eigen::Quaterniond(t.transform.rotation.w,
      t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z);
    if (buffer_.set_transform(transform, authority, is_static, &reason_))
    {
      ++inserted_;
      if (&authority == &kUnknownAuthority)
      {
        const std::string& child = transform.child_frame_id;
        unresolved_[message.publisher_gid].insert(
          !child.empty() && child[0] == '/' ? child.substr(1) : child); // as the buffer stores it
        has_unresolved_ = true;
      }
    }
    else
    {
      ++rejected_;
      last_rejection_ = reason_;
    }
  }
}

size_t TransformListener::process()
{
  // Messages that arrived before create() set the sinks (a transient-local /tf_static backlog):
  // taken by the first call; the sinks receive everything later.
  for (auto* subscription : { static_.get(), dynamic_.get() })
  {
    if (backlog_taken_)
      break;
    if (subscription->pending() == 0)
      continue;
    taken_.clear();
    subscription->take(taken_);
    for (const auto& message : taken_)
      insert(message, subscription == static_.get());
    taken_.clear();
  }
  backlog_taken_ = true;
  if (has_unresolved_.load())
  {
    resolve_authorities();
  }
  const uint64_t inserted = inserted_;
  const size_t count = static_cast<size_t>(inserted - inserted_reported_);
  inserted_reported_ = inserted;
  return count;
}

} // namespace tf2_ros
} // namespace ros2vtk
