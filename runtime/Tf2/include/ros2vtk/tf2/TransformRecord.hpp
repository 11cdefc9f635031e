// ros2vtk — one stored sample of a frame: where the child frame was in its parent at one time.
// Frames are stored per child, so the parent travels with every sample (it may change over time).
#ifndef ros2vtk_tf2_TransformRecord_hpp
#define ros2vtk_tf2_TransformRecord_hpp

#include "ros2vtk/tf2/FrameIds.hpp"
#include "ros2vtk/tf2/TimePoint.hpp"
#include "ros2vtk/tf2/Transform.hpp"

namespace ros2vtk {
namespace tf2 {

struct TransformRecord
{
  TimePoint stamp = 0;
  Transform transform; ///< pose of `child` in `parent`
  FrameId parent = kNoFrame;
  FrameId child = kNoFrame;

  /// All fields equal: the same sample received twice (tf2 stores it once).
  bool operator==(const TransformRecord& other) const
  {
    return stamp == other.stamp && parent == other.parent && child == other.child &&
      transform == other.transform;
  }
};

} // namespace tf2
} // namespace ros2vtk

#endif
