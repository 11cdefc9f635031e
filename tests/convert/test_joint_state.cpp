// sensor_msgs/JointState arrays <-> vtkTable.
#include "ros2vtk/convert/JointState.hpp"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <cmath>
#include <limits>

using namespace ros2vtk::convert;

TEST(JointState, OneRowPerJointAndBack)
{
  const std::vector<std::string> name = { "shoulder", "elbow" };
  const std::vector<double> position = { 0.5, -1.25 };
  const std::vector<double> velocity = { 0.0, 0.1 };
  const std::vector<double> effort = { std::numeric_limits<double>::quiet_NaN(), 3.0 };
  vtkNew<vtkTable> table;
  std::string error;
  ASSERT_TRUE(joint_state_to_table(name, position, velocity, effort, table, &error)) << error;
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  ASSERT_EQ(table->GetNumberOfColumns(), 4);
  EXPECT_STREQ(table->GetColumnName(0), "name");
  EXPECT_STREQ(table->GetColumnName(1), "position");
  EXPECT_STREQ(table->GetColumnName(2), "velocity");
  EXPECT_STREQ(table->GetColumnName(3), "effort");
  EXPECT_EQ(table->GetValue(1, 0).ToString(), "elbow");
  EXPECT_EQ(table->GetValue(1, 1).ToDouble(), -1.25); // radians: never scaled
  EXPECT_EQ(table->GetValue(1, 2).ToDouble(), 0.1);
  EXPECT_TRUE(std::isnan(table->GetValueByName(0, "effort").ToDouble())); // "unknown" kept

  JointStateArrays back;
  ASSERT_TRUE(table_to_joint_state(table, &back, &error)) << error;
  EXPECT_EQ(back.name, name);
  EXPECT_EQ(back.position, position);
  EXPECT_EQ(back.velocity, velocity);
  ASSERT_EQ(back.effort.size(), 2u);
  EXPECT_TRUE(std::isnan(back.effort[0]));
  EXPECT_EQ(back.effort[1], 3.0);
}

TEST(JointState, EmptyArraysHaveNoColumn)
{
  vtkNew<vtkTable> table;
  ASSERT_TRUE(joint_state_to_table({ "j1", "j2", "j3" }, { 1, 2, 3 }, {}, {}, table, nullptr));
  ASSERT_EQ(table->GetNumberOfColumns(), 2);
  EXPECT_EQ(table->GetColumnByName("velocity"), nullptr);
  JointStateArrays back;
  ASSERT_TRUE(table_to_joint_state(table, &back, nullptr));
  EXPECT_EQ(back.name.size(), 3u);
  EXPECT_TRUE(back.velocity.empty());
  EXPECT_TRUE(back.effort.empty());
}

TEST(JointState, MismatchedSizesAreRejected)
{
  vtkNew<vtkTable> table;
  ASSERT_TRUE(joint_state_to_table({ "a" }, { 1 }, {}, {}, table, nullptr));
  std::string error;
  EXPECT_FALSE(joint_state_to_table({ "a", "b" }, { 1, 2 }, { 0.5 }, {}, table, &error));
  EXPECT_NE(error.find("velocity has 1 entries but another array has 2"), std::string::npos)
    << error;
  EXPECT_EQ(table->GetNumberOfRows(), 1); // untouched
}

TEST(JointState, TableWithWrongColumnTypesIsRejected)
{
  vtkNew<vtkTable> table;
  vtkNew<vtkIntArray> not_names;
  not_names->SetName("name");
  not_names->InsertNextValue(3);
  table->AddColumn(not_names);
  JointStateArrays arrays;
  arrays.position = { 42 };
  std::string error;
  EXPECT_FALSE(table_to_joint_state(table, &arrays, &error));
  EXPECT_NE(error.find("'name' must be a vtkStringArray"), std::string::npos) << error;
  EXPECT_EQ(arrays.position, std::vector<double>{ 42 }); // untouched

  vtkNew<vtkTable> text_positions;
  vtkNew<vtkStringArray> positions;
  positions->SetName("position");
  positions->InsertNextValue("1.0");
  text_positions->AddColumn(positions);
  error.clear();
  EXPECT_FALSE(table_to_joint_state(text_positions, &arrays, &error));
  EXPECT_NE(error.find("'position' must be a one-component numeric array"), std::string::npos)
    << error;
}
