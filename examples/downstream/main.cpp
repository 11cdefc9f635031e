// The downstream program: build a needle_guide_msgs/msg/NeedleGuide, put it on the wire (CDR,
// as ROS 2 does) and read it back, then convert its pose with the generated converter into a
// vtkMatrix4x4 in millimetres and back.
#include "needle_guideConvert.hpp"  // generated: ros2vtk::nodes::ROS2ToVTK / VTKToROS2

#include <ros2vtk/needle_guide_msgs/msg/needle_guide.hpp>  // generated message type + CDR
#include <ros2vtk/wire/CdrReader.hpp>
#include <ros2vtk/wire/CdrWriter.hpp>

#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <cstdint>
#include <cstdio>
#include <vector>

extern "C" void ros2vtk_register_needle_guide_nodes();

int main()
{
  ros2vtk::needle_guide_msgs::msg::NeedleGuide guide;
  guide.pose.position.x = 0.1;    // metres
  guide.pose.position.y = -0.02;
  guide.pose.position.z = 0.035;
  guide.pose.orientation.w = 1.0;
  guide.depth = 0.045;

  // Serialize and deserialize (CDR, little-endian, with the 4-byte encapsulation header).
  std::vector<uint8_t> bytes;
  ros2vtk::wire::CdrWriter writer(bytes);
  cdr_serialize(guide, writer);
  ros2vtk::needle_guide_msgs::msg::NeedleGuide decoded;
  ros2vtk::wire::CdrReader reader(bytes.data(), bytes.size());
  if (!cdr_deserialize(decoded, reader) || !reader.ok() || !(decoded == guide))
  {
    std::fprintf(stderr, "round trip failed: %s\n", reader.error().c_str());
    return 1;
  }
  std::printf("serialized %zu bytes, round trip ok\n", bytes.size());

  // Convert with the generated converter: metres -> millimetres.
  vtkNew<vtkMatrix4x4> matrix;
  if (!ros2vtk::nodes::ROS2ToVTK(decoded, matrix))
  {
    std::fprintf(stderr, "ROS2ToVTK failed\n");
    return 1;
  }
  std::printf("translation_mm %.1f %.1f %.1f depth_m %.3f\n", matrix->GetElement(0, 3),
              matrix->GetElement(1, 3), matrix->GetElement(2, 3), decoded.depth);

  ros2vtk::needle_guide_msgs::msg::NeedleGuide back;
  back.depth = decoded.depth;
  if (!ros2vtk::nodes::VTKToROS2(matrix, back) || !(back == guide))
  {
    std::fprintf(stderr, "VTKToROS2 did not give the message back\n");
    return 1;
  }
  ros2vtk_register_needle_guide_nodes();
  std::printf("NeedleGuide OK\n");
  return 0;
}
