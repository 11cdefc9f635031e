// The generated ROS2ToVTK / VTKToROS2 converters of ros2vtk::Nodes, every mapped type both
// ways, against hand-computed values: the units policy (lengths x1000 into VTK, /1000 out,
// nothing else scaled), quaternion <-> rotation matrix, image encodings and row order,
// multi-array layouts, and bad input giving false + a message with the output untouched.
#include "ros2vtkNodesConvert.hpp"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkTransform.h"
#include "vtkTransformCollection.h"
#include "vtkTypeInt64Array.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {
namespace nodes = ros2vtk::nodes;
namespace geometry_msgs = ros2vtk::geometry_msgs::msg;
namespace sensor_msgs = ros2vtk::sensor_msgs::msg;
namespace std_msgs = ros2vtk::std_msgs::msg;
using ros2vtk::convert::kNoLengthScaling;

constexpr double kHalfSqrt2 = 0.70710678118654752;

// 90 degrees about z: x -> y, y -> -x.
void SetQuarterTurnAboutZ(geometry_msgs::Quaternion& q)
{
  q.x = 0.0;
  q.y = 0.0;
  q.z = kHalfSqrt2;
  q.w = kHalfSqrt2;
}

void ExpectQuarterTurnAboutZ(vtkMatrix4x4* m)
{
  const double expected[3][3] = { { 0, -1, 0 }, { 1, 0, 0 }, { 0, 0, 1 } };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(m->GetElement(r, c), expected[r][c], 1e-12) << r << "," << c;
    }
  }
}

std::vector<uint8_t> FloatBytes(const std::vector<float>& values)
{
  std::vector<uint8_t> bytes(values.size() * sizeof(float));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}
} // namespace

