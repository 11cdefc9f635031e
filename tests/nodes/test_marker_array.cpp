// The generated MarkerArray converters (kind marker_array) on rclpy's bytes: the three
// MarkerArray samples of tests/fixtures/cdr (visualization_msgs__MarkerArray__4..6, made by
// make_cdr_fixtures.py: three markers added, one deleted, DELETEALL then one added) folded in
// order into the MarkerSet a subscriber keeps, as RViz keeps markers by (ns, id). Expected
// shapes, places (mm) and colours are the samples' values, written out here.
#include "ros2vtkNodesConvert.hpp"

#include "Fixtures.hpp"

#include "ros2vtk/wire/CdrReader.hpp"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {
namespace visualization_msgs = ros2vtk::visualization_msgs::msg;

visualization_msgs::MarkerArray FromRclpy(int number)
{
  const auto fixture = ros2vtk_test::load_fixture(std::string(ROS2VTK_FIXTURES_DIR) +
    "/cdr/visualization_msgs__MarkerArray__" + std::to_string(number) + ".json");
  visualization_msgs::MarkerArray message;
  std::string error;
  EXPECT_TRUE(ros2vtk::wire::deserialize_message(visualization_msgs::MarkerArray::type_support(),
    fixture.payload.data(), fixture.payload.size(), &message, &error))
    << error;
  return message;
}

struct Drawn
{
  int markers = 0;
  std::array<double, 6> bounds{};
  std::vector<std::array<int, 4>>
    colors; // the RGBA of each marker's first cell's first point, by MarkerIndex
};

Drawn Draw(const ros2vtk::convert::MarkerSet& set)
{
  vtkNew<vtkPolyData> out;
  std::string error;
  EXPECT_TRUE(set.to_poly_data(1000.0, out, &error)) << error;
  Drawn drawn;
  out->GetBounds(drawn.bounds.data());
  auto* index = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("MarkerIndex"));
  vtkDataArray* color = out->GetPointData()->GetScalars();
  if (out->GetNumberOfCells() == 0)
  {
    return drawn;
  }
  EXPECT_NE(index, nullptr);
  EXPECT_NE(color, nullptr);
  EXPECT_EQ(color ? std::string(color->GetName()) : std::string(), "Color");
  // Cells come grouped by type (vertices, lines, polygons): MarkerIndex says whose each is.
  std::map<int, std::array<int, 4>> seen;
  for (vtkIdType cell = 0; cell < out->GetNumberOfCells(); ++cell)
  {
    const int marker = index->GetValue(cell);
    if (!seen.count(marker))
    {
      const vtkIdType point = out->GetCell(cell)->GetPointId(0);
      std::array<int, 4> rgba{};
      for (int c = 0; c < 4; ++c)
      {
        rgba[c] = static_cast<int>(color->GetComponent(point, c));
      }
      seen[marker] = rgba;
    }
  }
  for (const auto& entry : seen)
  {
    drawn.colors.push_back(entry.second);
  }
  drawn.markers = static_cast<int>(seen.size());
  return drawn;
}
} // namespace

TEST(MarkerArrayFromRclpy, AddDeleteDeleteAllAsRVizKeepsMarkers)
{
  ros2vtk::convert::MarkerSet kept;
  std::string error;

  // 4: a red cube at x 1 m, a green sphere at x 2 m (ns a, ids 1, 2), a blue line (ns b, id 1)
  //    from (0, 0) to (0.5, 0) to (0.5, 0.5) m; sizes 0.1 x 0.2 x 0.3 m.
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(4), kept, &error)) << error;
  EXPECT_EQ(kept.size(), 3u);
  Drawn drawn = Draw(kept);
  EXPECT_EQ(drawn.markers, 3);
  const std::vector<std::array<int, 4>> all = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 },
    { 0, 0, 255, 255 } };
  EXPECT_EQ(drawn.colors, all);               // (ns, id) order: a/1 cube, a/2 sphere, b/1 line
  EXPECT_NEAR(drawn.bounds[0], 0.0, 1e-6);    // the line starts at the origin
  EXPECT_NEAR(drawn.bounds[1], 2050.0, 1e-6); // the sphere's far side: 2 m + 0.1 m / 2
  EXPECT_NEAR(drawn.bounds[3], 500.0, 1e-6);  // the line's last point
  EXPECT_NEAR(drawn.bounds[5], 150.0, 1e-6);  // cube and sphere: 0.3 m high, centred at 0

  // 5: DELETE ns a, id 1 (the cube): sphere and line stay.
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(5), kept, &error)) << error;
  EXPECT_EQ(kept.size(), 2u);
  EXPECT_FALSE(kept.contains("a", 1));
  drawn = Draw(kept);
  EXPECT_EQ(drawn.markers, 2);
  const std::vector<std::array<int, 4>> left = { { 0, 255, 0, 255 }, { 0, 0, 255, 255 } };
  EXPECT_EQ(drawn.colors, left);

  // 6: DELETEALL, then a yellow cylinder (ns c, id 7) at x -1 m in the same message.
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(6), kept, &error)) << error;
  EXPECT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept.contains("c", 7));
  drawn = Draw(kept);
  EXPECT_EQ(drawn.markers, 1);
  const std::vector<std::array<int, 4>> yellow = { { 255, 255, 0, 255 } };
  EXPECT_EQ(drawn.colors, yellow);
  EXPECT_NEAR(drawn.bounds[0], -1050.0, 1e-6); // 0.1 m diameter about x = -1 m
  EXPECT_NEAR(drawn.bounds[1], -950.0, 1e-6);
  EXPECT_NEAR(drawn.bounds[4], -150.0, 1e-6); // 0.3 m long along z
  EXPECT_NEAR(drawn.bounds[5], 150.0, 1e-6);
}

