#include "NodeClassRegistry.hpp"
#include "Internal/TextAffixes.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <sstream>

namespace ros2vtk {
namespace scene {

// Defined in BuiltinNodeClasses.cxx: registers the runtime's own classes.
void register_builtin_node_classes(NodeClassRegistry& registry);

namespace {

// "vtkROS2PublisherStringNode" / "vtkMRMLROS2PublisherStringNode" -> ("Publisher", "String").
// False when the name has neither prefix.
bool split_class_name(const std::string& name, std::string& direction, std::string& short_name)
{
  std::string rest;
  if (starts_with(name, "vtkMRMLROS2"))
  {
    rest = name.substr(11);
  }
  else if (starts_with(name, "vtkROS2"))
  {
    rest = name.substr(7);
  }
  else
  {
    return false;
  }
  if (!ends_with(rest, "Node"))
  {
    return false;
  }
  rest = rest.substr(0, rest.size() - 4);
  for (const char* kind : { "Publisher", "Subscriber" })
  {
    if (starts_with(rest, kind) && rest.size() > std::char_traits<char>::length(kind))
    {
      direction = kind;
      short_name = rest.substr(std::char_traits<char>::length(kind));
      return true;
    }
  }
  return false;
}

} // namespace

//------------------------------------------------------------------------------
const char* to_string(NodeDirection direction)
{
  switch (direction)
  {
    case NodeDirection::Publisher:
      return "Publisher";
    case NodeDirection::Subscriber:
      return "Subscriber";
    case NodeDirection::Other:
      break;
  }
  return "Other";
}

//------------------------------------------------------------------------------
NodeClassRegistry& NodeClassRegistry::instance()
{
  // Built on first use, which also registers the runtime's own classes: no dependence on the
  // order in which static initializers of different libraries run.
  static NodeClassRegistry* registry = [] {
    auto* created = new NodeClassRegistry;
    register_builtin_node_classes(*created);
    return created;
  }();
  return *registry;
}

//------------------------------------------------------------------------------
bool NodeClassRegistry::add(const NodeClassInfo& info, std::string* error)
{
  auto fail = [&](const std::string& message) {
    if (error)
    {
      *error = "NodeClassRegistry: " + message;
    }
    return false;
  };
  if (info.class_name.empty() || !info.create)
  {
    return fail("a class needs a class name and a factory");
  }
  if (info.direction != NodeDirection::Other && info.short_name.empty())
  {
    return fail("publisher/subscriber class '" + info.class_name + "' needs a short name");
  }
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = classes_.find(info.class_name);
  if (it != classes_.end())
  {
    if (it->second.create == info.create)
    {
      return true;
    }
    return fail("class '" + info.class_name + "' is already registered by another library");
  }
  for (const auto& entry : classes_)
  {
    if (entry.second.direction == info.direction && info.direction != NodeDirection::Other &&
      entry.second.short_name == info.short_name)
    {
      return fail("short name '" + info.short_name + "' is already used by '" +
        entry.second.class_name + "'");
    }
  }
  classes_.emplace(info.class_name, info);
  return true;
}

//------------------------------------------------------------------------------
bool NodeClassRegistry::add_alias(
  const std::string& alias, const std::string& class_name, std::string* error)
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::string problem;
  if (classes_.count(alias))
  {
    problem = "'" + alias + "' is a registered class, not an alias";
  }
  else if (!classes_.count(class_name))
  {
    problem = "alias '" + alias + "' names the unknown class '" + class_name + "'";
  }
  else
  {
    auto it = aliases_.find(alias);
    if (it != aliases_.end() && it->second != class_name)
    {
      problem = "'" + alias + "' already names '" + it->second + "'";
    }
  }
  if (!problem.empty())
  {
    if (error)
    {
      *error = problem;
    }
    return false;
  }
  aliases_[alias] = class_name;
  return true;
}

//------------------------------------------------------------------------------
const NodeClassInfo* NodeClassRegistry::find_class(const std::string& class_name) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::string wanted = class_name;
  if (starts_with(wanted, "vtkMRMLROS2"))
  {
    wanted = "vtkROS2" + wanted.substr(11);
  }
  auto alias = aliases_.find(wanted);
  if (alias != aliases_.end())
  {
    wanted = alias->second;
  }
  auto it = classes_.find(wanted);
  return it == classes_.end() ? nullptr : &it->second;
}

//------------------------------------------------------------------------------
const NodeClassInfo* NodeClassRegistry::find_short_name(
  NodeDirection direction, const std::string& short_name) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& entry : classes_)
  {
    if (entry.second.direction == direction && entry.second.short_name == short_name)
    {
      return &entry.second;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::vector<const NodeClassInfo*> NodeClassRegistry::find_ros_type(
  NodeDirection direction, const std::string& ros_type) const
{
  std::vector<const NodeClassInfo*> found;
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& entry : classes_)
  {
    if (entry.second.direction == direction && entry.second.ros_type == ros_type)
    {
      found.push_back(&entry.second);
    }
  }
  return found;
}

//------------------------------------------------------------------------------
std::vector<const NodeClassInfo*> NodeClassRegistry::classes(NodeDirection direction) const
{
  std::vector<const NodeClassInfo*> found;
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& entry : classes_)
  {
    if (entry.second.direction == direction)
    {
      found.push_back(&entry.second);
    }
  }
  return found;
}

//------------------------------------------------------------------------------
NodeTypeResolution NodeClassRegistry::resolve(
  NodeDirection direction, const std::string& type) const
{
  NodeTypeResolution result;
  if (type.find('/') != std::string::npos)
  {
    const wire::MessageTypeSupport* message = wire::find_message_type(type);
    if (message)
    {
      auto mapped = this->find_ros_type(direction, message->ros_type);
      if (mapped.size() == 1)
      {
        result.mapped_class = mapped.front();
      }
      else
      {
        result.generic_type = message;
      }
      return result;
    }
  }
  else
  {
    std::string kind;
    std::string short_name = type;
    if (split_class_name(type, kind, short_name) && kind != to_string(direction))
    {
      result.error =
        "'" + type + "' is a " + kind + " class; use CreateAndAdd" + kind + "Node to create it";
      return result;
    }
    result.mapped_class = this->find_short_name(direction, short_name);
    if (result.mapped_class)
    {
      return result;
    }
  }

  std::ostringstream message;
  message << "unknown " << (direction == NodeDirection::Publisher ? "publisher" : "subscriber")
          << " type '" << type << "'. Known short names:";
  const auto known = this->classes(direction);
  for (const NodeClassInfo* info : known)
  {
    message << " " << info->short_name;
  }
  if (known.empty())
  {
    message << " (none: is the generated node library loaded?)";
  }
  message << "; class names: vtkROS2" << to_string(direction) << "<Short>Node or vtkMRMLROS2"
          << to_string(direction) << "<Short>Node; ROS types:";
  const auto ros_types = wire::registered_message_types();
  for (const auto& name : ros_types)
  {
    message << " " << name;
  }
  if (ros_types.empty())
  {
    message << " (none registered)";
  }
  result.error = message.str();
  return result;
}

} // namespace scene
} // namespace ros2vtk
