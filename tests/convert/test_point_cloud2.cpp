// sensor_msgs/PointCloud2 fields <-> vtkPolyData. Byte buffers are assembled by hand.
#include "ros2vtk/convert/PointCloud2.hpp"
#include "ros2vtk/convert/Units.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkSOADataArrayTemplate.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedShortArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace ros2vtk::convert;

namespace {

template<typename T>
void put(std::vector<uint8_t>& bytes, size_t at, T value, bool big_endian = false)
{
  uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian)
  {
    std::reverse(raw, raw + sizeof(T));
  }
  std::memcpy(bytes.data() + at, raw, sizeof(T));
}

template<typename T>
T get(const std::vector<uint8_t>& bytes, size_t at)
{
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  return value;
}

// 3 points: x y z float32 at 0, 4, 8; 4 bytes padding; intensity float32 at 16; point_step 20.
PointCloud2Layout xyzi_layout()
{
  PointCloud2Layout layout;
  layout.height = 1;
  layout.width = 3;
  layout.fields = { { "x", 0, point_field::kFloat32, 1 }, { "y", 4, point_field::kFloat32, 1 },
    { "z", 8, point_field::kFloat32, 1 }, { "intensity", 16, point_field::kFloat32, 1 } };
  layout.point_step = 20;
  layout.row_step = 60;
  return layout;
}

std::vector<uint8_t> xyzi_data()
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float points[3][4] = { { 0.1f, 0.2f, 0.3f, 7.0f }, { nan, 1.0f, 1.0f, 8.0f },
    { -1.0f, 0.5f, 2.0f, 9.5f } };
  std::vector<uint8_t> bytes(60, 0xAB);
  for (size_t i = 0; i < 3; ++i)
  {
    put(bytes, i * 20 + 0, points[i][0]);
    put(bytes, i * 20 + 4, points[i][1]);
    put(bytes, i * 20 + 8, points[i][2]);
    put(bytes, i * 20 + 16, points[i][3]);
  }
  return bytes;
}

} // namespace

TEST(PointCloud2, XyzFloat32PlusIntensity)
{
  vtkNew<vtkPolyData> poly;
  std::string error;
  ASSERT_TRUE(point_cloud2_to_poly_data(
    xyzi_layout(), xyzi_data(), kMillimetresPerMetre, NonFinitePoints::Keep, poly, &error))
    << error;
  ASSERT_EQ(poly->GetNumberOfPoints(), 3);
  EXPECT_EQ(poly->GetPoints()->GetDataType(), VTK_FLOAT);
  double p[3];
  poly->GetPoint(0, p);
  EXPECT_FLOAT_EQ(p[0], 100.0f);
  EXPECT_FLOAT_EQ(p[1], 200.0f);
  EXPECT_FLOAT_EQ(p[2], 300.0f);
  poly->GetPoint(1, p);
  EXPECT_TRUE(std::isnan(p[0]));
  poly->GetPoint(2, p);
  EXPECT_EQ(p[0], -1000.0);
  EXPECT_EQ(p[1], 500.0);
  EXPECT_EQ(p[2], 2000.0);

  vtkFloatArray* intensity =
    vtkFloatArray::SafeDownCast(poly->GetPointData()->GetArray("intensity"));
  ASSERT_NE(intensity, nullptr);
  ASSERT_EQ(intensity->GetNumberOfTuples(), 3);
  EXPECT_EQ(intensity->GetValue(0), 7.0f); // not scaled: not a length
  EXPECT_EQ(intensity->GetValue(1), 8.0f);
  EXPECT_EQ(intensity->GetValue(2), 9.5f);
  EXPECT_EQ(poly->GetPointData()->GetNumberOfArrays(), 1); // x, y, z are the points, not arrays

  // One vertex per point so it renders.
  ASSERT_EQ(poly->GetNumberOfVerts(), 3);
  vtkNew<vtkIdList> ids;
  poly->GetVerts()->GetCellAtId(2, ids);
  ASSERT_EQ(ids->GetNumberOfIds(), 1);
  EXPECT_EQ(ids->GetId(0), 2);
}

