// sensor_msgs/Image fields <-> vtkImageData: encodings, row padding, the row flip, byte order.
// Every expected pixel is written out by hand.
#include "ros2vtk/convert/Image.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>

using namespace ros2vtk::convert;

namespace {

ImageLayout layout_of(uint32_t width, uint32_t height, const std::string& encoding, uint32_t step,
  uint8_t big_endian = 0)
{
  ImageLayout layout;
  layout.width = width;
  layout.height = height;
  layout.encoding = encoding;
  layout.step = step;
  layout.is_bigendian = big_endian;
  return layout;
}

/// Component c of the VTK pixel at (x, y), where y = 0 is the BOTTOM row.
double vtk_pixel(vtkImageData* image, int x, int y, int c = 0)
{
  return image->GetScalarComponentAsDouble(x, y, 0, c);
}

// A 2 x 2 colour image, 3 bytes per pixel, step 8 (2 bytes of padding per row).
// ROS row 0 (top):    (1,2,3)   (4,5,6)    pad EE EE
// ROS row 1 (bottom): (7,8,9)   (10,11,12) pad EE EE
const std::vector<uint8_t> kColour2x2 = { 1, 2, 3, 4, 5, 6, 0xEE, 0xEE, 7, 8, 9, 10, 11, 12, 0xEE,
  0xEE };

} // namespace

TEST(Image, Rgb8WithPaddingIsFlippedUpright)
{
  vtkNew<vtkImageData> image;
  std::string error;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "rgb8", 8), kColour2x2, image, &error)) << error;
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 2);
  EXPECT_EQ(dims[2], 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr);
  EXPECT_EQ(scalars->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(scalars->GetNumberOfComponents(), 3);
  // VTK y = 1 (top) holds ROS row 0; VTK y = 0 (bottom) holds ROS row 1.
  EXPECT_EQ(vtk_pixel(image, 0, 1, 0), 1);
  EXPECT_EQ(vtk_pixel(image, 0, 1, 1), 2);
  EXPECT_EQ(vtk_pixel(image, 0, 1, 2), 3);
  EXPECT_EQ(vtk_pixel(image, 1, 1, 0), 4);
  EXPECT_EQ(vtk_pixel(image, 1, 1, 2), 6);
  EXPECT_EQ(vtk_pixel(image, 0, 0, 0), 7);
  EXPECT_EQ(vtk_pixel(image, 0, 0, 2), 9);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 0), 10);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 1), 11);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 2), 12);
  // Raw memory order: tuple 0 is the bottom-left pixel.
  const unsigned char expected_memory[12] = { 7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6 };
  EXPECT_EQ(std::memcmp(scalars->GetVoidPointer(0), expected_memory, 12), 0);

  ImageLayout layout;
  std::vector<uint8_t> data;
  ASSERT_TRUE(vtk_to_image(image, "", &layout, &data, &error)) << error;
  EXPECT_EQ(layout.encoding, "rgb8");
  EXPECT_EQ(layout.width, 2u);
  EXPECT_EQ(layout.height, 2u);
  EXPECT_EQ(layout.step, 6u); // no padding on the way out
  EXPECT_EQ(layout.is_bigendian, 0);
  const std::vector<uint8_t> expected_ros = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
  EXPECT_EQ(data, expected_ros);
}

TEST(Image, Bgr8IsReorderedToRgbAndBack)
{
  vtkNew<vtkImageData> image;
  std::string error;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "bgr8", 8), kColour2x2, image, &error)) << error;
  // ROS top-left pixel stored B=1 G=2 R=3 -> VTK RGB (3, 2, 1).
  EXPECT_EQ(vtk_pixel(image, 0, 1, 0), 3);
  EXPECT_EQ(vtk_pixel(image, 0, 1, 1), 2);
  EXPECT_EQ(vtk_pixel(image, 0, 1, 2), 1);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 0), 12);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 1), 11);
  EXPECT_EQ(vtk_pixel(image, 1, 0, 2), 10);

  ImageLayout layout;
  std::vector<uint8_t> data;
  ASSERT_TRUE(vtk_to_image(image, "bgr8", &layout, &data, &error)) << error;
  EXPECT_EQ(layout.encoding, "bgr8");
  const std::vector<uint8_t> expected_ros = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
  EXPECT_EQ(data, expected_ros);

  // The same VTK image published as rgb8 carries the real colour order.
  ASSERT_TRUE(vtk_to_image(image, "rgb8", &layout, &data, &error)) << error;
  const std::vector<uint8_t> expected_rgb = { 3, 2, 1, 6, 5, 4, 9, 8, 7, 12, 11, 10 };
  EXPECT_EQ(data, expected_rgb);
}

