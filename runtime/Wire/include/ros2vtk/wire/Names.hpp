// ros2vtk — ROS 2 name rules: validation and expansion as rcl does them, and the DDS mangling
// rmw_fastrtps applies (docs/wire-notes.md §1).
#ifndef ros2vtk_wire_Names_hpp
#define ros2vtk_wire_Names_hpp

#include <string>

namespace ros2vtk {
namespace wire {

/// A node name: [A-Za-z_][A-Za-z0-9_]*, at most 255 characters.
bool validate_node_name(const std::string& name, std::string* error);
/// "" -> "/", adds a missing leading '/', rejects invalid tokens.
bool normalize_namespace(const std::string& ns, std::string& normalized, std::string* error);
/// "/ns" + "node" -> "/ns/node"; "/" + "node" -> "/node".
std::string fully_qualified_node_name(const std::string& ns, const std::string& node);
/// rcl's expansion: absolute stays, `~` and `~/x` are private to the node, relative names go
/// under the namespace. Then validated as a fully qualified topic name.
bool expand_topic_name(const std::string& name, const std::string& node_name,
                       const std::string& ns, std::string& expanded, std::string* error);

/// "/chatter" -> "rt/chatter"; service request "rq/<name>Request", reply "rr/<name>Reply".
std::string topic_to_dds(const std::string& ros_topic);
std::string service_request_to_dds(const std::string& ros_service);
std::string service_reply_to_dds(const std::string& ros_service);
/// The reverse for topics: "rt/chatter" -> "/chatter"; false for non-ROS topics.
bool dds_to_topic(const std::string& dds_topic, std::string& ros_topic);
/// "std_msgs::msg::dds_::String_" -> "std_msgs/msg/String"; other names verbatim.
std::string dds_type_to_ros(const std::string& dds_type);

} // namespace wire
} // namespace ros2vtk

#endif
