// ros2vtk tests — helpers shared by the robot-loading tests: where the data is, and an
// independent binary-STL reader so expected bounds never come from the code under test.
#ifndef ros2vtk_tests_robot_test_support_hpp
#define ros2vtk_tests_robot_test_support_hpp

#include "chain_urdf.hpp"

#include <vtkPolyData.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace ros2vtk_test {

/// Repository root (set by tests/robot/CMakeLists.txt).
inline std::string source_dir()
{
  return ROS2VTK_TEST_SOURCE_DIR;
}
inline std::string data_dir()
{
  return source_dir() + "/tests/data/robots";
}
inline std::string robots_dir()
{
  return source_dir() + "/examples/robots";
}
inline std::string surgical_arm_urdf()
{
  return robots_dir() + "/surgical_arm/urdf/surgical_arm.urdf";
}

/// Axis-aligned bounds: xmin, xmax, ymin, ymax, zmin, zmax (VTK's order).
using Bounds = std::array<double, 6>;

/// Bounds of a binary STL read byte by byte here (80-byte header, uint32 count, 50-byte
/// records of normal + 3 vertices as little-endian float32), times a per-axis scale.
inline Bounds binary_stl_bounds(
  const std::string& path, const std::array<double, 3>& scale = { { 1, 1, 1 } })
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open " + path);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 84)
    throw std::runtime_error("too short for a binary STL: " + path);
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() < 84 + 50ull * count)
    throw std::runtime_error("truncated binary STL: " + path);
  Bounds bounds{ { std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), -std::numeric_limits<double>::max() } };
  for (std::uint32_t t = 0; t < count; ++t)
  {
    const char* record = bytes.data() + 84 + 50ull * t;
    for (int v = 0; v < 3; ++v)
    {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * v, 12);
      for (int axis = 0; axis < 3; ++axis)
      {
        const double value = static_cast<double>(xyz[axis]) * scale[static_cast<size_t>(axis)];
        bounds[2 * axis] = std::min(bounds[2 * axis], value);
        bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], value);
      }
    }
  }
  return bounds;
}

/// Writes a binary STL of one triangle (0,0,0), (size,0,0), (0,size,0); creates its folders.
inline void write_triangle_stl(const std::string& path, float size = 0.05f)
{
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path, std::ios::binary);
  const char header[80] = "ros2vtk test triangle";
  out.write(header, 80);
  const std::uint32_t count = 1;
  out.write(reinterpret_cast<const char*>(&count), 4);
  const float record[12] = { 0, 0, 1, 0, 0, 0, size, 0, 0, 0, size, 0 };
  out.write(reinterpret_cast<const char*>(record), sizeof(record));
  const std::uint16_t attributes = 0;
  out.write(reinterpret_cast<const char*>(&attributes), 2);
}

inline Bounds bounds_of(vtkPolyData* polydata)
{
  Bounds bounds{};
  polydata->GetBounds(bounds.data());
  return bounds;
}

} // namespace ros2vtk_test

#endif
