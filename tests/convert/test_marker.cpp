// A display marker <-> vtkPolyData: shapes from VTK's sources sized and placed in mm, points as a
// line or vertices, colour as an RGBA "Color" array; unsupported types refused with a reason.
#include "ros2vtk/convert/Marker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

using namespace ros2vtk::convert;

TEST(Marker, CubeSizedAndPlacedInMillimetres)
{
  Marker cube;
  cube.shape = MarkerShape::Cube;
  cube.position[0] = 0.1;
  cube.position[2] = 1.5;
  cube.scale[0] = 0.02;
  cube.scale[1] = 0.04;
  cube.scale[2] = 0.06;
  cube.color[1] = 0.0;
  vtkNew<vtkPolyData> out;
  std::string error;
  ASSERT_TRUE(marker_to_poly_data(cube, 1000.0, out, &error)) << error;
  double b[6];
  out->GetBounds(b);
  const double expected[6] = { 90.0, 110.0, -20.0, 20.0, 1470.0, 1530.0 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], expected[i], 1e-9) << i;
  }
  EXPECT_EQ(out->GetNumberOfPolys(), 6);
  auto* color = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Color"));
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->GetValue(0), 255);
  EXPECT_EQ(color->GetValue(1), 0);
  EXPECT_EQ(color->GetValue(3), 255);
}

TEST(Marker, UnsupportedAndBrokenMarkersAreRefused)
{
  vtkNew<vtkPolyData> out;
  std::string error;
  Marker text; // Unsupported (TEXT_VIEW_FACING and the like)
  EXPECT_FALSE(marker_to_poly_data(text, 1000.0, out, &error));
  EXPECT_NE(error.find("not supported"), std::string::npos) << error;
  Marker flat;
  flat.shape = MarkerShape::Sphere;
  flat.scale[2] = 0.0;
  EXPECT_FALSE(marker_to_poly_data(flat, 1000.0, out, &error));
  EXPECT_NE(error.find("positive scale"), std::string::npos) << error;
  Marker tilted;
  tilted.shape = MarkerShape::Cube;
  tilted.orientation[3] = 0.0;
  EXPECT_FALSE(marker_to_poly_data(tilted, 1000.0, out, &error));
  EXPECT_NE(error.find("unit quaternion"), std::string::npos) << error;
  EXPECT_EQ(out->GetNumberOfPoints(), 0) << "untouched on failure";
}

TEST(Marker, LineBackToALineStripInMetres)
{
  vtkNew<vtkPolyData> line;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(100, 0, 0);
  line->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[2] = { 0, 1 };
  cells->InsertNextCell(2, ids);
  line->SetLines(cells);
  Marker marker;
  std::string error;
  ASSERT_TRUE(poly_data_to_marker(line, 1000.0, &marker, &error)) << error;
  EXPECT_EQ(marker.shape, MarkerShape::LineStrip);
  ASSERT_EQ(marker.points.size(), 6u);
  EXPECT_DOUBLE_EQ(marker.points[3], 0.1);
  EXPECT_DOUBLE_EQ(marker.scale[0], 0.001);
  EXPECT_EQ(marker.color[0], 1.0);
}

