// ros2vtk — the constants of a .msg text, for types learnt at run time (DynamicType.hpp).
//
// The project's .msg grammar lives in the generator (generator/ros2vtk_gen/msg_parser.py), which
// runs at build time in Python; the runtime cannot call it. Only constant lines are needed here
// (a REP 2011 description already gives the fields), so this is a small parser of those lines
// following the same rules: comments start at a '#' outside quotes, `TYPE NAME=VALUE` with a
// primitive TYPE (a bounded string included) and an UPPER_CASE NAME, values normalised as the
// generator's constant_display (bool true/false, integers in decimal, floats as Python's repr,
// strings unquoted).
#include "ros2vtk/wire/DynamicType.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace ros2vtk {
namespace wire {

namespace {

/// The line without its comment: '#' inside single or double quotes is kept.
std::string strip_comment(const std::string& line)
{
  char quote = 0;
  bool escaped = false;
  for (size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (escaped)
    {
      escaped = false;
    }
    else if (c == '\\')
    {
      escaped = true;
    }
    else if (quote)
    {
      quote = c == quote ? 0 : quote;
    }
    else if (c == '\'' || c == '"')
    {
      quote = c;
    }
    else if (c == '#')
    {
      return line.substr(0, i);
    }
  }
  return line;
}

std::string trimmed(const std::string& text)
{
  const size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
  {
    return std::string();
  }
  const size_t end = text.find_last_not_of(" \t\r");
  return text.substr(begin, end - begin + 1);
}

bool primitive_type(const std::string& name, FieldType* type)
{
  const std::string base = name.substr(0, name.find("<="));
  if (base != name && base != "string" && base != "wstring")
  {
    return false;
  }
  for (int i = 0; i <= static_cast<int>(FieldType::WString); ++i)
  {
    if (base == field_type_name(static_cast<FieldType>(i)))
    {
      *type = static_cast<FieldType>(i);
      return true;
    }
  }
  return false;
}

bool identifier(const std::string& name)
{
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])))
  {
    return false;
  }
  for (char c : name)
  {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
    {
      return false;
    }
  }
  return true;
}

bool constant_name(const std::string& name)
{
  if (name.empty() || !std::isupper(static_cast<unsigned char>(name[0])))
  {
    return false;
  }
  for (char c : name)
  {
    if (!(std::isupper(static_cast<unsigned char>(c)) ||
          std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
    {
      return false;
    }
  }
  return true;
}

/// Python's repr of a finite double: the shortest text that reads back the same, with ".0"
/// when it would read as an integer.
std::string float_repr(double value)
{
  char text[40];
  for (int precision = 1; precision <= 17; ++precision)
  {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value)
    {
      break;
    }
  }
  std::string out = text;
  if (out.find_first_of(".en") == std::string::npos)
  {
    out += ".0";
  }
  return out;
}

bool integer_range(FieldType type, long double* low, long double* high)
{
  switch (type)
  {
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8:
      *low = 0, *high = 255;
      return true;
    case FieldType::Int8:
      *low = -128, *high = 127;
      return true;
    case FieldType::Int16:
      *low = -32768, *high = 32767;
      return true;
    case FieldType::UInt16:
      *low = 0, *high = 65535;
      return true;
    case FieldType::Int32:
      *low = -2147483648.0L, *high = 2147483647.0L;
      return true;
    case FieldType::UInt32:
      *low = 0, *high = 4294967295.0L;
      return true;
    case FieldType::Int64:
      *low = -9223372036854775808.0L, *high = 9223372036854775807.0L;
      return true;
    case FieldType::UInt64:
      *low = 0, *high = 18446744073709551615.0L;
      return true;
    default:
      return false;
  }
}

/// The value normalised, or false with the reason.
bool normalised(const std::string& text, FieldType type, std::string* value, std::string* reason)
{
  if (type == FieldType::String || type == FieldType::WString)
  {
    *value = text;
    if (text.size() >= 2 && (text[0] == '"' || text[0] == '\'') && text.back() == text[0])
    {
      value->clear();
      for (size_t i = 1; i + 1 < text.size(); ++i)
      {
        if (text[i] == '\\' && i + 2 < text.size())
        {
          ++i;
        }
        value->push_back(text[i]);
      }
    }
    return true;
  }
  if (text.empty())
  {
    *reason = "no value";
    return false;
  }
  if (type == FieldType::Bool)
  {
    std::string lowered;
    for (char c : text)
    {
      lowered.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
    if (lowered == "true" || lowered == "1" || lowered == "false" || lowered == "0")
    {
      *value = lowered == "true" || lowered == "1" ? "true" : "false";
      return true;
    }
    *reason = "'" + text + "' is not a bool";
    return false;
  }
  long double low = 0, high = 0;
  if (integer_range(type, &low, &high))
  {
    const bool negative = text[0] == '-';
    const std::string digits = negative || text[0] == '+' ? text.substr(1) : text;
    errno = 0;
    char* end = nullptr;
    const unsigned long long magnitude = std::strtoull(digits.c_str(), &end, 0);
    if (digits.empty() || !std::isdigit(static_cast<unsigned char>(digits[0])) || *end || errno)
    {
      *reason = "'" + text + "' is not an integer for " + field_type_name(type);
      return false;
    }
    const long double number = negative ? -static_cast<long double>(magnitude) : magnitude;
    if (number < low || number > high)
    {
      *reason = text + " is out of range for " + field_type_name(type);
      return false;
    }
    *value = (negative && magnitude ? "-" : "") + std::to_string(magnitude);
    return true;
  }
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (*end || !std::isfinite(number) ||
    (type == FieldType::Float32 && std::fabs(number) > std::numeric_limits<float>::max()))
  {
    *reason = "'" + text + "' is not a finite " + field_type_name(type);
    return false;
  }
  *value = float_repr(number);
  return true;
}

} // namespace

bool parse_msg_constants(
  const std::string& text, std::vector<DescriptionConstant>* constants, std::string* error)
{
  std::istringstream lines(text);
  std::string raw;
  for (int number = 1; std::getline(lines, raw); ++number)
  {
    const std::string line = trimmed(strip_comment(raw));
    const size_t space = line.find_first_of(" \t");
    const size_t equals = line.find('=');
    // A field's default ("int32 x 5") has no '='; a constant is TYPE NAME=VALUE (the type may
    // hold "<=": bounds are written string<=5).
    const size_t name_at =
      space == std::string::npos ? space : line.find_first_not_of(" \t", space);
    if (line.empty() || name_at == std::string::npos || equals == std::string::npos ||
      equals < name_at)
    {
      continue;
    }
    DescriptionConstant constant;
    const std::string type_name = line.substr(0, space);
    constant.name = trimmed(line.substr(name_at, equals - name_at));
    if (!identifier(constant.name))
    {
      continue; // a field whose default holds '=' (string s "a=b")
    }
    const std::string where =
      "line " + std::to_string(number) + ": constant '" + constant.name + "'";
    if (!primitive_type(type_name, &constant.type))
    {
      *error = where + " must have a primitive, non-array type, not " + type_name;
      return false;
    }
    if (!constant_name(constant.name))
    {
      *error = where + ": not an UPPER_CASE name";
      return false;
    }
    std::string reason;
    if (!normalised(trimmed(line.substr(equals + 1)), constant.type, &constant.value, &reason))
    {
      *error = where + ": " + reason;
      return false;
    }
    constants->push_back(std::move(constant));
  }
  return true;
}

} // namespace wire
} // namespace ros2vtk