TEST(MarkerArrayFromRclpy, OneMessageAloneAndBadMarkers)
{
  // ROS2ToVTK of one message into a poly data draws that message alone.
  vtkNew<vtkPolyData> only;
  std::string error;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(4), only.GetPointer(), 1000.0, &error)) << error;
  vtkNew<vtkPolyData> nothing;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(5), nothing.GetPointer(), 1000.0, &error))
    << error;
  EXPECT_EQ(nothing->GetNumberOfPoints(), 0); // a DELETE alone: nothing to draw

  // A TRIANGLE_LIST marker is not drawn: refused by name, the others of the message still kept.
  visualization_msgs::MarkerArray message = FromRclpy(4);
  message.markers[1].type = visualization_msgs::Marker::TRIANGLE_LIST;
  ros2vtk::convert::MarkerSet kept;
  EXPECT_FALSE(ros2vtk::nodes::ROS2ToVTK(message, kept, &error));
  EXPECT_NE(error.find("ns 'a', id 2"), std::string::npos) << error;
  EXPECT_EQ(kept.size(), 2u);
  EXPECT_FALSE(ros2vtk::nodes::ROS2ToVTK(message, only.GetPointer(), 1000.0, &error));
  message.markers[1].action = 1; // no such action in ROS 2 (ADD = MODIFY = 0)
  EXPECT_FALSE(ros2vtk::nodes::ROS2ToVTK(message, kept, &error));
  EXPECT_NE(error.find("unknown action 1"), std::string::npos) << error;
}

TEST(MarkerArrayFromRclpy, PolyDataOutAsOneAddedLineStripInMetres)
{
  visualization_msgs::MarkerArray in = FromRclpy(4);
  vtkNew<vtkPolyData> line;
  ros2vtk::convert::MarkerSet one;
  std::string error;
  visualization_msgs::MarkerArray just_line;
  just_line.markers.push_back(in.markers[2]);
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(just_line, line.GetPointer(), 1000.0, &error)) << error;
  visualization_msgs::MarkerArray out;
  ASSERT_TRUE(ros2vtk::nodes::VTKToROS2(line.GetPointer(), out, 1000.0, &error)) << error;
  ASSERT_EQ(out.markers.size(), 1u);
  EXPECT_EQ(out.markers[0].action, visualization_msgs::Marker::ADD);
  EXPECT_EQ(out.markers[0].type, visualization_msgs::Marker::LINE_STRIP);
  ASSERT_EQ(out.markers[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(out.markers[0].points[2].x, 0.5);
  EXPECT_DOUBLE_EQ(out.markers[0].points[2].y, 0.5);
  EXPECT_FLOAT_EQ(out.markers[0].color.b, 1.0f);
}

TEST(MarkerArrayFromRclpy, EachMarkersHeaderFrameAndStampAreLookedUp)
{
  // Sample 4's markers are in frame 'map' stamped 20.123456789 s (not frame_locked): placed in
  // the fixed frame by the lookup at that stamp. Here 'map' is 0.5 m along y of 'world'.
  ros2vtk::convert::MarkerSet kept;
  std::string error;
  ASSERT_TRUE(ros2vtk::nodes::ROS2ToVTK(FromRclpy(4), kept, &error)) << error;
  std::vector<std::pair<std::string, int64_t>> asked;
  const ros2vtk::convert::FrameLookup lookup = [&](const std::string& frame, int64_t stamp,
                                                 ros2vtk::convert::FramePose* pose, std::string*) {
    asked.emplace_back(frame, stamp);
    pose->translation[1] = 0.5;
    return true;
  };
  EXPECT_TRUE(kept.locate(lookup, "world", false));
  EXPECT_EQ(asked, (std::vector<std::pair<std::string, int64_t>>(3, { "map", 20'123'456'789 })));
  const Drawn drawn = Draw(kept);
  EXPECT_EQ(drawn.markers, 3);
  // The bounds of sample 4 (x 0 .. 2050, y -100 .. 500 mm) moved 500 mm along y.
  EXPECT_NEAR(drawn.bounds[0], 0.0, 1e-6);
  EXPECT_NEAR(drawn.bounds[1], 2050.0, 1e-6);
  EXPECT_NEAR(drawn.bounds[2], 400.0, 1e-6);
  EXPECT_NEAR(drawn.bounds[3], 1000.0, 1e-6);
  // Not frame_locked and placed: the next spin looks nothing up again.
  asked.clear();
  EXPECT_FALSE(kept.locate(lookup, "world", false));
  EXPECT_TRUE(asked.empty());
}