TEST(MarkerSet, AMarkerWithALifetimeExpiresThatLongAfterItWasAdded)
{
  MarkerSet kept;
  Marker cube;
  cube.shape = MarkerShape::Cube;
  cube.scale[0] = cube.scale[1] = cube.scale[2] = 0.1;
  Marker forever = cube;
  cube.lifetime = 0.5;
  std::string error;
  kept.set_time(2'000'000'000); // the clock when these arrive: 2 s
  ASSERT_TRUE(kept.add("a", 1, cube, &error)) << error;
  ASSERT_TRUE(kept.add("a", 2, forever, &error)) << error;
  EXPECT_FALSE(kept.expire(2'499'999'999)); // 0.5 s not yet over
  EXPECT_EQ(kept.size(), 2u);
  EXPECT_TRUE(kept.expire(2'500'000'000));
  EXPECT_FALSE(kept.contains("a", 1));
  EXPECT_TRUE(kept.contains("a", 2)); // lifetime 0: forever
  EXPECT_FALSE(kept.expire(1'000'000'000'000));

  // A re-added marker counts its lifetime from its new arrival; a clock that went backwards
  // expires nothing early.
  kept.set_time(3'000'000'000);
  ASSERT_TRUE(kept.add("a", 1, cube, &error)) << error;
  kept.set_time(3'400'000'000);
  ASSERT_TRUE(kept.add("a", 1, cube, &error)) << error;
  EXPECT_FALSE(kept.expire(3'500'000'000));
  EXPECT_FALSE(kept.expire(1'000'000'000));
  EXPECT_TRUE(kept.expire(3'900'000'000));
  EXPECT_EQ(kept.size(), 1u);
}

namespace {

/// The centre of the drawn cells of marker `index` (MarkerIndex) in `drawn`.
std::vector<double> MarkerCentre(vtkPolyData* drawn, int index)
{
  vtkDataArray* markers = drawn->GetCellData()->GetArray("MarkerIndex");
  double bounds[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (vtkIdType cell = 0; cell < drawn->GetNumberOfCells(); ++cell)
  {
    if (static_cast<int>(markers->GetTuple1(cell)) != index)
    {
      continue;
    }
    vtkIdList* ids = drawn->GetCell(cell)->GetPointIds();
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      const double* p = drawn->GetPoint(ids->GetId(i));
      for (int axis = 0; axis < 3; ++axis)
      {
        bounds[2 * axis] = std::min(bounds[2 * axis], p[axis]);
        bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], p[axis]);
      }
    }
  }
  return { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
}

} // namespace

TEST(MarkerSet, MarkersArePlacedAtTheirFramesPoseInTheFixedFrame)
{
  // Frame "turned": 90 degrees about z, then 1 m along x; frame "moving": y metres along y, y
  // changed by the test. Lookups are recorded: stamp 0 means the latest transform.
  double movingY = 0.1;
  std::vector<std::pair<std::string, int64_t>> asked;
  const FrameLookup lookup = [&](const std::string& frame, int64_t stamp, FramePose* pose,
                               std::string* error) {
    asked.emplace_back(frame, stamp);
    if (frame == "turned")
    {
      pose->translation[0] = 1.0;
      pose->rotation[2] = std::sqrt(0.5);
      pose->rotation[3] = std::sqrt(0.5);
      return true;
    }
    if (frame == "moving")
    {
      pose->translation[1] = movingY;
      return true;
    }
    *error = "frame does not exist";
    return false;
  };
  Marker cube;
  cube.shape = MarkerShape::Cube;
  cube.scale[0] = cube.scale[1] = cube.scale[2] = 0.01;
  cube.position[0] = 0.2; // 0.2 m along the frame's x
  Marker turned = cube, locked = cube, unlocked = cube, lost = cube;
  turned.frame_id = "turned";
  turned.stamp_nanoseconds = 5'000'000'000;
  locked.frame_id = unlocked.frame_id = "moving";
  locked.frame_locked = true;
  locked.stamp_nanoseconds = unlocked.stamp_nanoseconds = 7'000'000'000;
  lost.frame_id = "nowhere";
  MarkerSet kept;
  std::string error;
  ASSERT_TRUE(kept.add("m", 1, turned, &error)) << error;
  ASSERT_TRUE(kept.add("m", 2, locked, &error)) << error;
  ASSERT_TRUE(kept.add("m", 3, unlocked, &error)) << error;
  ASSERT_TRUE(kept.add("m", 4, lost, &error)) << error;
  EXPECT_TRUE(kept.locate(lookup, "world", false));
  // A frame-locked marker is looked up at the latest transform, the others at their stamp.
  EXPECT_EQ(asked,
    (std::vector<std::pair<std::string, int64_t>>{ { "turned", 5'000'000'000 }, { "moving", 0 },
      { "moving", 7'000'000'000 }, { "nowhere", 0 } }));
  EXPECT_EQ(kept.status(),
    "marker (ns 'm', id 4): No transform from [nowhere] to [world]: frame does not exist");

  vtkNew<vtkPolyData> drawn;
  ASSERT_TRUE(kept.to_poly_data(1000.0, drawn, &error)) << error;
  // The marker without a frame is not drawn: three markers, in mm.
  EXPECT_EQ(drawn->GetCellData()->GetArray("MarkerIndex")->GetRange()[1], 2.0);
  const std::vector<double> atTurned = MarkerCentre(drawn, 0);
  EXPECT_NEAR(atTurned[0], 1000.0, 1e-6); // x of the frame, the marker's x turned onto +y
  EXPECT_NEAR(atTurned[1], 200.0, 1e-6);
  EXPECT_NEAR(MarkerCentre(drawn, 1)[1], 100.0, 1e-6);
  EXPECT_NEAR(MarkerCentre(drawn, 2)[1], 100.0, 1e-6);

  // The frame moves: the next locate looks up the frame-locked marker (and the unplaced one)
  // only; the frame-locked marker follows, the other stays where its stamp put it.
  movingY = 0.3;
  asked.clear();
  EXPECT_TRUE(kept.locate(lookup, "world", false));
  EXPECT_EQ(
    asked, (std::vector<std::pair<std::string, int64_t>>{ { "moving", 0 }, { "nowhere", 0 } }));
  ASSERT_TRUE(kept.to_poly_data(1000.0, drawn, &error)) << error;
  EXPECT_NEAR(MarkerCentre(drawn, 1)[1], 300.0, 1e-6);
  EXPECT_NEAR(MarkerCentre(drawn, 2)[1], 100.0, 1e-6);
  // Nothing moved since: no change reported.
  EXPECT_FALSE(kept.locate(lookup, "world", false));

  // unlocate(): every marker at its own pose again, the lost one included.
  kept.unlocate();
  EXPECT_EQ(kept.status(), "");
  ASSERT_TRUE(kept.to_poly_data(1000.0, drawn, &error)) << error;
  EXPECT_EQ(drawn->GetCellData()->GetArray("MarkerIndex")->GetRange()[1], 3.0);
  EXPECT_NEAR(MarkerCentre(drawn, 0)[0], 200.0, 1e-6);
}

TEST(MarkerSet, ActionsAreAppliedInOrderAndMarkersOlderThanTheTfHistoryAreDropped)
{
  Marker cube;
  cube.shape = MarkerShape::Cube;
  cube.scale[0] = cube.scale[1] = cube.scale[2] = 0.1;
  cube.frame_id = "f";
  Marker a = cube, b = cube, old = cube, unknown = cube, gone = cube, all = cube, last = cube;
  a.ns = b.ns = old.ns = unknown.ns = gone.ns = "s";
  a.id = 1, b.id = 2, old.id = 3, unknown.id = 4, gone.id = 1;
  old.stamp_nanoseconds = 1; // before the lookup's history
  unknown.action = MarkerAction::Unknown;
  unknown.action_value = 9;
  gone.action = MarkerAction::Delete;
  all.action = MarkerAction::DeleteAll;
  last.ns = "t";
  MarkerSet kept;
  std::string error;
  // The first reason is given; the rest is still applied.
  EXPECT_FALSE(kept.apply({ a, b, old, unknown, gone }, &error));
  EXPECT_EQ(error, "marker (ns 's', id 4): unknown action 9");
  EXPECT_TRUE(!kept.contains("s", 1) && kept.contains("s", 2) && kept.contains("s", 3));
  const FrameLookup lookup = [](const std::string&, int64_t stamp, FramePose* pose,
                               std::string* reason) {
    if (stamp != 1)
    {
      return true;
    }
    *reason = "Lookup would require extrapolation into the past";
    pose->older_than_history = true;
    return false;
  };
  EXPECT_TRUE(kept.locate(lookup, "world", false));
  EXPECT_FALSE(kept.contains("s", 3)); // dropped, not retried
  EXPECT_EQ(kept.status(),
    "marker (ns 's', id 3): dropped: its stamp is older than the tf history (No transform from "
    "[f] to [world]: Lookup would require extrapolation into the past); RViz's tf filter drops "
    "it too");
  // Added again with a stamp the history holds: drawn, the status forgotten.
  old.stamp_nanoseconds = 0;
  EXPECT_TRUE(kept.apply({ old }, &error)) << error;
  kept.locate(lookup, "world", false);
  EXPECT_TRUE(kept.contains("s", 3));
  EXPECT_EQ(kept.status(), "");
  EXPECT_TRUE(kept.apply({ all, last }, &error)) << error; // DELETEALL, then one more
  EXPECT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept.contains("t", 0));
}

TEST(MarkerSet, TextMarkersBecomeLabelsBesideTheShapes)
{
  MarkerSet kept;
  Marker cube;
  cube.shape = MarkerShape::Cube;
  cube.scale[0] = cube.scale[1] = cube.scale[2] = 0.1;
  Marker text;
  text.shape = MarkerShape::Text;
  text.text = "tool";
  text.position[1] = 0.2;
  text.scale[2] = 0.05;
  text.color[0] = 0.0;
  std::string error;
  ASSERT_TRUE(kept.add("a", 1, cube, &error)) << error;
  ASSERT_TRUE(kept.add("a", 2, text, &error)) << error;
  vtkNew<vtkPolyData> out;
  ASSERT_TRUE(kept.to_poly_data(1000.0, out, &error)) << error;
  EXPECT_EQ(out->GetNumberOfPolys(), 6); // the cube alone: a label adds no geometry
  auto* names =
    vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(kLabelTextArray));
  ASSERT_NE(names, nullptr);
  ASSERT_EQ(names->GetNumberOfValues(), 1);
  EXPECT_EQ(names->GetValue(0), "tool");
  double at[3];
  out->GetFieldData()->GetArray(kLabelPositionArray)->GetTuple(0, at);
  EXPECT_DOUBLE_EQ(at[1], 200.0);
  EXPECT_DOUBLE_EQ(out->GetFieldData()->GetArray(kLabelHeightArray)->GetTuple1(0), 50.0);
  EXPECT_EQ(out->GetFieldData()->GetArray(kLabelColorArray)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(out->GetFieldData()->GetArray(kLabelColorArray)->GetComponent(0, 1), 255.0);

  text.scale[2] = 0.0;
  EXPECT_FALSE(kept.add("a", 2, text, &error));
  EXPECT_NE(error.find("scale.z"), std::string::npos) << error;
}

TEST(MarkerSet, MeshResourceMarkersAreReadByTheProcessLoader)
{
  Marker mesh;
  mesh.shape = MarkerShape::MeshResource;
  mesh.mesh_resource = "package://p/m.stl";
  mesh.color[2] = 0.0;
  vtkNew<vtkPolyData> out;
  std::string error;
  set_mesh_resource_loader(nullptr);
  EXPECT_FALSE(marker_to_poly_data(mesh, 1000.0, out, &error));
  EXPECT_NE(error.find("no mesh loader"), std::string::npos) << error;

  std::vector<std::string> asked;
  set_mesh_resource_loader(
    [&asked](const std::string& uri, vtkPolyData* polyData, std::string* why) {
      asked.push_back(uri);
      if (uri != "package://p/m.stl")
      {
        *why = "not there: " + uri;
        return false;
      }
      vtkNew<vtkPoints> points;
      points->InsertNextPoint(0, 0, 0);
      points->InsertNextPoint(1, 0, 0);
      points->InsertNextPoint(0, 1, 0);
      vtkNew<vtkCellArray> triangle;
      const vtkIdType ids[3] = { 0, 1, 2 };
      triangle->InsertNextCell(3, ids);
      polyData->SetPoints(points);
      polyData->SetPolys(triangle);
      return true;
    });
  mesh.scale[0] = 0.5; // metres: 500 mm along x
  ASSERT_TRUE(marker_to_poly_data(mesh, 1000.0, out, &error)) << error;
  double b[6];
  out->GetBounds(b);
  EXPECT_DOUBLE_EQ(b[1], 500.0);
  EXPECT_DOUBLE_EQ(b[3], 1000.0);
  auto* color = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Color"));
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->GetValue(2), 0); // the marker's colour (the mesh has none of its own)

  MarkerSet kept;
  mesh.mesh_resource = "package://p/gone.stl";
  EXPECT_FALSE(kept.add("m", 1, mesh, &error));
  EXPECT_NE(error.find("not there: package://p/gone.stl"), std::string::npos) << error;
  EXPECT_EQ(kept.size(), 0u);
  set_mesh_resource_loader(nullptr);
}

namespace {

/// The RGBA bytes of point `i` of the poly data's "Color" array.
std::vector<int> point_color(vtkPolyData* poly_data, vtkIdType i)
{
  auto* color = vtkUnsignedCharArray::SafeDownCast(poly_data->GetPointData()->GetArray("Color"));
  std::vector<int> rgba;
  for (int c = 0; color && c < 4; ++c)
  {
    rgba.push_back(color->GetValue(4 * i + c));
  }
  return rgba;
}

Marker listed(MarkerShape shape, std::vector<double> points, std::vector<double> colors)
{
  Marker marker;
  marker.shape = shape;
  marker.scale[0] = marker.scale[1] = marker.scale[2] = 0.1;
  marker.color[0] = 1.0;
  marker.color[1] = 1.0;
  marker.color[2] = 0.0; // yellow when colors do not apply
  marker.points = std::move(points);
  marker.colors = std::move(colors);
  return marker;
}

} // namespace

// RViz colours point i with colors[i] when there are as many colours as points
// (points_marker.cpp, line_marker_base.cpp); otherwise every point has `color`.
TEST(Marker, ColorsAsManyAsPointsColourEachPoint)
{
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  const std::vector<double> colors = { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 0.5 };
  for (MarkerShape shape : { MarkerShape::Points, MarkerShape::LineStrip })
  {
    vtkNew<vtkPolyData> out;
    std::string error;
    ASSERT_TRUE(marker_to_poly_data(listed(shape, points, colors), 1000.0, out, &error)) << error;
    ASSERT_EQ(out->GetNumberOfPoints(), 3);
    EXPECT_EQ(point_color(out, 0), (std::vector<int>{ 255, 0, 0, 255 }));
    EXPECT_EQ(point_color(out, 1), (std::vector<int>{ 0, 255, 0, 255 }));
    EXPECT_EQ(point_color(out, 2), (std::vector<int>{ 0, 0, 255, 128 }));
  }
  vtkNew<vtkPolyData> out;
  std::string error;
  const std::vector<double> two = { 1, 0, 0, 1, 0, 1, 0, 1 };
  ASSERT_TRUE(marker_to_poly_data(listed(MarkerShape::Points, points, two), 1000.0, out, &error));
  for (vtkIdType i = 0; i < 3; ++i)
  {
    EXPECT_EQ(point_color(out, i), (std::vector<int>{ 255, 255, 0, 255 })) << i;
  }
}

TEST(Marker, CubeListColoursEachCubeWithItsPointsColour)
{
  Marker cubes = listed(MarkerShape::CubeList, { 0, 0, 0, 2, 0, 0 }, { 1, 0, 0, 1, 0, 0, 1, 1 });
  vtkNew<vtkPolyData> out;
  std::string error;
  ASSERT_TRUE(marker_to_poly_data(cubes, 1000.0, out, &error)) << error;
  ASSERT_EQ(out->GetNumberOfPoints(), 48);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const bool first = out->GetPoint(i)[0] < 1000.0;
    EXPECT_EQ(point_color(out, i),
      first ? (std::vector<int>{ 255, 0, 0, 255 }) : (std::vector<int>{ 0, 0, 255, 255 }))
      << i;
  }
}

// triangle_list_marker.cpp: points in threes scaled by scale, a colour per vertex or per
// triangle with its alpha times color.a.
TEST(Marker, TriangleListScaledAndColouredPerTriangle)
{
  Marker triangles =
    listed(MarkerShape::TriangleList, { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, { 0, 1, 0, 1 });
  triangles.scale[0] = 2.0;
  triangles.scale[1] = 3.0;
  triangles.scale[2] = 1.0;
  triangles.color[3] = 0.5;
  vtkNew<vtkPolyData> out;
  std::string error;
  ASSERT_TRUE(marker_to_poly_data(triangles, 1000.0, out, &error)) << error;
  ASSERT_EQ(out->GetNumberOfPolys(), 1);
  EXPECT_DOUBLE_EQ(out->GetPoint(1)[0], 2000.0);
  EXPECT_DOUBLE_EQ(out->GetPoint(2)[1], 3000.0);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    EXPECT_EQ(point_color(out, i), (std::vector<int>{ 0, 255, 0, 128 })) << i;
  }
  triangles.points.resize(6);
  EXPECT_FALSE(marker_to_poly_data(triangles, 1000.0, out, &error));
  EXPECT_NE(error.find("in threes"), std::string::npos) << error;
}

// arrow_marker.cpp setArrowFromPoints: from points[0] to points[1], shaft diameter scale.x,
// head diameter scale.y, head length scale.z (23% of the length when 0); one point is refused.
TEST(Marker, ArrowFromTwoPointsGoesFromTheFirstToTheSecond)
{
  Marker arrow = listed(MarkerShape::Arrow, { 0, 0, 1, 0, 2, 1 }, {});
  arrow.scale[0] = 0.1;
  arrow.scale[1] = 0.2;
  arrow.scale[2] = 0.0;
  vtkNew<vtkPolyData> out;
  std::string error;
  ASSERT_TRUE(marker_to_poly_data(arrow, 1000.0, out, &error)) << error;
  double b[6];
  out->GetBounds(b);
  const double expected[6] = { -100.0, 100.0, 0.0, 2000.0, 900.0, 1100.0 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], expected[i], 1e-3) << i;
  }
  double head_start = 1e9;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const double* p = out->GetPoint(i);
    if (std::hypot(p[0], p[2] - 1000.0) > 75.0) // head (100 mm), not shaft (50 mm)
    {
      head_start = std::min(head_start, p[1]);
    }
  }
  EXPECT_NEAR(head_start, 2000.0 * (1.0 - 0.23), 1e-3);

  arrow.points.resize(3);
  EXPECT_FALSE(marker_to_poly_data(arrow, 1000.0, out, &error));
  EXPECT_NE(error.find("two points (start and end) or none, not 1"), std::string::npos) << error;
  arrow.points = { 0, 0, 0, 0, 0, 0 };
  EXPECT_FALSE(marker_to_poly_data(arrow, 1000.0, out, &error));
  EXPECT_NE(error.find("same point"), std::string::npos) << error;
}

TEST(Marker, ANonFiniteColourIsRefused)
{
  Marker points = listed(MarkerShape::Points, { 0, 0, 0 }, { 1, std::nan(""), 0, 1 });
  vtkNew<vtkPolyData> out;
  std::string error;
  EXPECT_FALSE(marker_to_poly_data(points, 1000.0, out, &error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;
}
