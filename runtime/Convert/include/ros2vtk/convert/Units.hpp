// ros2vtk — the one units constant of the VTK side.
//
// ROS is SI (metres); VTK/Slicer scenes are in millimetres. Every helper in ros2vtk::convert that
// touches a length (translation, point coordinate) takes a `double length_scale`: lengths are
// multiplied by it on the way into VTK and divided by it on the way out. Rotations, forces,
// torques, velocities and efforts are never scaled. A node that switches scaling off passes 1.
// Frames are never changed (no RAS/LPS flip).
#ifndef ros2vtk_convert_Units_hpp
#define ros2vtk_convert_Units_hpp

namespace ros2vtk {
namespace convert {

/// ROS metres -> VTK millimetres. The only place this number is written down.
constexpr double kMillimetresPerMetre = 1000.0;

/// For nodes whose scaling is switched off: VTK gets the ROS numbers unchanged.
constexpr double kNoLengthScaling = 1.0;

} // namespace convert
} // namespace ros2vtk

#endif
