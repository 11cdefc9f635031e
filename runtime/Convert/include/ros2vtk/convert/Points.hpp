// ros2vtk — flat x, y, z triples (sensor_msgs/PointCloud's Point32[], or any list of points)
// <-> vtkPoints.
//
// Coordinates are lengths: multiplied by length_scale into VTK, divided by it out of VTK (see
// Units.hpp). The triples are flat, x0 y0 z0 x1 y1 z1 ..., so a generated converter can fill
// them from whatever struct its message uses.
#ifndef ros2vtk_convert_Points_hpp
#define ros2vtk_convert_Points_hpp

#include <cstddef>
#include <string>
#include <vector>

class vtkPoints;

namespace ros2vtk {
namespace convert {

/// What to do with a point that has a NaN or infinite coordinate (sensors mark "no return" so).
enum class NonFinitePoints
{
  Keep,   ///< copy it as is (VTK bounds and rendering may then be affected)
  Drop,   ///< leave it out (point indices shift)
  Reject, ///< fail the whole conversion with a message
};

/// `xyz` holds 3 * count values. The output points get the input's precision (float -> VTK_FLOAT,
/// double -> VTK_DOUBLE). On failure `points` is untouched.
bool xyz_to_points(const float* xyz, size_t count, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error);
bool xyz_to_points(const double* xyz, size_t count, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error);
/// Vector forms: the size must be a multiple of 3.
bool xyz_to_points(const std::vector<float>& xyz, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error);
bool xyz_to_points(const std::vector<double>& xyz, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error);

/// vtkPoints -> flat triples in ROS units (any vtkPoints precision; float output rounds).
bool points_to_xyz(
  vtkPoints* points, double length_scale, std::vector<float>* xyz, std::string* error);
bool points_to_xyz(
  vtkPoints* points, double length_scale, std::vector<double>* xyz, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