TEST(PointCloud2, NonFinitePointsDroppedOrRejected)
{
  vtkNew<vtkPolyData> poly;
  std::string error;
  ASSERT_TRUE(point_cloud2_to_poly_data(
    xyzi_layout(), xyzi_data(), 1000.0, NonFinitePoints::Drop, poly, &error))
    << error;
  ASSERT_EQ(poly->GetNumberOfPoints(), 2);
  EXPECT_EQ(poly->GetPoint(1)[0], -1000.0);
  vtkDataArray* intensity = poly->GetPointData()->GetArray("intensity");
  ASSERT_NE(intensity, nullptr);
  EXPECT_EQ(intensity->GetComponent(0, 0), 7.0);
  EXPECT_EQ(intensity->GetComponent(1, 0), 9.5); // the NaN point's 8.0 left with it
  EXPECT_EQ(poly->GetNumberOfVerts(), 2);

  error.clear();
  EXPECT_FALSE(point_cloud2_to_poly_data(
    xyzi_layout(), xyzi_data(), 1000.0, NonFinitePoints::Reject, poly, &error));
  EXPECT_NE(error.find("point 1 (row 0, column 1) has a NaN"), std::string::npos) << error;
  EXPECT_EQ(poly->GetNumberOfPoints(), 2); // untouched
}

TEST(PointCloud2, OrganizedBigEndianFloat64WithRowPaddingAndMultiValueFields)
{
  // 2 x 2 organized cloud. Per point: x y z float64 at 0, 8, 16; ring uint16 at 24;
  // normal float32 x 3 at 28; point_step 40. row_step 88 (8 bytes of row padding). Big-endian.
  PointCloud2Layout layout;
  layout.height = 2;
  layout.width = 2;
  layout.is_bigendian = true;
  layout.fields = { { "x", 0, point_field::kFloat64, 1 }, { "y", 8, point_field::kFloat64, 1 },
    { "z", 16, point_field::kFloat64, 1 }, { "ring", 24, point_field::kUInt16, 1 },
    { "normal", 28, point_field::kFloat32, 3 } };
  layout.point_step = 40;
  layout.row_step = 88;
  std::vector<uint8_t> bytes(176, 0xEE);
  for (size_t row = 0; row < 2; ++row)
  {
    for (size_t col = 0; col < 2; ++col)
    {
      const size_t base = row * 88 + col * 40;
      const double k = static_cast<double>(row * 2 + col); // 0, 1, 2, 3
      put(bytes, base + 0, 0.001 * (k + 1), true);
      put(bytes, base + 8, -0.5 * k, true);
      put(bytes, base + 16, 2.0, true);
      put(bytes, base + 24, static_cast<uint16_t>(0x0100 + k), true);
      put(bytes, base + 28, 0.0f, true);
      put(bytes, base + 32, 0.0f, true);
      put(bytes, base + 36, 1.0f, true);
    }
  }
  vtkNew<vtkPolyData> poly;
  std::string error;
  ASSERT_TRUE(point_cloud2_to_poly_data(layout, bytes, 1000.0, NonFinitePoints::Keep, poly, &error))
    << error;
  ASSERT_EQ(poly->GetNumberOfPoints(), 4);
  EXPECT_EQ(poly->GetPoints()->GetDataType(), VTK_DOUBLE);
  // Point 3 = row 1, column 1: x = 0.004 m, y = -1.5 m, z = 2 m.
  EXPECT_NEAR(poly->GetPoint(3)[0], 4.0, 1e-12);
  EXPECT_NEAR(poly->GetPoint(3)[1], -1500.0, 1e-12);
  EXPECT_NEAR(poly->GetPoint(3)[2], 2000.0, 1e-12);
  EXPECT_NEAR(poly->GetPoint(2)[0], 3.0, 1e-12);

  vtkUnsignedShortArray* ring =
    vtkUnsignedShortArray::SafeDownCast(poly->GetPointData()->GetArray("ring"));
  ASSERT_NE(ring, nullptr);
  EXPECT_EQ(ring->GetValue(0), 0x0100);
  EXPECT_EQ(ring->GetValue(3), 0x0103);
  vtkFloatArray* normal = vtkFloatArray::SafeDownCast(poly->GetPointData()->GetArray("normal"));
  ASSERT_NE(normal, nullptr);
  EXPECT_EQ(normal->GetNumberOfComponents(), 3);
  EXPECT_EQ(normal->GetComponent(2, 2), 1.0);
  EXPECT_EQ(normal->GetComponent(2, 0), 0.0);
}

