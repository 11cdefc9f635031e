// Rigid transforms: ROS pose (m, quaternion x y z w) <-> vtkMatrix4x4 / vtkTransform(Collection).
// Expected matrices and quaternions are written out by hand.
#include "ros2vtk/convert/RigidTransform.hpp"
#include "ros2vtk/convert/Units.hpp"

#include <gtest/gtest.h>

#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkTransformCollection.h>

#include <cmath>
#include <limits>

using namespace ros2vtk::convert;

namespace {

const double kHalfSqrt2 = std::sqrt(0.5);

/// Compares a matrix with 16 values given row by row.
void expect_matrix(vtkMatrix4x4* matrix, const double (&expected)[16], double tolerance = 1e-12)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      EXPECT_NEAR(matrix->GetElement(row, col), expected[row * 4 + col], tolerance)
        << "element (" << row << ", " << col << ")";
    }
  }
}

RigidPose make_pose(double x, double y, double z, double qx, double qy, double qz, double qw)
{
  RigidPose pose;
  pose.translation = { { x, y, z } };
  pose.rotation = { { qx, qy, qz, qw } };
  return pose;
}

} // namespace

TEST(RigidTransform, TranslationIsScaledToMillimetres)
{
  vtkNew<vtkMatrix4x4> matrix;
  std::string error;
  ASSERT_TRUE(
    pose_to_matrix(make_pose(0.1, -0.25, 2.0, 0, 0, 0, 1), kMillimetresPerMetre, matrix, &error))
    << error;
  const double expected[16] = { 1, 0, 0, 100, 0, 1, 0, -250, 0, 0, 1, 2000, 0, 0, 0, 1 };
  expect_matrix(matrix, expected);

  RigidPose back;
  ASSERT_TRUE(matrix_to_pose(matrix, kMillimetresPerMetre, &back, &error)) << error;
  EXPECT_NEAR(back.translation[0], 0.1, 1e-15);
  EXPECT_NEAR(back.translation[1], -0.25, 1e-15);
  EXPECT_NEAR(back.translation[2], 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(back.rotation[3], 1.0);
}

TEST(RigidTransform, ScalingSwitchedOffKeepsMetres)
{
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(
    pose_to_matrix(make_pose(0.1, 0.2, 0.3, 0, 0, 0, 1), kNoLengthScaling, matrix, nullptr));
  EXPECT_DOUBLE_EQ(matrix->GetElement(0, 3), 0.1);
  EXPECT_DOUBLE_EQ(matrix->GetElement(1, 3), 0.2);
  EXPECT_DOUBLE_EQ(matrix->GetElement(2, 3), 0.3);
}

TEST(RigidTransform, NinetyDegreesAboutZ)
{
  vtkNew<vtkMatrix4x4> matrix;
  std::string error;
  ASSERT_TRUE(
    pose_to_matrix(make_pose(1, 2, 3, 0, 0, kHalfSqrt2, kHalfSqrt2), 1000.0, matrix, &error))
    << error;
  // x -> y, y -> -x: columns are the images of the axes.
  const double expected[16] = { 0, -1, 0, 1000, 1, 0, 0, 2000, 0, 0, 1, 3000, 0, 0, 0, 1 };
  expect_matrix(matrix, expected, 1e-15);

  RigidPose back;
  ASSERT_TRUE(matrix_to_pose(matrix, 1000.0, &back, &error)) << error;
  EXPECT_NEAR(back.rotation[0], 0.0, 1e-15);
  EXPECT_NEAR(back.rotation[1], 0.0, 1e-15);
  EXPECT_NEAR(back.rotation[2], kHalfSqrt2, 1e-15);
  EXPECT_NEAR(back.rotation[3], kHalfSqrt2, 1e-15);
}

TEST(RigidTransform, OneHundredTwentyDegreesAboutDiagonal)
{
  // Rotation by 120 deg about (1,1,1)/sqrt(3) cycles the axes x -> y -> z -> x;
  // its quaternion is (0.5, 0.5, 0.5, 0.5).
  const double cycle[16] = { 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1 };
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(pose_to_matrix(make_pose(0, 0, 0, 0.5, 0.5, 0.5, 0.5), 1000.0, matrix, nullptr));
  expect_matrix(matrix, cycle, 1e-15);

  vtkNew<vtkMatrix4x4> given;
  given->DeepCopy(cycle);
  RigidPose back;
  std::string error;
  ASSERT_TRUE(matrix_to_pose(given, 1000.0, &back, &error)) << error;
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(back.rotation[i], 0.5, 1e-15) << "component " << i;
  }
}

