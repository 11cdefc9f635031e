// ros2vtk — rclcpp's parameter semantics (rclcpp/src/rclcpp/node_interfaces/node_parameters.cpp,
// summarised in WIRE_NOTES §5.3), re-implemented over the generated rcl_interfaces types.
#include "ros2vtk/wire/ParameterStore.hpp"

#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace ros2vtk {
namespace wire {

namespace {

// rcl_interfaces/msg/ParameterType's constants (generated from its spec: the one place they
// are defined), under the short names this file uses.
using ParameterType = rcl::ParameterType;
constexpr uint8_t kNotSet = ParameterType::PARAMETER_NOT_SET;
constexpr uint8_t kBool = ParameterType::PARAMETER_BOOL;
constexpr uint8_t kInteger = ParameterType::PARAMETER_INTEGER;
constexpr uint8_t kDouble = ParameterType::PARAMETER_DOUBLE;
constexpr uint8_t kString = ParameterType::PARAMETER_STRING;
constexpr uint8_t kByteArray = ParameterType::PARAMETER_BYTE_ARRAY;
constexpr uint8_t kBoolArray = ParameterType::PARAMETER_BOOL_ARRAY;
constexpr uint8_t kIntegerArray = ParameterType::PARAMETER_INTEGER_ARRAY;
constexpr uint8_t kDoubleArray = ParameterType::PARAMETER_DOUBLE_ARRAY;
constexpr uint8_t kStringArray = ParameterType::PARAMETER_STRING_ARRAY;

template<typename T, typename Format>
std::string join(const std::vector<T>& values, Format format)
{
  std::ostringstream out;
  out << "[";
  for (size_t i = 0; i < values.size(); ++i)
  {
    out << (i ? ", " : "") << format(values[i]);
  }
  out << "]";
  return out.str();
}

std::string format_double(double value)
{
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

size_t count_dots(const std::string& text)
{
  return static_cast<size_t>(std::count(text.begin(), text.end(), '.'));
}

} // namespace

std::string parameter_type_name(uint8_t type)
{
  switch (type)
  {
    case kBool:
      return "bool";
    case kInteger:
      return "integer";
    case kDouble:
      return "double";
    case kString:
      return "string";
    case kByteArray:
      return "byte_array";
    case kBoolArray:
      return "bool_array";
    case kIntegerArray:
      return "integer_array";
    case kDoubleArray:
      return "double_array";
    case kStringArray:
      return "string_array";
    default:
      return "not set";
  }
}

std::string parameter_value_to_string(const rcl::ParameterValue& value)
{
  switch (value.type)
  {
    case kBool:
      return value.bool_value ? "true" : "false";
    case kInteger:
      return std::to_string(value.integer_value);
    case kDouble:
      return format_double(value.double_value);
    case kString:
      return value.string_value;
    case kByteArray:
      return join(value.byte_array_value, [](uint8_t b) { return std::to_string(b); });
    case kBoolArray:
    {
      std::vector<int> bools(value.bool_array_value.begin(), value.bool_array_value.end());
      return join(bools, [](int b) { return std::string(b ? "true" : "false"); });
    }
    case kIntegerArray:
      return join(value.integer_array_value, [](int64_t v) { return std::to_string(v); });
    case kDoubleArray:
      return join(value.double_array_value, format_double);
    case kStringArray:
      return join(value.string_array_value, [](const std::string& s) { return "'" + s + "'"; });
    default:
      return "not set";
  }
}

bool ParameterStore::declare(const std::string& name, const rcl::ParameterValue& value,
  const rcl::ParameterDescriptor& descriptor, std::string* error)
{
  if (name.empty())
  {
    if (error)
      *error = "parameter name must not be empty";
    return false;
  }
  if (parameters_.count(name))
  {
    if (error)
      *error = "parameter '" + name + "' has already been declared";
    return false;
  }
  Entry entry{ value, descriptor };
  entry.descriptor.name = name;
  entry.descriptor.type = value.type;
  parameters_[name] = entry;
  rcl::ParameterEvent event;
  rcl::Parameter parameter;
  parameter.name = name;
  parameter.value = value;
  event.new_parameters.push_back(parameter);
  events_.push_back(event);
  return true;
}

bool ParameterStore::declare(
  const std::string& name, const rcl::ParameterValue& value, std::string* error)
{
  return declare(name, value, rcl::ParameterDescriptor(), error);
}

bool ParameterStore::undeclare(const std::string& name, std::string* error)
{
  auto it = parameters_.find(name);
  if (it == parameters_.end())
  {
    if (error)
      *error = "parameter '" + name + "' is not declared";
    return false;
  }
  if (it->second.descriptor.read_only)
  {
    if (error)
      *error = "parameter '" + name + "' is read only";
    return false;
  }
  rcl::ParameterEvent event;
  rcl::Parameter parameter;
  parameter.name = name;
  parameter.value = it->second.value;
  event.deleted_parameters.push_back(parameter);
  events_.push_back(event);
  parameters_.erase(it);
  return true;
}

bool ParameterStore::has(const std::string& name) const
{
  return parameters_.count(name) > 0;
}

const rcl::ParameterValue* ParameterStore::get(const std::string& name) const
{
  auto it = parameters_.find(name);
  return it == parameters_.end() ? nullptr : &it->second.value;
}

std::vector<rcl::ParameterValue> ParameterStore::get_parameters(
  const std::vector<std::string>& names) const
{
  std::vector<rcl::ParameterValue> values;
  for (const auto& name : names)
  {
    auto it = parameters_.find(name);
    if (it == parameters_.end())
      return {};
    values.push_back(it->second.value);
  }
  return values;
}

std::vector<uint8_t> ParameterStore::get_parameter_types(
  const std::vector<std::string>& names) const
{
  std::vector<uint8_t> types;
  for (const auto& name : names)
  {
    auto it = parameters_.find(name);
    if (it == parameters_.end())
      return {};
    types.push_back(it->second.value.type);
  }
  return types;
}

size_t parameter_value_size(const rcl::ParameterValue& value)
{
  switch (value.type)
  {
    case kString:
      return value.string_value.size();
    case kByteArray:
      return value.byte_array_value.size();
    case kBoolArray:
      return value.bool_array_value.size();
    case kIntegerArray:
      return value.integer_array_value.size() * sizeof(int64_t);
    case kDoubleArray:
      return value.double_array_value.size() * sizeof(double);
    case kStringArray:
    {
      size_t bytes = 0;
      for (const auto& text : value.string_array_value)
        bytes += text.size() + sizeof(uint32_t);
      return bytes;
    }
    default:
      return 0;
  }
}

std::string ParameterStore::check(const rcl::Parameter& parameter) const
{
  auto it = parameters_.find(parameter.name);
  if (it == parameters_.end())
  {
    return "parameter '" + parameter.name + "' cannot be set because it was not declared";
  }
  const rcl::ParameterDescriptor& descriptor = it->second.descriptor;
  if (descriptor.read_only)
  {
    return "parameter '" + parameter.name + "' cannot be set because it is read-only";
  }
  // Before the type: an oversized value is refused for its size, whatever its type.
  const size_t size = parameter_value_size(parameter.value);
  if (size > value_size_limit_)
  {
    return "parameter '" + parameter.name + "' cannot be set: its " +
      parameter_type_name(parameter.value.type) + " value holds " + std::to_string(size) +
      " bytes, more than this node accepts (" + std::to_string(value_size_limit_) + ")";
  }
  const uint8_t current = it->second.value.type;
  if (!descriptor.dynamic_typing && current != kNotSet && parameter.value.type != current)
  {
    return "Wrong parameter type, parameter {" + parameter.name + "} is of type {" +
      parameter_type_name(current) + "}, setting it to {" +
      parameter_type_name(parameter.value.type) + "} is not allowed.";
  }
  if (parameter.value.type == kInteger && !descriptor.integer_range.empty())
  {
    const auto& range = descriptor.integer_range.front();
    const int64_t v = parameter.value.integer_value;
    if (v < range.from_value || v > range.to_value ||
      (range.step != 0 && v != range.to_value &&
        (v - range.from_value) % static_cast<int64_t>(range.step) != 0))
    {
      return "Parameter {" + parameter.name + "} doesn't comply with integer range.";
    }
  }
  if (parameter.value.type == kDouble && !descriptor.floating_point_range.empty())
  {
    const auto& range = descriptor.floating_point_range.front();
    const double v = parameter.value.double_value;
    if (std::isnan(v) || v < range.from_value || v > range.to_value)
    {
      return "Parameter {" + parameter.name + "} doesn't comply with floating point range.";
    }
  }
  if (validator_)
  {
    return validator_(parameter);
  }
  return std::string();
}

size_t ParameterStore::add_post_set_callback(PostSetCallback callback)
{
  const size_t id = next_callback_id_++;
  post_set_callbacks_.emplace_back(id, std::move(callback));
  return id;
}

void ParameterStore::remove_post_set_callback(size_t id)
{
  post_set_callbacks_.erase(std::remove_if(post_set_callbacks_.begin(), post_set_callbacks_.end(),
                              [id](const auto& entry) { return entry.first == id; }),
    post_set_callbacks_.end());
}

void ParameterStore::notify_post_set(const std::vector<rcl::Parameter>& changed)
{
  if (changed.empty())
    return;
  // A copy: a callback may add or remove callbacks.
  const auto callbacks = post_set_callbacks_;
  for (const auto& entry : callbacks)
    entry.second(changed);
}

std::vector<rcl::SetParametersResult> ParameterStore::set_parameters(
  const std::vector<rcl::Parameter>& parameters)
{
  std::vector<rcl::SetParametersResult> results;
  for (const auto& parameter : parameters)
  {
    rcl::SetParametersResult result;
    result.reason = check(parameter);
    result.successful = result.reason.empty();
    if (result.successful)
    {
      parameters_[parameter.name].value = parameter.value;
      rcl::ParameterEvent event;
      event.changed_parameters.push_back(parameter);
      events_.push_back(event);
      // Per parameter, as rclpy's set_parameters sets them one by one.
      notify_post_set({ parameter });
    }
    results.push_back(result);
  }
  return results;
}

rcl::SetParametersResult ParameterStore::set_parameters_atomically(
  const std::vector<rcl::Parameter>& parameters)
{
  rcl::SetParametersResult result;
  for (const auto& parameter : parameters)
  {
    if (!parameters_.count(parameter.name))
    {
      result.successful = false;
      result.reason = "One or more parameters were not declared before setting";
      return result;
    }
    const std::string reason = check(parameter);
    if (!reason.empty())
    {
      result.successful = false;
      result.reason = reason;
      return result;
    }
  }
  rcl::ParameterEvent event;
  for (const auto& parameter : parameters)
  {
    parameters_[parameter.name].value = parameter.value;
    event.changed_parameters.push_back(parameter);
  }
  if (!parameters.empty())
    events_.push_back(event);
  result.successful = true;
  notify_post_set(parameters);
  return result;
}

std::vector<rcl::ParameterDescriptor> ParameterStore::describe_parameters(
  const std::vector<std::string>& names) const
{
  std::vector<rcl::ParameterDescriptor> descriptors;
  for (const auto& name : names)
  {
    auto it = parameters_.find(name);
    if (it == parameters_.end())
      return {};
    descriptors.push_back(it->second.descriptor);
  }
  return descriptors;
}

rcl::ListParametersResult ParameterStore::list_parameters(
  const std::vector<std::string>& prefixes, uint64_t depth) const
{
  rcl::ListParametersResult result;
  std::set<std::string> found_prefixes;
  for (const auto& entry : parameters_)
  {
    const std::string& name = entry.first;
    bool listed = false;
    if (prefixes.empty())
    {
      listed = depth == 0 || count_dots(name) < depth;
    }
    else
    {
      for (const auto& prefix : prefixes)
      {
        if (name == prefix)
        {
          listed = true;
        }
        else if (name.compare(0, prefix.size() + 1, prefix + ".") == 0)
        {
          listed = depth == 0 || count_dots(name.substr(prefix.size() + 1)) < depth;
        }
        if (listed)
          break;
      }
    }
    if (!listed)
      continue;
    result.names.push_back(name);
    const size_t last_dot = name.rfind('.');
    if (last_dot != std::string::npos)
      found_prefixes.insert(name.substr(0, last_dot));
  }
  result.prefixes.assign(found_prefixes.begin(), found_prefixes.end());
  return result;
}

std::vector<std::string> ParameterStore::names() const
{
  std::vector<std::string> result;
  for (const auto& entry : parameters_)
    result.push_back(entry.first);
  return result;
}

std::vector<rcl::ParameterEvent> ParameterStore::take_events()
{
  std::vector<rcl::ParameterEvent> events;
  events.swap(events_);
  return events;
}

} // namespace wire
} // namespace ros2vtk
