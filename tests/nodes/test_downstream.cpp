// A project's own specs and rules through ros2vtk_generate() (the downstream CMake function):
// a float listed under `lengths` is scaled, a pose with other field names maps, and the
// classes register under their short names and aliases.
#include "ros2vtkTestNodesConvert.hpp"

#include "NodeClassRegistry.hpp"
#include "vtkROS2SceneNode.h"

#include "vtkMatrix4x4.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include "ros2vtkTestNodesRegister.hpp" // ros2vtk_register_ros2vtkTestNodes_nodes()

TEST(DownstreamNodes, ScaledValueBothWays)
{
  ros2vtk::ros2vtk_nodes_test_msgs::msg::Distance distance;
  distance.metres = 0.25;
  double millimetres = 0.0;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(distance, &millimetres));
  EXPECT_DOUBLE_EQ(millimetres, 250.0);
  ASSERT_TRUE(
    ros2vtk::nodes::ROS2ToVTK(distance, &millimetres, ros2vtk::convert::kNoLengthScaling));
  EXPECT_DOUBLE_EQ(millimetres, 0.25);
  ros2vtk::ros2vtk_nodes_test_msgs::msg::Distance back;
  ASSERT_TRUE(ros2vtk::nodes::VTKToROS2(1500.0, back));
  EXPECT_DOUBLE_EQ(back.metres, 1.5);
  std::string error;
  EXPECT_FALSE(ros2vtk::nodes::VTKToROS2(1.0, back, 0.0, &error));
  EXPECT_NE(error.find("length scale"), std::string::npos) << error;
}

TEST(DownstreamNodes, PoseWithOwnFieldNames)
{
  ros2vtk::ros2vtk_nodes_test_msgs::msg::Marker marker;
  marker.where.y = 0.002;
  marker.facing.w = 1.0;
  marker.id = 7;
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(marker, matrix));
  EXPECT_NEAR(matrix->GetElement(1, 3), 2.0, 1e-12);
  ros2vtk::ros2vtk_nodes_test_msgs::msg::Marker back;
  back.id = 7;
  ASSERT_TRUE(ros2vtk::nodes::VTKToROS2(matrix, back));
  EXPECT_EQ(back, marker);
}

TEST(DownstreamNodes, ClassesRegisterWithAliases)
{
  ros2vtk_register_ros2vtkTestNodes_nodes();
  auto& registry = ros2vtk::scene::NodeClassRegistry::instance();
  using ros2vtk::scene::NodeDirection;
  const auto* info = registry.find_short_name(NodeDirection::Subscriber, "Range");
  ASSERT_NE(info, nullptr);
  vtkSmartPointer<vtkROS2SceneNode> node;
  node.TakeReference(info->create());
  EXPECT_STREQ(node->GetClassName(), "vtkROS2SubscriberDistanceNode");
  const auto resolution =
    registry.resolve(NodeDirection::Publisher, "ros2vtk_nodes_test_msgs/msg/Marker");
  ASSERT_NE(resolution.mapped_class, nullptr) << resolution.error;
  EXPECT_EQ(resolution.mapped_class->class_name, "vtkROS2PublisherMarkerNode");
}

// Kind point: one position in metres <-> a vtkPoints of one point in millimetres.
TEST(DownstreamNodes, SinglePointScaledBothWays)
{
  ros2vtk::ros2vtk_nodes_test_msgs::msg::NeedleTarget target;
  target.target.x = 0.01;
  target.target.y = -0.02;
  target.target.z = 0.125;
  vtkNew<vtkPoints> points;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(target, points));
  ASSERT_EQ(points->GetNumberOfPoints(), 1);
  double p[3];
  points->GetPoint(0, p);
  EXPECT_NEAR(p[0], 10.0, 1e-12);
  EXPECT_NEAR(p[1], -20.0, 1e-12);
  EXPECT_NEAR(p[2], 125.0, 1e-12);
  ros2vtk::ros2vtk_nodes_test_msgs::msg::NeedleTarget back;
  ASSERT_TRUE(ros2vtk::nodes::VTKToROS2(points, back));
  EXPECT_NEAR(back.target.x, 0.01, 1e-15);
  EXPECT_NEAR(back.target.z, 0.125, 1e-15);

  std::string error;
  points->InsertNextPoint(1.0, 2.0, 3.0);
  EXPECT_FALSE(ros2vtk::nodes::VTKToROS2(points, back, 1000.0, &error));
  EXPECT_NE(error.find("exactly one point"), std::string::npos) << error;
}

TEST(DownstreamNodes, MarkerArrayKindWithOwnFieldNamesKeepsBlipsByKey)
{
  using Blip = ros2vtk::ros2vtk_nodes_test_msgs::msg::Blip;
  ros2vtk::ros2vtk_nodes_test_msgs::msg::BlipArray added;
  for (int number : { 1, 2 })
  {
    Blip blip;
    blip.group = "lab";
    blip.number = number;
    blip.op = Blip::ADD;
    blip.shape = Blip::CUBE;
    blip.at.x = 0.1 * number; // 100 mm, 200 mm
    blip.facing.w = 1.0;
    blip.size.x = blip.size.y = blip.size.z = 0.01;
    blip.tint.r = blip.tint.a = 1.0f;
    added.blips.push_back(blip);
  }
  ros2vtk::convert::MarkerSet kept;
  std::string error;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(added, kept, &error)) << error;
  EXPECT_EQ(kept.size(), 2u);
  ros2vtk::ros2vtk_nodes_test_msgs::msg::BlipArray removed;
  removed.blips.resize(1);
  removed.blips[0].group = "lab";
  removed.blips[0].number = 1;
  removed.blips[0].op = Blip::DELETE;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(removed, kept, &error)) << error;
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept.contains("lab", 2));
  vtkNew<vtkPolyData> drawn;
  ASSERT_TRUE(kept.to_poly_data(1000.0, drawn, &error)) << error;
  double bounds[6];
  drawn->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], 195.0, 1e-9); // the second cube: 10 mm about x = 200 mm
  EXPECT_NEAR(bounds[1], 205.0, 1e-9);
  EXPECT_NE(drawn->GetCellData()->GetArray("MarkerIndex"), nullptr);

  // Out: one ADD blip, the poly data's points as POINTS, back in metres.
  ros2vtk::ros2vtk_nodes_test_msgs::msg::BlipArray out;
  ASSERT_TRUE(ros2vtk::nodes::VTKToROS2(drawn, out, 1000.0, &error)) << error;
  ASSERT_EQ(out.blips.size(), 1u);
  EXPECT_EQ(out.blips[0].op, Blip::ADD);
  EXPECT_EQ(out.blips[0].shape, Blip::POINTS);
  EXPECT_EQ(out.blips[0].path.size(), static_cast<size_t>(drawn->GetNumberOfPoints()));
  EXPECT_NEAR(out.blips[0].path[0].x, drawn->GetPoint(0)[0] / 1000.0, 1e-12);
}
