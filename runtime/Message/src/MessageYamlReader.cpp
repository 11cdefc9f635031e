// ros2vtk — from_yaml (MessageYaml.hpp): YAML text (what `ros2 topic pub` takes) into a message
// through its introspection table, with yaml-cpp (Debian's libyaml-cpp-dev); every error names
// the field path.
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
// Reading with yaml-cpp.
// ---------------------------------------------------------------------------------------------

bool is_plain(const YAML::Node& node)
{
  return node.Tag() == "?"; // yaml-cpp tags quoted scalars "!" and plain ones "?"
}

/// Decimal or 0x-hexadecimal integer literal with an optional sign.
bool parse_integer_literal(
  const std::string& text, bool& negative, unsigned long long& magnitude, bool& overflow)
{
  size_t i = 0;
  negative = false;
  overflow = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-'))
  {
    negative = text[i] == '-';
    ++i;
  }
  int base = 10;
  if (text.size() > i + 2 && text[i] == '0' && (text[i + 1] == 'x' || text[i + 1] == 'X'))
  {
    base = 16;
    i += 2;
  }
  if (i == text.size())
  {
    return false;
  }
  const char* first = text.data() + i;
  const char* last = text.data() + text.size();
  const auto result = std::from_chars(first, last, magnitude, base);
  if (result.ptr != last)
  {
    return false;
  }
  overflow = result.ec == std::errc::result_out_of_range;
  return result.ec == std::errc() || overflow;
}

bool parse_float_literal(const std::string& text, double& value, bool& overflow)
{
  overflow = false;
  std::string body = text;
  bool negative = false;
  if (!body.empty() && (body[0] == '+' || body[0] == '-'))
  {
    negative = body[0] == '-';
    body.erase(0, 1);
  }
  if (body == ".inf" || body == ".Inf" || body == ".INF")
  {
    value =
      negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    return true;
  }
  if (body == ".nan" || body == ".NaN" || body == ".NAN")
  {
    value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (body.empty() || body.find_first_not_of("0123456789.eE+-") != std::string::npos)
  {
    return false; // keeps strtod's "inf", "nan" and hex floats out
  }
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size())
  {
    return false;
  }
  overflow = errno == ERANGE && std::isinf(parsed);
  value = parsed;
  return true;
}

const std::regex& yaml_bool_true()
{
  static const std::regex pattern("true|True|TRUE|yes|Yes|YES|on|On|ON");
  return pattern;
}

const std::regex& yaml_bool_false()
{
  static const std::regex pattern("false|False|FALSE|no|No|NO|off|Off|OFF");
  return pattern;
}

/// yaml-cpp 0.7 folds a single-quoted scalar made only of blanks and line breaks to ""
/// (PyYAML writes the string "\n" as '\n\n  ', and reads it back as "\n"). This applies the
/// YAML 1.1 folding rule to such a scalar's source text: k empty lines become k line feeds, a
/// lone line break a space.
std::string fold_blank_single_quoted(const std::string& source, size_t quote)
{
  const size_t close = source.find('\'', quote + 1);
  if (quote >= source.size() || source[quote] != '\'' || close == std::string::npos)
  {
    return "";
  }
  const std::string inner = source.substr(quote + 1, close - quote - 1);
  if (inner.find_first_not_of(" \t\r\n") != std::string::npos)
  {
    return ""; // not the case yaml-cpp gets wrong
  }
  size_t breaks = 0;
  for (char c : inner)
  {
    breaks += c == '\n' ? 1 : 0;
  }
  if (breaks == 0)
  {
    return inner;
  }
  return breaks == 1 ? std::string(" ") : std::string(breaks - 1, '\n');
}

class YamlReader
{
public:
  explicit YamlReader(const std::string& source)
    : source_(source)
    , budget_(4 * source.size() + 64)
  {
  }

  std::string error;

