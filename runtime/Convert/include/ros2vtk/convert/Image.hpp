// ros2vtk — sensor_msgs/Image fields <-> vtkImageData.
//
// Pixel layout on the VTK side:
//   * dimensions (width, height, 1); one point-data scalar array "ImageScalars" whose scalar type
//     and number of components come from the encoding (e.g. rgb8 -> unsigned char x 3,
//     mono16 -> unsigned short x 1, 32FC1 -> float x 1).
//   * colour images are always RGB(A) in VTK: bgr8/bgra8 (and bgr16/bgra16) are reordered on
//     the way in and back on the way out, so a VTK view shows the right colours.
//   * ROS row 0 is the TOP row of the picture; VTK's y axis points up, so VTK row 0 is the
//     bottom row. Rows are flipped in both directions: ROS row r is VTK row (height - 1 - r).
//     A vtkImageViewer / slice view of the result is upright, not mirrored.
//   * pixel values are in host byte order: big-endian 16/32/64-bit data is byte-swapped on the
//     way in; the way out writes host order and sets is_bigendian to match.
//   * origin, spacing and direction of the vtkImageData are not touched (the message has none).
//
// This is a hot path (camera streams): rows are copied with memcpy when no reordering or byte
// swapping is needed, and the existing scalar array is reused when it has the right type and
// size and nobody else holds it.
#ifndef ros2vtk_convert_Image_hpp
#define ros2vtk_convert_Image_hpp

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

class vtkImageData;

namespace ros2vtk {
namespace convert {

/// sensor_msgs/Image minus header and data.
struct ImageLayout
{
  uint32_t height = 0;
  uint32_t width = 0;
  std::string encoding;     ///< sensor_msgs image_encodings name, e.g. "rgb8", "32FC1"
  uint8_t is_bigendian = 0; ///< byte order of multi-byte channels in data
  uint32_t step = 0;        ///< bytes per row in data, >= width * bytes per pixel (padding allowed)
};

/// The encodings understood in both directions, in a fixed order (for messages and docs).
std::vector<std::string> supported_image_encodings();

/// ROS -> VTK. Fails (image untouched) on: unknown encoding (message lists the supported ones),
/// zero width or height, step < width * bytes per pixel, step * height > data_size, null image.
bool image_to_vtk(const ImageLayout& layout, const uint8_t* data, size_t data_size,
  vtkImageData* image, std::string* error);

/// Same, for the message's byte vector.
bool image_to_vtk(const ImageLayout& layout, const std::vector<uint8_t>& data, vtkImageData* image,
  std::string* error);

/// VTK -> ROS. `encoding` empty: chosen from the scalar type and number of components
/// (unsigned char 1/3/4 -> mono8/rgb8/rgba8, unsigned short 1/3/4 -> mono16/rgb16/rgba16,
/// short 1 -> 16SC1, int 1 -> 32SC1, float 1 -> 32FC1, double 1 -> 64FC1). A given encoding must
/// match the image's scalar type and components (bgr8 for an RGB unsigned char image is fine:
/// channels are reordered). The image must be 2-D (one slice). Rows are written without padding
/// (step = width * bytes per pixel). On failure the outputs are untouched.
bool vtk_to_image(vtkImageData* image, const std::string& encoding, ImageLayout* layout,
  std::vector<uint8_t>* data, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
