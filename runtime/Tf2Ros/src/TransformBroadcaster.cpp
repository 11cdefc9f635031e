// ros2vtk — /tf and /tf_static broadcasters (tf2_ros semantics, incl. the accumulated static set).
#include "ros2vtk/tf2_ros/TransformBroadcaster.hpp"

#include "ros2vtk/tf2_msgs/msg/tf_message.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"

#include <chrono>
#include <cmath>

namespace ros2vtk {
namespace tf2_ros {

tf2::TimePoint now()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
    .count();
}

std::unique_ptr<TransformBroadcaster> TransformBroadcaster::create(
  wire::Participant& participant, bool is_static, std::string* error)
{
  std::unique_ptr<TransformBroadcaster> broadcaster(new TransformBroadcaster());
  broadcaster->is_static_ = is_static;
  const wire::QoS qos = is_static
    ? wire::QoS::transient_local(1)
    : wire::QoS{ wire::QoS::History::KeepLast, 100, wire::QoS::Reliability::Reliable,
        wire::QoS::Durability::Volatile };
  broadcaster->publisher_ = participant.create_publisher(
    tf2_msgs::msg::TFMessage::type_support(), is_static ? "/tf_static" : "/tf", qos, error);
  if (!broadcaster->publisher_)
    return nullptr;
  return broadcaster;
}

TransformBroadcaster::~TransformBroadcaster() = default;

namespace {

bool valid(const tf2::TransformStamped& t, std::string* error)
{
  auto fail = [error](const std::string& message) {
    if (error)
      *error = message;
    return false;
  };
  if (t.frame_id.empty() || t.child_frame_id.empty())
    return fail("a transform needs a parent and a child frame id");
  if (t.frame_id == t.child_frame_id)
    return fail("parent and child frame are both '" + t.frame_id + "'");
  const auto& p = t.transform.translation;
  const auto& q = t.transform.rotation;
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()) ||
    !std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()) ||
    !std::isfinite(q.w()))
    return fail("transform " + t.frame_id + " -> " + t.child_frame_id + " has non-finite values");
  return true;
}

void fill(const tf2::TransformStamped& t, geometry_msgs::msg::TransformStamped& m)
{
  m.header.stamp.sec = static_cast<int32_t>(t.stamp / 1000000000);
  m.header.stamp.nanosec = static_cast<uint32_t>(t.stamp % 1000000000);
  m.header.frame_id = t.frame_id;
  m.child_frame_id = t.child_frame_id;
  m.transform.translation.x = t.transform.translation.x();
  m.transform.translation.y = t.transform.translation.y();
  m.transform.translation.z = t.transform.translation.z();
  m.transform.rotation.x = t.transform.rotation.x();
  m.transform.rotation.y = t.transform.rotation.y();
  m.transform.rotation.z = t.transform.rotation.z();
  m.transform.rotation.w = t.transform.rotation.w();
}

} // namespace

bool TransformBroadcaster::send(
  const std::vector<tf2::TransformStamped>& transforms, std::string* error)
{
  for (const auto& t : transforms)
  {
    if (!valid(t, error))
      return false;
  }
  tf2_msgs::msg::TFMessage message;
  if (is_static_)
  {
    for (const auto& t : transforms)
      static_set_[t.child_frame_id] = t;
    for (const auto& entry : static_set_)
    {
      message.transforms.emplace_back();
      fill(entry.second, message.transforms.back());
    }
  }
  else
  {
    for (const auto& t : transforms)
    {
      message.transforms.emplace_back();
      fill(t, message.transforms.back());
    }
  }
  if (!publisher_->publish(&message))
  {
    if (error)
      *error = "DDS refused the transform message";
    return false;
  }
  return true;
}

} // namespace tf2_ros
} // namespace ros2vtk