  bool read_message(
    const MessageTypeSupport& type, const YAML::Node& node, void* message, const std::string& path)
  {
    if (!spend(path))
    {
      return false;
    }
    if (node.IsNull())
    {
      return true; // `{}`-like: every field keeps its default
    }
    if (!node.IsMap())
    {
      return fail(path, std::string("expected a mapping for ") + type.ros_type);
    }
    for (const auto& entry : node)
    {
      if (!entry.first.IsScalar())
      {
        return fail(path, "mapping keys must be field names");
      }
      const std::string name = entry.first.Scalar();
      const FieldInfo* field = find_field(type, name);
      const std::string field_path = path.empty() ? name : path + "." + name;
      if (!field)
      {
        return fail(field_path,
          std::string("unknown field of ") + type.ros_type + " (fields: " + field_list(type) + ")");
      }
      if (!read_field(*field, entry.second, field_address(message, *field), field_path))
      {
        return false;
      }
    }
    return true;
  }

private:
  const std::string& source_;
  // Values (and string bytes) read so far, against a budget proportional to the text: without
  // aliases every value takes at least one byte of text, with them (`*a` repeated, nested) a
  // 1 kB document could expand to billions of values or gigabytes of strings (issue 11.5).
  size_t visited_ = 0;
  size_t budget_;

  bool spend(const std::string& path, size_t units = 1)
  {
    visited_ += units;
    if (visited_ <= budget_)
    {
      return true;
    }
    return fail(path,
      "the YAML expands to more than " + std::to_string(budget_) + " values for its " +
        std::to_string(source_.size()) + " bytes (aliases?)");
  }

  /// The scalar's text, with yaml-cpp's blank single-quoted scalars repaired.
  std::string scalar(const YAML::Node& node) const
  {
    const std::string& text = node.Scalar();
    if (!text.empty() || is_plain(node) || node.Mark().pos < 0)
    {
      return text;
    }
    return fold_blank_single_quoted(source_, static_cast<size_t>(node.Mark().pos));
  }

  bool fail(const std::string& path, const std::string& what)
  {
    if (error.empty())
    {
      // `what` may quote the user's text; capped at a character boundary (issue 11.9).
      error =
        clip_for_message((path.empty() ? std::string("<message>") : path) + ": " + what, 1000);
    }
    return false;
  }

  static const FieldInfo* find_field(const MessageTypeSupport& type, const std::string& name)
  {
    for (uint32_t i = 0; i < type.field_count; ++i)
    {
      if (name == type.fields[i].name)
      {
        return &type.fields[i];
      }
    }
    return nullptr;
  }

  static std::string field_list(const MessageTypeSupport& type)
  {
    std::string names;
    for (uint32_t i = 0; i < type.field_count; ++i)
    {
      if (!is_placeholder_field(type.fields[i]))
      {
        names += (names.empty() ? "" : ", ") + std::string(type.fields[i].name);
      }
    }
    return names.empty() ? "none" : names;
  }

  bool read_field(
    const FieldInfo& field, const YAML::Node& node, void* value, const std::string& path)
  {
    if (field.container == Container::None)
    {
      return read_element(field, node, value, path);
    }
    if (!node.IsSequence())
    {
      return fail(path, std::string("expected a sequence of ") + field_type_name(field.type));
    }
    const size_t count = node.size();
    if (field.container == Container::Array && count != field.array_size)
    {
      return fail(path,
        "expected exactly " + std::to_string(field.array_size) + " elements, got " +
          std::to_string(count));
    }
    if (field.container == Container::BoundedSequence && count > field.array_size)
    {
      return fail(path,
        "at most " + std::to_string(field.array_size) + " elements allowed, got " +
          std::to_string(count));
    }
    if (!field.resize(value, count))
    {
      return fail(path, "cannot hold " + std::to_string(count) + " elements");
    }
    for (size_t i = 0; i < count; ++i)
    {
      const std::string item_path = path + "[" + std::to_string(i) + "]";
      if (!spend(item_path))
      {
        return false;
      }
      if (field.type == FieldType::Bool)
      {
        bool flag = false;
        if (!read_bool(node[i], flag, item_path))
        {
          return false;
        }
        field.set_bool(value, i, flag);
      }
      else if (!read_element(field, node[i], field.element(value, i), item_path))
      {
        return false;
      }
    }
    return true;
  }

