// ros2vtk — one field of any generated message read or written as text, by its dotted path
// ("header.frame_id", "success"), through the message's introspection table. The service nodes
// use it for field-by-field requests and responses; YAML covers sequences and whole messages.
#ifndef ros2vtk_scene_MessageFields_hpp
#define ros2vtk_scene_MessageFields_hpp

#include <string>

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}

namespace scene {

/// Writes `value` into the single (non-sequence) field at `path`: numbers in decimal, bools as
/// true/false/1/0, strings as given. False and `error` naming the path on an unknown field, a
/// container field, a wstring field or a value that does not fit the field's type.
bool set_field_from_text(const wire::MessageTypeSupport& type, void* message,
  const std::string& path, const std::string& value, std::string* error);

/// The single field at `path` as text (bools true/false, floats as YAML writes them, a nested
/// message as its YAML). False and `error` on an unknown path, a sequence or a wstring.
bool get_field_as_text(const wire::MessageTypeSupport& type, const void* message,
  const std::string& path, std::string& value, std::string* error);

} // namespace scene
} // namespace ros2vtk

#endif
