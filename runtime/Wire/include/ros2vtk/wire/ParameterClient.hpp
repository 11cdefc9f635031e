// ros2vtk — watches parameters of one remote ROS node (the paper's parameter node): asks its
// get_parameters service for the watched names, then follows /parameter_events so remote changes
// arrive without polling. An absent node is a state, not an error; when it comes back (or
// restarts) the values are fetched again.
#ifndef ros2vtk_wire_ParameterClient_hpp
#define ros2vtk_wire_ParameterClient_hpp

#include "ros2vtk/rcl_interfaces/msg/parameter_value.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {

class Participant;

class ParameterClient
{
public:
  enum class State
  {
    WaitingForNode, ///< the node's parameter services are not (or no longer) available
    Ready           ///< values are being kept up to date
  };

  /// `remote_node` is the fully qualified node name ("/robot_state_publisher", "/PSM1/rsp").
  static std::unique_ptr<ParameterClient> create(
    Participant& participant, const std::string& remote_node, std::string* error);
  ~ParameterClient();
  ParameterClient(const ParameterClient&) = delete;
  ParameterClient& operator=(const ParameterClient&) = delete;

  const std::string& remote_node() const;
  State state() const;

  /// Starts (or stops) following a parameter; the value arrives on a later process().
  void add(const std::string& name);
  void remove(const std::string& name);
  std::vector<std::string> watched() const;

  /// The current value, nullptr when not known (not fetched yet, or not set on the node). A
  /// parameter never added is known once /parameter_events reports it (as in SlicerROS2).
  const ::ros2vtk::rcl_interfaces::msg::ParameterValue* value(const std::string& name) const;

  /// Sends pending requests, takes responses and events. Returns the names whose value changed
  /// (or became known / unknown) since the previous call. Call it from the owning thread.
  std::set<std::string> process();

  class Impl;

private:
  explicit ParameterClient(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace wire
} // namespace ros2vtk

#endif