  bool read_bool(const YAML::Node& node, bool& value, const std::string& path)
  {
    if (node.IsScalar() && is_plain(node))
    {
      if (std::regex_match(node.Scalar(), yaml_bool_true()))
      {
        value = true;
        return true;
      }
      if (std::regex_match(node.Scalar(), yaml_bool_false()))
      {
        value = false;
        return true;
      }
    }
    return fail(path, "expected true or false, got " + describe(node));
  }

  static std::string describe(const YAML::Node& node)
  {
    if (node.IsScalar())
    {
      return (is_plain(node) ? "'" : "quoted '") + node.Scalar() + "'";
    }
    if (node.IsSequence())
    {
      return "a sequence";
    }
    if (node.IsMap())
    {
      return "a mapping";
    }
    return "nothing (null)";
  }

  template<typename T>
  bool read_integer(const YAML::Node& node, void* value, const std::string& path)
  {
    bool negative = false;
    bool overflow = false;
    unsigned long long magnitude = 0;
    if (!node.IsScalar() || !is_plain(node) ||
      !parse_integer_literal(node.Scalar(), negative, magnitude, overflow))
    {
      return fail(path,
        std::string("expected an integer (") + type_name_of<T>() + "), got " + describe(node));
    }
    using Limits = std::numeric_limits<T>;
    bool in_range = !overflow;
    if (in_range && negative)
    {
      // The magnitude of the most negative value is max + 1.
      in_range = magnitude == 0 ||
        (Limits::is_signed && magnitude <= static_cast<unsigned long long>(Limits::max()) + 1ULL);
    }
    else if (in_range)
    {
      in_range = magnitude <= static_cast<unsigned long long>(Limits::max());
    }
    if (!in_range)
    {
      return fail(path, node.Scalar() + " is out of range for " + type_name_of<T>());
    }
    T result = 0;
    if (negative && magnitude != 0)
    {
      // -(magnitude - 1) - 1 cannot overflow, even for the most negative value.
      result = static_cast<T>(-static_cast<long long>(magnitude - 1) - 1);
    }
    else
    {
      result = static_cast<T>(magnitude);
    }
    *static_cast<T*>(value) = result;
    return true;
  }

  template<typename T>
  static const char* type_name_of()
  {
    if (std::is_same<T, int8_t>::value)
      return "int8";
    if (std::is_same<T, uint8_t>::value)
      return "uint8";
    if (std::is_same<T, int16_t>::value)
      return "int16";
    if (std::is_same<T, uint16_t>::value)
      return "uint16";
    if (std::is_same<T, int32_t>::value)
      return "int32";
    if (std::is_same<T, uint32_t>::value)
      return "uint32";
    if (std::is_same<T, int64_t>::value)
      return "int64";
    return "uint64";
  }

  bool read_float(const YAML::Node& node, FieldType type, void* value, const std::string& path)
  {
    double parsed = 0.0;
    bool overflow = false;
    if (!node.IsScalar() || !is_plain(node) ||
      !parse_float_literal(node.Scalar(), parsed, overflow))
    {
      return fail(path,
        std::string("expected a number (") + field_type_name(type) + "), got " + describe(node));
    }
    if (type == FieldType::Float32)
    {
      if (overflow ||
        (std::isfinite(parsed) &&
          std::fabs(parsed) > static_cast<double>(std::numeric_limits<float>::max())))
      {
        return fail(path, node.Scalar() + " is out of range for float32");
      }
      *static_cast<float*>(value) = static_cast<float>(parsed);
      return true;
    }
    if (overflow)
    {
      return fail(path, node.Scalar() + " is out of range for float64");
    }
    *static_cast<double*>(value) = parsed;
    return true;
  }

  bool read_byte(const YAML::Node& node, void* value, const std::string& path)
  {
    if (node.IsScalar())
    {
      // `ros2 topic echo` writes a byte as the character chr(b); users may write 0..255.
      bool negative = false;
      bool overflow = false;
      unsigned long long magnitude = 0;
      if (is_plain(node) && parse_integer_literal(node.Scalar(), negative, magnitude, overflow))
      {
        if (negative || overflow || magnitude > 255)
        {
          return fail(path, node.Scalar() + " is out of range for byte (0..255)");
        }
        *static_cast<uint8_t*>(value) = static_cast<uint8_t>(magnitude);
        return true;
      }
      const std::u32string text = decode_utf8(scalar(node));
      if (text.size() == 1 && text[0] <= 0xFF)
      {
        *static_cast<uint8_t*>(value) = static_cast<uint8_t>(text[0]);
        return true;
      }
    }
    return fail(
      path, "expected a byte (one character U+0000..U+00FF or 0..255), got " + describe(node));
  }

