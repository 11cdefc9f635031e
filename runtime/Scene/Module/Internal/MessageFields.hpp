// ros2vtk — one field of any generated message read or written by its path ("header.frame_id",
// "success", "poses[2].position.x", "data[0]"), through the message's introspection table. The
// service nodes use it for field-by-field requests and responses, vtkROS2Message for typed access
// to every field of every type; YAML covers whole messages.
#ifndef ros2vtk_scene_MessageFields_hpp
#define ros2vtk_scene_MessageFields_hpp

#include <cstddef>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}

namespace scene {

/// Writes `value` into the single value at `path` (a non-container field, or one element
/// `name[i]` of a container): numbers in decimal, bools as true/false/1/0, strings as given.
/// False and `error` naming the path on an unknown field, a whole container, a wstring, an index
/// out of range or a value that does not fit the field's type.
bool set_field_from_text(const wire::MessageTypeSupport& type, void* message,
  const std::string& path, const std::string& value, std::string* error);

/// The single value at `path` as text (bools true/false, floats as YAML writes them, exact), or
/// a nested message as its YAML. False and `error` on an unknown path, a whole container or a
/// wstring.
bool get_field_as_text(const wire::MessageTypeSupport& type, const void* message,
  const std::string& path, std::string& value, std::string* error);

/// What a field is, for typed access: `type_name` as in a .msg file ("float64", "string",
/// "geometry_msgs/msg/Point", with "[]", "[N]", "[<=N]" for containers), `nested` the element
/// message type (nullptr for primitives).
struct FieldDescription
{
  std::string name;
  std::string type_name;
  std::string element_type_name; ///< type_name without the container suffix
  bool is_container = false;
  bool is_fixed_size = false; ///< T[N]: cannot be resized
  bool is_message = false;
  const wire::MessageTypeSupport* nested = nullptr;
};

/// Describes the field at `path` (an index in the last segment describes one element). "" is
/// the message itself (is_message, nested = type).
bool describe_field(const wire::MessageTypeSupport& type, const std::string& path,
  FieldDescription& description, std::string* error);

/// The fields of the message at `path` ("" = the top level), in declaration order.
bool list_fields(const wire::MessageTypeSupport& type, const std::string& path,
  std::vector<FieldDescription>& fields, std::string* error);

/// Number of elements of the container at `path`.
bool get_field_length(const wire::MessageTypeSupport& type, const void* message,
  const std::string& path, size_t& length, std::string* error);

/// Resizes the sequence at `path` (new elements default-initialised). False for fixed arrays of
/// another size and beyond a bounded sequence's bound.
bool resize_field(const wire::MessageTypeSupport& type, void* message, const std::string& path,
  size_t length, std::string* error);

/// The message at `path` ("" = the top level; a nested field, or `name[i]` of a message
/// container) with its type, for copying it whole. nullptr and `error` otherwise.
void* locate_message(const wire::MessageTypeSupport& type, void* message, const std::string& path,
  const wire::MessageTypeSupport*& found_type, std::string* error);

} // namespace scene
} // namespace ros2vtk

#endif
