// A display marker <-> vtkPolyData: shapes from VTK's sources sized and placed in mm, points as a
// line or vertices, colour as an RGBA "Color" array; unsupported types refused with a reason.
#include "ros2vtk/convert/Marker.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
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
