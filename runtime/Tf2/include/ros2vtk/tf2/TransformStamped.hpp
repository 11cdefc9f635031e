// ros2vtk — the buffer's input: geometry_msgs/TransformStamped reduced to what tf2 uses, with no
// dependency on generated message code (the tf listener converts; tests build these directly).
#ifndef ros2vtk_tf2_TransformStamped_hpp
#define ros2vtk_tf2_TransformStamped_hpp

#include "ros2vtk/tf2/TimePoint.hpp"
#include "ros2vtk/tf2/Transform.hpp"

#include <string>

namespace ros2vtk {
namespace tf2 {

struct TransformStamped
{
  std::string frame_id;       ///< parent (header.frame_id)
  std::string child_frame_id; ///< the frame whose pose this is
  TimePoint stamp = 0;        ///< header.stamp in nanoseconds
  Transform transform;        ///< pose of child_frame_id in frame_id
};

} // namespace tf2
} // namespace ros2vtk

#endif
