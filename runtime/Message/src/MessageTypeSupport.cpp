// ros2vtk — registry of generated type supports and whole-payload helpers.
#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/CdrWriter.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <mutex>

namespace ros2vtk {
namespace wire {
namespace {

struct Registry
{
  std::mutex mutex;
  std::map<std::string, const MessageTypeSupport*> messages;
  std::map<std::string, const ServiceTypeSupport*> services;
  std::map<std::string, const ActionTypeSupport*> actions;
};

Registry& registry()
{
  static Registry instance;
  return instance;
}

// "pkg/Type" -> "pkg/<kind>/Type"; "pkg/msg/Type" stays.
std::string full_name(const std::string& name, const char* kind)
{
  const size_t first = name.find('/');
  if (first == std::string::npos || name.find('/', first + 1) != std::string::npos)
  {
    return name;
  }
  return name.substr(0, first) + "/" + kind + name.substr(first);
}

} // namespace

bool is_placeholder_field(const FieldInfo& field)
{
  return std::strcmp(field.name, "structure_needs_at_least_one_member") == 0;
}

const char* field_type_name(FieldType type)
{
  switch (type)
  {
    case FieldType::Bool:
      return "bool";
    case FieldType::Byte:
      return "byte";
    case FieldType::Char:
      return "char";
    case FieldType::Int8:
      return "int8";
    case FieldType::UInt8:
      return "uint8";
    case FieldType::Int16:
      return "int16";
    case FieldType::UInt16:
      return "uint16";
    case FieldType::Int32:
      return "int32";
    case FieldType::UInt32:
      return "uint32";
    case FieldType::Int64:
      return "int64";
    case FieldType::UInt64:
      return "uint64";
    case FieldType::Float32:
      return "float32";
    case FieldType::Float64:
      return "float64";
    case FieldType::String:
      return "string";
    case FieldType::WString:
      return "wstring";
    case FieldType::Message:
      return "message";
  }
  return "unknown";
}

void register_message_type(const MessageTypeSupport* type)
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.messages[type->ros_type] = type;
}

void register_service_type(const ServiceTypeSupport* type)
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.services[type->ros_type] = type;
}

void register_action_type(const ActionTypeSupport* type)
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.actions[type->ros_type] = type;
}

const ActionTypeSupport* find_action_type(const std::string& ros_type, std::string* error)
{
  const ActionTypeSupport* type = nullptr;
  {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    auto it = r.actions.find(full_name(ros_type, "action"));
    type = it == r.actions.end() ? nullptr : it->second;
  }
  if (!type && error)
  {
    *error = "unknown action type '" + ros_type + "' (known:";
    for (const std::string& name : registered_action_types())
    {
      *error += ' ' + name;
    }
    *error += ')';
  }
  return type;
}

std::vector<std::string> registered_action_types()
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.actions)
  {
    names.push_back(entry.first);
  }
  return names;
}

const MessageTypeSupport* find_message_type(const std::string& ros_type)
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  auto it = r.messages.find(full_name(ros_type, "msg"));
  return it == r.messages.end() ? nullptr : it->second;
}

const ServiceTypeSupport* find_service_type(const std::string& ros_type)
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  auto it = r.services.find(full_name(ros_type, "srv"));
  return it == r.services.end() ? nullptr : it->second;
}

const ServiceTypeSupport* find_service_type(const std::string& ros_type, std::string* error)
{
  const ServiceTypeSupport* type = find_service_type(ros_type);
  if (!type && error)
  {
    *error = "unknown service type '" + ros_type + "' (known:";
    for (const std::string& name : registered_service_types())
    {
      *error += ' ' + name;
    }
    *error += ')';
  }
  return type;
}

std::vector<std::string> registered_message_types()
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.messages)
  {
    names.push_back(entry.first);
  }
  return names;
}

std::vector<std::string> registered_service_types()
{
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.services)
  {
    names.push_back(entry.first);
  }
  return names;
}

void serialize_message(
  const MessageTypeSupport& type, const void* message, std::vector<uint8_t>& buffer)
{
  CdrWriter writer(buffer);
  writer.reserve(type.serialized_size(message));
  type.serialize(message, writer);
}

bool deserialize_message(const MessageTypeSupport& type, const uint8_t* data, size_t size,
  void* message, std::string* error)
{
  CdrReader reader(data, size);
  const bool ok = reader.ok() && type.deserialize(message, reader) && reader.ok();
  if (!ok && error)
  {
    *error = reader.error().empty() ? std::string("rejected by the deserializer") : reader.error();
  }
  return ok;
}

} // namespace wire
} // namespace ros2vtk