TEST(PointCloud2, IntegerCoordinatesAreAccepted)
{
  // x y z as int16 millimetre-ish counts, no scaling.
  PointCloud2Layout layout;
  layout.width = 1;
  layout.fields = { { "x", 0, point_field::kInt16, 1 }, { "y", 2, point_field::kInt16, 1 },
    { "z", 4, point_field::kInt16, 1 } };
  layout.point_step = 6;
  layout.row_step = 6;
  std::vector<uint8_t> bytes(6);
  put<int16_t>(bytes, 0, -3);
  put<int16_t>(bytes, 2, 4);
  put<int16_t>(bytes, 4, 5);
  vtkNew<vtkPolyData> poly;
  ASSERT_TRUE(point_cloud2_to_poly_data(layout, bytes, 1.0, NonFinitePoints::Drop, poly, nullptr));
  EXPECT_EQ(poly->GetPoint(0)[0], -3.0);
  EXPECT_EQ(poly->GetPoint(0)[2], 5.0);
}

TEST(PointCloud2, ZeroWidthIsAnEmptyCloudWhateverTheHeight)
{
  PointCloud2Layout layout = xyzi_layout();
  layout.width = 0;
  layout.row_step = 0;
  layout.height = 0xFFFFFFFFu; // must not walk 4e9 empty rows
  vtkNew<vtkPolyData> poly;
  std::string error;
  ASSERT_TRUE(point_cloud2_to_poly_data(
    layout, std::vector<uint8_t>{}, 1000.0, NonFinitePoints::Drop, poly, &error))
    << error;
  EXPECT_EQ(poly->GetNumberOfPoints(), 0);
  ASSERT_NE(poly->GetPointData()->GetArray("intensity"), nullptr);
  EXPECT_EQ(poly->GetPointData()->GetArray("intensity")->GetNumberOfTuples(), 0);
}

// Points stored as float, as double, or in an array type other than VTK's usual one (structure
// of arrays) give the same cloud: the first two are read straight from their memory, the last
// through vtkPoints::GetPoint.
TEST(PointCloud2, PolyDataToCloudReadsFloatDoubleAndOtherPointStorageAlike)
{
  const double coordinates[2][3] = { { 100.0, -200.5, 300.25 }, { -50.0, 0.0, 1000.0 } };
  auto cloud_of = [&](vtkDataArray* storage, std::vector<uint8_t>* data) {
    storage->SetNumberOfComponents(3);
    storage->SetNumberOfTuples(2);
    for (vtkIdType i = 0; i < 2; ++i)
    {
      storage->SetTuple(i, coordinates[i]);
    }
    vtkNew<vtkPoints> points;
    points->SetData(storage);
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    PointCloud2Layout layout;
    std::string error;
    EXPECT_TRUE(poly_data_to_point_cloud2(poly, kMillimetresPerMetre, &layout, data, &error))
      << error;
    return layout;
  };
  vtkNew<vtkFloatArray> floats;
  vtkNew<vtkDoubleArray> doubles;
  vtkNew<vtkSOADataArrayTemplate<double>> separate;
  std::vector<uint8_t> from_floats, from_doubles, from_separate;
  EXPECT_EQ(cloud_of(floats, &from_floats).fields[0].datatype, point_field::kFloat32);
  EXPECT_EQ(cloud_of(doubles, &from_doubles).fields[0].datatype, point_field::kFloat64);
  EXPECT_EQ(cloud_of(separate, &from_separate).fields[0].datatype, point_field::kFloat64);
  for (size_t i = 0; i < 2; ++i)
  {
    for (size_t axis = 0; axis < 3; ++axis)
    {
      const double metres = coordinates[i][axis] / 1000.0;
      EXPECT_FLOAT_EQ(get<float>(from_floats, 12 * i + 4 * axis), static_cast<float>(metres));
      EXPECT_DOUBLE_EQ(get<double>(from_doubles, 24 * i + 8 * axis), metres);
      EXPECT_DOUBLE_EQ(get<double>(from_separate, 24 * i + 8 * axis), metres);
    }
  }
}

