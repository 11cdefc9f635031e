// ros2vtk — an ordered list of positions (nav_msgs/Path's poses) <-> a vtkPolyData holding
// those points and one polyline cell through them, ready to draw as a line.
//
// Coordinates are lengths: multiplied by length_scale into VTK, divided by it out (Units.hpp).
#ifndef ros2vtk_convert_Polyline_hpp
#define ros2vtk_convert_Polyline_hpp

#include <string>
#include <vector>

class vtkPolyData;

namespace ros2vtk {
namespace convert {

/// ROS -> VTK: flat x0 y0 z0 x1 ... (size a multiple of 3, all finite). The poly data gets
/// exactly these points (double precision) and, with 2 or more points, one polyline cell
/// 0, 1, ..., n-1 (no cell for 0 or 1 point); its other data is cleared. On failure it is
/// untouched.
bool xyz_to_polyline(
  const std::vector<double>& xyz, double length_scale, vtkPolyData* polyline, std::string* error);

/// VTK -> ROS: the points along the poly data's one line cell, in cell order; a poly data
/// without line cells gives its points in order; more than one line cell is refused.
bool polyline_to_xyz(
  vtkPolyData* polyline, double length_scale, std::vector<double>* xyz, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
