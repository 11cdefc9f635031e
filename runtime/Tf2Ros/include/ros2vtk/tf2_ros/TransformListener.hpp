// ros2vtk — feeds a tf2 BufferCore from /tf and /tf_static as tf2_ros's TransformListener does
// (QoS: keep last 100 reliable volatile for /tf, keep last 100 reliable transient local for
// /tf_static). DDS threads only queue; process() inserts on the owner's thread.
#ifndef ros2vtk_tf2_ros_TransformListener_hpp
#define ros2vtk_tf2_ros_TransformListener_hpp

#include "ros2vtk/tf2/BufferCore.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {
class MessagePtr;
class Participant;
class Subscription;
}
namespace tf2_ros {

class TransformListener
{
public:
  /// The authority of transforms whose writer no node announcement lists (yet).
  static const std::string kUnknownAuthority; // "ros2vtk_tf_listener"

  static std::unique_ptr<TransformListener> create(
    wire::Participant& participant, tf2::BufferCore& buffer, std::string* error);
  ~TransformListener();

  /// Inserts every queued transform into the buffer. Returns how many were inserted; rejected
  /// ones (NaN, self transform, bad quaternion…) are counted, the last reason kept.
  size_t process();

  uint64_t rejected_count() const { return rejected_; }
  const std::string& last_rejection() const { return last_rejection_; }

private:
  TransformListener(wire::Participant& participant, tf2::BufferCore& buffer);
  size_t drain(wire::Subscription& subscription, bool is_static);
  /// The authority recorded with a transform: the node of the writer that sent it (from the
  /// ROS graph, as `ros2 topic info -v` names it), or kUnknownAuthority until the graph knows it.
  const std::string& authority_of(const std::array<uint8_t, 16>& writer);

  wire::Participant& participant_;
  tf2::BufferCore& buffer_;
  std::map<std::array<uint8_t, 16>, std::string> authorities_; ///< writers whose node is known
  std::unique_ptr<wire::Subscription> dynamic_;
  std::unique_ptr<wire::Subscription> static_;
  uint64_t rejected_ = 0;
  std::string last_rejection_;
  std::vector<wire::MessagePtr> taken_; ///< drain's batch; emptied after use, capacity kept
};

} // namespace tf2_ros
} // namespace ros2vtk

#endif
