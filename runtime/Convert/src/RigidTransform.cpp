#include "ros2vtk/convert/RigidTransform.hpp"

#include "Validation.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkTransformCollection.h>

#include <cstring>

#include <array>
#include <cmath>

namespace ros2vtk {
namespace convert {

using detail::fail;
using detail::number_text;

namespace {

/// Checks a ROS pose and returns its rotation as a unit Eigen quaternion.
bool checked_rotation(
  const RigidPose& pose, const char* where, Eigen::Quaterniond* rotation, std::string* error)
{
  if (!detail::all_finite(pose.translation.data(), 3))
  {
    return fail(error, where, "translation contains NaN or infinity");
  }
  if (!detail::all_finite(pose.rotation.data(), 4))
  {
    return fail(error, where, "quaternion contains NaN or infinity");
  }
  const Eigen::Quaterniond q(
    pose.rotation[3], pose.rotation[0], pose.rotation[1], pose.rotation[2]);
  const double norm2 = q.squaredNorm();
  if (std::abs(norm2 - 1.0) >= kQuaternionNormTolerance)
  {
    return fail(error, where,
      "quaternion (x, y, z, w) = (" + number_text(pose.rotation[0]) + ", " +
        number_text(pose.rotation[1]) + ", " + number_text(pose.rotation[2]) + ", " +
        number_text(pose.rotation[3]) + ") is not a unit quaternion (|q|^2 = " +
        number_text(norm2) + ", tolerance " + number_text(kQuaternionNormTolerance) + ")");
  }
  *rotation = q.normalized();
  return true;
}

/// Fills row-major `elements` from a checked pose; cannot fail.
void fill_elements(const RigidPose& pose, const Eigen::Quaterniond& rotation, double length_scale,
  double elements[16])
{
  const Eigen::Matrix3d r = rotation.toRotationMatrix();
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      elements[row * 4 + col] = r(row, col);
    }
    elements[row * 4 + 3] = pose.translation[row] * length_scale;
  }
  elements[12] = 0.0;
  elements[13] = 0.0;
  elements[14] = 0.0;
  elements[15] = 1.0;
}

/// A pose as the row-major elements of its matrix, with every check of pose_to_matrix.
bool pose_to_elements(const RigidPose& pose, double length_scale, const char* where,
  double elements[16], std::string* error)
{
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  if (!detail::check_length_scale(length_scale, where, error) ||
    !checked_rotation(pose, where, &rotation, error))
  {
    return false;
  }
  // Finite in metres is not enough: 1e306 m is infinite in millimetres (issue 11.9).
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!std::isfinite(pose.translation[static_cast<size_t>(axis)] * length_scale))
    {
      return fail(error, where,
        "translation (" + number_text(pose.translation[0]) + ", " +
          number_text(pose.translation[1]) + ", " + number_text(pose.translation[2]) +
          ") is not finite once scaled by " + number_text(length_scale));
    }
  }
  fill_elements(pose, rotation, length_scale, elements);
  return true;
}

} // namespace

bool pose_to_matrix(
  const RigidPose& pose, double length_scale, vtkMatrix4x4* matrix, std::string* error)
{
  const char* where = "pose_to_matrix";
  if (!matrix)
  {
    return fail(error, where, "output matrix is null");
  }
  double elements[16];
  if (!pose_to_elements(pose, length_scale, where, elements, error))
  {
    return false;
  }
  matrix->DeepCopy(elements);
  return true;
}

bool matrix_to_pose(vtkMatrix4x4* matrix, double length_scale, RigidPose* pose, std::string* error)
{
  const char* where = "matrix_to_pose";
  if (!matrix || !pose)
  {
    return fail(error, where, matrix ? "output pose is null" : "input matrix is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  const double* m = matrix->GetData(); // row-major, 16 values
  if (!detail::all_finite(m, 16))
  {
    return fail(error, where, "matrix contains NaN or infinity");
  }
  if (std::abs(m[12]) > kBottomRowTolerance || std::abs(m[13]) > kBottomRowTolerance ||
    std::abs(m[14]) > kBottomRowTolerance || std::abs(m[15] - 1.0) > kBottomRowTolerance)
  {
    return fail(error, where,
      "not a rigid transform: bottom row is (" + number_text(m[12]) + ", " + number_text(m[13]) +
        ", " + number_text(m[14]) + ", " + number_text(m[15]) + "), expected (0, 0, 0, 1)");
  }
  Eigen::Matrix3d r;
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      r(row, col) = m[row * 4 + col];
    }
  }
  const double orthogonality_error =
    (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality_error > kRotationOrthogonalityTolerance)
  {
    return fail(error, where,
      "not a rigid transform: the 3x3 part has scale or shear (max |R^T R - I| = " +
        number_text(orthogonality_error) + ", tolerance " +
        number_text(kRotationOrthogonalityTolerance) + ")");
  }
  if (r.determinant() <= 0.0)
  {
    return fail(error, where, "not a rigid transform: the 3x3 part is a reflection (det < 0)");
  }
  // Nearest rotation in the Frobenius sense: U V^T of the SVD (det is +1 here because R is
  // within tolerance of a proper rotation).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d orthonormal = svd.matrixU() * svd.matrixV().transpose();
  Eigen::Quaterniond q(orthonormal);
  q.normalize();
  if (q.w() < 0.0)
  {
    q.coeffs() *= -1.0;
  }
  const std::array<double, 3> translation = { { m[3] / length_scale, m[7] / length_scale,
    m[11] / length_scale } };
  if (!detail::all_finite(translation.data(), 3))
  {
    return fail(
      error, where, "translation is not finite once scaled by 1/" + number_text(length_scale));
  }
  pose->translation = translation;
  pose->rotation = { { q.x(), q.y(), q.z(), q.w() } };
  return true;
}

