// ros2vtk — feeds a tf2 BufferCore from /tf and /tf_static as tf2_ros's TransformListener does
// (QoS: keep last 100 reliable volatile for /tf, keep last 100 reliable transient local for
// /tf_static). As tf2_ros's listener thread does, the DDS thread that deserialized a /tf message
// inserts it into the (locked) buffer, so the owner's spin only looks transforms up; process()
// inserts what arrived before the DDS threads took over and reports the counts.
#ifndef ros2vtk_tf2_ros_TransformListener_hpp
#define ros2vtk_tf2_ros_TransformListener_hpp

#include "ros2vtk/tf2/BufferCore.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
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

  /// Inserts any transform still queued, and returns how many were inserted since the last call
  /// (on any thread); rejected ones (NaN, self transform, bad quaternion…) are counted, the last
  /// reason kept.
  size_t process();

  uint64_t rejected_count() const { return rejected_; }
  std::string last_rejection() const;

private:
  TransformListener(wire::Participant& participant, tf2::BufferCore& buffer);
  /// Every transform of one /tf or /tf_static message into the buffer: on a DDS thread, or from
  /// process() for messages queued before the sinks were set.
  void insert(const wire::MessagePtr& message, bool is_static);
  /// The authority recorded with a transform: the node of the writer that sent it (from the
  /// ROS graph, as `ros2 topic info -v` names it), or kUnknownAuthority until the graph knows it.
  const std::string& authority_of(const std::array<uint8_t, 16>& writer);
  /// Names the frames inserted with kUnknownAuthority whose writer's node the graph knows now
  /// (a latched /tf_static message often arrives before its node's announcement, and is not
  /// sent again).
  void resolve_authorities();

  wire::Participant& participant_;
  tf2::BufferCore& buffer_;
  /// Guards what insert() uses: /tf and /tf_static may arrive on two DDS threads at once.
  mutable std::mutex mutex_;
  std::map<std::array<uint8_t, 16>, std::string> authorities_; ///< writers whose node is known
  /// Frames last set by a writer whose node was unknown then, by writer.
  std::map<std::array<uint8_t, 16>, std::set<std::string>> unresolved_;
  std::atomic<bool> has_unresolved_{ false }; ///< !unresolved_.empty(), read without the lock
  std::string last_rejection_;
  tf2::TransformStamped scratch_; ///< reused: its strings keep their storage between messages
  std::string reason_;
  std::vector<wire::MessagePtr> taken_; ///< process()'s batch; emptied after use
  /// The queues were drained once after create() set the sinks: nothing enters them since.
  bool backlog_taken_ = false;
  std::atomic<uint64_t> inserted_{ 0 };
  std::atomic<uint64_t> rejected_{ 0 };
  uint64_t inserted_reported_ = 0; ///< inserted_ at the last process()
  // Last: destroyed first, so no DDS thread runs insert() on members already gone.
  std::unique_ptr<wire::Subscription> dynamic_;
  std::unique_ptr<wire::Subscription> static_;
};

} // namespace tf2_ros
} // namespace ros2vtk

#endif