TEST(PointCloud2, PolyDataToCloudLaysOutFieldsAndComesBack)
{
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points; // float by default
  points->InsertNextPoint(100.0, 200.0, 300.0);
  points->InsertNextPoint(-50.0, 0.0, 1000.0);
  poly->SetPoints(points);
  vtkNew<vtkFloatArray> intensity;
  intensity->SetName("intensity");
  intensity->InsertNextValue(0.5f);
  intensity->InsertNextValue(0.75f);
  vtkNew<vtkUnsignedShortArray> label;
  label->SetName("label");
  label->InsertNextValue(7);
  label->InsertNextValue(9);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->InsertNextTuple3(0, 0, 1);
  normals->InsertNextTuple3(1, 0, 0);
  vtkNew<vtkIdTypeArray> ids; // 64-bit: no PointField for it, skipped
  ids->SetName("ids");
  ids->InsertNextValue(1);
  ids->InsertNextValue(2);
  poly->GetPointData()->AddArray(intensity);
  poly->GetPointData()->AddArray(label);
  poly->GetPointData()->AddArray(normals);
  poly->GetPointData()->AddArray(ids);

  PointCloud2Layout layout;
  std::vector<uint8_t> data;
  std::string error;
  ASSERT_TRUE(poly_data_to_point_cloud2(poly, kMillimetresPerMetre, &layout, &data, &error))
    << error;
  EXPECT_EQ(layout.height, 1u);
  EXPECT_EQ(layout.width, 2u);
  EXPECT_FALSE(layout.is_bigendian);
  EXPECT_TRUE(layout.is_dense);
  // x@0 y@4 z@8 intensity@12 (float32), label@16 (uint16), Normals@20 (aligned to 4, 3 floats),
  // point_step 32.
  ASSERT_EQ(layout.fields.size(), 6u);
  const struct
  {
    const char* name;
    uint32_t offset;
    uint8_t datatype;
    uint32_t count;
  } expected[] = { { "x", 0, point_field::kFloat32, 1 }, { "y", 4, point_field::kFloat32, 1 },
    { "z", 8, point_field::kFloat32, 1 }, { "intensity", 12, point_field::kFloat32, 1 },
    { "label", 16, point_field::kUInt16, 1 }, { "Normals", 20, point_field::kFloat32, 3 } };
  for (size_t i = 0; i < 6; ++i)
  {
    EXPECT_EQ(layout.fields[i].name, expected[i].name);
    EXPECT_EQ(layout.fields[i].offset, expected[i].offset) << expected[i].name;
    EXPECT_EQ(layout.fields[i].datatype, expected[i].datatype) << expected[i].name;
    EXPECT_EQ(layout.fields[i].count, expected[i].count) << expected[i].name;
  }
  EXPECT_EQ(layout.point_step, 32u);
  EXPECT_EQ(layout.row_step, 64u);
  ASSERT_EQ(data.size(), 64u);
  EXPECT_FLOAT_EQ(get<float>(data, 0), 0.1f);
  EXPECT_FLOAT_EQ(get<float>(data, 4), 0.2f);
  EXPECT_FLOAT_EQ(get<float>(data, 8), 0.3f);
  EXPECT_EQ(get<float>(data, 12), 0.5f);
  EXPECT_EQ(get<uint16_t>(data, 16), 7);
  EXPECT_EQ(get<float>(data, 28), 1.0f);         // normal z of point 0
  EXPECT_FLOAT_EQ(get<float>(data, 32), -0.05f); // x of point 1
  EXPECT_EQ(get<uint16_t>(data, 48), 9);
  EXPECT_EQ(get<float>(data, 52), 1.0f); // normal x of point 1

  vtkNew<vtkPolyData> back;
  ASSERT_TRUE(point_cloud2_to_poly_data(
    layout, data, kMillimetresPerMetre, NonFinitePoints::Keep, back, &error))
    << error;
  ASSERT_EQ(back->GetNumberOfPoints(), 2);
  EXPECT_NEAR(back->GetPoint(1)[0], -50.0, 1e-4);
  EXPECT_NEAR(back->GetPoint(1)[2], 1000.0, 1e-4);
  EXPECT_EQ(back->GetPointData()->GetArray("label")->GetComponent(1, 0), 9);
  EXPECT_EQ(back->GetPointData()->GetArray("Normals")->GetNumberOfComponents(), 3);
  EXPECT_EQ(back->GetPointData()->GetArray("ids"), nullptr);
}