bool pose_to_transform(
  const RigidPose& pose, double length_scale, vtkTransform* transform, std::string* error)
{
  if (!transform)
  {
    return fail(error, "pose_to_transform", "output transform is null");
  }
  double elements[16];
  if (!pose_to_elements(pose, length_scale, "pose_to_matrix", elements, error))
  {
    return false;
  }
  transform->SetMatrix(elements);
  return true;
}

bool transform_to_pose(
  vtkTransform* transform, double length_scale, RigidPose* pose, std::string* error)
{
  if (!transform)
  {
    return fail(error, "transform_to_pose", "input transform is null");
  }
  return matrix_to_pose(transform->GetMatrix(), length_scale, pose, error);
}

bool poses_to_transform_collection(const std::vector<RigidPose>& poses, double length_scale,
  vtkTransformCollection* collection, std::string* error)
{
  const char* where = "poses_to_transform_collection";
  if (!collection)
  {
    return fail(error, where, "output collection is null");
  }
  // Every pose is checked before the collection is touched: a bad one leaves it as it was.
  std::vector<double> elements(16 * poses.size());
  for (size_t i = 0; i < poses.size(); ++i)
  {
    std::string reason;
    if (!pose_to_elements(poses[i], length_scale, "pose_to_matrix", &elements[16 * i], &reason))
    {
      return fail(error, where, "pose " + std::to_string(i) + ": " + reason);
    }
  }
  // A transform only the collection holds is refilled rather than replaced: a subscriber converts
  // every message of a stream into the same collection, and a PoseArray of 1000 poses otherwise
  // costs 1000 vtkTransform allocations (each with its matrix and concatenation) per message.
  // One that anybody else holds (a script, a filter) keeps the pose it had.
  std::vector<vtkSmartPointer<vtkTransform>> transforms;
  transforms.reserve(poses.size());
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  for (int i = 0, n = collection->GetNumberOfItems(); i < n && transforms.size() < poses.size();
       ++i)
  {
    vtkObject* item = collection->GetNextItemAsObject(it);
    auto* transform = vtkTransform::SafeDownCast(item);
    // Exactly a vtkTransform, plain (no input transform, not inverted), held by the collection
    // only.
    if (transform && transform->GetReferenceCount() == 1 &&
      std::strcmp(transform->GetClassName(), "vtkTransform") == 0 && !transform->GetInput() &&
      !transform->GetInverseFlag())
    {
      transforms.emplace_back(transform);
    }
  }
  while (transforms.size() < poses.size())
  {
    transforms.push_back(vtkSmartPointer<vtkTransform>::New());
  }
  for (size_t i = 0; i < poses.size(); ++i)
  {
    transforms[i]->SetMatrix(&elements[16 * i]);
  }
  collection->RemoveAllItems();
  for (const auto& transform : transforms)
  {
    collection->AddItem(transform);
  }
  return true;
}

bool transform_collection_to_poses(vtkTransformCollection* collection, double length_scale,
  std::vector<RigidPose>* poses, std::string* error)
{
  const char* where = "transform_collection_to_poses";
  if (!collection || !poses)
  {
    return fail(error, where, collection ? "output poses are null" : "input collection is null");
  }
  std::vector<RigidPose> result;
  result.reserve(static_cast<size_t>(collection->GetNumberOfItems()));
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  for (int i = 0; i < collection->GetNumberOfItems(); ++i)
  {
    // Untyped traversal + SafeDownCast: the typed GetNextItem() static_casts whatever is stored
    // (vtkCollection::AddItem accepts any vtkObject).
    vtkTransform* transform = vtkTransform::SafeDownCast(collection->GetNextItemAsObject(it));
    if (!transform)
    {
      return fail(error, where, "item " + std::to_string(i) + " is not a vtkTransform");
    }
    RigidPose pose;
    std::string reason;
    if (!transform_to_pose(transform, length_scale, &pose, &reason))
    {
      return fail(error, where, "item " + std::to_string(i) + ": " + reason);
    }
    result.push_back(pose);
  }
  *poses = std::move(result);
  return true;
}

} // namespace convert
} // namespace ros2vtk
