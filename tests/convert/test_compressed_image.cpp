// PNG / JPEG bytes <-> vtkImageData through VTK's codecs: round trips, and malformed data refused
// with a reason (no crash, output untouched).
#include "ros2vtk/convert/CompressedImage.hpp"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

using namespace ros2vtk::convert;

namespace {

void fill_rgb(vtkImageData* image)
{
  image->SetDimensions(3, 2, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (vtkIdType i = 0; i < 6; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image->GetPointData()->GetScalars()->SetComponent(i, c, 40 * i + c);
    }
  }
}

} // namespace

TEST(CompressedImage, PngRoundTripIsExact)
{
  vtkNew<vtkImageData> image;
  fill_rgb(image);
  std::string format;
  std::vector<uint8_t> data;
  std::string error;
  ASSERT_TRUE(image_to_compressed(image, "", &format, &data, &error)) << error;
  EXPECT_EQ(format, "png");
  ASSERT_GT(data.size(), 8u);
  EXPECT_EQ(data[1], 'P');
  vtkNew<vtkImageData> back;
  ASSERT_TRUE(compressed_to_image(format, data, back, &error)) << error;
  EXPECT_EQ(back->GetDimensions()[0], 3);
  EXPECT_EQ(back->GetDimensions()[1], 2);
  vtkDataArray* scalars = back->GetPointData()->GetScalars();
  ASSERT_EQ(scalars->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < 6; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(scalars->GetComponent(i, c), 40 * i + c) << i << " " << c;
    }
  }
}

TEST(CompressedImage, JpegRoundTripKeepsSizeAndRoughValues)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(16, 8, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  image->GetPointData()->GetScalars()->Fill(128);
  std::string format;
  std::vector<uint8_t> data;
  std::string error;
  ASSERT_TRUE(image_to_compressed(image, "jpeg", &format, &data, &error)) << error;
  EXPECT_EQ(format, "jpeg");
  EXPECT_EQ(data[0], 0xff);
  EXPECT_EQ(data[1], 0xd8);
  vtkNew<vtkImageData> back;
  ASSERT_TRUE(compressed_to_image(format, data, back, &error)) << error;
  EXPECT_EQ(back->GetDimensions()[0], 16);
  EXPECT_EQ(back->GetDimensions()[1], 8);
  EXPECT_NEAR(back->GetPointData()->GetScalars()->GetComponent(5, 0), 128.0, 2.0);
}

TEST(CompressedImage, MalformedDataIsRefusedWithAReason)
{
  vtkNew<vtkImageData> image;
  fill_rgb(image);
  std::string format;
  std::vector<uint8_t> png;
  std::string error;
  ASSERT_TRUE(image_to_compressed(image, "png", &format, &png, &error)) << error;

  vtkNew<vtkImageData> out;
  out->SetDimensions(7, 7, 1);
  EXPECT_FALSE(compressed_to_image("jpeg", { 1, 2, 3, 4 }, out, &error));
  EXPECT_NE(error.find("neither PNG nor JPEG"), std::string::npos) << error;
  EXPECT_FALSE(compressed_to_image("png", {}, out, &error));

  std::vector<uint8_t> truncated(png.begin(), png.begin() + 20);
  EXPECT_FALSE(compressed_to_image("png", truncated, out, &error));
  EXPECT_NE(error.find("cannot decode"), std::string::npos) << error;

  const std::vector<uint8_t> jpeg_head = { 0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F', 0 };
  EXPECT_FALSE(compressed_to_image("jpeg", jpeg_head, out, &error));
  EXPECT_NE(error.find("cannot decode"), std::string::npos) << error;
  EXPECT_NE(error.find("a segment of 16 bytes at byte 4 runs past the end of the data (11 bytes)"),
    std::string::npos)
    << error; // VTK's memory source would read past the buffer
  EXPECT_EQ(out->GetDimensions()[0], 7) << "untouched on failure";
  // A real JPEG cut inside its header, and one whose scan comes before any frame header.
  std::vector<uint8_t> jpeg;
  ASSERT_TRUE(image_to_compressed(image, "jpeg", &format, &jpeg, &error)) << error;
  EXPECT_FALSE(compressed_to_image(
    "jpeg", std::vector<uint8_t>(jpeg.begin(), jpeg.begin() + 30), out, &error));
  EXPECT_NE(error.find("runs past the end of the data (30 bytes)"), std::string::npos) << error;
  const std::vector<uint8_t> scan_first = { 0xff, 0xd8, 0xff, 0xda, 0, 2, 0 };
  EXPECT_FALSE(compressed_to_image("jpeg", scan_first, out, &error));
  EXPECT_NE(error.find("a scan before any frame header"), std::string::npos) << error;

  vtkNew<vtkImageData> doubles;
  doubles->SetDimensions(2, 2, 1);
  doubles->AllocateScalars(VTK_DOUBLE, 1);
  EXPECT_FALSE(image_to_compressed(doubles, "png", &format, &png, &error));
  EXPECT_NE(error.find("png takes unsigned char or unsigned short"), std::string::npos) << error;
  EXPECT_FALSE(image_to_compressed(image, "tiff", &format, &png, &error));
}

TEST(CompressedImage, MutatedPngAndJpegBytesNeverCrash)
{
  // 1500 mutations (flipped bytes, truncations) of a valid PNG and JPEG: each one is decoded or
  // refused with a reason; libpng errors would crash the process (VTK 9.1's reader sets no setjmp).
  vtkNew<vtkImageData> image;
  image->SetDimensions(16, 8, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (vtkIdType i = 0; i < 16 * 8; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image->GetPointData()->GetScalars()->SetComponent(i, c, (7 * i + 31 * c) % 256);
    }
  }
  uint32_t state = 12345;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  for (const char* codec : { "png", "jpeg" })
  {
    std::string format;
    std::vector<uint8_t> good;
    std::string error;
    ASSERT_TRUE(image_to_compressed(image, codec, &format, &good, &error)) << error;
    int refused = 0;
    for (int round = 0; round < 750; ++round)
    {
      std::vector<uint8_t> bad = good;
      if (round % 3 == 0)
      {
        bad.resize(next() % bad.size());
      }
      else
      {
        for (int k = 0; k < 1 + round % 4; ++k)
        {
          bad[3 + next() % (bad.size() - 3)] ^= static_cast<uint8_t>(1 + next() % 255);
        }
      }
      vtkNew<vtkImageData> out;
      error.clear();
      if (!compressed_to_image(format, bad, out, &error))
      {
        ++refused;
        EXPECT_FALSE(error.empty());
      }
    }
    EXPECT_GT(refused, 0) << codec;
  }
}
