// The downstream program: build a needle_guide_msgs/msg/NeedleGuide, put it on the wire (CDR,
// as ROS 2 does) and read it back, then convert its pose with the generated converter into a
// vtkMatrix4x4 in millimetres and back. Then the installed runtime libraries: where the guide
// is in the world (ros2vtk::Tf2), its topic's DDS name (ros2vtk::Wire), and a small guide holder
// robot: forward kinematics (ros2vtk::RobotModel) and its visuals (ros2vtk::RobotLoader), and its
// pose as an OpenIGTLink TRANSFORM (ros2vtk::IGTL).
#include "needle_guideConvert.hpp" // generated: ros2vtk::nodes::ROS2ToVTK / VTKToROS2

#include <ros2vtk/needle_guide_msgs/msg/needle_guide.hpp> // generated message type + CDR
#include <ros2vtk/igtl/Codec.hpp>
#include <ros2vtk/robot/KinematicTree.hpp>
#include <ros2vtk/robot/RobotLoader.hpp>
#include <ros2vtk/tf2/BufferCore.hpp>
#include <ros2vtk/wire/CdrReader.hpp>
#include <ros2vtk/wire/CdrWriter.hpp>
#include <ros2vtk/wire/Names.hpp>

#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "needle_guideRegister.hpp" // ros2vtk_register_needle_guide_nodes()

int main()
{
  ros2vtk::needle_guide_msgs::msg::NeedleGuide guide;
  guide.pose.position.x = 0.1; // metres
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

  // tf2: world -> base 1 m along x, base -> guide the guide's pose; the guide in the world.
  ros2vtk::tf2::BufferCore buffer;
  ros2vtk::tf2::TransformStamped base;
  base.frame_id = "world";
  base.child_frame_id = "base";
  base.transform.translation = Eigen::Vector3d(1.0, 0.0, 0.0);
  ros2vtk::tf2::TransformStamped tool;
  tool.frame_id = "base";
  tool.child_frame_id = "guide";
  tool.transform.translation =
    Eigen::Vector3d(guide.pose.position.x, guide.pose.position.y, guide.pose.position.z);
  std::string error;
  if (!buffer.set_transform(base, "needle_guide_demo", true, &error) ||
    !buffer.set_transform(tool, "needle_guide_demo", true, &error))
  {
    std::fprintf(stderr, "set_transform failed: %s\n", error.c_str());
    return 1;
  }
  const ros2vtk::tf2::LookupResult in_world =
    buffer.lookup_transform("world", "guide", ros2vtk::tf2::kLatestTime);
  if (!in_world.ok)
  {
    std::fprintf(stderr, "lookup_transform failed: %s\n", in_world.message.c_str());
    return 1;
  }
  const Eigen::Vector3d& t = in_world.transform.translation;
  std::printf("tf2 world->guide %.3f %.3f %.3f\n", t.x(), t.y(), t.z());

  std::string topic;
  if (!ros2vtk::wire::expand_topic_name("needle_guide", "needle_guide_demo", "/", topic, &error))
  {
    std::fprintf(stderr, "expand_topic_name failed: %s\n", error.c_str());
    return 1;
  }
  std::printf("dds topic %s\n", ros2vtk::wire::topic_to_dds(topic).c_str());

  // A guide holder: a base box and a 45 mm prismatic insertion stage.
  const std::string holder = R"(<robot name="holder">
    <link name="base"><visual><geometry><box size="0.1 0.1 0.02"/></geometry></visual></link>
    <link name="stage"><visual><geometry><cylinder radius="0.005" length="0.05"/></geometry></visual></link>
    <joint name="insert" type="prismatic"><parent link="base"/><child link="stage"/>
      <origin xyz="0 0 0.01"/><axis xyz="0 0 1"/><limit lower="0" upper="0.1" effort="1" velocity="1"/>
    </joint></robot>)";
  const auto tree = ros2vtk::robot::KinematicTree::from_urdf(holder, &error);
  if (!tree)
  {
    std::fprintf(stderr, "KinematicTree: %s\n", error.c_str());
    return 1;
  }
  const auto poses = tree->link_poses({ { "insert", decoded.depth } });
  std::printf("holder stage z %.3f\n", poses.at("stage").translation().z());
  ros2vtk::robot::RobotLoader loader;
  ros2vtk::robot::RobotVisuals visuals;
  if (!loader.load_xml(holder, ros2vtk::robot::RobotLoadOptions(), &visuals, &error))
  {
    std::fprintf(stderr, "RobotLoader: %s\n", error.c_str());
    return 1;
  }
  std::printf("holder visuals %zu\n", visuals.visual_count());

  // OpenIGTLink (ros2vtk::IGTL): the guide's pose as the TRANSFORM a Slicer would read, framed
  // into bytes and read back.
  ros2vtk::igtl::Matrix pose{};
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      pose[r * 4 + c] = matrix->GetElement(r, c);
    }
  }
  const std::vector<std::uint8_t> igtl_bytes =
    ros2vtk::igtl::encode_frame(ros2vtk::igtl::encode_transform("guide", pose, 0));
  ros2vtk::igtl::FrameReader igtl_reader;
  igtl_reader.feed(igtl_bytes.data(), igtl_bytes.size());
  ros2vtk::igtl::Frame igtl_frame;
  ros2vtk::igtl::Matrix igtl_pose{};
  if (igtl_reader.next(igtl_frame, error) != ros2vtk::igtl::FrameReader::Result::Frame ||
    !ros2vtk::igtl::decode_transform(igtl_frame, igtl_pose, error))
  {
    std::fprintf(stderr, "IGTL: %s\n", error.c_str());
    return 1;
  }
  std::printf("igtl %s %s %zu bytes x_mm %.1f\n", igtl_frame.type.c_str(),
    igtl_frame.device.c_str(), igtl_bytes.size(), igtl_pose[3]);
  return 0;
}