TEST(PointCloud2, EmptyPolyDataGivesEmptyCloud)
{
  vtkNew<vtkPolyData> poly;
  PointCloud2Layout layout;
  std::vector<uint8_t> data(3, 1);
  ASSERT_TRUE(poly_data_to_point_cloud2(poly, 1000.0, &layout, &data, nullptr));
  EXPECT_EQ(layout.width, 0u);
  EXPECT_TRUE(data.empty());
  EXPECT_EQ(layout.fields.size(), 3u);
}

TEST(PointCloud2, BadLayoutsAreRejected)
{
  const std::vector<uint8_t> data = xyzi_data();
  vtkNew<vtkPolyData> poly;
  std::string error;
  auto expect_rejected = [&](const PointCloud2Layout& layout, const std::vector<uint8_t>& bytes,
                           const std::string& fragment) {
    error.clear();
    EXPECT_FALSE(
      point_cloud2_to_poly_data(layout, bytes, 1000.0, NonFinitePoints::Keep, poly, &error));
    EXPECT_NE(error.find(fragment), std::string::npos) << "got: " << error;
  };

  PointCloud2Layout no_z = xyzi_layout();
  no_z.fields.erase(no_z.fields.begin() + 2);
  expect_rejected(no_z, data, "needs fields 'x', 'y' and 'z' (fields: 'x', 'y', 'intensity')");

  PointCloud2Layout past_end = xyzi_layout();
  past_end.fields[3].offset = 18;
  expect_rejected(
    past_end, data, "field 'intensity' (offset 18, 4 bytes) reaches past point_step 20");

  PointCloud2Layout small_row = xyzi_layout();
  small_row.row_step = 59;
  expect_rejected(small_row, data, "row_step 59 is smaller than width 3 x point_step 20");

  expect_rejected(xyzi_layout(), std::vector<uint8_t>(data.begin(), data.end() - 1),
    "data has 59 bytes but row_step 60 x height 1 needs 60");

  PointCloud2Layout bad_type = xyzi_layout();
  bad_type.fields[3].datatype = 9;
  expect_rejected(bad_type, data, "field 'intensity' has unknown datatype 9");

  PointCloud2Layout zero_count = xyzi_layout();
  zero_count.fields[3].count = 0;
  expect_rejected(zero_count, data, "field 'intensity' has count 0");

  PointCloud2Layout vector_x = xyzi_layout();
  vector_x.fields[0].count = 2;
  expect_rejected(vector_x, data, "field 'x' must have count 1");

  PointCloud2Layout huge = xyzi_layout();
  huge.height = 0xFFFFFFFFu;
  expect_rejected(huge, data, "needs");

  error.clear();
  EXPECT_FALSE(point_cloud2_to_poly_data(
    xyzi_layout(), data, std::nan(""), NonFinitePoints::Keep, poly, &error));
  EXPECT_NE(error.find("length_scale"), std::string::npos) << error;

  EXPECT_EQ(poly->GetNumberOfPoints(), 0); // never touched
}

// Issue 11.9: a float64 x of 1e306 m is finite on the wire and infinite in millimetres.
TEST(PointCloud2, Float64CoordinatesThatOverflowOnceScaledAreRefused)
{
  PointCloud2Layout layout;
  layout.height = 1;
  layout.width = 2;
  layout.fields = { { "x", 0, point_field::kFloat64, 1 }, { "y", 8, point_field::kFloat64, 1 },
    { "z", 16, point_field::kFloat64, 1 } };
  layout.point_step = 24;
  layout.row_step = 48;
  std::vector<uint8_t> data(48, 0);
  put<double>(data, 24 + 8, 1e306);
  vtkNew<vtkPolyData> cloud;
  std::string error;
  for (auto policy : { NonFinitePoints::Keep, NonFinitePoints::Drop, NonFinitePoints::Reject })
  {
    error.clear();
    EXPECT_FALSE(
      point_cloud2_to_poly_data(layout, data, kMillimetresPerMetre, policy, cloud, &error));
    EXPECT_NE(error.find("point at byte 24: y = 1e+306 is not finite once scaled by 1000"),
      std::string::npos)
      << error;
  }
  EXPECT_EQ(cloud->GetNumberOfPoints(), 0);
  ASSERT_TRUE(point_cloud2_to_poly_data(
    layout, data, kNoLengthScaling, NonFinitePoints::Keep, cloud, &error));
  EXPECT_EQ(cloud->GetPoint(1)[1], 1e306);
}
