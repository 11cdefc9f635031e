// ros2vtk (private) — urdfdom parsing with captured diagnostics.
#include "UrdfDiagnostics.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <mutex>
#include <vector>

namespace ros2vtk {
namespace robot {
namespace {

class CollectingOutputHandler : public console_bridge::OutputHandler
{
public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override
  {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN)
      messages.push_back(text);
  }
  std::vector<std::string> messages;
};

std::mutex& console_mutex()
{
  static std::mutex mutex;
  return mutex;
}

} // namespace

urdf::ModelInterfaceSharedPtr parse_urdf_with_diagnostics(
  const std::string& urdf_xml, std::string* error, std::vector<std::string>* messages)
{
  if (urdf_xml.find_first_not_of(" \t\r\n") == std::string::npos)
  {
    if (error)
      *error = "URDF is empty";
    return nullptr;
  }
  CollectingOutputHandler handler;
  urdf::ModelInterfaceSharedPtr model;
  {
    std::lock_guard<std::mutex> lock(console_mutex());
    console_bridge::OutputHandler* previous = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(&handler);
    try
    {
      model = urdf::parseURDF(urdf_xml);
    }
    catch (const std::exception& exception)
    {
      handler.messages.push_back(exception.what());
      model.reset();
    }
    console_bridge::useOutputHandler(previous);
  }
  if (messages)
    *messages = handler.messages;
  if (!model && error)
  {
    std::string details;
    for (const auto& message : handler.messages)
      details += (details.empty() ? "" : "; ") + message;
    *error = "URDF rejected by urdfdom: " +
      (details.empty() ? std::string("no diagnostic given (malformed XML or no <robot> element?)")
                       : details);
  }
  return model;
}

} // namespace robot
} // namespace ros2vtk
