// ros2vtk — YAML of any message through its introspection table.
//
// Writing is hand-written on purpose: no C++ YAML library writes PyYAML's exact text (its scalar
// quoting rules, its indentless sequences, Python's float repr), and `ros2 topic echo` users
// compare the two by eye. The rules below follow PyYAML 6's emitter (analyze_scalar,
// choose_scalar_style, write_single_quoted, write_double_quoted) and resolver (implicit types)
// with the options rosidl_runtime_py.message_to_yaml passes (block style, allow_unicode, no
// line width). tests/fixtures/yaml_scalars.json holds PyYAML's own output for tricky values.
// Reading uses yaml-cpp (Debian's libyaml-cpp-dev).
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
namespace {

// ---------------------------------------------------------------------------------------------
// Unicode helpers: PyYAML decides per code point, so strings are handled as UTF-32.
// ---------------------------------------------------------------------------------------------

/// Decodes UTF-8; a byte that does not start a valid sequence stands for itself (Latin-1), so
/// no input is lost or rejected on the way to YAML.
std::u32string decode_utf8(const std::string& text)
{
  std::u32string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size())
  {
    const auto byte = static_cast<unsigned char>(text[i]);
    size_t length = 0;
    char32_t code = 0;
    if (byte < 0x80)
    {
      length = 1;
      code = byte;
    }
    else if ((byte & 0xE0) == 0xC0)
    {
      length = 2;
      code = byte & 0x1F;
    }
    else if ((byte & 0xF0) == 0xE0)
    {
      length = 3;
      code = byte & 0x0F;
    }
    else if ((byte & 0xF8) == 0xF0)
    {
      length = 4;
      code = byte & 0x07;
    }
    bool valid = length != 0 && i + length <= text.size();
    for (size_t k = 1; valid && k < length; ++k)
    {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next & 0xC0) == 0x80;
      code = (code << 6) | (next & 0x3F);
    }
    if (valid)
    {
      out.push_back(code);
      i += length;
    }
    else
    {
      out.push_back(byte);
      i += 1;
    }
  }
  return out;
}

