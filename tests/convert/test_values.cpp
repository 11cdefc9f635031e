// Fixed-size number groups (a Wrench's 6 values) <-> vtkDoubleArray, never scaled.
#include "ros2vtk/convert/Values.hpp"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>

#include <limits>

using namespace ros2vtk::convert;

TEST(Values, WrenchSixValuesBothWaysUnscaled)
{
  // force (N) then torque (N m): no length scaling applies.
  const double wrench[6] = { 1.5, -2.0, 9.81, 0.1, 0.0, -0.25 };
  vtkNew<vtkDoubleArray> array;
  std::string error;
  ASSERT_TRUE(values_to_array(wrench, 6, array, &error)) << error;
  ASSERT_EQ(array->GetNumberOfTuples(), 6);
  EXPECT_EQ(array->GetNumberOfComponents(), 1);
  EXPECT_EQ(array->GetValue(2), 9.81);
  EXPECT_EQ(array->GetValue(5), -0.25);

  double back[6] = {};
  ASSERT_TRUE(array_to_values(array, 6, back, &error)) << error;
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(back[i], wrench[i]) << i;
  }
}

TEST(Values, TwoTuplesOfThreeReadInMemoryOrder)
{
  vtkNew<vtkFloatArray> array;
  array->SetNumberOfComponents(3);
  array->InsertNextTuple3(1, 2, 3);
  array->InsertNextTuple3(4, 5, 6);
  double values[6] = {};
  ASSERT_TRUE(array_to_values(array, 6, values, nullptr));
  EXPECT_EQ(values[3], 4.0);
  EXPECT_EQ(values[5], 6.0);
}

TEST(Values, WrongSizeOrNonFiniteIsRejected)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfValues(5);
  array->FillValue(1.0);
  double values[6] = { 7, 7, 7, 7, 7, 7 };
  std::string error;
  EXPECT_FALSE(array_to_values(array, 6, values, &error));
  EXPECT_NE(error.find("array holds 5 values, expected exactly 6"), std::string::npos) << error;
  EXPECT_EQ(values[0], 7.0);

  array->SetNumberOfValues(6);
  array->FillValue(1.0);
  array->SetValue(4, std::numeric_limits<double>::infinity());
  error.clear();
  EXPECT_FALSE(array_to_values(array, 6, values, &error));
  EXPECT_NE(error.find("value 4 is NaN or infinite"), std::string::npos) << error;
  EXPECT_EQ(values[0], 7.0);

  const double with_nan[2] = { 0.0, std::numeric_limits<double>::quiet_NaN() };
  error.clear();
  EXPECT_FALSE(values_to_array(with_nan, 2, array, &error));
  EXPECT_NE(error.find("value 1 is NaN"), std::string::npos) << error;
  EXPECT_EQ(array->GetNumberOfValues(), 6); // untouched
}