  bool read_element(
    const FieldInfo& field, const YAML::Node& node, void* value, const std::string& path)
  {
    switch (field.type)
    {
      case FieldType::Bool:
        return read_bool(node, *static_cast<bool*>(value), path);
      case FieldType::Byte:
        return read_byte(node, value, path);
      case FieldType::Char:
      case FieldType::UInt8:
        return read_integer<uint8_t>(node, value, path);
      case FieldType::Int8:
        return read_integer<int8_t>(node, value, path);
      case FieldType::Int16:
        return read_integer<int16_t>(node, value, path);
      case FieldType::UInt16:
        return read_integer<uint16_t>(node, value, path);
      case FieldType::Int32:
        return read_integer<int32_t>(node, value, path);
      case FieldType::UInt32:
        return read_integer<uint32_t>(node, value, path);
      case FieldType::Int64:
        return read_integer<int64_t>(node, value, path);
      case FieldType::UInt64:
        return read_integer<uint64_t>(node, value, path);
      case FieldType::Float32:
      case FieldType::Float64:
        return read_float(node, field.type, value, path);
      case FieldType::String:
      case FieldType::WString:
        return read_string(field, node, value, path);
      case FieldType::Message:
        return read_message(*field.nested(), node, value, path);
    }
    return fail(path, "unsupported field type");
  }

  bool read_string(
    const FieldInfo& field, const YAML::Node& node, void* value, const std::string& path)
  {
    if (!node.IsScalar())
    {
      return fail(
        path, std::string("expected a ") + field_type_name(field.type) + ", got " + describe(node));
    }
    std::string text = scalar(node);
    if (!spend(path, text.size()))
    {
      return false;
    }
    repair_utf8(text); // the project's invalid-UTF-8 policy (Utf8.hpp)
    if (field.type == FieldType::String)
    {
      if (field.string_bound != 0 && text.size() > field.string_bound)
      {
        return fail(path,
          "string of " + std::to_string(text.size()) + " bytes exceeds its bound " +
            std::to_string(field.string_bound));
      }
      *static_cast<std::string*>(value) = text;
      return true;
    }
    const std::u16string wide = utf32_to_utf16(decode_utf8(text));
    if (field.string_bound != 0 && wide.size() > field.string_bound)
    {
      return fail(path,
        "wstring of " + std::to_string(wide.size()) + " units exceeds its bound " +
          std::to_string(field.string_bound));
    }
    *static_cast<std::u16string*>(value) = wide;
    return true;
  }
};

struct MessageDeleter
{
  const MessageTypeSupport* type;
  void operator()(void* message) const { type->destroy(message); }
};

} // namespace yaml_detail
} // namespace wire
} // namespace ros2vtk

namespace ros2vtk {
namespace wire {
using namespace yaml_detail; // the helpers shared by the YAML files (MessageYamlDetail.hpp)

bool from_yaml(
  const MessageTypeSupport& type, const std::string& yaml, void* message, std::string* error)
{
  std::string failure;
  try
  {
    const YAML::Node root = YAML::Load(yaml);
    std::unique_ptr<void, MessageDeleter> scratch(type.create(), MessageDeleter{ &type });
    YamlReader reader(yaml);
    if (reader.read_message(type, root, scratch.get(), ""))
    {
      type.copy(scratch.get(), message);
      return true;
    }
    failure = reader.error;
  }
  catch (const YAML::Exception& exception)
  {
    failure = std::string("invalid YAML: ") + exception.what();
  }
  catch (const std::exception& exception)
  {
    failure = std::string("cannot read YAML: ") + exception.what();
  }
  if (error)
  {
    *error = failure;
  }
  return false;
}

} // namespace wire
} // namespace ros2vtk
