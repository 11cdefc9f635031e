// ros2vtk — the answer to a transform lookup: either a transform or tf2's error class and message.
// A value, not an exception, so callers on the VTK side report failures without try/catch.
#ifndef ros2vtk_tf2_LookupResult_hpp
#define ros2vtk_tf2_LookupResult_hpp

#include "ros2vtk/tf2/Tf2Error.hpp"
#include "ros2vtk/tf2/TimePoint.hpp"
#include "ros2vtk/tf2/Transform.hpp"

#include <cstdint>
#include <string>

namespace ros2vtk {
namespace tf2 {

struct LookupResult
{
  bool ok = false;
  Tf2Error error = Tf2Error::NoError;
  std::string message;      ///< tf2's wording; empty when ok
  std::string target_frame; ///< header.frame_id of the answer
  std::string source_frame; ///< child_frame_id of the answer
  TimePoint stamp = 0;      ///< the time actually used (the latest common time for time 0)
  Transform transform;      ///< maps points given in source_frame into target_frame

  /// Set by BufferCore's reused-result lookup: the buffer (its serial) and frame ids that
  /// target_frame and source_frame resolved to. A later lookup of the same names into this
  /// result skips hashing and checking them (ids are never reused within a buffer).
  std::uint64_t resolved_by = 0;
  std::uint32_t resolved_target = 0;
  std::uint32_t resolved_source = 0;

  Eigen::Isometry3d isometry() const { return transform.to_isometry(); }
  explicit operator bool() const { return ok; }
};

} // namespace tf2
} // namespace ros2vtk

#endif
