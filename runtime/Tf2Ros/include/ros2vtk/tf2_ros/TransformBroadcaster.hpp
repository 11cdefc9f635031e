// ros2vtk — publishes transforms as tf2_ros's broadcasters do: dynamic ones on /tf (keep last
// 100, reliable, volatile); static ones on /tf_static (keep last 1, reliable, transient local),
// where every send re-publishes the whole accumulated set so late joiners get all of them.
#ifndef ros2vtk_tf2_ros_TransformBroadcaster_hpp
#define ros2vtk_tf2_ros_TransformBroadcaster_hpp

#include "ros2vtk/tf2/TransformStamped.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {
class Participant;
class Publisher;
}
namespace tf2_ros {

class TransformBroadcaster
{
public:
  /// `is_static` picks /tf_static semantics.
  static std::unique_ptr<TransformBroadcaster> create(
    wire::Participant& participant, bool is_static, std::string* error);
  ~TransformBroadcaster();

  /// False when a transform is invalid (empty or equal frame ids, non-finite values); nothing
  /// is sent then.
  bool send(const std::vector<tf2::TransformStamped>& transforms, std::string* error);
  bool send(const tf2::TransformStamped& transform, std::string* error)
  {
    return send(std::vector<tf2::TransformStamped>{ transform }, error);
  }

private:
  TransformBroadcaster() = default;
  bool is_static_ = false;
  std::unique_ptr<wire::Publisher> publisher_;
  std::map<std::string, tf2::TransformStamped> static_set_; ///< by child frame
};

/// Now (system clock) as a tf2 time stamp: broadcasts carry the current time, never zero.
tf2::TimePoint now();

} // namespace tf2_ros
} // namespace ros2vtk

#endif
