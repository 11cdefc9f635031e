// ros2vtk — to_yaml (MessageYaml.hpp): the walk over a message's introspection table that writes
// the text `ros2 topic echo` prints (block style, PyYAML's indentless sequences). Hand-written on
// purpose: no C++ YAML library writes PyYAML's exact text, and users compare the two by eye.
#include "MessageYamlDetail.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Utf8.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <regex>
#include <string>

namespace ros2vtk {
namespace wire {
namespace yaml_detail {
// ---------------------------------------------------------------------------------------------
// The formatting walk.
// ---------------------------------------------------------------------------------------------

uint32_t visible_field_count(const MessageTypeSupport& type)
{
  uint32_t count = 0;
  for (uint32_t i = 0; i < type.field_count; ++i)
  {
    count += is_placeholder_field(type.fields[i]) ? 0 : 1;
  }
  return count;
}

/// One non-message, non-bool-container element: `value` points at its storage.
std::string format_scalar(FieldType type, const void* value, int indent)
{
  switch (type)
  {
    case FieldType::Bool:
      return at<bool>(value) ? "true" : "false";
    case FieldType::Byte:
      // rosidl_runtime_py turns bytes into ''.join(chr(b)): one character per byte.
      return format_scalar_string(std::u32string(1, at<uint8_t>(value)), indent);
    case FieldType::Char:
    case FieldType::UInt8:
      return std::to_string(at<uint8_t>(value));
    case FieldType::Int8:
      return std::to_string(at<int8_t>(value));
    case FieldType::Int16:
      return std::to_string(at<int16_t>(value));
    case FieldType::UInt16:
      return std::to_string(at<uint16_t>(value));
    case FieldType::Int32:
      return std::to_string(at<int32_t>(value));
    case FieldType::UInt32:
      return std::to_string(at<uint32_t>(value));
    case FieldType::Int64:
      return std::to_string(at<int64_t>(value));
    case FieldType::UInt64:
      return std::to_string(at<uint64_t>(value));
    case FieldType::Float32:
      return format_yaml_float(static_cast<double>(at<float>(value)));
    case FieldType::Float64:
      return format_yaml_float(at<double>(value));
    case FieldType::String:
      return format_scalar_string(decode_utf8(at<std::string>(value)), indent);
    case FieldType::WString:
      return format_scalar_string(utf16_to_utf32(at<std::u16string>(value)), indent);
    case FieldType::Message:
      break;
  }
  return "";
}

class YamlWriter
{
public:
  std::string text;

  /// The fields of `message` as a block mapping at `indent`. When `inline_first`, the first
  /// key continues the current line (a `- ` sequence item).
  void write_fields(
    const MessageTypeSupport& type, const void* message, int indent, bool inline_first)
  {
    bool first = true;
    for (uint32_t i = 0; i < type.field_count; ++i)
    {
      const FieldInfo& field = type.fields[i];
      if (is_placeholder_field(field))
      {
        continue;
      }
      if (!first || !inline_first)
      {
        text.append(static_cast<size_t>(indent), ' ');
      }
      first = false;
      text += field.name;
      text += ':';
      write_field_value(field, field_address(message, field), indent);
    }
  }

private:
  void write_field_value(const FieldInfo& field, const void* value, int indent)
  {
    if (field.container == Container::None)
    {
      if (field.type == FieldType::Message)
      {
        write_nested(*field.nested(), value, indent + 2, false);
      }
      else
      {
        text += ' ' + format_scalar(field.type, value, indent + 2) + '\n';
      }
      return;
    }
    const size_t count = field.size(value);
    if (count == 0)
    {
      text += " []\n";
      return;
    }
    text += '\n';
    // PyYAML does not indent a sequence that is a mapping value: its `- ` sit at `indent`.
    void* mutable_value = const_cast<void*>(value); // element() is shared with the reader
    for (size_t i = 0; i < count; ++i)
    {
      text.append(static_cast<size_t>(indent), ' ');
      text += '-';
      if (field.type == FieldType::Bool)
      {
        text += field.get_bool(value, i) ? " true\n" : " false\n";
      }
      else if (field.type == FieldType::Message)
      {
        write_nested(*field.nested(), field.element(mutable_value, i), indent + 2, true);
      }
      else
      {
        text += ' ' + format_scalar(field.type, field.element(mutable_value, i), indent + 2) + '\n';
      }
    }
  }

  void write_nested(const MessageTypeSupport& type, const void* message, int indent, bool as_item)
  {
    if (visible_field_count(type) == 0)
    {
      text += " {}\n";
      return;
    }
    if (as_item)
    {
      text += ' ';
      write_fields(type, message, indent, true);
    }
    else
    {
      text += '\n';
      write_fields(type, message, indent, false);
    }
  }
};

} // namespace yaml_detail
} // namespace wire
} // namespace ros2vtk

namespace ros2vtk {
namespace wire {
using namespace yaml_detail; // the helpers shared by the YAML files (MessageYamlDetail.hpp)

std::string to_yaml(const MessageTypeSupport& type, const void* message)
{
  if (visible_field_count(type) == 0)
  {
    return "{}\n";
  }
  YamlWriter writer;
  writer.write_fields(type, message, 0, false);
  return writer.text;
}

} // namespace wire
} // namespace ros2vtk