//------------------------------------------------------------------------------
TEST(PoseStampedConvert, PositionMetresBecomeMillimetresAndBack)
{
  geometry_msgs::PoseStamped pose;
  pose.pose.position.x = 0.1;
  pose.pose.position.y = -0.25;
  pose.pose.position.z = 2.0;
  SetQuarterTurnAboutZ(pose.pose.orientation);

  vtkNew<vtkMatrix4x4> matrix;
  std::string error;
  ASSERT_TRUE(nodes::ROS2ToVTK(pose, matrix, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  EXPECT_NEAR(matrix->GetElement(0, 3), 100.0, 1e-9);
  EXPECT_NEAR(matrix->GetElement(1, 3), -250.0, 1e-9);
  EXPECT_NEAR(matrix->GetElement(2, 3), 2000.0, 1e-9);
  ExpectQuarterTurnAboutZ(matrix);

  geometry_msgs::PoseStamped back;
  back.header.frame_id = "kept";
  ASSERT_TRUE(nodes::VTKToROS2(matrix, back, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  EXPECT_NEAR(back.pose.position.x, 0.1, 1e-12);
  EXPECT_NEAR(back.pose.position.y, -0.25, 1e-12);
  EXPECT_NEAR(back.pose.position.z, 2.0, 1e-12);
  EXPECT_NEAR(back.pose.orientation.z, kHalfSqrt2, 1e-12);
  EXPECT_NEAR(back.pose.orientation.w, kHalfSqrt2, 1e-12);
  EXPECT_EQ(back.header.frame_id, "kept") << "the converter does not touch the header";
}

TEST(PoseStampedConvert, ScalingOffKeepsMetres)
{
  geometry_msgs::PoseStamped pose;
  pose.pose.position.x = 0.1;
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(nodes::ROS2ToVTK(pose, matrix, kNoLengthScaling));
  EXPECT_DOUBLE_EQ(matrix->GetElement(0, 3), 0.1);
  geometry_msgs::PoseStamped back;
  ASSERT_TRUE(nodes::VTKToROS2(matrix, back, kNoLengthScaling));
  EXPECT_DOUBLE_EQ(back.pose.position.x, 0.1);
}

TEST(PoseStampedConvert, DefaultScaleIsMillimetres)
{
  geometry_msgs::PoseStamped pose;
  pose.pose.position.z = 0.001;
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(nodes::ROS2ToVTK(pose, matrix));
  EXPECT_NEAR(matrix->GetElement(2, 3), 1.0, 1e-12);
}

TEST(PoseStampedConvert, ZeroQuaternionIsRejectedAndMatrixUntouched)
{
  geometry_msgs::PoseStamped pose;
  pose.pose.orientation.w = 0.0; // all four zero
  vtkNew<vtkMatrix4x4> matrix;
  matrix->SetElement(0, 3, 42.0);
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(pose, matrix, ros2vtk::convert::kMillimetresPerMetre, &error));
  EXPECT_NE(error.find("quaternion"), std::string::npos) << error;
  EXPECT_EQ(matrix->GetElement(0, 3), 42.0);
}

TEST(PoseStampedConvert, NullMatrixIsAnErrorNotACrash)
{
  geometry_msgs::PoseStamped pose;
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(
    pose, static_cast<vtkMatrix4x4*>(nullptr), ros2vtk::convert::kMillimetresPerMetre, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(nodes::VTKToROS2(
    static_cast<vtkMatrix4x4*>(nullptr), pose, ros2vtk::convert::kMillimetresPerMetre, &error));
}

TEST(TransformStampedConvert, TranslationScaledRotationNot)
{
  geometry_msgs::TransformStamped transform;
  transform.transform.translation.x = 0.5;
  SetQuarterTurnAboutZ(transform.transform.rotation);
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(nodes::ROS2ToVTK(transform, matrix));
  EXPECT_NEAR(matrix->GetElement(0, 3), 500.0, 1e-9);
  ExpectQuarterTurnAboutZ(matrix);
  geometry_msgs::TransformStamped back;
  ASSERT_TRUE(nodes::VTKToROS2(matrix, back));
  EXPECT_NEAR(back.transform.translation.x, 0.5, 1e-12);
  EXPECT_NEAR(back.transform.rotation.z, kHalfSqrt2, 1e-12);
}

//------------------------------------------------------------------------------
TEST(PoseArrayConvert, OneTransformPerPoseScaledAndBack)
{
  geometry_msgs::PoseArray poses;
  poses.poses.resize(2);
  poses.poses[0].position.x = 0.01;
  poses.poses[1].position.y = 0.2;
  SetQuarterTurnAboutZ(poses.poses[1].orientation);

  vtkNew<vtkTransformCollection> collection;
  std::string error;
  ASSERT_TRUE(nodes::ROS2ToVTK(poses, collection, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  ASSERT_EQ(collection->GetNumberOfItems(), 2);
  collection->InitTraversal();
  vtkTransform* first = collection->GetNextItem();
  vtkTransform* second = collection->GetNextItem();
  EXPECT_NEAR(first->GetMatrix()->GetElement(0, 3), 10.0, 1e-9);
  EXPECT_NEAR(second->GetMatrix()->GetElement(1, 3), 200.0, 1e-9);
  ExpectQuarterTurnAboutZ(second->GetMatrix());

  geometry_msgs::PoseArray back;
  ASSERT_TRUE(nodes::VTKToROS2(collection, back, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  ASSERT_EQ(back.poses.size(), 2u);
  EXPECT_NEAR(back.poses[0].position.x, 0.01, 1e-12);
  EXPECT_NEAR(back.poses[1].position.y, 0.2, 1e-12);
  EXPECT_NEAR(back.poses[1].orientation.z, kHalfSqrt2, 1e-12);
  EXPECT_NEAR(back.poses[0].orientation.w, 1.0, 1e-12);
}

//------------------------------------------------------------------------------
TEST(WrenchStampedConvert, SixValuesNeverScaled)
{
  geometry_msgs::WrenchStamped wrench;
  wrench.wrench.force.x = 1.5;
  wrench.wrench.force.y = -2.0;
  wrench.wrench.force.z = 3.0;
  wrench.wrench.torque.x = 0.25;
  wrench.wrench.torque.y = 0.5;
  wrench.wrench.torque.z = -0.75;
  vtkNew<vtkDoubleArray> array;
  // The millimetre scale is passed on purpose: forces and torques must ignore it.
  ASSERT_TRUE(nodes::ROS2ToVTK(wrench, array, ros2vtk::convert::kMillimetresPerMetre));
  ASSERT_EQ(array->GetNumberOfValues(), 6);
  const double expected[6] = { 1.5, -2.0, 3.0, 0.25, 0.5, -0.75 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(array->GetValue(i), expected[i]) << i;
  }
  array->SetValue(5, 9.0);
  geometry_msgs::WrenchStamped back;
  ASSERT_TRUE(nodes::VTKToROS2(array, back, ros2vtk::convert::kMillimetresPerMetre));
  EXPECT_EQ(back.wrench.force.x, 1.5);
  EXPECT_EQ(back.wrench.torque.z, 9.0);
}

TEST(WrenchStampedConvert, WrongSizeIsRejected)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfValues(5);
  geometry_msgs::WrenchStamped back;
  back.wrench.force.x = 7.0;
  std::string error;
  EXPECT_FALSE(nodes::VTKToROS2(array, back, 1.0, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(back.wrench.force.x, 7.0);
}

//------------------------------------------------------------------------------
TEST(ImageConvert, Rgb8RowsFlippedIntoVtkAndBack)
{
  sensor_msgs::Image image;
  image.width = 2;
  image.height = 2;
  image.encoding = "rgb8";
  image.step = 6;
  // ROS row 0 (top): red, green; row 1 (bottom): blue, white.
  image.data = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255 };
  vtkNew<vtkImageData> vtkImage;
  std::string error;
  ASSERT_TRUE(nodes::ROS2ToVTK(image, vtkImage, 1.0, &error)) << error;
  int dims[3];
  vtkImage->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 2);
  EXPECT_EQ(vtkImage->GetNumberOfScalarComponents(), 3);
  EXPECT_EQ(vtkImage->GetScalarType(), VTK_UNSIGNED_CHAR);
  // VTK y = 1 is the top row.
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(0, 1, 0, 0), 255); // red
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(1, 1, 0, 1), 255); // green
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(0, 0, 0, 2), 255); // blue
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(0, 0, 0, 0), 0);

  sensor_msgs::Image back;
  ASSERT_TRUE(nodes::VTKToROS2(vtkImage, back, 1.0, &error)) << error;
  EXPECT_EQ(back.encoding, "rgb8");
  EXPECT_EQ(back.width, 2u);
  EXPECT_EQ(back.height, 2u);
  EXPECT_EQ(back.step, 6u);
  EXPECT_EQ(back.data, image.data);
}

TEST(ImageConvert, Mono16LittleEndian)
{
  sensor_msgs::Image image;
  image.width = 2;
  image.height = 1;
  image.encoding = "mono16";
  image.is_bigendian = 0;
  image.step = 4;
  image.data = { 0x34, 0x12, 0xff, 0xff }; // 0x1234, 65535
  vtkNew<vtkImageData> vtkImage;
  ASSERT_TRUE(nodes::ROS2ToVTK(image, vtkImage));
  EXPECT_EQ(vtkImage->GetScalarType(), VTK_UNSIGNED_SHORT);
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(0, 0, 0, 0), 0x1234);
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(1, 0, 0, 0), 65535);
  sensor_msgs::Image back;
  ASSERT_TRUE(nodes::VTKToROS2(vtkImage, back));
  EXPECT_EQ(back.encoding, "mono16");
  EXPECT_EQ(back.data, image.data);
}

TEST(ImageConvert, Float32OneChannel)
{
  sensor_msgs::Image image;
  image.width = 3;
  image.height = 1;
  image.encoding = "32FC1";
  image.step = 12;
  image.data = FloatBytes({ 0.5f, -1.25f, 1000.0f });
  vtkNew<vtkImageData> vtkImage;
  ASSERT_TRUE(nodes::ROS2ToVTK(image, vtkImage));
  EXPECT_EQ(vtkImage->GetScalarType(), VTK_FLOAT);
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(1, 0, 0, 0), -1.25);
  EXPECT_EQ(vtkImage->GetScalarComponentAsDouble(2, 0, 0, 0), 1000.0) << "pixels never scaled";
  sensor_msgs::Image back;
  ASSERT_TRUE(nodes::VTKToROS2(vtkImage, back));
  EXPECT_EQ(back.encoding, "32FC1");
  EXPECT_EQ(back.data, image.data);
}

