#include "GenericMessageType.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkObject.h"
#include "vtkXMLDataElement.h"

#include <cctype>
#include <vector>

namespace ros2vtk {
namespace scene {

const wire::MessageTypeSupport* find_generic_type(const char* ros_type, std::string& error)
{
  const wire::MessageTypeSupport* type = ros_type ? wire::find_message_type(ros_type) : nullptr;
  if (!type)
  {
    error = std::string("unknown ROS message type '") + (ros_type ? ros_type : "(null)") +
      "'; registered types:";
    const auto known = wire::registered_message_types();
    for (const auto& name : known)
    {
      error += " " + name;
    }
    if (known.empty())
    {
      error += " (none: is the generated message library loaded?)";
    }
  }
  return type;
}

std::string assign_generic_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, bool& changed)
{
  changed = false;
  if (added_to_ros_node)
  {
    return "cannot change the type while added to a ROS node";
  }
  std::string error;
  const wire::MessageTypeSupport* found = find_generic_type(ros_type, error);
  if (!found)
  {
    return error;
  }
  changed = found != type;
  type = found;
  return std::string();
}

bool runtime_type_name(std::string& ros_type)
{
  std::vector<std::string> parts;
  size_t start = 0;
  while (true)
  {
    const size_t slash = ros_type.find('/', start);
    parts.push_back(
      ros_type.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos)
    {
      break;
    }
    start = slash + 1;
  }
  if (parts.size() < 2 || parts.size() > 3 || (parts.size() == 3 && parts[1] != "msg") ||
    ros_type.size() > 256)
  {
    return false;
  }
  for (const std::string& part : parts)
  {
    if (part.empty() || !std::isalpha(static_cast<unsigned char>(part[0])))
    {
      return false;
    }
    for (char c : part)
    {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      {
        return false;
      }
    }
  }
  ros_type = parts[0] + "/msg/" + parts.back();
  return true;
}

const char* saved_generic_type(vtkXMLDataElement* element)
{
  const char* ros_type = element ? element->GetAttribute("rosType") : nullptr;
  return ros_type && *ros_type ? ros_type : nullptr;
}

std::string assign_learnt_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, LearntMessageType& learnt,
  wire::RuntimeTypeResolver::Peers peers, bool& changed)
{
  changed = false;
  std::string name = ros_type ? ros_type : "";
  if (!runtime_type_name(name))
  {
    return std::string("'") + (ros_type ? ros_type : "(null)") +
      "' is not a message type name (pkg/msg/Type)";
  }
  if (added_to_ros_node)
  {
    return "cannot change the type while added to a ROS node";
  }
  if (name == learnt.name() && !type)
  {
    return std::string();
  }
  type = nullptr;
  learnt.set(name.c_str(), peers);
  changed = true;
  return std::string();
}

bool finish_type_change(vtkObject* node, const char* call, const std::string& error, bool changed)
{
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(node, << call << ": " << error);
    return false;
  }
  if (changed)
  {
    node->Modified();
  }
  return true;
}

LearntMessageType::LearntMessageType() = default;
LearntMessageType::~LearntMessageType() = default;

bool LearntMessageType::set(const char* ros_type, Peers peers)
{
  std::string name = ros_type ? ros_type : "";
  if (!runtime_type_name(name))
  {
    return false;
  }
  resolver_.reset();
  name_ = name;
  peers_ = peers;
  named_only_.reset(new wire::MessageTypeSupport{});
  named_only_->ros_type = name_.c_str();
  named_only_->dds_type_name = "";
  named_only_->type_hash = "";
  status_ = waiting_to_be_added();
  return true;
}

void LearntMessageType::clear()
{
  resolver_.reset();
  named_only_.reset();
  name_.clear();
  status_.clear();
}

std::string LearntMessageType::waiting_to_be_added() const
{
  return "waiting to be added to a ROS node to learn " + name_ + " from a " +
    (peers_ == Peers::Publishers ? "publisher" : "subscriber or publisher");
}

void LearntMessageType::start(wire::Participant& participant, const std::string& topic)
{
  resolver_.reset(new wire::RuntimeTypeResolver(
    participant, topic, name_, std::chrono::milliseconds(3000), peers_));
  status_ = resolver_->status();
}

void LearntMessageType::stop()
{
  resolver_.reset();
  if (!name_.empty())
  {
    status_ = waiting_to_be_added();
  }
}

const wire::MessageTypeSupport* LearntMessageType::poll(bool& status_changed)
{
  status_changed = false;
  if (!resolver_)
  {
    return nullptr;
  }
  const auto state = resolver_->poll();
  if (resolver_->status() != status_)
  {
    status_ = resolver_->status();
    status_changed = true;
  }
  if (state != wire::RuntimeTypeResolver::State::Ready)
  {
    return nullptr;
  }
  const wire::MessageTypeSupport* type = resolver_->type();
  resolver_.reset();
  return type;
}

std::string LearntMessageType::set_registered(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, bool& changed)
{
  const std::string error = assign_generic_type(ros_type, added_to_ros_node, type, changed);
  if (error.empty() && !empty())
  {
    clear(); // a registered type replaces one to be learnt
    changed = true;
  }
  return error;
}

std::string LearntMessageType::set_resolved_at_runtime(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, Peers peers, bool& changed)
{
  if (ros_type && wire::find_message_type(ros_type))
  {
    return set_registered(ros_type, added_to_ros_node, type, changed);
  }
  return assign_learnt_type(ros_type, added_to_ros_node, type, *this, peers, changed);
}

bool LearntMessageType::watch_unless_known(
  const wire::MessageTypeSupport* type, wire::Participant& participant, const std::string& topic)
{
  if (type)
  {
    return false;
  }
  start(participant, topic);
  return true;
}

void LearntMessageType::stop_unless_known(const wire::MessageTypeSupport* type)
{
  if (!type)
  {
    stop();
  }
}

void LearntMessageType::spin_node(vtkObject* node, const wire::MessageTypeSupport*& type,
  wire::Participant* participant, const char* verb,
  const std::function<bool(wire::Participant&, std::string&)>& create)
{
  const bool changed = spin(
    type, verb, [&](std::string& error) { return participant && create(*participant, error); });
  if (changed && !type && !asking())
  {
    vtkErrorWithObjectMacro(node, << status());
  }
  if (changed)
  {
    node->Modified();
  }
}

} // namespace scene
} // namespace ros2vtk
