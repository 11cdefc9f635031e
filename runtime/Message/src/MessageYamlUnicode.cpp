// ros2vtk — UTF-8/16/32 conversions for the YAML writer and reader (MessageYaml.hpp): PyYAML
// decides quoting per code point, so strings are analysed as UTF-32; wstring fields are UTF-16.
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

} // namespace yaml_detail
} // namespace wire
} // namespace ros2vtk