TEST(ImageConvert, RequestedEncodingBgr8ReordersChannels)
{
  vtkNew<vtkImageData> vtkImage;
  vtkImage->SetDimensions(1, 1, 1);
  vtkImage->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixel = static_cast<unsigned char*>(vtkImage->GetScalarPointer(0, 0, 0));
  pixel[0] = 10;
  pixel[1] = 20;
  pixel[2] = 30;
  sensor_msgs::Image back;
  std::string error;
  ASSERT_TRUE(nodes::VTKToROS2(vtkImage, back, 1.0, &error, "bgr8")) << error;
  EXPECT_EQ(back.encoding, "bgr8");
  EXPECT_EQ(back.data, (std::vector<uint8_t>{ 30, 20, 10 }));
}

TEST(ImageConvert, StepBeyondDataIsRejected)
{
  sensor_msgs::Image image;
  image.width = 2;
  image.height = 2;
  image.encoding = "mono8";
  image.step = 2;
  image.data = { 1, 2, 3 }; // 4 needed
  vtkNew<vtkImageData> vtkImage;
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(image, vtkImage, 1.0, &error));
  EXPECT_FALSE(error.empty());
  int dims[3];
  vtkImage->GetDimensions(dims);
  EXPECT_EQ(dims[0], 0) << "image untouched";
}