TEST(Image, Bgra8KeepsAlphaInPlace)
{
  // 1 x 1, B=10 G=20 R=30 A=40.
  const std::vector<uint8_t> data = { 10, 20, 30, 40 };
  vtkNew<vtkImageData> image;
  ASSERT_TRUE(image_to_vtk(layout_of(1, 1, "bgra8", 4), data, image, nullptr));
  EXPECT_EQ(vtk_pixel(image, 0, 0, 0), 30);
  EXPECT_EQ(vtk_pixel(image, 0, 0, 1), 20);
  EXPECT_EQ(vtk_pixel(image, 0, 0, 2), 10);
  EXPECT_EQ(vtk_pixel(image, 0, 0, 3), 40);
  ImageLayout layout;
  std::vector<uint8_t> out;
  ASSERT_TRUE(vtk_to_image(image, "", &layout, &out, nullptr));
  EXPECT_EQ(layout.encoding, "rgba8");
  EXPECT_EQ(out, (std::vector<uint8_t>{ 30, 20, 10, 40 }));
}

TEST(Image, Mono16LittleEndianWithPadding)
{
  // 3 x 2, step 8 (6 bytes of pixels + 2 padding). Values little-endian.
  // top row: 0x0201=513, 0x0403=1027, 0xFFFF=65535; bottom row: 1, 256, 0
  const std::vector<uint8_t> data = { 0x01, 0x02, 0x03, 0x04, 0xFF, 0xFF, 0xAA, 0xAA, 0x01, 0x00,
    0x00, 0x01, 0x00, 0x00, 0xAA, 0xAA };
  vtkNew<vtkImageData> image;
  std::string error;
  ASSERT_TRUE(image_to_vtk(layout_of(3, 2, "mono16", 8), data, image, &error)) << error;
  EXPECT_EQ(image->GetScalarType(), VTK_UNSIGNED_SHORT);
  EXPECT_EQ(vtk_pixel(image, 0, 1), 513);
  EXPECT_EQ(vtk_pixel(image, 1, 1), 1027);
  EXPECT_EQ(vtk_pixel(image, 2, 1), 65535);
  EXPECT_EQ(vtk_pixel(image, 0, 0), 1);
  EXPECT_EQ(vtk_pixel(image, 1, 0), 256);
  EXPECT_EQ(vtk_pixel(image, 2, 0), 0);

  ImageLayout layout;
  std::vector<uint8_t> out;
  ASSERT_TRUE(vtk_to_image(image, "", &layout, &out, &error)) << error;
  EXPECT_EQ(layout.encoding, "mono16");
  EXPECT_EQ(layout.step, 6u);
  const std::vector<uint8_t> expected = { 0x01, 0x02, 0x03, 0x04, 0xFF, 0xFF, 0x01, 0x00, 0x00,
    0x01, 0x00, 0x00 };
  EXPECT_EQ(out, expected);
}

TEST(Image, BigEndian16BitIsByteSwapped)
{
  // 2 x 1 big-endian: 0x0102 = 258, 0xFF00 = 65280.
  const std::vector<uint8_t> data = { 0x01, 0x02, 0xFF, 0x00 };
  vtkNew<vtkImageData> image;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 1, "16UC1", 4, 1), data, image, nullptr));
  EXPECT_EQ(vtk_pixel(image, 0, 0), 258);
  EXPECT_EQ(vtk_pixel(image, 1, 0), 65280);

  // Signed: 0xFFFE big-endian = -2.
  const std::vector<uint8_t> signed_data = { 0xFF, 0xFE };
  ASSERT_TRUE(image_to_vtk(layout_of(1, 1, "16SC1", 2, 1), signed_data, image, nullptr));
  EXPECT_EQ(image->GetScalarType(), VTK_SHORT);
  EXPECT_EQ(vtk_pixel(image, 0, 0), -2);
}

