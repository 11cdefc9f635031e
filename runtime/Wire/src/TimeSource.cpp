// ros2vtk — use_sim_time and /clock into a ROSClock (rclpy/time_source.py semantics).
#include "ros2vtk/wire/TimeSource.hpp"

#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/rosgraph_msgs/msg/clock.hpp"
#include "ros2vtk/wire/ParameterStore.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/ROSClock.hpp"
#include "ros2vtk/wire/Subscription.hpp"

#include <vector>

namespace ros2vtk {
namespace wire {

namespace {
constexpr uint8_t kBool = rcl::ParameterType::PARAMETER_BOOL;

/// rclpy's QoS for /clock: QoSProfile(depth=1, reliability=BEST_EFFORT), volatile. Only the
/// newest time matters, and best effort matches both kinds of publisher.
QoS clock_qos()
{
  return QoS{ QoS::History::KeepLast, 1, QoS::Reliability::BestEffort, QoS::Durability::Volatile };
}
} // namespace

std::unique_ptr<TimeSource> TimeSource::create(
  Participant& participant, ParameterStore& store, ROSClock& clock, std::string* error)
{
  std::unique_ptr<TimeSource> source(new TimeSource(participant, store, clock));
  const rcl::ParameterValue* value = store.get(kUseSimTimeParameter);
  if (!value)
  {
    rcl::ParameterValue off;
    off.type = kBool;
    off.bool_value = false;
    if (!store.declare(kUseSimTimeParameter, off, error))
      return nullptr;
    value = store.get(kUseSimTimeParameter);
  }
  if (value->type != kBool)
  {
    if (error)
      *error = std::string(kUseSimTimeParameter) + " is declared with type " +
        parameter_type_name(value->type) + ", not bool";
    return nullptr;
  }
  if (!source->set_active(value->bool_value, error))
    return nullptr;
  // The store refuses a set of another type (use_sim_time is not dynamically typed), so every
  // set that reaches here carries a bool.
  TimeSource* self = source.get();
  source->callback_id_ =
    store.add_post_set_callback([self](const std::vector<rcl::Parameter>& changed) {
      for (const auto& parameter : changed)
      {
        if (parameter.name == kUseSimTimeParameter && parameter.value.type == kBool)
        {
          std::string reason;
          self->last_error_.clear();
          if (!self->set_active(parameter.value.bool_value, &reason))
            self->last_error_ = reason;
        }
      }
    });
  return source;
}

TimeSource::TimeSource(Participant& participant, ParameterStore& store, ROSClock& clock)
  : participant_(participant)
  , store_(store)
  , clock_(clock)
{
}

TimeSource::~TimeSource()
{
  if (callback_id_)
    store_.remove_post_set_callback(callback_id_);
}

bool TimeSource::set_active(bool active, std::string* error)
{
  if (active && !subscription_)
  {
    subscription_ = participant_.create_subscription(
      rosgraph_msgs::msg::Clock::type_support(), kClockTopic, clock_qos(), error);
    if (!subscription_)
      return false;
  }
  else if (!active)
  {
    subscription_.reset();
  }
  clock_.set_sim_time_active(active);
  return true;
}

size_t TimeSource::process()
{
  if (!subscription_)
    return 0;
  std::vector<MessagePtr> messages;
  subscription_->take(messages);
  for (const auto& message : messages)
  {
    const auto* sample = static_cast<const rosgraph_msgs::msg::Clock*>(message.get());
    clock_.set_sim_time(static_cast<int64_t>(sample->clock.sec) * 1000000000 +
      static_cast<int64_t>(sample->clock.nanosec));
  }
  return messages.size();
}

} // namespace wire
} // namespace ros2vtk
