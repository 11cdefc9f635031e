// ros2vtk — PNG or JPEG bytes (sensor_msgs/CompressedImage's data) <-> vtkImageData, decoded and
// encoded by VTK's own readers and writers (vtkPNGReader / vtkJPEGReader from memory,
// vtkPNGWriter / vtkJPEGWriter to memory).
//
// Rows follow VTK's convention as for raw images: the file's top row is VTK's highest y.
#ifndef ros2vtk_convert_CompressedImage_hpp
#define ros2vtk_convert_CompressedImage_hpp

#include <cstdint>
#include <string>
#include <vector>

class vtkImageData;

namespace ros2vtk {
namespace convert {

/// ROS -> VTK: the codec is told by the bytes (PNG or JPEG signature), not by `format` (which
/// only appears in errors: "jpeg", "bgr8; jpeg compressed bgr8", ... name the same bytes).
/// Data that is neither, or that the codec cannot decode, is refused with the reason; `image`
/// is then untouched.
bool compressed_to_image(const std::string& format, const std::vector<uint8_t>& data,
  vtkImageData* image, std::string* error);

/// VTK -> ROS: `codec` is "png" (also ""), or "jpeg" / "jpg". PNG takes unsigned char or
/// unsigned short scalars with 1 to 4 components, JPEG unsigned char with 1 or 3; anything else
/// is refused. `format` is set to the codec's name ("png" or "jpeg").
bool image_to_compressed(vtkImageData* image, const std::string& codec, std::string* format,
  std::vector<uint8_t>* data, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
