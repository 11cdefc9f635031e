// ros2vtk — scalars as PyYAML writes them: PyYAML 6's analyze_scalar / choose_scalar_style,
// its resolver's implicit types, single- and double-quoted styles, Python's float repr
// (format_yaml_float / format_yaml_string of MessageYaml.hpp). tests/fixtures/yaml_scalars.json
// holds PyYAML's own output for tricky values.
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
    const bool printable =
      (ch >= 0x20 && ch <= 0x7E) || (ch >= 0xA0 && ch <= 0xD7FF) || (ch >= 0xE000 && ch <= 0xFFFD);
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
      case 0x00:
        short_escape = "\\0";
        break;
      case 0x07:
        short_escape = "\\a";
        break;
      case 0x08:
        short_escape = "\\b";
        break;
      case 0x09:
        short_escape = "\\t";
        break;
      case 0x0A:
        short_escape = "\\n";
        break;
      case 0x0B:
        short_escape = "\\v";
        break;
      case 0x0C:
        short_escape = "\\f";
        break;
      case 0x0D:
        short_escape = "\\r";
        break;
      case 0x1B:
        short_escape = "\\e";
        break;
      case U'"':
        short_escape = "\\\"";
        break;
      case U'\\':
        short_escape = "\\\\";
        break;
      case 0x85:
        short_escape = "\\N";
        break;
      case 0xA0:
        short_escape = "\\_";
        break;
      case 0x2028:
        short_escape = "\\L";
        break;
      case 0x2029:
        short_escape = "\\P";
        break;
      default:
        break;
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

} // namespace yaml_detail
} // namespace wire
} // namespace ros2vtk

namespace ros2vtk {
namespace wire {
using namespace yaml_detail; // the helpers shared by the YAML files (MessageYamlDetail.hpp)

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

} // namespace wire
} // namespace ros2vtk
