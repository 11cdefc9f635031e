// Prints how long the hot conversions take on this machine (median of many runs). Not a test:
// timings depend on the machine; benchmarks are reported (docs/benchmarks.md), never asserted.
#include "ros2vtk/convert/Image.hpp"
#include "ros2vtk/convert/PointCloud2.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace ros2vtk::convert;

namespace {

double median_ms(const std::function<bool()>& run, int repetitions)
{
  std::vector<double> times;
  for (int i = 0; i < repetitions; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    if (!run())
    {
      std::fprintf(stderr, "conversion failed\n");
      return -1.0;
    }
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

} // namespace

int main()
{
  const int repetitions = 200;
  for (const char* encoding : { "rgb8", "bgr8", "mono16", "32FC1" })
  {
    ImageLayout layout;
    layout.width = 640;
    layout.height = 480;
    layout.encoding = encoding;
    const uint32_t pixel_bytes = std::string(encoding) == "mono16" ? 2
      : std::string(encoding) == "32FC1"                           ? 4
                                                                   : 3;
    layout.step = 640 * pixel_bytes;
    std::vector<uint8_t> data(static_cast<size_t>(layout.step) * 480, 0x5A);
    vtkNew<vtkImageData> image;
    std::string error;
    const double in_ms =
      median_ms([&] { return image_to_vtk(layout, data, image, &error); }, repetitions);
    ImageLayout out_layout;
    std::vector<uint8_t> out;
    const double out_ms = median_ms(
      [&] { return vtk_to_image(image, encoding, &out_layout, &out, &error); }, repetitions);
    std::printf(
      "image 640x480 %-6s  ROS->VTK %.3f ms   VTK->ROS %.3f ms\n", encoding, in_ms, out_ms);
  }

  PointCloud2Layout layout;
  layout.height = 1;
  layout.width = 100000;
  layout.fields = { { "x", 0, point_field::kFloat32, 1 }, { "y", 4, point_field::kFloat32, 1 },
    { "z", 8, point_field::kFloat32, 1 }, { "intensity", 16, point_field::kFloat32, 1 } };
  layout.point_step = 32;
  layout.row_step = layout.point_step * layout.width;
  std::vector<uint8_t> data(layout.row_step);
  for (uint32_t i = 0; i < layout.width; ++i)
  {
    const float values[4] = { 0.001f * i, 0.5f, -0.25f, 1.0f };
    std::memcpy(data.data() + i * 32, values, 12);
    std::memcpy(data.data() + i * 32 + 16, &values[3], 4);
  }
  vtkNew<vtkPolyData> poly;
  std::string error;
  const double keep_ms = median_ms(
    [&] {
      return point_cloud2_to_poly_data(layout, data, 1000.0, NonFinitePoints::Keep, poly, &error);
    },
    50);
  const double drop_ms = median_ms(
    [&] {
      return point_cloud2_to_poly_data(layout, data, 1000.0, NonFinitePoints::Drop, poly, &error);
    },
    50);
  PointCloud2Layout out_layout;
  std::vector<uint8_t> out;
  const double out_ms = median_ms(
    [&] { return poly_data_to_point_cloud2(poly, 1000.0, &out_layout, &out, &error); }, 50);
  std::printf(
    "PointCloud2 100k xyz+intensity  ROS->VTK keep %.3f ms, drop-NaN %.3f ms   VTK->ROS %.3f ms\n",
    keep_ms, drop_ms, out_ms);
  return 0;
}
