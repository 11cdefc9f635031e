// ros2vtk — rigid transforms: ROS translation + quaternion <-> vtkMatrix4x4 / vtkTransform.
//
// Used by the PoseStamped, TransformStamped, PoseArray (and tf) converters. A ROS pose and a
// ROS transform are the same numbers (translation in metres, unit quaternion x, y, z, w); the VTK
// side is a 4x4 homogeneous matrix whose translation column is in VTK length units (mm unless the
// node switched scaling off, see Units.hpp). Frames are not changed.
//
// Every function returns false and writes a message into *error (when given) on bad input, and
// then leaves its output untouched. Nothing throws.
#ifndef ros2vtk_convert_RigidTransform_hpp
#define ros2vtk_convert_RigidTransform_hpp

#include <array>
#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkTransform;
class vtkTransformCollection;

namespace ros2vtk {
namespace convert {

/// The numbers of a geometry_msgs Pose / Transform, in ROS units.
struct RigidPose
{
  std::array<double, 3> translation{ { 0.0, 0.0, 0.0 } };   ///< metres
  std::array<double, 4> rotation{ { 0.0, 0.0, 0.0, 1.0 } }; ///< quaternion x, y, z, w
};

/// tf2's tolerance: a quaternion is accepted when | |q|^2 - 1 | < this, and then normalised.
constexpr double kQuaternionNormTolerance = 1e-2;

/// A matrix counts as rigid when every entry of R^T R - I is within this (so a 0.1 % scale or
/// shear is rejected, float round-off from VTK pipelines is not) and det(R) > 0.
constexpr double kRotationOrthogonalityTolerance = 1e-3;

/// The bottom row must be 0 0 0 1 within this.
constexpr double kBottomRowTolerance = 1e-9;

/// ROS -> VTK. Rejects non-finite numbers and quaternions too far from unit length; normalises
/// the others. Translation is multiplied by length_scale.
bool pose_to_matrix(
  const RigidPose& pose, double length_scale, vtkMatrix4x4* matrix, std::string* error);

/// VTK -> ROS. Rejects null or non-finite matrices, a bottom row other than 0 0 0 1 and
/// rotations with scale/shear beyond kRotationOrthogonalityTolerance (or a reflection). The
/// rotation part is re-orthonormalised (nearest rotation, by SVD) before it becomes a quaternion,
/// which is returned with w >= 0 so the result is unique. Translation is divided by length_scale.
bool matrix_to_pose(vtkMatrix4x4* matrix, double length_scale, RigidPose* pose, std::string* error);

/// Same as pose_to_matrix, for a vtkTransform (its matrix is replaced; its input and
/// concatenation are cleared by vtkTransform::SetMatrix).
bool pose_to_transform(
  const RigidPose& pose, double length_scale, vtkTransform* transform, std::string* error);

/// Same as matrix_to_pose, reading the transform's current matrix.
bool transform_to_pose(
  vtkTransform* transform, double length_scale, RigidPose* pose, std::string* error);

/// PoseArray -> one new vtkTransform per pose, in order. The collection is emptied first; on
/// error (message names the index of the bad pose) it is left as it was.
bool poses_to_transform_collection(const std::vector<RigidPose>& poses, double length_scale,
  vtkTransformCollection* collection, std::string* error);

/// vtkTransformCollection -> poses, in collection order. Every item must be a rigid vtkTransform.
bool transform_collection_to_poses(vtkTransformCollection* collection, double length_scale,
  std::vector<RigidPose>* poses, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
