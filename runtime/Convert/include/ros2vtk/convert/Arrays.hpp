// ros2vtk — numeric fields that are arrays in ROS <-> VTK arrays and matrices: a fixed 3x3
// row-major float64[9] (CameraInfo's K) <-> vtkMatrix3x3, and a sequence of numbers of any
// element type (CameraInfo's D, Joy's axes and buttons) <-> a one-component vtkDataArray.
//
// Never scaled: pixel intrinsics, distortion coefficients, joystick axes and buttons are not
// lengths of the scene.
#ifndef ros2vtk_convert_Arrays_hpp
#define ros2vtk_convert_Arrays_hpp

#include <cstddef>
#include <string>
#include <vector>

class vtkDataArray;
class vtkMatrix3x3;

namespace ros2vtk {
namespace convert {

/// ROS -> VTK: `values` are 9 numbers, row-major (K = [fx 0 cx; 0 fy cy; 0 0 1]). NaN/inf are
/// rejected; the matrix is then untouched.
bool values_to_matrix3x3(const double* values, vtkMatrix3x3* matrix, std::string* error);

/// VTK -> ROS: the 9 elements, row-major, all finite. `values` must have room for 9.
bool matrix3x3_to_values(vtkMatrix3x3* matrix, double* values, std::string* error);

/// ROS -> VTK: the array becomes `count` one-component values (set as doubles, so it keeps its
/// own class: vtkDoubleArray, vtkFloatArray, vtkIntArray). NaN/inf are rejected.
bool numbers_to_array(const double* values, size_t count, vtkDataArray* array, std::string* error);

/// What a ROS sequence can hold: values outside [lowest, highest], or with a fraction when
/// `integral`, are refused (never wrapped or rounded).
struct NumberLimits
{
  double lowest;
  double highest;
  bool integral;
};

/// VTK -> ROS: every value of the array (tuples x components, in memory order), finite and
/// within `limits`. On failure `values` is untouched.
bool array_to_numbers(
  vtkDataArray* array, const NumberLimits& limits, std::vector<double>* values, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
