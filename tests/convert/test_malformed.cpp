// Malformed input from the network must give false + message, never a crash or an out-of-bounds
// read. Deterministic pseudo-random layouts over small buffers; run under AddressSanitizer to make
// a stray read fail loudly (the asserts below check the claims that can be checked without it).
#include "ros2vtk/convert/Image.hpp"
#include "ros2vtk/convert/MultiArray.hpp"
#include "ros2vtk/convert/PointCloud2.hpp"

#include <gtest/gtest.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <random>

using namespace ros2vtk::convert;

TEST(Malformed, RandomImageLayoutsAreCheckedAgainstTheBuffer)
{
  std::mt19937 random(12345);
  const std::vector<std::string> encodings = { "mono8", "rgb8", "bgra8", "mono16", "32FC1", "64FC1",
    "bgr16", "nonsense", "" };
  vtkNew<vtkImageData> image;
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    ImageLayout layout;
    layout.width = random() % 9;
    layout.height = random() % 9;
    layout.encoding = encodings[random() % encodings.size()];
    layout.step = random() % 80;
    layout.is_bigendian = random() % 2;
    std::vector<uint8_t> data(random() % 200);
    std::string error;
    if (image_to_vtk(layout, data, image, &error))
    {
      ++accepted;
      EXPECT_LE(static_cast<size_t>(layout.step) * layout.height, data.size());
      int dims[3];
      image->GetDimensions(dims);
      EXPECT_EQ(dims[0], static_cast<int>(layout.width));
      EXPECT_EQ(dims[1], static_cast<int>(layout.height));
    }
    else
    {
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_GT(accepted, 50); // the generator does produce valid layouts too
}

TEST(Malformed, RandomPointCloudLayoutsAreCheckedAgainstTheBuffer)
{
  std::mt19937 random(777);
  const char* names[] = { "x", "y", "z", "intensity", "rgb" };
  vtkNew<vtkPolyData> poly;
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    PointCloud2Layout layout;
    layout.width = random() % 6;
    layout.height = random() % 4;
    layout.point_step = random() % 40;
    layout.row_step = random() % 160;
    layout.is_bigendian = random() % 2;
    const int field_count = static_cast<int>(random() % 6);
    for (int f = 0; f < field_count; ++f)
    {
      layout.fields.push_back({ names[random() % 5], static_cast<uint32_t>(random() % 40),
        static_cast<uint8_t>(random() % 10), static_cast<uint32_t>(random() % 3) });
    }
    if (trial % 3 == 0) // bias towards clouds that have coordinates
    {
      layout.fields.push_back({ "x", 0, point_field::kFloat32, 1 });
      layout.fields.push_back({ "y", 4, point_field::kFloat32, 1 });
      layout.fields.push_back({ "z", 8, point_field::kFloat32, 1 });
    }
    std::vector<uint8_t> data(random() % 400);
    for (uint8_t& byte : data)
    {
      byte = static_cast<uint8_t>(random());
    }
    std::string error;
    const auto policy = static_cast<NonFinitePoints>(random() % 3);
    if (point_cloud2_to_poly_data(layout, data, 1000.0, policy, poly, &error))
    {
      ++accepted;
      EXPECT_LE(static_cast<size_t>(layout.row_step) * layout.height, data.size());
      EXPECT_LE(poly->GetNumberOfPoints(), static_cast<vtkIdType>(layout.width) * layout.height);
    }
    else
    {
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_GT(accepted, 20);
}

TEST(Malformed, RandomMultiArrayLayoutsAreCheckedAgainstTheData)
{
  std::mt19937 random(99);
  vtkNew<vtkTable> table;
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    MultiArrayLayout layout;
    const int dims = static_cast<int>(random() % 4);
    for (int d = 0; d < dims; ++d)
    {
      layout.dim.push_back(
        { "d", static_cast<uint32_t>(random() % 6), static_cast<uint32_t>(random() % 12) });
    }
    layout.data_offset = random() % 5;
    std::vector<double> data(random() % 30, 1.0);
    std::string error;
    if (multi_array_to_table(layout, data, table, &error))
    {
      ++accepted;
    }
    else
    {
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_GT(accepted, 50);
}
