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

/// The 16 elements (row-major, as vtkMatrix4x4::DeepCopy takes them) of a rigid transform's
/// homogeneous matrix, translation multiplied by length_scale. A template so that this header
/// needs no Eigen: `Isometry` is Eigen::Isometry3d (anything with linear()(i, j) and
/// translation()(i)). Used wherever a tf result becomes a VTK matrix (lookup nodes, robot links).
template<typename Isometry>
void isometry_to_elements(const Isometry& isometry, double length_scale, double elements[16])
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      elements[4 * i + j] = isometry.linear()(i, j);
    }
    elements[4 * i + 3] = isometry.translation()(i) * length_scale;
  }
  elements[12] = elements[13] = elements[14] = 0.0;
  elements[15] = 1.0;
}

} // namespace convert
} // namespace ros2vtk

#endif
