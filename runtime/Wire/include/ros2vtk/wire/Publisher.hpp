// ros2vtk — a typed-by-table ROS 2 publisher (DDS DataWriter on `rt/<topic>`).
#ifndef ros2vtk_wire_Publisher_hpp
#define ros2vtk_wire_Publisher_hpp

#include "ros2vtk/wire/QoS.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace ros2vtk {
namespace wire {

struct MessageTypeSupport;

class Publisher
{
public:
  ~Publisher();
  Publisher(const Publisher&) = delete;
  Publisher& operator=(const Publisher&) = delete;

  /// `message` points at a struct of this publisher's type. False when DDS refused it.
  bool publish(const void* message);
  /// Publishes an already serialized payload (encapsulation header included).
  bool publish_serialized(const uint8_t* data, size_t size);

  const std::string& topic() const; ///< resolved ROS name
  const MessageTypeSupport& type() const;
  const QoS& qos() const;
  size_t matched_subscriptions() const;
  uint64_t published_count() const;

  class Impl;

private:
  friend class Participant;
  explicit Publisher(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace wire
} // namespace ros2vtk

#endif
