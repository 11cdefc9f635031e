// ros2vtk — text access to one message field by path (see MessageFields.hpp).
#include "MessageFields.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace ros2vtk {
namespace scene {

namespace {

using wire::Container;
using wire::FieldInfo;
using wire::FieldType;
using wire::MessageTypeSupport;

/// Walks `path` to its field; `owner` is the struct holding it. nullptr and `error` when unknown.
const FieldInfo* find_field(const MessageTypeSupport& type, const std::string& path,
  const MessageTypeSupport*& owner_type, size_t& owner_offset, std::string* error)
{
  const MessageTypeSupport* current = &type;
  size_t offset = 0;
  size_t start = 0;
  while (true)
  {
    const size_t dot = path.find('.', start);
    const std::string name = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    const FieldInfo* found = nullptr;
    for (uint32_t i = 0; i < current->field_count; ++i)
    {
      if (name == current->fields[i].name)
      {
        found = &current->fields[i];
        break;
      }
    }
    if (!found)
    {
      if (error)
      {
        std::ostringstream text;
        text << current->ros_type << " has no field '" << name << "' (path '" << path << "'; fields:";
        for (uint32_t i = 0; i < current->field_count; ++i)
        {
          text << ' ' << current->fields[i].name;
        }
        text << ')';
        *error = text.str();
      }
      return nullptr;
    }
    if (dot == std::string::npos)
    {
      owner_type = current;
      owner_offset = offset;
      return found;
    }
    if (found->type != FieldType::Message || found->container != Container::None)
    {
      if (error)
      {
        *error = "'" + name + "' in path '" + path + "' is not a nested message";
      }
      return nullptr;
    }
    offset += found->offset;
    current = found->nested();
    start = dot + 1;
  }
}

template <typename Int>
bool parse_integer(const std::string& text, Int& out)
{
  errno = 0;
  char* end = nullptr;
  if (std::numeric_limits<Int>::is_signed)
  {
    const long long value = std::strtoll(text.c_str(), &end, 0);
    if (errno || end == text.c_str() || *end || value < static_cast<long long>(std::numeric_limits<Int>::min()) ||
      value > static_cast<long long>(std::numeric_limits<Int>::max()))
    {
      return false;
    }
    out = static_cast<Int>(value);
    return true;
  }
  if (text.find('-') != std::string::npos)
  {
    return false;
  }
  const unsigned long long value = std::strtoull(text.c_str(), &end, 0);
  if (errno || end == text.c_str() || *end || value > static_cast<unsigned long long>(std::numeric_limits<Int>::max()))
  {
    return false;
  }
  out = static_cast<Int>(value);
  return true;
}

bool parse_double(const std::string& text, double& out)
{
  errno = 0;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return !errno && end != text.c_str() && !*end;
}

template <typename T>
T& at(void* message, size_t offset)
{
  return *reinterpret_cast<T*>(static_cast<char*>(message) + offset);
}

template <typename T>
const T& at(const void* message, size_t offset)
{
  return *reinterpret_cast<const T*>(static_cast<const char*>(message) + offset);
}

} // namespace

//------------------------------------------------------------------------------
bool set_field_from_text(const MessageTypeSupport& type, void* message, const std::string& path,
  const std::string& value, std::string* error)
{
  const MessageTypeSupport* owner = nullptr;
  size_t base = 0;
  const FieldInfo* field = find_field(type, path, owner, base, error);
  if (!field)
  {
    return false;
  }
  if (field->container != Container::None || field->type == FieldType::Message ||
    field->type == FieldType::WString)
  {
    if (error)
    {
      *error = "field '" + path + "' is a sequence, a message or a wstring: set it with YAML";
    }
    return false;
  }
  const size_t offset = base + field->offset;
  bool ok = true;
  switch (field->type)
  {
    case FieldType::Bool:
      if (value == "true" || value == "True" || value == "1")
        at<bool>(message, offset) = true;
      else if (value == "false" || value == "False" || value == "0")
        at<bool>(message, offset) = false;
      else
        ok = false;
      break;
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8: ok = parse_integer(value, at<uint8_t>(message, offset)); break;
    case FieldType::Int8: ok = parse_integer(value, at<int8_t>(message, offset)); break;
    case FieldType::Int16: ok = parse_integer(value, at<int16_t>(message, offset)); break;
    case FieldType::UInt16: ok = parse_integer(value, at<uint16_t>(message, offset)); break;
    case FieldType::Int32: ok = parse_integer(value, at<int32_t>(message, offset)); break;
    case FieldType::UInt32: ok = parse_integer(value, at<uint32_t>(message, offset)); break;
    case FieldType::Int64: ok = parse_integer(value, at<int64_t>(message, offset)); break;
    case FieldType::UInt64: ok = parse_integer(value, at<uint64_t>(message, offset)); break;
    case FieldType::Float32:
    {
      double parsed = 0;
      ok = parse_double(value, parsed);
      if (ok)
        at<float>(message, offset) = static_cast<float>(parsed);
      break;
    }
    case FieldType::Float64: ok = parse_double(value, at<double>(message, offset)); break;
    case FieldType::String:
      if (field->string_bound && value.size() > field->string_bound)
      {
        if (error)
          *error = "field '" + path + "' holds at most " + std::to_string(field->string_bound) + " characters";
        return false;
      }
      at<std::string>(message, offset) = value;
      break;
    default: ok = false; break;
  }
  if (!ok && error)
  {
    *error = "'" + value + "' does not fit field '" + path + "'";
  }
  return ok;
}

//------------------------------------------------------------------------------
bool get_field_as_text(const MessageTypeSupport& type, const void* message, const std::string& path,
  std::string& value, std::string* error)
{
  const MessageTypeSupport* owner = nullptr;
  size_t base = 0;
  const FieldInfo* field = find_field(type, path, owner, base, error);
  if (!field)
  {
    return false;
  }
  const size_t offset = base + field->offset;
  if (field->container != Container::None || field->type == FieldType::WString)
  {
    if (error)
    {
      *error = "field '" + path + "' is a sequence or a wstring: read it from the YAML";
    }
    return false;
  }
  switch (field->type)
  {
    case FieldType::Bool: value = at<bool>(message, offset) ? "true" : "false"; break;
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8: value = std::to_string(at<uint8_t>(message, offset)); break;
    case FieldType::Int8: value = std::to_string(at<int8_t>(message, offset)); break;
    case FieldType::Int16: value = std::to_string(at<int16_t>(message, offset)); break;
    case FieldType::UInt16: value = std::to_string(at<uint16_t>(message, offset)); break;
    case FieldType::Int32: value = std::to_string(at<int32_t>(message, offset)); break;
    case FieldType::UInt32: value = std::to_string(at<uint32_t>(message, offset)); break;
    case FieldType::Int64: value = std::to_string(at<int64_t>(message, offset)); break;
    case FieldType::UInt64: value = std::to_string(at<uint64_t>(message, offset)); break;
    case FieldType::Float32: value = wire::format_yaml_float(at<float>(message, offset)); break;
    case FieldType::Float64: value = wire::format_yaml_float(at<double>(message, offset)); break;
    case FieldType::String: value = at<std::string>(message, offset); break;
    case FieldType::Message:
      value = wire::to_yaml(*field->nested(), static_cast<const char*>(message) + offset);
      break;
    default: value.clear(); break;
  }
  return true;
}

} // namespace scene
} // namespace ros2vtk
