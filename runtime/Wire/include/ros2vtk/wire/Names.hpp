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
/// rcl_validate_topic_name: a topic or service name as written, before expansion
/// (letters, digits, '_', '/', a leading '~', {substitutions}).
bool validate_topic_name(const std::string& name, std::string* error);
/// rcl_expand_topic_name then rmw_validate_full_topic_name, as rclpy resolves names: a leading
/// `~` becomes the node's fully qualified name, `{node}`, `{ns}` and `{namespace}` are replaced,
/// a name still relative goes under the namespace; the result must be a valid full topic name
/// of at most 247 characters (docs/wire-notes.md §1.2).
bool expand_topic_name(const std::string& name, const std::string& node_name, const std::string& ns,
  std::string& expanded, std::string* error);

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
