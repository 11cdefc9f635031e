// ros2vtk — sensor_msgs/JointState arrays <-> vtkTable (mapping kind "joint_state_table").
//
// One row per joint; columns "name" (vtkStringArray), "position", "velocity", "effort"
// (vtkDoubleArray), in that order. ROS allows each array to be empty ("not provided"); an empty
// array has no column, so a table converted back gives the same empty array. Values are not
// scaled (units table: joint positions, velocities and efforts are SI on both sides) and NaN is
// passed through, because drivers use it for "unknown" (e.g. effort on a position-only joint).
#ifndef ros2vtk_convert_JointState_hpp
#define ros2vtk_convert_JointState_hpp

#include <string>
#include <vector>

class vtkTable;

namespace ros2vtk {
namespace convert {

/// The four arrays of a JointState.
struct JointStateArrays
{
  std::vector<std::string> name;
  std::vector<double> position;
  std::vector<double> velocity;
  std::vector<double> effort;
};

/// ROS -> VTK. Every non-empty array must have the same length (that of the longest one); the
/// message names the array that does not. The table's columns are replaced; on error the table
/// is untouched.
bool joint_state_to_table(const std::vector<std::string>& name, const std::vector<double>& position,
  const std::vector<double>& velocity, const std::vector<double>& effort, vtkTable* table,
  std::string* error);

/// VTK -> ROS. Reads the four columns by name (a missing column gives an empty array; other
/// columns are ignored). "name" must be a vtkStringArray, the others one-component numeric
/// arrays. On error `arrays` is untouched.
bool table_to_joint_state(vtkTable* table, JointStateArrays* arrays, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
