// Numeric ROS arrays <-> vtkMatrix3x3 (CameraInfo's K) and one-component VTK arrays (CameraInfo's
// D, Joy's axes and buttons), and positions <-> a polyline vtkPolyData (a Path drawn as a line).
#include "ros2vtk/convert/Arrays.hpp"
#include "ros2vtk/convert/Polyline.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <limits>

using namespace ros2vtk::convert;

TEST(Arrays, IntrinsicsRowMajorBothWays)
{
  // fx 0 cx; 0 fy cy; 0 0 1 (pixels)
  const double k[9] = { 525.0, 0.0, 319.5, 0.0, 526.5, 239.5, 0.0, 0.0, 1.0 };
  vtkNew<vtkMatrix3x3> matrix;
  std::string error;
  ASSERT_TRUE(values_to_matrix3x3(k, matrix, &error)) << error;
  EXPECT_EQ(matrix->GetElement(0, 0), 525.0);
  EXPECT_EQ(matrix->GetElement(0, 2), 319.5);
  EXPECT_EQ(matrix->GetElement(1, 1), 526.5);
  EXPECT_EQ(matrix->GetElement(1, 2), 239.5);
  EXPECT_EQ(matrix->GetElement(2, 2), 1.0);
  double back[9] = {};
  ASSERT_TRUE(matrix3x3_to_values(matrix, back, &error)) << error;
  for (int i = 0; i < 9; ++i)
  {
    EXPECT_EQ(back[i], k[i]) << i;
  }
  const double bad[9] = { 1, 0, 0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0, 1 };
  EXPECT_FALSE(values_to_matrix3x3(bad, matrix, &error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;
  EXPECT_EQ(matrix->GetElement(1, 1), 526.5) << "untouched on failure";
  EXPECT_FALSE(values_to_matrix3x3(k, nullptr, &error));
}

TEST(Arrays, SequencesKeepTheArrayClassAndRefuseWhatTheFieldCannotHold)
{
  const double d[5] = { -0.28, 0.07, 0.0001, -0.0002, 0.0 };
  vtkNew<vtkDoubleArray> distortion;
  std::string error;
  ASSERT_TRUE(numbers_to_array(d, 5, distortion, &error)) << error;
  ASSERT_EQ(distortion->GetNumberOfValues(), 5);
  EXPECT_EQ(distortion->GetValue(0), -0.28);
  EXPECT_EQ(distortion->GetValue(3), -0.0002);

  const double buttons[3] = { 0, 1, 1 };
  vtkNew<vtkIntArray> ints;
  ASSERT_TRUE(numbers_to_array(buttons, 3, ints, &error)) << error;
  EXPECT_EQ(ints->GetValue(1), 1);

  const NumberLimits int32{ -2147483648.0, 2147483647.0, true };
  std::vector<double> back;
  ASSERT_TRUE(array_to_numbers(ints, int32, &back, &error)) << error;
  EXPECT_EQ(back, (std::vector<double>{ 0, 1, 1 }));

  vtkNew<vtkDoubleArray> fraction;
  fraction->InsertNextValue(1.0);
  fraction->InsertNextValue(0.5);
  EXPECT_FALSE(array_to_numbers(fraction, int32, &back, &error));
  EXPECT_NE(error.find("value 1 (0.5) is not an integer"), std::string::npos) << error;
  EXPECT_EQ(back.size(), 3u) << "untouched on failure";
  vtkNew<vtkDoubleArray> huge;
  huge->InsertNextValue(3e9);
  EXPECT_FALSE(array_to_numbers(huge, int32, &back, &error));
  EXPECT_NE(error.find("outside"), std::string::npos) << error;

  const double nan[1] = { std::numeric_limits<double>::infinity() };
  vtkNew<vtkFloatArray> axes;
  EXPECT_FALSE(numbers_to_array(nan, 1, axes, &error));
  EXPECT_EQ(axes->GetNumberOfValues(), 0);
  EXPECT_TRUE(numbers_to_array(nullptr, 0, axes, &error)) << "an empty sequence is fine";
}

TEST(Polyline, PositionsBecomeOneScaledLineAndComeBackInCellOrder)
{
  const std::vector<double> xyz = { 0.1, -0.25, 1.5, -0.2, 0.0, 0.3, 0.0, 0.0, 0.0 };
  vtkNew<vtkPolyData> line;
  std::string error;
  ASSERT_TRUE(xyz_to_polyline(xyz, 1000.0, line, &error)) << error;
  ASSERT_EQ(line->GetNumberOfPoints(), 3);
  double p[3];
  line->GetPoint(0, p);
  EXPECT_DOUBLE_EQ(p[0], 100.0);
  EXPECT_DOUBLE_EQ(p[1], -250.0);
  EXPECT_DOUBLE_EQ(p[2], 1500.0);
  ASSERT_EQ(line->GetLines()->GetNumberOfCells(), 1);
  vtkNew<vtkIdList> ids;
  line->GetLines()->GetCellAtId(0, ids);
  ASSERT_EQ(ids->GetNumberOfIds(), 3);
  EXPECT_EQ(ids->GetId(2), 2);

  std::vector<double> back;
  ASSERT_TRUE(polyline_to_xyz(line, 1000.0, &back, &error)) << error;
  ASSERT_EQ(back.size(), 9u);
  for (size_t i = 0; i < 9; ++i)
  {
    EXPECT_NEAR(back[i], xyz[i], 1e-15) << i;
  }

  // The cell's order wins over the point order.
  vtkNew<vtkPolyData> reversed;
  reversed->SetPoints(line->GetPoints());
  vtkNew<vtkCellArray> cells;
  const vtkIdType order[3] = { 2, 1, 0 };
  cells->InsertNextCell(3, order);
  reversed->SetLines(cells);
  ASSERT_TRUE(polyline_to_xyz(reversed, 1000.0, &back, &error)) << error;
  EXPECT_NEAR(back[0], 0.0, 1e-15);
  EXPECT_NEAR(back[6], 0.1, 1e-15);

  cells->InsertNextCell(3, order);
  EXPECT_FALSE(polyline_to_xyz(reversed, 1000.0, &back, &error));
  EXPECT_NE(error.find("2 line cells"), std::string::npos) << error;

  EXPECT_FALSE(xyz_to_polyline({ 1.0, 2.0 }, 1000.0, line, &error));
  EXPECT_EQ(line->GetNumberOfPoints(), 3) << "untouched on failure";
  ASSERT_TRUE(xyz_to_polyline({ 1.0, 2.0, 3.0 }, 1.0, line, &error)) << error;
  EXPECT_EQ(line->GetNumberOfPoints(), 1);
  EXPECT_EQ(line->GetLines()->GetNumberOfCells(), 0) << "one point makes no line";
}
