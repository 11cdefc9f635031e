// ros2vtk — any generated message as YAML and back, through its introspection table.
//
// `ros2 topic echo` prints messages with rosidl_runtime_py.message_to_yaml (PyYAML, block style);
// SlicerROS2 users read GetLastMessageYAML() next to it, so to_yaml() writes the same text byte
// for byte: floats as Python's repr, strings quoted exactly when PyYAML quotes them, nested
// messages indented by two, sequences as `- ` items (not indented under their key), `[]` for an
// empty sequence, `byte` fields as one-character strings. from_yaml() reads that text (or any
// YAML a user writes) with yaml-cpp; it never throws.
#ifndef ros2vtk_wire_MessageYaml_hpp
#define ros2vtk_wire_MessageYaml_hpp

#include <string>

namespace ros2vtk {
namespace wire {

struct MessageTypeSupport;

/// The message as `ros2 topic echo` prints it (without the `---` separator); "{}\n" for a
/// message without fields.
std::string to_yaml(const MessageTypeSupport& type, const void* message);

/// Fills `message` (an instance of `type`) from YAML. Fields the YAML leaves out get their
/// default values. Unknown fields, values of the wrong kind, out-of-range numbers and arrays of
/// the wrong length are errors naming the field path (`poses[2].position.x`). On failure
/// `message` is left unchanged, false is returned and `error` (if given) says why.
bool from_yaml(
  const MessageTypeSupport& type, const std::string& yaml, void* message, std::string* error);

/// One double as PyYAML writes a Python float: repr() digits, lower case, `1.0e+16` not
/// `1e+16`, `.nan`, `.inf`, `-.inf`. Exposed for the generic nodes and for tests.
std::string format_yaml_float(double value);

/// One UTF-8 string as PyYAML writes a block-mapping value: plain when it reads back as the
/// same string, else 'single' or "double" quoted. `indent` is the column that continuation
/// lines of a multi-line single-quoted string start at (the enclosing mapping's indent + 2).
std::string format_yaml_string(const std::string& utf8, int indent);

} // namespace wire
} // namespace ros2vtk

#endif
