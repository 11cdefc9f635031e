// ros2vtk — text access to one message field by path (see MessageFields.hpp).
#include "MessageFields.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

namespace ros2vtk {
namespace scene {

namespace {

using wire::Container;
using wire::FieldInfo;
using wire::FieldType;
using wire::MessageTypeSupport;

/// Where a path leads: the field (nullptr for "" = the message itself), the struct member it
/// names (nullptr when walking types only) and, for `name[i]`, the element index.
struct Location
{
  const MessageTypeSupport* owner = nullptr;
  const FieldInfo* field = nullptr;
  void* member = nullptr;
  bool indexed = false;
  size_t index = 0;
};

/// Splits "name" or "name[12]". False for a malformed index.
bool parse_segment(const std::string& segment, std::string& name, bool& indexed, size_t& index)
{
  const size_t open = segment.find('[');
  indexed = open != std::string::npos;
  name = segment.substr(0, open);
  if (!indexed)
  {
    return !name.empty();
  }
  if (segment.back() != ']' || open + 2 > segment.size() - 1)
  {
    return false;
  }
  const std::string digits = segment.substr(open + 1, segment.size() - open - 2);
  if (digits.empty() || digits.size() > 9 ||
    digits.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  index = static_cast<size_t>(std::stoul(digits));
  return !name.empty();
}

/// Walks `path` ("a.b[2].c"); `message` may be nullptr to walk the types only (no bounds
/// checks then). False and `error` naming the path when it leads nowhere.
bool locate(const MessageTypeSupport& type, void* message, const std::string& path,
  Location& location, std::string* error)
{
  auto fail = [&](const std::string& text) {
    if (error)
    {
      *error = text;
    }
    return false;
  };
  location = Location();
  location.owner = &type;
  location.member = message;
  if (path.empty())
  {
    return true;
  }
  const MessageTypeSupport* current_type = &type;
  void* current = message;
  size_t start = 0;
  while (true)
  {
    const size_t dot = path.find('.', start);
    const std::string segment =
      path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    std::string name;
    bool indexed = false;
    size_t index = 0;
    if (!parse_segment(segment, name, indexed, index))
    {
      return fail("malformed path '" + path + "' (fields are name or name[index], joined by '.')");
    }
    const FieldInfo* found = nullptr;
    for (uint32_t i = 0; i < current_type->field_count; ++i)
    {
      if (name == current_type->fields[i].name)
      {
        found = &current_type->fields[i];
        break;
      }
    }
    if (!found)
    {
      std::ostringstream text;
      text << current_type->ros_type << " has no field '" << name << "' (path '" << path
           << "'; fields:";
      for (uint32_t i = 0; i < current_type->field_count; ++i)
      {
        text << ' ' << current_type->fields[i].name;
      }
      text << ')';
      return fail(text.str());
    }
    void* member = current ? static_cast<char*>(current) + found->offset : nullptr;
    if (indexed)
    {
      if (found->container == Container::None)
      {
        return fail(
          "'" + name + "' in path '" + path + "' is not an array or sequence: it has no index");
      }
      if (member && index >= found->size(member))
      {
        return fail("index " + std::to_string(index) + " of '" + name + "' in path '" + path +
          "' is out of range (it holds " + std::to_string(found->size(member)) + ")");
      }
    }
    const bool last = dot == std::string::npos;
    if (last)
    {
      location.owner = current_type;
      location.field = found;
      location.member = member;
      location.indexed = indexed;
      location.index = index;
      return true;
    }
    if (found->type != FieldType::Message)
    {
      return fail("'" + name + "' in path '" + path + "' is not a nested message");
    }
    if (found->container != Container::None && !indexed)
    {
      return fail("'" + name + "' in path '" + path + "' is a sequence of messages: pick one, " +
        name + "[i]");
    }
    current = member ? (indexed ? found->element(member, index) : member) : nullptr;
    current_type = found->nested();
    start = dot + 1;
  }
}

template<typename Int>
bool parse_integer(const std::string& text, Int& out)
{
  errno = 0;
  char* end = nullptr;
  if (std::numeric_limits<Int>::is_signed)
  {
    const long long value = std::strtoll(text.c_str(), &end, 0);
    if (errno || end == text.c_str() || *end ||
      value < static_cast<long long>(std::numeric_limits<Int>::min()) ||
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
  if (errno || end == text.c_str() || *end ||
    value > static_cast<unsigned long long>(std::numeric_limits<Int>::max()))
  {
    return false;
  }
  out = static_cast<Int>(value);
  return true;
}

/// `out` is written only on success (a failed set leaves the field as it was).
bool parse_double(const std::string& text, double& out)
{
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (errno || end == text.c_str() || *end)
  {
    return false;
  }
  out = value;
  return true;
}

template<typename T>
T& at(void* message, size_t offset)
{
  return *reinterpret_cast<T*>(static_cast<char*>(message) + offset);
}

template<typename T>
const T& at(const void* message, size_t offset)
{
  return *reinterpret_cast<const T*>(static_cast<const char*>(message) + offset);
}

/// The address of the single value a location names (a member, or one element), or nullptr
/// for a whole container / bool sequence element (read through get_bool / set_bool).
void* value_address(const Location& location)
{
  if (!location.indexed)
  {
    return location.field->container == Container::None ? location.member : nullptr;
  }
  if (location.field->type == FieldType::Bool)
  {
    return nullptr; // std::vector<bool> has no element address
  }
  return location.field->element(location.member, location.index);
}

bool is_single_value(
  const Location& location, const std::string& path, const char* how, std::string* error)
{
  if (!location.field)
  {
    if (error)
    {
      *error = std::string("the path is empty: name a field ") + how;
    }
    return false;
  }
  if (location.field->container != Container::None && !location.indexed)
  {
    if (error)
    {
      *error =
        "field '" + path + "' is an array or sequence: name one element, " + path + "[i], " + how;
    }
    return false;
  }
  if (location.field->type == FieldType::WString)
  {
    if (error)
    {
      *error = "field '" + path + "' is a wstring: use the YAML " + how;
    }
    return false;
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool set_field_from_text(const MessageTypeSupport& type, void* message, const std::string& path,
  const std::string& value, std::string* error)
{
  Location location;
  if (!locate(type, message, path, location, error) ||
    !is_single_value(location, path, "to set it", error))
  {
    return false;
  }
  const FieldInfo* field = location.field;
  if (field->type == FieldType::Message)
  {
    if (error)
    {
      *error = "field '" + path + "' is a message: set its fields, or set it with YAML";
    }
    return false;
  }
  void* target = value_address(location);
  bool ok = true;
  switch (field->type)
  {
    case FieldType::Bool:
    {
      bool parsed = false;
      if (value == "true" || value == "True" || value == "1")
        parsed = true;
      else if (value == "false" || value == "False" || value == "0")
        parsed = false;
      else
      {
        ok = false;
        break;
      }
      if (target)
        at<bool>(target, 0) = parsed;
      else
        field->set_bool(location.member, location.index, parsed);
      break;
    }
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8:
      ok = parse_integer(value, at<uint8_t>(target, 0));
      break;
    case FieldType::Int8:
      ok = parse_integer(value, at<int8_t>(target, 0));
      break;
    case FieldType::Int16:
      ok = parse_integer(value, at<int16_t>(target, 0));
      break;
    case FieldType::UInt16:
      ok = parse_integer(value, at<uint16_t>(target, 0));
      break;
    case FieldType::Int32:
      ok = parse_integer(value, at<int32_t>(target, 0));
      break;
    case FieldType::UInt32:
      ok = parse_integer(value, at<uint32_t>(target, 0));
      break;
    case FieldType::Int64:
      ok = parse_integer(value, at<int64_t>(target, 0));
      break;
    case FieldType::UInt64:
      ok = parse_integer(value, at<uint64_t>(target, 0));
      break;
    case FieldType::Float32:
    {
      double parsed = 0;
      ok = parse_double(value, parsed);
      if (ok)
        at<float>(target, 0) = static_cast<float>(parsed);
      break;
    }
    case FieldType::Float64:
      ok = parse_double(value, at<double>(target, 0));
      break;
    case FieldType::String:
      if (field->string_bound && value.size() > field->string_bound)
      {
        if (error)
          *error = "field '" + path + "' holds at most " + std::to_string(field->string_bound) +
            " characters";
        return false;
      }
      at<std::string>(target, 0) = value;
      break;
    default:
      ok = false;
      break;
  }
  if (!ok && error)
  {
    *error = "'" + value + "' does not fit field '" + path + "' (" +
      ros2vtk::wire::field_type_name(field->type) + ")";
  }
  return ok;
}

//------------------------------------------------------------------------------
bool get_field_as_text(const MessageTypeSupport& type, const void* message, const std::string& path,
  std::string& value, std::string* error)
{
  Location location;
  // locate() takes a mutable message to serve the setters; nothing is written here.
  if (!locate(type, const_cast<void*>(message), path, location, error) ||
    !is_single_value(location, path, "to read it", error))
  {
    return false;
  }
  const FieldInfo* field = location.field;
  const void* source = value_address(location);
  switch (field->type)
  {
    case FieldType::Bool:
      value = (source ? at<bool>(source, 0) : field->get_bool(location.member, location.index))
        ? "true"
        : "false";
      break;
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8:
      value = std::to_string(at<uint8_t>(source, 0));
      break;
    case FieldType::Int8:
      value = std::to_string(at<int8_t>(source, 0));
      break;
    case FieldType::Int16:
      value = std::to_string(at<int16_t>(source, 0));
      break;
    case FieldType::UInt16:
      value = std::to_string(at<uint16_t>(source, 0));
      break;
    case FieldType::Int32:
      value = std::to_string(at<int32_t>(source, 0));
      break;
    case FieldType::UInt32:
      value = std::to_string(at<uint32_t>(source, 0));
      break;
    case FieldType::Int64:
      value = std::to_string(at<int64_t>(source, 0));
      break;
    case FieldType::UInt64:
      value = std::to_string(at<uint64_t>(source, 0));
      break;
    case FieldType::Float32:
      value = wire::format_yaml_float(at<float>(source, 0));
      break;
    case FieldType::Float64:
      value = wire::format_yaml_float(at<double>(source, 0));
      break;
    case FieldType::String:
      value = at<std::string>(source, 0);
      break;
    case FieldType::Message:
      value = wire::to_yaml(*field->nested(), source);
      break;
    default:
      value.clear();
      break;
  }
  return true;
}

//------------------------------------------------------------------------------
bool describe_field(const MessageTypeSupport& type, const std::string& path,
  FieldDescription& description, std::string* error)
{
  Location location;
  if (!locate(type, nullptr, path, location, error))
  {
    return false;
  }
  description = FieldDescription();
  if (!location.field)
  {
    description.type_name = description.element_type_name = type.ros_type;
    description.is_message = true;
    description.nested = &type;
    return true;
  }
  const FieldInfo& field = *location.field;
  description.name = field.name;
  description.is_message = field.type == FieldType::Message;
  description.nested = description.is_message ? field.nested() : nullptr;
  description.element_type_name = description.is_message
    ? description.nested->ros_type
    : ros2vtk::wire::field_type_name(field.type);
  if (field.string_bound)
  {
    description.element_type_name += "<=" + std::to_string(field.string_bound);
  }
  description.type_name = description.element_type_name;
  if (field.container != Container::None && !location.indexed)
  {
    description.is_container = true;
    description.is_fixed_size = field.container == Container::Array;
    switch (field.container)
    {
      case Container::Array:
        description.type_name += "[" + std::to_string(field.array_size) + "]";
        break;
      case Container::BoundedSequence:
        description.type_name += "[<=" + std::to_string(field.array_size) + "]";
        break;
      default:
        description.type_name += "[]";
        break;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool list_fields(const MessageTypeSupport& type, const std::string& path,
  std::vector<FieldDescription>& fields, std::string* error)
{
  FieldDescription owner;
  if (!describe_field(type, path, owner, error))
  {
    return false;
  }
  if (!owner.is_message || owner.is_container)
  {
    if (error)
    {
      *error = "'" + path + "' is not a message (it is " + owner.type_name + ")";
    }
    return false;
  }
  fields.clear();
  for (uint32_t i = 0; i < owner.nested->field_count; ++i)
  {
    if (ros2vtk::wire::is_placeholder_field(owner.nested->fields[i]))
    {
      continue;
    }
    FieldDescription field;
    const std::string child =
      path.empty() ? owner.nested->fields[i].name : path + "." + owner.nested->fields[i].name;
    if (!describe_field(type, child, field, error))
    {
      return false;
    }
    fields.push_back(field);
  }
  return true;
}

//------------------------------------------------------------------------------
bool get_field_length(const MessageTypeSupport& type, const void* message, const std::string& path,
  size_t& length, std::string* error)
{
  Location location;
  if (!locate(type, const_cast<void*>(message), path, location, error))
  {
    return false;
  }
  if (!location.field || location.field->container == Container::None || location.indexed)
  {
    if (error)
    {
      *error = "field '" + path + "' is not an array or sequence";
    }
    return false;
  }
  length = location.field->size(location.member);
  return true;
}

//------------------------------------------------------------------------------
bool resize_field(const MessageTypeSupport& type, void* message, const std::string& path,
  size_t length, std::string* error)
{
  Location location;
  if (!locate(type, message, path, location, error))
  {
    return false;
  }
  const FieldInfo* field = location.field;
  if (!field || field->container == Container::None || location.indexed)
  {
    if (error)
    {
      *error = "field '" + path + "' is not an array or sequence";
    }
    return false;
  }
  if ((field->container == Container::Array && length != field->array_size) ||
    (field->container == Container::BoundedSequence && length > field->array_size))
  {
    if (error)
    {
      *error = "field '" + path + "' holds " +
        (field->container == Container::Array ? "exactly " : "at most ") +
        std::to_string(field->array_size) + " elements, not " + std::to_string(length);
    }
    return false;
  }
  if (!field->resize(location.member, length))
  {
    if (error)
    {
      *error = "field '" + path + "' cannot hold " + std::to_string(length) + " elements";
    }
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void* locate_message(const MessageTypeSupport& type, void* message, const std::string& path,
  const MessageTypeSupport*& found_type, std::string* error)
{
  Location location;
  if (!locate(type, message, path, location, error))
  {
    return nullptr;
  }
  if (!location.field)
  {
    found_type = &type;
    return message;
  }
  if (location.field->type != FieldType::Message ||
    (location.field->container != Container::None && !location.indexed))
  {
    if (error)
    {
      *error = "field '" + path + "' is not a single message";
    }
    return nullptr;
  }
  found_type = location.field->nested();
  return location.indexed ? location.field->element(location.member, location.index)
                          : location.member;
}

} // namespace scene
} // namespace ros2vtk
