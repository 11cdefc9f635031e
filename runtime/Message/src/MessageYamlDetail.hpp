// ros2vtk — what the four files of the YAML code share (private to ros2vtk::Message):
// MessageYamlUnicode.cpp (UTF conversions), MessageYamlScalars.cpp (PyYAML's scalar styles),
// MessageYamlWriter.cpp (to_yaml) and MessageYamlReader.cpp (from_yaml).
#ifndef ros2vtk_wire_MessageYamlDetail_hpp
#define ros2vtk_wire_MessageYamlDetail_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <cstddef>
#include <cstring>
#include <string>

namespace ros2vtk {
namespace wire {
namespace yaml_detail {

// MessageYamlUnicode.cpp
/// Decodes UTF-8; a byte that does not start a valid sequence stands for itself (Latin-1), so
/// no input is lost or rejected on the way to YAML.
std::u32string decode_utf8(const std::string& text);
void append_utf8(std::string& out, char32_t code);
/// UTF-8 of text[begin, end).
std::string encode_utf8(const std::u32string& text, size_t begin, size_t end);
std::u32string utf16_to_utf32(const std::u16string& text);
std::u16string utf32_to_utf16(const std::u32string& text);

// MessageYamlScalars.cpp
/// A string as the value of a block mapping at `indent`, in the style PyYAML picks.
std::string format_scalar_string(const std::u32string& text, int indent);

template<typename T>
const T& at(const void* pointer)
{
  return *static_cast<const T*>(pointer);
}

inline const void* field_address(const void* message, const FieldInfo& field)
{
  return static_cast<const char*>(message) + field.offset;
}

inline void* field_address(void* message, const FieldInfo& field)
{
  return static_cast<char*>(message) + field.offset;
}

} // namespace yaml_detail
} // namespace wire
} // namespace ros2vtk

#endif
