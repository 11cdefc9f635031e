// ros2vtk — a node's REP 2011 type description service, as rclpy and rclcpp nodes serve it
// (rcl_node_type_description_service_*): `~/get_type_description`
// (type_description_interfaces/srv/GetTypeDescription) answers, for the RIHS01 hash of any
// type the node's endpoints use (NodeTypeCache), that type's description, so tools such as
// `ros2 topic echo` of a type they lack can learn it from our node.
#ifndef ros2vtk_wire_TypeDescriptionService_hpp
#define ros2vtk_wire_TypeDescriptionService_hpp

#include "ros2vtk/type_description_interfaces/srv/get_type_description.hpp"
#include "ros2vtk/wire/DynamicType.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"

#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

class ParameterStore;
class Participant;

/// A generated description table as the message the service sends.
void to_message(const TypeDescriptionTable& table,
  ::ros2vtk::type_description_interfaces::msg::TypeDescription& message);

/// A received description in the plain form build_dynamic_message_type reads (DynamicType.hpp).
TypeDescriptionData from_message(
  const ::ros2vtk::type_description_interfaces::msg::TypeDescription& message);

/// Fills `response` for `request` from `types`, as
/// rcl_node_type_description_service_handle_request: the type is looked up by its hash alone; an
/// unparsable hash answers "Failed to parse type hash", a hash no endpoint of the node uses "Type
/// not currently in use by this node". With include_type_sources, type_sources holds the type's
/// source and each referenced type's, in the description's order, as rcl copies them from the
/// type support (the generated tables embed the interface files' text).
void answer_type_description_request(const NodeTypeCache& types,
  const ::ros2vtk::type_description_interfaces::srv::GetTypeDescription_Request& request,
  ::ros2vtk::type_description_interfaces::srv::GetTypeDescription_Response& response);

class ServiceServer;

class TypeDescriptionService
{
public:
  /// The node parameter that switches the service on (bool, default true, read-only), as
  /// rclpy's TypeDescriptionService and rclcpp's NodeTypeDescriptions declare it.
  static const char* const kEnableParameter;

  /// Declares kEnableParameter in `parameters` with `default_value` unless it is declared, and
  /// returns its value (false, with `error`, when it is not a bool, as rclpy logs).
  static bool enabled(ParameterStore& parameters, bool default_value, std::string* error);

  /// Serves `participant`'s types. nullptr (and `error`) when DDS refused the endpoints.
  static std::unique_ptr<TypeDescriptionService> create(
    Participant& participant, std::string* error);
  ~TypeDescriptionService();
  TypeDescriptionService(const TypeDescriptionService&) = delete;
  TypeDescriptionService& operator=(const TypeDescriptionService&) = delete;

  /// Answers every queued request (call it from the spin). Returns how many.
  size_t process();

  /// Requests answered since creation.
  uint64_t answered_count() const { return answered_; }

private:
  TypeDescriptionService(const NodeTypeCache& types, std::unique_ptr<ServiceServer> server);
  const NodeTypeCache& types_;
  std::unique_ptr<ServiceServer> server_;
  uint64_t answered_ = 0;
};

} // namespace wire
} // namespace ros2vtk

#endif
