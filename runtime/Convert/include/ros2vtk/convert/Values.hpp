// ros2vtk — fixed-size groups of plain numbers <-> vtkDoubleArray (e.g. a Wrench's force and
// torque as 6 values, the paper's WrenchStamped -> vtkDoubleArray(6)).
//
// No scaling: this helper is for quantities the units policy leaves alone (forces, torques,
// velocities, efforts). Lengths go through the helpers that take a length_scale.
#ifndef ros2vtk_convert_Values_hpp
#define ros2vtk_convert_Values_hpp

#include <cstddef>
#include <string>

class vtkDataArray;
class vtkDoubleArray;

namespace ros2vtk {
namespace convert {

/// ROS -> VTK: the array becomes `count` one-component values. NaN/inf are rejected (a wrench
/// with NaN is a broken sensor reading, not data); the array is then left untouched.
bool values_to_array(const double* values, size_t count, vtkDoubleArray* array, std::string* error);

/// VTK -> ROS: the array must hold exactly `count` numbers (tuples x components, read in memory
/// order), all finite; any numeric array type is accepted. `values` must have room for `count`.
bool array_to_values(vtkDataArray* array, size_t count, double* values, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
