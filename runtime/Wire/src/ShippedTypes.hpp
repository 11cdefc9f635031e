// ros2vtk — the generated types the wire layer itself speaks (graph, parameters, tf), found
// through the type-support registry so this code never depends on generated accessor names.
#ifndef ros2vtk_wire_ShippedTypes_hpp
#define ros2vtk_wire_ShippedTypes_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <string>

namespace ros2vtk {
namespace wire {

/// The table of a shipped message type; aborts with a message naming the type when the
/// shipped message library is not linked (a build error, not a runtime condition).
const MessageTypeSupport& shipped_message_type(const std::string& ros_type);
const ServiceTypeSupport& shipped_service_type(const std::string& ros_type);

} // namespace wire
} // namespace ros2vtk

#endif