//------------------------------------------------------------------------------
TEST(PointCloudConvert, PointsScaledIntoVtkAndBack)
{
  sensor_msgs::PointCloud cloud;
  cloud.points.resize(2);
  cloud.points[0].x = 0.001f;
  cloud.points[0].y = 0.002f;
  cloud.points[0].z = 0.003f;
  cloud.points[1].x = -0.5f;
  vtkNew<vtkPoints> points;
  ASSERT_TRUE(nodes::ROS2ToVTK(cloud, points));
  ASSERT_EQ(points->GetNumberOfPoints(), 2);
  double p[3];
  points->GetPoint(0, p);
  EXPECT_NEAR(p[0], 1.0, 1e-4);
  EXPECT_NEAR(p[1], 2.0, 1e-4);
  EXPECT_NEAR(p[2], 3.0, 1e-4);
  points->GetPoint(1, p);
  EXPECT_NEAR(p[0], -500.0, 1e-3);

  sensor_msgs::PointCloud back;
  ASSERT_TRUE(nodes::VTKToROS2(points, back));
  ASSERT_EQ(back.points.size(), 2u);
  EXPECT_NEAR(back.points[0].z, 0.003f, 1e-7);
  EXPECT_NEAR(back.points[1].x, -0.5f, 1e-7);

  vtkNew<vtkPoints> unscaled;
  ASSERT_TRUE(nodes::ROS2ToVTK(cloud, unscaled, kNoLengthScaling));
  unscaled->GetPoint(1, p);
  EXPECT_NEAR(p[0], -0.5, 1e-7);
}

