// ros2vtk — /rosout publishing and the process-wide fan-out of log messages.
#include "ros2vtk/wire/Rosout.hpp"

#include "ros2vtk/rcl_interfaces/msg/log.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <vector>

namespace ros2vtk {
namespace wire {

namespace {

// The live Rosout objects of the process. log() publishes while holding the lock, so none is
// destroyed mid-publish.
std::mutex& registry_mutex()
{
  static std::mutex mutex;
  return mutex;
}

std::vector<Rosout*>& registry()
{
  static std::vector<Rosout*> live;
  return live;
}

// A message received over the network can end up in a warning; /rosout carries at most this
// much of it (rcl does not bound it, but a Log sample of megabytes helps nobody).
constexpr size_t kMaxText = 4096;

} // namespace

std::unique_ptr<Rosout> Rosout::create(Participant& participant, std::string* error)
{
  auto publisher = participant.create_publisher(
    rcl_interfaces::msg::Log::type_support(), "/rosout", QoS::transient_local(1000), error);
  if (!publisher)
  {
    return nullptr;
  }
  std::unique_ptr<Rosout> rosout(new Rosout(
    std::move(publisher), logger_name(participant.node_namespace(), participant.name())));
  std::lock_guard<std::mutex> lock(registry_mutex());
  registry().push_back(rosout.get());
  return rosout;
}

Rosout::Rosout(std::unique_ptr<Publisher> publisher, std::string logger)
  : publisher_(std::move(publisher))
  , logger_(std::move(logger))
{
}

Rosout::~Rosout()
{
  std::lock_guard<std::mutex> lock(registry_mutex());
  auto& live = registry();
  live.erase(std::remove(live.begin(), live.end(), this), live.end());
}

void Rosout::set_level(LogSeverity level)
{
  level_ = level;
}

LogSeverity Rosout::level() const
{
  return level_;
}

uint64_t Rosout::published_count() const
{
  return published_;
}

bool Rosout::publish(LogSeverity severity, const std::string& text, const std::string& file,
  const std::string& function, uint32_t line)
{
  if (static_cast<uint8_t>(severity) < static_cast<uint8_t>(level_.load()))
  {
    return false;
  }
  rcl_interfaces::msg::Log message;
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  const auto nanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch).count();
  message.stamp.sec = static_cast<int32_t>(nanoseconds / 1000000000);
  message.stamp.nanosec = static_cast<uint32_t>(nanoseconds % 1000000000);
  message.level = static_cast<uint8_t>(severity);
  message.name = logger_;
  message.msg = text.size() > kMaxText ? text.substr(0, kMaxText) + "..." : text;
  message.file = file;
  message.function = function;
  message.line = line;
  if (!publisher_->publish(&message))
  {
    return false;
  }
  ++published_;
  return true;
}

size_t Rosout::log(LogSeverity severity, const std::string& text, const std::string& file,
  const std::string& function, uint32_t line)
{
  std::lock_guard<std::mutex> lock(registry_mutex());
  size_t published = 0;
  for (Rosout* rosout : registry())
  {
    published += rosout->publish(severity, text, file, function, line) ? 1 : 0;
  }
  return published;
}

std::string Rosout::logger_name(const std::string& node_namespace, const std::string& node_name)
{
  std::string name;
  for (char c : node_namespace)
  {
    if (c == '/')
    {
      if (!name.empty() && name.back() != '.')
      {
        name += '.';
      }
    }
    else
    {
      name += c;
    }
  }
  if (!name.empty() && name.back() != '.')
  {
    name += '.';
  }
  return name + node_name;
}

} // namespace wire
} // namespace ros2vtk
