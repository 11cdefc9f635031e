// ros2vtk — OpenIGTLink message content ↔ plain values, through Debian's OpenIGTLink 1.11 message
// classes (their Pack/Unpack do the byte order and layout; Frame.hpp does the framing around):
// TRANSFORM, POSITION, POINT, STRING, IMAGE, POLYDATA, TDATA.
// Values are what the protocol carries: millimetres, row-major 4x4 matrices, image matrices
// with the translation at the volume centre. No VTK here; the connector node converts.
#ifndef ros2vtk_igtl_Codec_hpp
#define ros2vtk_igtl_Codec_hpp

#include "ros2vtk/igtl/Frame.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ros2vtk {
namespace igtl {

using Matrix = std::array<double, 16>; ///< row-major 4x4

struct PointItem
{
  std::string name;
  std::string group;
  std::array<std::uint8_t, 4> rgba{ { 255, 255, 255, 255 } };
  std::array<float, 3> position{ { 0.f, 0.f, 0.f } };
  float radius = 0.f;
};

/// Scalar types as the IMAGE header numbers them (image.md): only those Slicer reads safely.
enum class ScalarType : int
{
  Int8 = 2,
  UInt8 = 3,
  Int16 = 4,
  UInt16 = 5,
  Float32 = 10,
  Float64 = 11
};

struct Image
{
  std::array<int, 3> size{ { 0, 0, 0 } };            ///< i, j, k
  std::array<float, 3> spacing{ { 1.f, 1.f, 1.f } }; ///< mm
  Matrix ijk_to_world{}; ///< unit direction columns; translation = first voxel (corner)
  int components = 1;
  ScalarType scalar = ScalarType::UInt8;
  std::vector<std::uint8_t> data; ///< i fastest, native byte order
};

struct Mesh
{
  std::vector<float> points; ///< x, y, z, … (mm)
  std::vector<std::vector<std::uint32_t>> polygons;
  std::vector<std::vector<std::uint32_t>> lines;
  std::vector<std::vector<std::uint32_t>> vertices;
};

/// One TDATA element (tdata.md): an instrument's name (≤ 20 bytes) and its 6D pose (mm).
struct TrackingItem
{
  std::string name;
  Matrix matrix{};
};

std::size_t scalar_size(ScalarType type);

// Encoders: a complete frame (header v1) ready for encode_frame (after adding metadata, if any).
Frame encode_transform(const std::string& device, const Matrix& matrix, std::uint64_t timestamp);
Frame encode_string(const std::string& device, const std::string& text, std::uint64_t timestamp);
Frame encode_points(
  const std::string& device, const std::vector<PointItem>& points, std::uint64_t timestamp);
Frame encode_image(const std::string& device, const Image& image, std::uint64_t timestamp);
Frame encode_polydata(const std::string& device, const Mesh& mesh, std::uint64_t timestamp);
/// TDATA: every element as a 6D instrument (Slicer makes one linear transform per name).
Frame encode_tracking_data(
  const std::string& device, const std::vector<TrackingItem>& items, std::uint64_t timestamp);

// Decoders: false with `error` when the content is not a valid body of the frame's type.
bool decode_transform(const Frame& frame, Matrix& matrix, std::string& error);
/// POSITION: position (mm) + quaternion (x, y, z, w) as a matrix.
bool decode_position(const Frame& frame, Matrix& matrix, std::string& error);
bool decode_string(const Frame& frame, std::string& text, std::string& error);
bool decode_points(const Frame& frame, std::vector<PointItem>& points, std::string& error);
bool decode_image(const Frame& frame, Image& image, std::string& error);
bool decode_tracking_data(const Frame& frame, std::vector<TrackingItem>& items, std::string& error);

} // namespace igtl
} // namespace ros2vtk

#endif