//------------------------------------------------------------------------------
TEST(PointCloud2Convert, XyzScaledOtherFieldsNot)
{
  sensor_msgs::PointCloud2 cloud;
  cloud.height = 1;
  cloud.width = 2;
  const char* names[4] = { "x", "y", "z", "intensity" };
  for (uint32_t i = 0; i < 4; ++i)
  {
    sensor_msgs::PointField field;
    field.name = names[i];
    field.offset = 4 * i;
    field.datatype = sensor_msgs::PointField::FLOAT32;
    field.count = 1;
    cloud.fields.push_back(field);
  }
  cloud.point_step = 16;
  cloud.row_step = 32;
  cloud.is_dense = true;
  cloud.data = FloatBytes({ 0.1f, 0.2f, 0.3f, 7.0f, -1.0f, 0.0f, 0.5f, 8.0f });

  vtkNew<vtkPolyData> polyData;
  std::string error;
  ASSERT_TRUE(nodes::ROS2ToVTK(cloud, polyData, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  ASSERT_EQ(polyData->GetNumberOfPoints(), 2);
  double p[3];
  polyData->GetPoint(0, p);
  EXPECT_NEAR(p[0], 100.0, 1e-3);
  EXPECT_NEAR(p[2], 300.0, 1e-3);
  polyData->GetPoint(1, p);
  EXPECT_NEAR(p[0], -1000.0, 1e-3);
  vtkDataArray* intensity = polyData->GetPointData()->GetArray("intensity");
  ASSERT_NE(intensity, nullptr);
  EXPECT_EQ(intensity->GetTuple1(0), 7.0);
  EXPECT_EQ(intensity->GetTuple1(1), 8.0);

  sensor_msgs::PointCloud2 back;
  ASSERT_TRUE(nodes::VTKToROS2(polyData, back, ros2vtk::convert::kMillimetresPerMetre, &error))
    << error;
  EXPECT_EQ(back.width, 2u);
  ASSERT_EQ(back.fields.size(), 4u);
  EXPECT_EQ(back.fields[0].name, "x");
  EXPECT_EQ(back.fields[3].name, "intensity");
  ASSERT_EQ(back.point_step, 16u);
  ASSERT_EQ(back.data.size(), 32u);
  float values[8];
  std::memcpy(values, back.data.data(), sizeof(values));
  EXPECT_NEAR(values[0], 0.1f, 1e-6);
  EXPECT_NEAR(values[4], -1.0f, 1e-6);
  EXPECT_EQ(values[7], 8.0f);
}

TEST(PointCloud2Convert, MissingXyzIsRejected)
{
  sensor_msgs::PointCloud2 cloud;
  cloud.width = 1;
  cloud.height = 1;
  cloud.point_step = 4;
  cloud.row_step = 4;
  cloud.data.resize(4);
  vtkNew<vtkPolyData> polyData;
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(cloud, polyData, 1.0, &error));
  EXPECT_FALSE(error.empty());
}

//------------------------------------------------------------------------------
TEST(JointStateConvert, OneRowPerJointNothingScaled)
{
  sensor_msgs::JointState state;
  state.name = { "shoulder", "elbow" };
  state.position = { 0.5, -1.0 };
  state.effort = { 2.0, 3.0 };
  vtkNew<vtkTable> table;
  ASSERT_TRUE(nodes::ROS2ToVTK(state, table, ros2vtk::convert::kMillimetresPerMetre));
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  auto* names = vtkStringArray::SafeDownCast(table->GetColumnByName("name"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(1), "elbow");
  EXPECT_EQ(table->GetColumnByName("position")->GetVariantValue(1).ToDouble(), -1.0);
  EXPECT_EQ(table->GetColumnByName("velocity"), nullptr) << "empty array, no column";
  sensor_msgs::JointState back;
  ASSERT_TRUE(nodes::VTKToROS2(table, back));
  EXPECT_EQ(back.name, state.name);
  EXPECT_EQ(back.position, state.position);
  EXPECT_TRUE(back.velocity.empty());
  EXPECT_EQ(back.effort, state.effort);
}

//------------------------------------------------------------------------------
TEST(MultiArrayConvert, Int64TwoDimsBecomeRowsAndColumns)
{
  std_msgs::Int64MultiArray array;
  array.layout.dim.resize(2);
  array.layout.dim[0].label = "rows";
  array.layout.dim[0].size = 2;
  array.layout.dim[0].stride = 6;
  array.layout.dim[1].label = "col";
  array.layout.dim[1].size = 3;
  array.layout.dim[1].stride = 3;
  array.data = { 1, 2, 3, 4, 5, 6 };
  vtkNew<vtkTable> table;
  std::string error;
  ASSERT_TRUE(nodes::ROS2ToVTK(array, table, 1.0, &error)) << error;
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  ASSERT_EQ(table->GetNumberOfColumns(), 3);
  EXPECT_EQ(table->GetValue(1, 0).ToTypeInt64(), 4);
  EXPECT_EQ(table->GetValue(0, 2).ToTypeInt64(), 3);
  EXPECT_STREQ(table->GetColumn(2)->GetName(), "col_2");

  std_msgs::Int64MultiArray back;
  ASSERT_TRUE(nodes::VTKToROS2(table, back, 1.0, &error)) << error;
  EXPECT_EQ(back.data, array.data);
  ASSERT_EQ(back.layout.dim.size(), 2u);
  EXPECT_EQ(back.layout.dim[0].size, 2u);
  EXPECT_EQ(back.layout.dim[1].size, 3u);
  EXPECT_EQ(back.layout.dim[1].label, "col");
}

TEST(MultiArrayConvert, Float64TableAndDataOffset)
{
  std_msgs::Float64MultiArray array;
  array.layout.dim.resize(2);
  array.layout.dim[0].size = 2;
  array.layout.dim[1].size = 2;
  array.layout.data_offset = 1;
  array.data = { 99.0, 0.5, 1.5, 2.5, 3.5 };
  vtkNew<vtkTable> table;
  ASSERT_TRUE(nodes::ROS2ToVTK(array, table));
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  EXPECT_EQ(table->GetValue(0, 0).ToDouble(), 0.5);
  EXPECT_EQ(table->GetValue(1, 1).ToDouble(), 3.5);
}

TEST(MultiArrayConvert, LayoutBeyondDataIsRejected)
{
  std_msgs::Int64MultiArray array;
  array.layout.dim.resize(2);
  array.layout.dim[0].size = 3;
  array.layout.dim[1].size = 3;
  array.data = { 1, 2 };
  vtkNew<vtkTable> table;
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(array, table, 1.0, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(table->GetNumberOfColumns(), 0);
}

TEST(MultiArrayConvert, DoubleArrayOneDimension)
{
  std_msgs::Float64MultiArray array;
  array.data = { 1.0, 2.0, 3.0 };
  vtkNew<vtkDoubleArray> values;
  ASSERT_TRUE(nodes::ROS2ToVTK(array, values));
  ASSERT_EQ(values->GetNumberOfTuples(), 3);
  EXPECT_EQ(values->GetValue(2), 3.0);
  std_msgs::Float64MultiArray back;
  ASSERT_TRUE(nodes::VTKToROS2(values, back));
  EXPECT_EQ(back.data, array.data);
  ASSERT_EQ(back.layout.dim.size(), 1u);
  EXPECT_EQ(back.layout.dim[0].size, 3u);
}

TEST(MultiArrayConvert, IntArrayKeepsSixtyFourBits)
{
  std_msgs::Int64MultiArray array;
  array.data = { 9007199254740993LL, -5 }; // 2^53 + 1: not representable as a double
  vtkNew<vtkTypeInt64Array> values;
  ASSERT_TRUE(nodes::ROS2ToVTK(array, values));
  ASSERT_EQ(values->GetNumberOfValues(), 2);
  EXPECT_EQ(values->GetValue(0), 9007199254740993LL);
  std_msgs::Int64MultiArray back;
  ASSERT_TRUE(nodes::VTKToROS2(values, back));
  EXPECT_EQ(back.data, array.data);
}

//------------------------------------------------------------------------------
TEST(ValueConvert, StringBoolIntDoubleBothWays)
{
  std_msgs::String text;
  ASSERT_TRUE(nodes::VTKToROS2(std::string("Hello world."), text));
  EXPECT_EQ(text.data, "Hello world.");
  std::string textOut;
  ASSERT_TRUE(nodes::ROS2ToVTK(text, &textOut));
  EXPECT_EQ(textOut, "Hello world.");

  std_msgs::Bool flag;
  ASSERT_TRUE(nodes::VTKToROS2(true, flag));
  bool flagOut = false;
  ASSERT_TRUE(nodes::ROS2ToVTK(flag, &flagOut));
  EXPECT_TRUE(flagOut);

  std_msgs::Int64 number;
  ASSERT_TRUE(nodes::VTKToROS2(static_cast<vtkTypeInt64>(-9007199254740993LL), number));
  vtkTypeInt64 numberOut = 0;
  ASSERT_TRUE(nodes::ROS2ToVTK(number, &numberOut));
  EXPECT_EQ(numberOut, -9007199254740993LL);

  std_msgs::Float64 real;
  ASSERT_TRUE(nodes::VTKToROS2(0.125, real));
  double realOut = 0.0;
  // Float64 carries no length rule: the scale must not touch it.
  ASSERT_TRUE(nodes::ROS2ToVTK(real, &realOut, ros2vtk::convert::kMillimetresPerMetre));
  EXPECT_EQ(realOut, 0.125);
}

TEST(ValueConvert, NullOutputIsAnError)
{
  std_msgs::String text;
  std::string error;
  EXPECT_FALSE(nodes::ROS2ToVTK(text, static_cast<std::string*>(nullptr), 1.0, &error));
  EXPECT_NE(error.find("null"), std::string::npos);
}