TEST(Image, Float32WithPaddingAndBigEndian)
{
  // 2 x 2 32FC1, step 12 (8 bytes + 4 padding). top: 1.5, -2.25; bottom: 3.0, 1e6.
  const float values[4] = { 1.5f, -2.25f, 3.0f, 1e6f };
  std::vector<uint8_t> data(24, 0xCC);
  std::memcpy(data.data(), &values[0], 8);
  std::memcpy(data.data() + 12, &values[2], 8);
  vtkNew<vtkImageData> image;
  std::string error;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "32FC1", 12), data, image, &error)) << error;
  EXPECT_EQ(image->GetScalarType(), VTK_FLOAT);
  EXPECT_EQ(vtk_pixel(image, 0, 1), 1.5);
  EXPECT_EQ(vtk_pixel(image, 1, 1), -2.25);
  EXPECT_EQ(vtk_pixel(image, 0, 0), 3.0);
  EXPECT_EQ(vtk_pixel(image, 1, 0), 1e6);

  ImageLayout layout;
  std::vector<uint8_t> out;
  ASSERT_TRUE(vtk_to_image(image, "", &layout, &out, &error)) << error;
  EXPECT_EQ(layout.encoding, "32FC1");
  ASSERT_EQ(out.size(), 16u);
  float back[4];
  std::memcpy(back, out.data(), 16);
  EXPECT_EQ(back[0], 1.5f);
  EXPECT_EQ(back[1], -2.25f);
  EXPECT_EQ(back[2], 3.0f);
  EXPECT_EQ(back[3], 1e6f);

  // 1.5f is 0x3FC00000: big-endian bytes 3F C0 00 00.
  const std::vector<uint8_t> big = { 0x3F, 0xC0, 0x00, 0x00 };
  ASSERT_TRUE(image_to_vtk(layout_of(1, 1, "32FC1", 4, 1), big, image, &error)) << error;
  EXPECT_EQ(vtk_pixel(image, 0, 0), 1.5);
}

TEST(Image, OtherEncodingsMapToTheirScalarTypes)
{
  struct Case
  {
    const char* encoding;
    int type;
    int components;
  };
  const Case cases[] = { { "mono8", VTK_UNSIGNED_CHAR, 1 }, { "8UC1", VTK_UNSIGNED_CHAR, 1 },
    { "8UC3", VTK_UNSIGNED_CHAR, 3 }, { "8UC4", VTK_UNSIGNED_CHAR, 4 },
    { "rgba8", VTK_UNSIGNED_CHAR, 4 }, { "64FC1", VTK_DOUBLE, 1 },
    { "16UC1", VTK_UNSIGNED_SHORT, 1 } };
  for (const Case& c : cases)
  {
    ImageLayout layout = layout_of(2, 1, c.encoding, 0);
    const int pixel_bytes = c.components *
      (c.type == VTK_DOUBLE              ? 8
          : c.type == VTK_UNSIGNED_SHORT ? 2
                                         : 1);
    layout.step = static_cast<uint32_t>(2 * pixel_bytes);
    std::vector<uint8_t> data(layout.step, 0);
    vtkNew<vtkImageData> image;
    std::string error;
    ASSERT_TRUE(image_to_vtk(layout, data, image, &error)) << c.encoding << ": " << error;
    EXPECT_EQ(image->GetScalarType(), c.type) << c.encoding;
    EXPECT_EQ(image->GetNumberOfScalarComponents(), c.components) << c.encoding;
  }
}

TEST(Image, Float64RoundTrip)
{
  const double values[2] = { -0.125, 42.0 };
  std::vector<uint8_t> data(16);
  std::memcpy(data.data(), values, 16);
  vtkNew<vtkImageData> image;
  ASSERT_TRUE(image_to_vtk(layout_of(1, 2, "64FC1", 8), data, image, nullptr));
  EXPECT_EQ(vtk_pixel(image, 0, 1), -0.125); // top row
  EXPECT_EQ(vtk_pixel(image, 0, 0), 42.0);
  ImageLayout layout;
  std::vector<uint8_t> out;
  ASSERT_TRUE(vtk_to_image(image, "", &layout, &out, nullptr));
  EXPECT_EQ(layout.encoding, "64FC1");
  EXPECT_EQ(out, data);
}