void append_utf8(std::string& out, char32_t code)
{
  if (code < 0x80)
  {
    out.push_back(static_cast<char>(code));
  }
  else if (code < 0x800)
  {
    out.push_back(static_cast<char>(0xC0 | (code >> 6)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
  else if (code < 0x10000)
  {
    out.push_back(static_cast<char>(0xE0 | (code >> 12)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
  else
  {
    out.push_back(static_cast<char>(0xF0 | (code >> 18)));
    out.push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
}

std::string encode_utf8(const std::u32string& text, size_t begin, size_t end)
{
  std::string out;
  for (size_t i = begin; i < end; ++i)
  {
    append_utf8(out, text[i]);
  }
  return out;
}

std::u32string utf16_to_utf32(const std::u16string& text)
{
  std::u32string out;
  for (size_t i = 0; i < text.size(); ++i)
  {
    const char32_t unit = text[i];
    if (unit >= 0xD800 && unit <= 0xDBFF && i + 1 < text.size() && text[i + 1] >= 0xDC00 &&
        text[i + 1] <= 0xDFFF)
    {
      out.push_back(0x10000 + ((unit - 0xD800) << 10) + (text[i + 1] - 0xDC00));
      ++i;
    }
    else
    {
      out.push_back(unit);
    }
  }
  return out;
}

std::u16string utf32_to_utf16(const std::u32string& text)
{
  std::u16string out;
  for (char32_t code : text)
  {
    if (code >= 0x10000)
    {
      code -= 0x10000;
      out.push_back(static_cast<char16_t>(0xD800 + (code >> 10)));
      out.push_back(static_cast<char16_t>(0xDC00 + (code & 0x3FF)));
    }
    else
    {
      out.push_back(static_cast<char16_t>(code));
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Scalars as PyYAML writes them.
// ---------------------------------------------------------------------------------------------

bool is_break(char32_t c)
{
  return c == U'\n' || c == 0x85 || c == 0x2028 || c == 0x2029;
}

bool is_whitespace_or_end(char32_t c)
{
  return c == 0 || c == U' ' || c == U'\t' || c == U'\r' || is_break(c);
}

bool contains(const char* set, char32_t c)
{
  return c < 0x80 && c != 0 && std::strchr(set, static_cast<int>(c)) != nullptr;
}

/// What PyYAML's Emitter.analyze_scalar decides, reduced to what block-mapping values need.
struct ScalarAnalysis
{
  bool multiline = false;
  bool allow_block_plain = true;
  bool allow_single_quoted = true;
};

ScalarAnalysis analyze_scalar(const std::u32string& s)
{
  ScalarAnalysis result;
  if (s.empty())
  {
    return result;
  }
  bool block_indicators = false;
  bool line_breaks = false;
  bool special_characters = false;
  bool leading_space = false;
  bool leading_break = false;
  bool trailing_space = false;
  bool trailing_break = false;
  bool break_space = false;
  bool space_break = false;
  if (s.compare(0, 3, U"---") == 0 || s.compare(0, 3, U"...") == 0)
  {
    block_indicators = true;
  }
  bool preceded_by_whitespace = true;
  bool followed_by_whitespace = s.size() == 1 || is_whitespace_or_end(s[1]);
  bool previous_space = false;
  bool previous_break = false;
  for (size_t index = 0; index < s.size(); ++index)
  {
    const char32_t ch = s[index];
    if (index == 0)
    {
      if (contains("#,[]{}&*!|>'\"%@`", ch) || (contains("?:-", ch) && followed_by_whitespace))
      {
        block_indicators = true;
      }
    }
    else if ((ch == U':' && followed_by_whitespace) || (ch == U'#' && preceded_by_whitespace))
    {
      block_indicators = true;
    }
    if (is_break(ch))
    {
      line_breaks = true;
    }
    if (!(ch == U'\n' || (ch >= 0x20 && ch <= 0x7E)))
    {
      // allow_unicode=True: these are written as they are; everything else is escaped.
      const bool unicode = (ch == 0x85 || (ch >= 0xA0 && ch <= 0xD7FF) ||
                            (ch >= 0xE000 && ch <= 0xFFFD) || (ch >= 0x10000 && ch < 0x10FFFF)) &&
        ch != 0xFEFF;
      if (!unicode)
      {
        special_characters = true;
      }
    }
    if (ch == U' ')
    {
      leading_space = leading_space || index == 0;
      trailing_space = trailing_space || index == s.size() - 1;
      break_space = break_space || previous_break;
      previous_space = true;
      previous_break = false;
    }
    else if (is_break(ch))
    {
      leading_break = leading_break || index == 0;
      trailing_break = trailing_break || index == s.size() - 1;
      space_break = space_break || previous_space;
      previous_space = false;
      previous_break = true;
    }
    else
    {
      previous_space = false;
      previous_break = false;
    }
    preceded_by_whitespace = is_whitespace_or_end(ch);
    followed_by_whitespace = index + 2 >= s.size() || is_whitespace_or_end(s[index + 2]);
  }
  result.multiline = line_breaks;
  if (leading_space || leading_break || trailing_space || trailing_break || line_breaks ||
      block_indicators)
  {
    result.allow_block_plain = false;
  }
  if (break_space || space_break || special_characters)
  {
    result.allow_block_plain = false;
    result.allow_single_quoted = false;
  }
  return result;
}

/// True when a plain scalar would read back as something other than a string (PyYAML's
/// implicit resolvers: bool, float, int, merge, null, timestamp, value).
bool resolves_to_non_string(const std::string& text)
{
  static const std::regex implicit_types[] = {
    std::regex("yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF"),
    std::regex("[-+]?(?:[0-9][0-9_]*)\\.[0-9_]*(?:[eE][-+][0-9]+)?"
               "|\\.[0-9][0-9_]*(?:[eE][-+][0-9]+)?"
               "|[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\\.[0-9_]*"
               "|[-+]?\\.(?:inf|Inf|INF)"
               "|\\.(?:nan|NaN|NAN)"),
    std::regex("[-+]?0b[0-1_]+"
               "|[-+]?0[0-7_]+"
               "|[-+]?(?:0|[1-9][0-9_]*)"
               "|[-+]?0x[0-9a-fA-F_]+"
               "|[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+"),
    std::regex("<<"),
    std::regex("~|null|Null|NULL|"),
    std::regex("[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]"
               "|[0-9][0-9][0-9][0-9]-[0-9][0-9]?-[0-9][0-9]?"
               "(?:[Tt]|[ \\t]+)[0-9][0-9]?:[0-9][0-9]:[0-9][0-9](?:\\.[0-9]*)?"
               "(?:[ \\t]*(?:Z|[-+][0-9][0-9]?(?::[0-9][0-9])?))?"),
    std::regex("="),
  };
  for (const std::regex& pattern : implicit_types)
  {
    if (std::regex_match(text, pattern))
    {
      return true;
    }
  }
  return false;
}

std::string single_quoted(const std::u32string& text, int indent)
{
  std::string out = "'";
  bool spaces = false;
  bool breaks = false;
  size_t start = 0;
  for (size_t end = 0; end <= text.size(); ++end)
  {
    const bool at_end = end == text.size();
    const char32_t ch = at_end ? 0 : text[end];
    if (spaces)
    {
      if (at_end || ch != U' ')
      {
        out += encode_utf8(text, start, end);
        start = end;
      }
    }
    else if (breaks)
    {
      if (at_end || !is_break(ch))
      {
        // A run of k breaks is written as k+1 line breaks when it starts with '\n' (folding).
        if (text[start] == U'\n')
        {
          out += '\n';
        }
        for (size_t i = start; i < end; ++i)
        {
          append_utf8(out, text[i]);
        }
        out.append(static_cast<size_t>(indent), ' ');
        start = end;
      }
    }
    else if (at_end || ch == U' ' || is_break(ch) || ch == U'\'')
    {
      out += encode_utf8(text, start, end);
      start = end;
    }
    if (!at_end && ch == U'\'')
    {
      out += "''";
      start = end + 1;
    }
    if (!at_end)
    {
      spaces = ch == U' ';
      breaks = is_break(ch);
    }
  }
  out += '\'';
  return out;
}

std::string double_quoted(const std::u32string& text)
{
  std::string out = "\"";
  for (char32_t ch : text)
  {
    const bool printable = (ch >= 0x20 && ch <= 0x7E) || (ch >= 0xA0 && ch <= 0xD7FF) ||
      (ch >= 0xE000 && ch <= 0xFFFD);
    const bool needs_escape = ch == U'"' || ch == U'\\' || ch == 0x85 || ch == 0x2028 ||
      ch == 0x2029 || ch == 0xFEFF || !printable;
    if (!needs_escape)
    {
      append_utf8(out, ch);
      continue;
    }
    const char* short_escape = nullptr;
    switch (ch)
    {
      case 0x00: short_escape = "\\0"; break;
      case 0x07: short_escape = "\\a"; break;
      case 0x08: short_escape = "\\b"; break;
      case 0x09: short_escape = "\\t"; break;
      case 0x0A: short_escape = "\\n"; break;
      case 0x0B: short_escape = "\\v"; break;
      case 0x0C: short_escape = "\\f"; break;
      case 0x0D: short_escape = "\\r"; break;
      case 0x1B: short_escape = "\\e"; break;
      case U'"': short_escape = "\\\""; break;
      case U'\\': short_escape = "\\\\"; break;
      case 0x85: short_escape = "\\N"; break;
      case 0xA0: short_escape = "\\_"; break;
      case 0x2028: short_escape = "\\L"; break;
      case 0x2029: short_escape = "\\P"; break;
      default: break;
    }
    if (short_escape)
    {
      out += short_escape;
      continue;
    }
    char buffer[16];
    if (ch <= 0xFF)
    {
      std::snprintf(buffer, sizeof(buffer), "\\x%02X", static_cast<unsigned>(ch));
    }
    else if (ch <= 0xFFFF)
    {
      std::snprintf(buffer, sizeof(buffer), "\\u%04X", static_cast<unsigned>(ch));
    }
    else
    {
      std::snprintf(buffer, sizeof(buffer), "\\U%08X", static_cast<unsigned>(ch));
    }
    out += buffer;
  }
  out += '"';
  return out;
}

std::string format_scalar_string(const std::u32string& text, int indent)
{
  const ScalarAnalysis analysis = analyze_scalar(text);
  const std::string utf8 = encode_utf8(text, 0, text.size());
  if (analysis.allow_block_plain && !text.empty() && !resolves_to_non_string(utf8))
  {
    return utf8;
  }
  if (analysis.allow_single_quoted)
  {
    return single_quoted(text, indent);
  }
  return double_quoted(text);
}

// ---------------------------------------------------------------------------------------------
// The formatting walk.
// ---------------------------------------------------------------------------------------------

/// rosidl gives a message without fields one dummy member; rosidl_runtime_py hides it (the
/// Python class has no fields), so `ros2 topic echo` prints such a message as `{}`.
bool is_dummy_member(const FieldInfo& field)
{
  return std::strcmp(field.name, "structure_needs_at_least_one_member") == 0;
}

uint32_t visible_field_count(const MessageTypeSupport& type)
{
  uint32_t count = 0;
  for (uint32_t i = 0; i < type.field_count; ++i)
  {
    count += is_dummy_member(type.fields[i]) ? 0 : 1;
  }
  return count;
}

template <typename T>
const T& at(const void* pointer)
{
  return *static_cast<const T*>(pointer);
}

const void* field_address(const void* message, const FieldInfo& field)
{
  return static_cast<const char*>(message) + field.offset;
}

void* field_address(void* message, const FieldInfo& field)
{
  return static_cast<char*>(message) + field.offset;
}

/// One non-message, non-bool-container element: `value` points at its storage.
std::string format_scalar(FieldType type, const void* value, int indent)
{
  switch (type)
  {
    case FieldType::Bool: return at<bool>(value) ? "true" : "false";
    case FieldType::Byte:
      // rosidl_runtime_py turns bytes into ''.join(chr(b)): one character per byte.
      return format_scalar_string(std::u32string(1, at<uint8_t>(value)), indent);
    case FieldType::Char:
    case FieldType::UInt8: return std::to_string(at<uint8_t>(value));
    case FieldType::Int8: return std::to_string(at<int8_t>(value));
    case FieldType::Int16: return std::to_string(at<int16_t>(value));
    case FieldType::UInt16: return std::to_string(at<uint16_t>(value));
    case FieldType::Int32: return std::to_string(at<int32_t>(value));
    case FieldType::UInt32: return std::to_string(at<uint32_t>(value));
    case FieldType::Int64: return std::to_string(at<int64_t>(value));
    case FieldType::UInt64: return std::to_string(at<uint64_t>(value));
    case FieldType::Float32: return format_yaml_float(static_cast<double>(at<float>(value)));
    case FieldType::Float64: return format_yaml_float(at<double>(value));
    case FieldType::String: return format_scalar_string(decode_utf8(at<std::string>(value)), indent);
    case FieldType::WString:
      return format_scalar_string(utf16_to_utf32(at<std::u16string>(value)), indent);
    case FieldType::Message: break;
  }
  return "";
}

class YamlWriter
{
public:
  std::string text;

  /// The fields of `message` as a block mapping at `indent`. When `inline_first`, the first
  /// key continues the current line (a `- ` sequence item).
  void write_fields(const MessageTypeSupport& type, const void* message, int indent,
                    bool inline_first)
  {
    bool first = true;
    for (uint32_t i = 0; i < type.field_count; ++i)
    {
      const FieldInfo& field = type.fields[i];
      if (is_dummy_member(field))
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
        text += ' ' + format_scalar(field.type, field.element(mutable_value, i), indent + 2) +
          '\n';
      }
    }
  }

  void write_nested(const MessageTypeSupport& type, const void* message, int indent,
                    bool as_item)
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

// ---------------------------------------------------------------------------------------------
// Reading with yaml-cpp.
// ---------------------------------------------------------------------------------------------

bool is_plain(const YAML::Node& node)
{
  return node.Tag() == "?"; // yaml-cpp tags quoted scalars "!" and plain ones "?"
}

const char* type_name(FieldType type)
{
  switch (type)
  {
    case FieldType::Bool: return "bool";
    case FieldType::Byte: return "byte";
    case FieldType::Char: return "char";
    case FieldType::Int8: return "int8";
    case FieldType::UInt8: return "uint8";
    case FieldType::Int16: return "int16";
    case FieldType::UInt16: return "uint16";
    case FieldType::Int32: return "int32";
    case FieldType::UInt32: return "uint32";
    case FieldType::Int64: return "int64";
    case FieldType::UInt64: return "uint64";
    case FieldType::Float32: return "float32";
    case FieldType::Float64: return "float64";
    case FieldType::String: return "string";
    case FieldType::WString: return "wstring";
    case FieldType::Message: return "message";
  }
  return "?";
}

/// Decimal or 0x-hexadecimal integer literal with an optional sign.
bool parse_integer_literal(const std::string& text, bool& negative, unsigned long long& magnitude,
                           bool& overflow)
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
    value = negative ? -std::numeric_limits<double>::infinity()
                     : std::numeric_limits<double>::infinity();
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

  bool read_message(const MessageTypeSupport& type, const YAML::Node& node, void* message,
                    const std::string& path)
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
        return fail(field_path, std::string("unknown field of ") + type.ros_type +
                      " (fields: " + field_list(type) + ")");
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
    return fail(path, "the YAML expands to more than " + std::to_string(budget_) +
                  " values for its " + std::to_string(source_.size()) + " bytes (aliases?)");
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
      error = clip_for_message((path.empty() ? std::string("<message>") : path) + ": " + what, 1000);
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
      if (!is_dummy_member(type.fields[i]))
      {
        names += (names.empty() ? "" : ", ") + std::string(type.fields[i].name);
      }
    }
    return names.empty() ? "none" : names;
  }

  bool read_field(const FieldInfo& field, const YAML::Node& node, void* value,
                  const std::string& path)
  {
    if (field.container == Container::None)
    {
      return read_element(field, node, value, path);
    }
    if (!node.IsSequence())
    {
      return fail(path, std::string("expected a sequence of ") + type_name(field.type));
    }
    const size_t count = node.size();
    if (field.container == Container::Array && count != field.array_size)
    {
      return fail(path, "expected exactly " + std::to_string(field.array_size) +
                    " elements, got " + std::to_string(count));
    }
    if (field.container == Container::BoundedSequence && count > field.array_size)
    {
      return fail(path, "at most " + std::to_string(field.array_size) + " elements allowed, got " +
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

  template <typename T>
  bool read_integer(const YAML::Node& node, void* value, const std::string& path)
  {
    bool negative = false;
    bool overflow = false;
    unsigned long long magnitude = 0;
    if (!node.IsScalar() || !is_plain(node) ||
        !parse_integer_literal(node.Scalar(), negative, magnitude, overflow))
    {
      return fail(path, std::string("expected an integer (") + type_name_of<T>() + "), got " +
                    describe(node));
    }
    using Limits = std::numeric_limits<T>;
    bool in_range = !overflow;
    if (in_range && negative)
    {
      // The magnitude of the most negative value is max + 1.
      in_range = magnitude == 0 ||
        (Limits::is_signed &&
         magnitude <= static_cast<unsigned long long>(Limits::max()) + 1ULL);
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

  template <typename T>
  static const char* type_name_of()
  {
    if (std::is_same<T, int8_t>::value) return "int8";
    if (std::is_same<T, uint8_t>::value) return "uint8";
    if (std::is_same<T, int16_t>::value) return "int16";
    if (std::is_same<T, uint16_t>::value) return "uint16";
    if (std::is_same<T, int32_t>::value) return "int32";
    if (std::is_same<T, uint32_t>::value) return "uint32";
    if (std::is_same<T, int64_t>::value) return "int64";
    return "uint64";
  }

  bool read_float(const YAML::Node& node, FieldType type, void* value, const std::string& path)
  {
    double parsed = 0.0;
    bool overflow = false;
    if (!node.IsScalar() || !is_plain(node) || !parse_float_literal(node.Scalar(), parsed, overflow))
    {
      return fail(path, std::string("expected a number (") + type_name(type) + "), got " +
                    describe(node));
    }
    if (type == FieldType::Float32)
    {
      if (overflow || (std::isfinite(parsed) &&
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
    return fail(path, "expected a byte (one character U+0000..U+00FF or 0..255), got " +
                  describe(node));
  }

  bool read_element(const FieldInfo& field, const YAML::Node& node, void* value,
                    const std::string& path)
  {
    switch (field.type)
    {
      case FieldType::Bool: return read_bool(node, *static_cast<bool*>(value), path);
      case FieldType::Byte: return read_byte(node, value, path);
      case FieldType::Char:
      case FieldType::UInt8: return read_integer<uint8_t>(node, value, path);
      case FieldType::Int8: return read_integer<int8_t>(node, value, path);
      case FieldType::Int16: return read_integer<int16_t>(node, value, path);
      case FieldType::UInt16: return read_integer<uint16_t>(node, value, path);
      case FieldType::Int32: return read_integer<int32_t>(node, value, path);
      case FieldType::UInt32: return read_integer<uint32_t>(node, value, path);
      case FieldType::Int64: return read_integer<int64_t>(node, value, path);
      case FieldType::UInt64: return read_integer<uint64_t>(node, value, path);
      case FieldType::Float32:
      case FieldType::Float64: return read_float(node, field.type, value, path);
      case FieldType::String:
      case FieldType::WString: return read_string(field, node, value, path);
      case FieldType::Message: return read_message(*field.nested(), node, value, path);
    }
    return fail(path, "unsupported field type");
  }

  bool read_string(const FieldInfo& field, const YAML::Node& node, void* value,
                   const std::string& path)
  {
    if (!node.IsScalar())
    {
      return fail(path, std::string("expected a ") + type_name(field.type) + ", got " +
                    describe(node));
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
        return fail(path, "string of " + std::to_string(text.size()) + " bytes exceeds its bound " +
                      std::to_string(field.string_bound));
      }
      *static_cast<std::string*>(value) = text;
      return true;
    }
    const std::u16string wide = utf32_to_utf16(decode_utf8(text));
    if (field.string_bound != 0 && wide.size() > field.string_bound)
    {
      return fail(path, "wstring of " + std::to_string(wide.size()) +
                    " units exceeds its bound " + std::to_string(field.string_bound));
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

} // namespace

std::string format_yaml_float(double value)
{
  if (std::isnan(value))
  {
    return ".nan";
  }
  if (std::isinf(value))
  {
    return value > 0 ? ".inf" : "-.inf";
  }
  // Shortest round-trip digits (what Python's repr uses), then Python's layout rules.
  char buffer[64];
  const auto result =
    std::to_chars(buffer, buffer + sizeof(buffer), std::fabs(value), std::chars_format::scientific);
  const std::string scientific(buffer, result.ptr); // "1.2345e+03", "5e-324"
  const size_t e = scientific.find('e');
  std::string digits;
  for (size_t i = 0; i < e; ++i)
  {
    if (scientific[i] != '.')
    {
      digits += scientific[i];
    }
  }
  const int exponent = std::atoi(scientific.c_str() + e + 1);
  const int decimal_point = exponent + 1; // digits d1d2.. mean 0.d1d2.. x 10^decimal_point
  const int count = static_cast<int>(digits.size());
  std::string text = std::signbit(value) ? "-" : "";
  if (decimal_point <= -4 || decimal_point > 16)
  {
    // repr gives "1e+16"; PyYAML adds ".0" so that YAML reads it back as a float.
    text += digits.substr(0, 1) + "." + (count > 1 ? digits.substr(1) : std::string("0"));
    char exponent_text[16];
    std::snprintf(exponent_text, sizeof(exponent_text), "e%c%02d", exponent < 0 ? '-' : '+',
                  std::abs(exponent));
    text += exponent_text;
  }
  else if (decimal_point <= 0)
  {
    text += "0." + std::string(static_cast<size_t>(-decimal_point), '0') + digits;
  }
  else if (decimal_point >= count)
  {
    text += digits + std::string(static_cast<size_t>(decimal_point - count), '0') + ".0";
  }
  else
  {
    text += digits.substr(0, static_cast<size_t>(decimal_point)) + "." +
      digits.substr(static_cast<size_t>(decimal_point));
  }
  return text;
}

std::string format_yaml_string(const std::string& utf8, int indent)
{
  return format_scalar_string(decode_utf8(utf8), indent);
}

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

bool from_yaml(const MessageTypeSupport& type, const std::string& yaml, void* message,
               std::string* error)
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