TEST(RigidTransform, QuaternionWithNegativeWComesBackWithPositiveW)
{
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(
    pose_to_matrix(make_pose(0, 0, 0, 0, 0, -kHalfSqrt2, -kHalfSqrt2), 1000.0, matrix, nullptr));
  EXPECT_NEAR(matrix->GetElement(0, 1), -1.0, 1e-15); // same rotation as +q
  RigidPose back;
  ASSERT_TRUE(matrix_to_pose(matrix, 1000.0, &back, nullptr));
  EXPECT_NEAR(back.rotation[2], kHalfSqrt2, 1e-15);
  EXPECT_NEAR(back.rotation[3], kHalfSqrt2, 1e-15);
}

TEST(RigidTransform, MatrixToPoseChoosesTheQuaternionWithPositiveW)
{
  // 200 deg about z (trace < 0). Its quaternions are +-(0, 0, sin 100deg, cos 100deg) with
  // cos 100deg = -0.17364817766693; the one with w >= 0 is (0, 0, -0.984807753012208,
  // 0.17364817766693).
  const double c = -0.9396926207859084; // cos 200deg
  const double s = -0.3420201433256687; // sin 200deg
  const double rotation[16] = { c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(rotation);
  RigidPose pose;
  std::string error;
  ASSERT_TRUE(matrix_to_pose(matrix, 1000.0, &pose, &error)) << error;
  EXPECT_NEAR(pose.rotation[0], 0.0, 1e-15);
  EXPECT_NEAR(pose.rotation[1], 0.0, 1e-15);
  EXPECT_NEAR(pose.rotation[2], -0.984807753012208, 1e-14);
  EXPECT_NEAR(pose.rotation[3], 0.17364817766693, 1e-14);
}

TEST(RigidTransform, SlightlyDenormalisedQuaternionIsNormalised)
{
  // |q|^2 = 1.0025^2 = 1.005..., inside tf2's 1e-2 tolerance.
  vtkNew<vtkMatrix4x4> matrix;
  std::string error;
  ASSERT_TRUE(pose_to_matrix(make_pose(0, 0, 0, 0, 0, 0, 1.0025), 1000.0, matrix, &error)) << error;
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  expect_matrix(matrix, identity, 1e-15);
}

TEST(RigidTransform, RejectsBadPoses)
{
  vtkNew<vtkMatrix4x4> matrix;
  const double marker[16] = { 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7 };
  matrix->DeepCopy(marker);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::string error;

  EXPECT_FALSE(pose_to_matrix(make_pose(0, 0, 0, 0, 0, 0, 0), 1000.0, matrix, &error));
  EXPECT_NE(error.find("not a unit quaternion"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(pose_to_matrix(make_pose(0, 0, 0, 0, 0, 0, 1.1), 1000.0, matrix, &error));
  EXPECT_NE(error.find("not a unit quaternion"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(pose_to_matrix(make_pose(nan, 0, 0, 0, 0, 0, 1), 1000.0, matrix, &error));
  EXPECT_NE(error.find("translation contains NaN"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(pose_to_matrix(make_pose(0, 0, 0, 0, inf, 0, 1), 1000.0, matrix, &error));
  EXPECT_NE(error.find("quaternion contains NaN or infinity"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(pose_to_matrix(make_pose(0, 0, 0, 0, 0, 0, 1), 0.0, matrix, &error));
  EXPECT_NE(error.find("length_scale"), std::string::npos) << error;

  EXPECT_FALSE(pose_to_matrix(make_pose(0, 0, 0, 0, 0, 0, 1), 1000.0, nullptr, &error));
  expect_matrix(matrix, marker); // untouched by every failure
}

TEST(RigidTransform, RejectsNonRigidMatrices)
{
  std::string error;
  RigidPose pose;
  vtkNew<vtkMatrix4x4> matrix;

  matrix->Identity();
  matrix->SetElement(0, 0, 1.01); // 1 % scale along x
  EXPECT_FALSE(matrix_to_pose(matrix, 1000.0, &pose, &error));
  EXPECT_NE(error.find("scale or shear"), std::string::npos) << error;

  matrix->Identity();
  matrix->SetElement(0, 1, 0.2); // shear
  error.clear();
  EXPECT_FALSE(matrix_to_pose(matrix, 1000.0, &pose, &error));
  EXPECT_NE(error.find("scale or shear"), std::string::npos) << error;

  matrix->Identity();
  matrix->SetElement(2, 2, -1.0); // mirror
  error.clear();
  EXPECT_FALSE(matrix_to_pose(matrix, 1000.0, &pose, &error));
  EXPECT_NE(error.find("reflection"), std::string::npos) << error;

  matrix->Identity();
  matrix->SetElement(3, 0, 0.5); // projective bottom row
  error.clear();
  EXPECT_FALSE(matrix_to_pose(matrix, 1000.0, &pose, &error));
  EXPECT_NE(error.find("bottom row"), std::string::npos) << error;

  matrix->Identity();
  matrix->SetElement(1, 3, std::numeric_limits<double>::quiet_NaN());
  error.clear();
  EXPECT_FALSE(matrix_to_pose(matrix, 1000.0, &pose, &error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(matrix_to_pose(nullptr, 1000.0, &pose, &error));
  EXPECT_NE(error.find("null"), std::string::npos) << error;
}

TEST(RigidTransform, SlightlyNonOrthogonalRotationIsReorthonormalised)
{
  // 90 deg about z with float-level noise in two entries: accepted, and the quaternion is the
  // exact one to ~1e-5 and of unit length.
  const double noisy[16] = { 2e-5, -1, 0, 0, 1, -1e-5, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(noisy);
  RigidPose pose;
  std::string error;
  ASSERT_TRUE(matrix_to_pose(matrix, 1000.0, &pose, &error)) << error;
  EXPECT_NEAR(pose.rotation[2], kHalfSqrt2, 2e-5);
  EXPECT_NEAR(pose.rotation[3], kHalfSqrt2, 2e-5);
  const double norm2 = pose.rotation[0] * pose.rotation[0] + pose.rotation[1] * pose.rotation[1] +
    pose.rotation[2] * pose.rotation[2] + pose.rotation[3] * pose.rotation[3];
  EXPECT_NEAR(norm2, 1.0, 1e-14);
}

TEST(RigidTransform, VtkTransformBothWays)
{
  vtkNew<vtkTransform> transform;
  std::string error;
  ASSERT_TRUE(pose_to_transform(
    make_pose(0.5, 0, 0, 0, 0, kHalfSqrt2, kHalfSqrt2), 1000.0, transform, &error))
    << error;
  double point[3] = { 10, 0, 0 };
  transform->TransformPoint(point, point);
  // Rotate (10, 0, 0) to (0, 10, 0), then add (500, 0, 0).
  EXPECT_NEAR(point[0], 500.0, 1e-12);
  EXPECT_NEAR(point[1], 10.0, 1e-12);
  EXPECT_NEAR(point[2], 0.0, 1e-12);

  RigidPose back;
  ASSERT_TRUE(transform_to_pose(transform, 1000.0, &back, &error)) << error;
  EXPECT_NEAR(back.translation[0], 0.5, 1e-15);
  EXPECT_NEAR(back.rotation[2], kHalfSqrt2, 1e-15);
}

TEST(RigidTransform, PoseArrayToTransformCollectionAndBack)
{
  std::vector<RigidPose> poses = { make_pose(0.001, 0, 0, 0, 0, 0, 1),
    make_pose(0, 0, -0.2, 0, 0, kHalfSqrt2, kHalfSqrt2) };
  vtkNew<vtkTransformCollection> collection;
  std::string error;
  ASSERT_TRUE(poses_to_transform_collection(poses, 1000.0, collection, &error)) << error;
  ASSERT_EQ(collection->GetNumberOfItems(), 2);
  vtkTransform* first = vtkTransform::SafeDownCast(collection->GetItemAsObject(0));
  vtkTransform* second = vtkTransform::SafeDownCast(collection->GetItemAsObject(1));
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_NEAR(first->GetMatrix()->GetElement(0, 3), 1.0, 1e-12); // 1 mm
  EXPECT_NEAR(second->GetMatrix()->GetElement(2, 3), -200.0, 1e-12);
  EXPECT_NEAR(second->GetMatrix()->GetElement(1, 0), 1.0, 1e-15);

  std::vector<RigidPose> back;
  ASSERT_TRUE(transform_collection_to_poses(collection, 1000.0, &back, &error)) << error;
  ASSERT_EQ(back.size(), 2u);
  EXPECT_NEAR(back[0].translation[0], 0.001, 1e-15);
  EXPECT_NEAR(back[1].translation[2], -0.2, 1e-15);
  EXPECT_NEAR(back[1].rotation[2], kHalfSqrt2, 1e-15);
}

// A subscriber converts every PoseArray of a stream into the same collection. Transforms only the
// collection holds are refilled in place (no allocation per pose per message); one that somebody
// else holds keeps its pose and is replaced in the collection; a shorter array drops the rest.
TEST(RigidTransform, CollectionRefillsOnlyTheTransformsNobodyElseHolds)
{
  vtkNew<vtkTransformCollection> collection;
  std::string error;
  const std::vector<RigidPose> three = { make_pose(0.001, 0, 0, 0, 0, 0, 1),
    make_pose(0.002, 0, 0, 0, 0, 0, 1), make_pose(0.003, 0, 0, 0, 0, 0, 1) };
  ASSERT_TRUE(poses_to_transform_collection(three, 1000.0, collection, &error)) << error;
  vtkTransform* first = vtkTransform::SafeDownCast(collection->GetItemAsObject(0));
  vtkSmartPointer<vtkTransform> kept = vtkTransform::SafeDownCast(collection->GetItemAsObject(1));
  ASSERT_NE(first, nullptr);
  ASSERT_NE(kept, nullptr);

  const std::vector<RigidPose> two = { make_pose(0.010, 0, 0, 0, 0, 0, 1),
    make_pose(0.020, 0, 0, 0, 0, kHalfSqrt2, kHalfSqrt2) };
  ASSERT_TRUE(poses_to_transform_collection(two, 1000.0, collection, &error)) << error;
  ASSERT_EQ(collection->GetNumberOfItems(), 2);
  EXPECT_EQ(collection->GetItemAsObject(0), first) << "refilled, not replaced";
  EXPECT_NEAR(first->GetMatrix()->GetElement(0, 3), 10.0, 1e-12);
  auto* second = vtkTransform::SafeDownCast(collection->GetItemAsObject(1));
  ASSERT_NE(second, nullptr);
  EXPECT_NE(second, kept.GetPointer()) << "held elsewhere: not reused";
  EXPECT_NEAR(second->GetMatrix()->GetElement(0, 3), 20.0, 1e-12);
  EXPECT_NEAR(second->GetMatrix()->GetElement(1, 0), 1.0, 1e-15);
  EXPECT_NEAR(kept->GetMatrix()->GetElement(0, 3), 2.0, 1e-12) << "the held one kept its pose";
  EXPECT_EQ(kept->GetReferenceCount(), 1) << "and the collection let it go";
}

TEST(RigidTransform, CollectionErrorsNameTheItemAndLeaveOutputAlone)
{
  vtkNew<vtkTransformCollection> collection;
  vtkNew<vtkTransform> existing;
  collection->AddItem(existing);
  std::vector<RigidPose> poses = { make_pose(0, 0, 0, 0, 0, 0, 1), make_pose(0, 0, 0, 0, 0, 0, 2) };
  std::string error;
  EXPECT_FALSE(poses_to_transform_collection(poses, 1000.0, collection, &error));
  EXPECT_NE(error.find("pose 1"), std::string::npos) << error;
  ASSERT_EQ(collection->GetNumberOfItems(), 1);
  EXPECT_EQ(collection->GetItemAsObject(0), existing.GetPointer());

  vtkNew<vtkMatrix4x4> not_a_transform;
  static_cast<vtkCollection*>(collection.GetPointer())->AddItem(not_a_transform);
  std::vector<RigidPose> out(5);
  error.clear();
  EXPECT_FALSE(transform_collection_to_poses(collection, 1000.0, &out, &error));
  EXPECT_NE(error.find("item 1 is not a vtkTransform"), std::string::npos) << error;
  EXPECT_EQ(out.size(), 5u);
}

// Issue 11.9: 1e306 m is finite, 1e309 mm is not; the matrix must not hold infinity.
TEST(RigidTransform, TranslationThatOverflowsOnceScaledIsRefused)
{
  vtkNew<vtkMatrix4x4> matrix;
  std::string error;
  EXPECT_FALSE(
    pose_to_matrix(make_pose(1e306, 0, 0, 0, 0, 0, 1), kMillimetresPerMetre, matrix, &error));
  EXPECT_NE(
    error.find("pose_to_matrix: translation (1e+306, 0, 0) is not finite once scaled by 1000"),
    std::string::npos)
    << error;
  EXPECT_EQ(matrix->GetElement(0, 3), 0.0); // untouched
  EXPECT_TRUE(pose_to_matrix(make_pose(1e306, 0, 0, 0, 0, 0, 1), kNoLengthScaling, matrix, &error));
}
