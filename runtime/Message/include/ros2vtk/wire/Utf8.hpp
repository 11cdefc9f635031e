// ros2vtk — the one policy for text that is not valid UTF-8 (issue 11.9): every string read
// from the wire (CdrReader::read_string) or from a file the scene reads has each invalid
// sequence replaced by U+FFFD, the way rclpy decodes strings (rosidl_generator_py: "replace"),
// and the replacements are counted (per reader and process-wide). VTK's Python wrapping then
// always hands Python a `str`, never `bytes`. Also: cutting received text short for error
// messages without splitting a character.
#ifndef ros2vtk_wire_Utf8_hpp
#define ros2vtk_wire_Utf8_hpp

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>

namespace ros2vtk {
namespace wire {

/// Invalid sequences replaced since the process started (all readers, all threads).
inline std::atomic<uint64_t>& invalid_utf8_replacements()
{
  static std::atomic<uint64_t> count{ 0 };
  return count;
}

namespace detail {

/// Length of the well-formed UTF-8 sequence at text[i] (Unicode table 3-7), or 0 with `*bad`
/// set to the length of its maximal invalid subpart (what one U+FFFD replaces, as in Python).
inline size_t utf8_sequence(const std::string& text, size_t i, size_t* bad)
{
  const auto byte = [&](size_t k) {
    return static_cast<unsigned char>(text[k]);
  };
  const unsigned char lead = byte(i);
  if (lead < 0x80)
    return 1;
  size_t length = 0;
  unsigned char low = 0x80, high = 0xBF; // range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF)
  {
    length = 3;
    low = lead == 0xE0 ? 0xA0 : 0x80;
    high = lead == 0xED ? 0x9F : 0xBF;
  }
  else if (lead >= 0xF0 && lead <= 0xF4)
  {
    length = 4;
    low = lead == 0xF0 ? 0x90 : 0x80;
    high = lead == 0xF4 ? 0x8F : 0xBF;
  }
  else
  {
    *bad = 1;
    return 0;
  }
  for (size_t k = 1; k < length; ++k)
  {
    const bool in_range = i + k < text.size() &&
      (k == 1 ? byte(i + k) >= low && byte(i + k) <= high : (byte(i + k) & 0xC0) == 0x80);
    if (!in_range)
    {
      *bad = k;
      return 0;
    }
  }
  return length;
}

} // namespace detail

/// Replaces each invalid sequence of `text` by U+FFFD; returns how many were replaced (and adds
/// them to invalid_utf8_replacements()). Valid text is left as it is, without copying.
inline size_t repair_utf8(std::string& text)
{
  size_t i = 0;
  size_t bad = 0;
  while (i < text.size())
  {
    const size_t length = detail::utf8_sequence(text, i, &bad);
    if (length == 0)
      break;
    i += length;
  }
  if (i == text.size())
    return 0;
  std::string repaired(text, 0, i);
  size_t replaced = 0;
  while (i < text.size())
  {
    const size_t length = detail::utf8_sequence(text, i, &bad);
    if (length == 0)
    {
      repaired += "\xEF\xBF\xBD";
      ++replaced;
      i += bad;
    }
    else
    {
      repaired.append(text, i, length);
      i += length;
    }
  }
  text.swap(repaired);
  invalid_utf8_replacements() += replaced;
  return replaced;
}

/// At most `max_bytes` of received text for an error message, cut at a character boundary,
/// with a note of the full size when cut (a 1 MB frame name must not make a 1 MB error).
inline std::string clip_for_message(const std::string& text, size_t max_bytes = 200)
{
  if (text.size() <= max_bytes)
    return text;
  size_t cut = max_bytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
    --cut;
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

} // namespace wire
} // namespace ros2vtk

#endif
