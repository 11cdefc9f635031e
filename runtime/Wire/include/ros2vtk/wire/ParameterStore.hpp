// ros2vtk — the parameters of one ROS node with rclcpp's semantics (declare, get, set,
// set atomically, describe, list, events), independent of DDS so it is easy to test.
// ParameterServer puts it on the wire (the six rcl_interfaces services + /parameter_events).
#ifndef ros2vtk_wire_ParameterStore_hpp
#define ros2vtk_wire_ParameterStore_hpp

#include "ros2vtk/rcl_interfaces/msg/list_parameters_result.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_descriptor.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_event.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_value.hpp"
#include "ros2vtk/rcl_interfaces/msg/set_parameters_result.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ros2vtk {
namespace wire {

namespace rcl = ::ros2vtk::rcl_interfaces::msg;

/// "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
/// "double_array", "string_array", "not set" — SlicerROS2's GetParameterType names.
std::string parameter_type_name(uint8_t type);
/// Human-readable value ("[1, 2, 3]", "true", "0.5"), as `ros2 param get` shows it.
std::string parameter_value_to_string(const rcl::ParameterValue& value);
/// Bytes a value holds: string and array payloads (8 per integer/double, 1 per bool/byte,
/// each string of an array plus its 4-byte CDR length); scalars count 0.
size_t parameter_value_size(const rcl::ParameterValue& value);

class ParameterStore
{
public:
  /// Called before a set is applied; return a non-empty reason to refuse it.
  using Validator = std::function<std::string(const rcl::Parameter&)>;

  /// Declares a parameter (rclcpp's declare_parameter). False (and `error`) when it exists.
  bool declare(const std::string& name, const rcl::ParameterValue& value,
    const rcl::ParameterDescriptor& descriptor, std::string* error);
  bool declare(const std::string& name, const rcl::ParameterValue& value, std::string* error);
  bool undeclare(const std::string& name, std::string* error);
  bool has(const std::string& name) const;
  const rcl::ParameterValue* get(const std::string& name) const;

  void set_validator(Validator validator) { validator_ = std::move(validator); }

  /// Called after a set succeeded, with the parameters it changed (rclpy's post-set parameters
  /// callbacks): how a node follows its own parameters (use_sim_time) whether the set came from
  /// its own code or from another node through the services. Not called for declarations: who
  /// declares reads the value. Returns an id for remove_post_set_callback.
  using PostSetCallback = std::function<void(const std::vector<rcl::Parameter>&)>;
  size_t add_post_set_callback(PostSetCallback callback);
  void remove_post_set_callback(size_t id);

  /// Largest value (parameter_value_size) a set may bring; bigger ones are refused with a reason
  /// naming both sizes. Other nodes set our parameters through the services, so this bounds what
  /// they can make us keep. Declarations (our own code) are not bounded.
  static constexpr size_t kDefaultValueSizeLimit = 4u << 20;
  void set_value_size_limit(size_t bytes) { value_size_limit_ = bytes; }
  size_t value_size_limit() const { return value_size_limit_; }

  // The services' semantics (WIRE_NOTES §5.3). Empty results when any name is undeclared.
  std::vector<rcl::ParameterValue> get_parameters(const std::vector<std::string>& names) const;
  std::vector<uint8_t> get_parameter_types(const std::vector<std::string>& names) const;
  std::vector<rcl::SetParametersResult> set_parameters(
    const std::vector<rcl::Parameter>& parameters);
  rcl::SetParametersResult set_parameters_atomically(const std::vector<rcl::Parameter>& parameters);
  std::vector<rcl::ParameterDescriptor> describe_parameters(
    const std::vector<std::string>& names) const;
  rcl::ListParametersResult list_parameters(
    const std::vector<std::string>& prefixes, uint64_t depth) const;
  std::vector<std::string> names() const;

  /// Events since the last call (declarations, changes, undeclarations), for /parameter_events.
  std::vector<rcl::ParameterEvent> take_events();

private:
  /// Why `parameter` cannot be set, or "" when it can.
  std::string check(const rcl::Parameter& parameter) const;

  struct Entry
  {
    rcl::ParameterValue value;
    rcl::ParameterDescriptor descriptor;
  };
  std::map<std::string, Entry> parameters_;
  void notify_post_set(const std::vector<rcl::Parameter>& changed);

  Validator validator_;
  std::vector<std::pair<size_t, PostSetCallback>> post_set_callbacks_;
  size_t next_callback_id_ = 1;
  size_t value_size_limit_ = kDefaultValueSizeLimit;
  std::vector<rcl::ParameterEvent> events_;
};

} // namespace wire
} // namespace ros2vtk

#endif