TEST(Image, ScalarArrayIsReusedUnlessSharedElsewhere)
{
  vtkNew<vtkImageData> image;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "rgb8", 8), kColour2x2, image, nullptr));
  vtkDataArray* first = image->GetPointData()->GetScalars();
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "bgr8", 8), kColour2x2, image, nullptr));
  EXPECT_EQ(image->GetPointData()->GetScalars(), first); // same size and type: written in place

  vtkNew<vtkImageData> kept_frame;
  kept_frame->ShallowCopy(image); // someone keeps this frame
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "rgb8", 8), kColour2x2, image, nullptr));
  EXPECT_NE(image->GetPointData()->GetScalars(), first);
  // The kept frame still shows the bgr8 conversion: top-left (3, 2, 1).
  EXPECT_EQ(kept_frame->GetScalarComponentAsDouble(0, 1, 0, 0), 3);
  EXPECT_EQ(image->GetScalarComponentAsDouble(0, 1, 0, 0), 1);
}

TEST(Image, BadInputIsRejectedAndImageUntouched)
{
  vtkNew<vtkImageData> image;
  ASSERT_TRUE(image_to_vtk(layout_of(2, 2, "rgb8", 8), kColour2x2, image, nullptr));
  vtkDataArray* before = image->GetPointData()->GetScalars();
  std::string error;

  EXPECT_FALSE(image_to_vtk(layout_of(2, 2, "rgb8", 5), kColour2x2, image, &error));
  EXPECT_NE(error.find("step 5 is smaller than width 2 x 3 bytes per pixel"), std::string::npos)
    << error;

  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(2, 3, "rgb8", 8), kColour2x2, image, &error));
  EXPECT_NE(error.find("data has 16 bytes but step 8 x height 3 needs 24"), std::string::npos)
    << error;

  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(2, 2, "yuv422", 8), kColour2x2, image, &error));
  EXPECT_NE(error.find("unsupported encoding 'yuv422'"), std::string::npos) << error;
  EXPECT_NE(error.find("mono8"), std::string::npos) << error;
  EXPECT_NE(error.find("bgra8"), std::string::npos) << error;
  EXPECT_NE(error.find("32FC1"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(0, 2, "rgb8", 8), kColour2x2, image, &error));
  EXPECT_NE(error.find("no pixels"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(2, 2, "rgb8", 8), nullptr, 0, image, &error));
  EXPECT_FALSE(error.empty());

  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(2, 2, "rgb8", 8), kColour2x2, nullptr, &error));
  EXPECT_NE(error.find("null"), std::string::npos) << error;

  // A step so large that step * height overflows 32 bits must still be caught.
  error.clear();
  EXPECT_FALSE(image_to_vtk(layout_of(2, 4, "rgb8", 0xFFFFFFFFu), kColour2x2, image, &error));
  EXPECT_NE(error.find("needs"), std::string::npos) << error;

  EXPECT_EQ(image->GetPointData()->GetScalars(), before);
  EXPECT_EQ(image->GetScalarComponentAsDouble(0, 1, 0, 0), 1);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 2);
}

TEST(Image, VtkToRosRejectsWhatRosCannotCarry)
{
  std::string error;
  ImageLayout layout;
  std::vector<uint8_t> data;

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(2, 2, 2);
  volume->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  EXPECT_FALSE(vtk_to_image(volume, "", &layout, &data, &error));
  EXPECT_NE(error.find("2-D"), std::string::npos) << error;

  vtkNew<vtkImageData> floats;
  floats->SetDimensions(2, 2, 1);
  floats->AllocateScalars(VTK_FLOAT, 1);
  error.clear();
  EXPECT_FALSE(vtk_to_image(floats, "rgb8", &layout, &data, &error));
  EXPECT_NE(error.find("encoding 'rgb8' needs"), std::string::npos) << error;

  vtkNew<vtkImageData> two_floats;
  two_floats->SetDimensions(2, 2, 1);
  two_floats->AllocateScalars(VTK_FLOAT, 2);
  error.clear();
  EXPECT_FALSE(vtk_to_image(two_floats, "", &layout, &data, &error));
  EXPECT_NE(error.find("no ROS encoding for float scalars with 2 components"), std::string::npos)
    << error;

  vtkNew<vtkImageData> empty;
  error.clear();
  EXPECT_FALSE(vtk_to_image(empty, "", &layout, &data, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_TRUE(data.empty()); // outputs untouched
}

TEST(Image, SupportedEncodingsListsTheRequiredOnes)
{
  const std::vector<std::string> names = supported_image_encodings();
  for (const char* required : { "mono8", "8UC1", "mono16", "16UC1", "16SC1", "32FC1", "64FC1",
         "rgb8", "bgr8", "rgba8", "bgra8", "8UC3", "8UC4" })
  {
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  }
}
