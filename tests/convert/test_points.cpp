// Flat x, y, z triples <-> vtkPoints, with the length scale and the NaN policy.
#include "ros2vtk/convert/Points.hpp"
#include "ros2vtk/convert/Units.hpp"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkPoints.h>

#include <cmath>
#include <limits>

using namespace ros2vtk::convert;

TEST(Points, FloatTriplesAreScaledToMillimetres)
{
  const std::vector<float> xyz = { 0.1f, 0.2f, -0.5f, 1.0f, 0.0f, 0.25f };
  vtkNew<vtkPoints> points;
  std::string error;
  ASSERT_TRUE(xyz_to_points(xyz, kMillimetresPerMetre, NonFinitePoints::Keep, points, &error))
    << error;
  EXPECT_EQ(points->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(points->GetNumberOfPoints(), 2);
  double p[3];
  points->GetPoint(0, p);
  EXPECT_FLOAT_EQ(p[0], 100.0f);
  EXPECT_FLOAT_EQ(p[1], 200.0f);
  EXPECT_FLOAT_EQ(p[2], -500.0f);
  points->GetPoint(1, p);
  EXPECT_EQ(p[0], 1000.0);
  EXPECT_EQ(p[1], 0.0);
  EXPECT_EQ(p[2], 250.0);

  std::vector<float> back;
  ASSERT_TRUE(points_to_xyz(points, kMillimetresPerMetre, &back, &error)) << error;
  ASSERT_EQ(back.size(), 6u);
  EXPECT_FLOAT_EQ(back[0], 0.1f);
  EXPECT_FLOAT_EQ(back[2], -0.5f);
  EXPECT_FLOAT_EQ(back[5], 0.25f);
}

TEST(Points, DoubleTriplesWithoutScaling)
{
  const std::vector<double> xyz = { 0.1, 0.2, 0.3 };
  vtkNew<vtkPoints> points;
  ASSERT_TRUE(xyz_to_points(xyz, kNoLengthScaling, NonFinitePoints::Keep, points, nullptr));
  EXPECT_EQ(points->GetDataType(), VTK_DOUBLE);
  double p[3];
  points->GetPoint(0, p);
  EXPECT_EQ(p[0], 0.1);
  EXPECT_EQ(p[1], 0.2);
  EXPECT_EQ(p[2], 0.3);
  std::vector<double> back;
  ASSERT_TRUE(points_to_xyz(points, kNoLengthScaling, &back, nullptr));
  EXPECT_EQ(back, xyz);
}

TEST(Points, NonFinitePolicy)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> xyz = { 1, 1, 1, nan, 0, 0, 2, 2, 2 };
  vtkNew<vtkPoints> points;
  std::string error;

  ASSERT_TRUE(xyz_to_points(xyz, 1000.0, NonFinitePoints::Keep, points, &error)) << error;
  ASSERT_EQ(points->GetNumberOfPoints(), 3);
  EXPECT_TRUE(std::isnan(points->GetPoint(1)[0]));

  ASSERT_TRUE(xyz_to_points(xyz, 1000.0, NonFinitePoints::Drop, points, &error)) << error;
  ASSERT_EQ(points->GetNumberOfPoints(), 2);
  EXPECT_EQ(points->GetPoint(0)[0], 1000.0);
  EXPECT_EQ(points->GetPoint(1)[0], 2000.0);

  EXPECT_FALSE(xyz_to_points(xyz, 1000.0, NonFinitePoints::Reject, points, &error));
  EXPECT_NE(error.find("point 1 has a NaN or infinite coordinate"), std::string::npos) << error;
  EXPECT_EQ(points->GetNumberOfPoints(), 2); // untouched by the failure
}

TEST(Points, BadInput)
{
  vtkNew<vtkPoints> points;
  std::string error;
  EXPECT_FALSE(
    xyz_to_points(std::vector<float>{ 1, 2, 3, 4 }, 1000.0, NonFinitePoints::Keep, points, &error));
  EXPECT_NE(error.find("4 values is not a whole number of x, y, z triples"), std::string::npos)
    << error;

  error.clear();
  EXPECT_FALSE(
    xyz_to_points(std::vector<float>{ 1, 2, 3 }, -1.0, NonFinitePoints::Keep, points, &error));
  EXPECT_NE(error.find("length_scale"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(xyz_to_points(
    static_cast<const float*>(nullptr), 2, 1000.0, NonFinitePoints::Keep, points, &error));
  EXPECT_NE(error.find("null"), std::string::npos) << error;

  std::vector<double> out;
  error.clear();
  EXPECT_FALSE(points_to_xyz(nullptr, 1000.0, &out, &error));
  EXPECT_NE(error.find("null"), std::string::npos) << error;
}

// Issue 11.9: finite in metres, not finite in millimetres: an error under every policy (the
// policy is about the sender's own NaN points).
TEST(Points, CoordinatesThatOverflowOnceScaledAreRefused)
{
  vtkNew<vtkPoints> points;
  std::string error;
  for (auto policy : { NonFinitePoints::Keep, NonFinitePoints::Drop, NonFinitePoints::Reject })
  {
    error.clear();
    EXPECT_FALSE(xyz_to_points(
      std::vector<float>{ 0, 0, 0, 1, 1e37f, 1 }, kMillimetresPerMetre, policy, points, &error));
    EXPECT_NE(
      error.find("point 1: coordinate 1e+37 is not finite once scaled by 1000"), std::string::npos)
      << error;
    error.clear();
    EXPECT_FALSE(xyz_to_points(
      std::vector<double>{ 1e306, 0, 0 }, kMillimetresPerMetre, policy, points, &error));
    EXPECT_NE(error.find("point 0: coordinate 1e+306"), std::string::npos) << error;
  }
  EXPECT_TRUE(xyz_to_points(
    std::vector<float>{ 1e37f, 0, 0 }, kNoLengthScaling, NonFinitePoints::Keep, points, &error));
}
