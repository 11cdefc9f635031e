// ros2vtk — a display marker <-> vtkPolyData through VTK's shape sources (Marker.hpp).
#include "ros2vtk/convert/Marker.hpp"

#include "ros2vtk/convert/Polyline.hpp"

#include "Validation.hpp"

#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkQuaternion.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

/// One solid shape of `shape` (Arrow, Cube, Sphere or Cylinder) of sizes sx, sy, sz (scene
/// units), centred on the origin of the marker's frame as RViz draws it.
void solid_shape(MarkerShape shape, double sx, double sy, double sz, vtkPolyData* out)
{
  if (shape == MarkerShape::Cube)
  {
    vtkNew<vtkCubeSource> source;
    source->SetXLength(sx);
    source->SetYLength(sy);
    source->SetZLength(sz);
    source->Update();
    out->DeepCopy(source->GetOutput());
    return;
  }
  // Unit shapes, then stretched: a sphere of diameter 1; a cylinder of diameter 1 and
  // height 1 turned from VTK's y axis onto z; an arrow of length 1 along x whose head is
  // 1 wide, with the shaft scale.y / scale.z of it.
  vtkSmartPointer<vtkPolyDataAlgorithm> source;
  vtkNew<vtkTransform> unit;
  if (shape == MarkerShape::Sphere)
  {
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetRadius(0.5);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(17); // 11.25 degree steps: the equator is sampled
    source = sphere;
    unit->Scale(sx, sy, sz);
  }
  else if (shape == MarkerShape::Cylinder)
  {
    auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
    cylinder->SetRadius(0.5);
    cylinder->SetHeight(1.0);
    cylinder->SetResolution(24);
    source = cylinder;
    unit->Scale(sx, sy, sz);
    unit->RotateX(90.0);
  }
  else
  {
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipRadius(0.5);
    arrow->SetTipLength(0.23);
    arrow->SetShaftRadius(0.5 * sy / sz);
    arrow->SetTipResolution(24);
    arrow->SetShaftResolution(24);
    source = arrow;
    unit->Scale(sx, sz, sz);
  }
  vtkNew<vtkTransformPolyDataFilter> stretch;
  stretch->SetInputConnection(source->GetOutputPort());
  stretch->SetTransform(unit);
  stretch->Update();
  out->DeepCopy(stretch->GetOutput());
}

/// An arrow from `from` to `to` (scene units) as RViz's ArrowMarker::setArrowFromPoints draws a
/// marker with two points (rviz_default_plugins/.../markers/arrow_marker.cpp): shaft diameter
/// scale.x, head diameter scale.y, head length scale.z clamped to the distance, or 23% of the
/// distance when scale.z is 0. False when the two points are one.
bool arrow_from_points(const double from[3], const double to[3], double shaft_diameter,
  double head_diameter, double head_length, vtkPolyData* out)
{
  double direction[3] = { to[0] - from[0], to[1] - from[1], to[2] - from[2] };
  const double distance = vtkMath::Norm(direction);
  if (!(distance > 0))
  {
    return false;
  }
  const double head =
    head_length != 0.0 ? std::max(0.0, std::min(head_length, distance)) : 0.23 * distance;
  // vtkArrowSource draws a unit arrow along +x; sizes are fractions of the distance.
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipLength(head / distance);
  arrow->SetTipRadius(0.5 * head_diameter / distance);
  arrow->SetShaftRadius(0.5 * shaft_diameter / distance);
  arrow->SetTipResolution(24);
  arrow->SetShaftResolution(24);
  vtkNew<vtkTransform> place;
  place->Translate(from);
  vtkMath::Normalize(direction);
  const double x[3] = { 1, 0, 0 };
  double axis[3];
  vtkMath::Cross(x, direction, axis);
  const double angle = std::atan2(vtkMath::Norm(axis), vtkMath::Dot(x, direction));
  if (vtkMath::Norm(axis) > 1e-12)
  {
    place->RotateWXYZ(vtkMath::DegreesFromRadians(angle), axis);
  }
  else if (angle > 1.0) // pointing along -x: any perpendicular axis turns it round
  {
    place->RotateZ(180.0);
  }
  place->Scale(distance, distance, distance);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputConnection(arrow->GetOutputPort());
  move->SetTransform(place);
  move->Update();
  out->DeepCopy(move->GetOutput());
  return true;
}

/// The RGBA bytes of a colour in 0..1.
void color_bytes(const double color[4], unsigned char rgba[4])
{
  for (int c = 0; c < 4; ++c)
  {
    const double v = std::min(1.0, std::max(0.0, color[c]));
    rgba[c] = static_cast<unsigned char>(std::lround(v * 255.0));
  }
}

/// The "Color" array of a marker's `count` drawn points. RViz colours point i with colors[i]
/// when a POINTS, LINE_STRIP, LINE_LIST, CUBE_LIST or SPHERE_LIST marker has as many colours as
/// points (points_marker.cpp addPointsFromMessage, line_marker_base.cpp has_per_point_color_),
/// and a TRIANGLE_LIST vertex i with colors[i] (as many as points) or triangle i / 3 with
/// colors[i / 3] (one per triangle), its alpha times color.a (triangle_list_marker.cpp);
/// otherwise every point has `color`. `per_point`: drawn points per marker point (the points of
/// one cube or sphere of a list, 1 otherwise).
vtkSmartPointer<vtkUnsignedCharArray> marker_colors(
  const Marker& marker, vtkIdType count, vtkIdType per_point)
{
  auto color = vtkSmartPointer<vtkUnsignedCharArray>::New();
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  color->SetNumberOfTuples(count);
  const size_t points = marker.points.size() / 3, colors = marker.colors.size() / 4;
  const bool listed = marker.shape == MarkerShape::Points ||
    marker.shape == MarkerShape::LineStrip || marker.shape == MarkerShape::LineList ||
    marker.shape == MarkerShape::CubeList || marker.shape == MarkerShape::SphereList;
  const bool triangles = marker.shape == MarkerShape::TriangleList;
  const bool per_vertex = points > 0 && colors == points && (listed || triangles);
  const bool per_face = triangles && points > 0 && !per_vertex && colors == points / 3;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double rgba[4] = { marker.color[0], marker.color[1], marker.color[2], marker.color[3] };
    const size_t point = static_cast<size_t>(i / std::max<vtkIdType>(1, per_point));
    if (per_vertex || per_face)
    {
      const size_t index = per_vertex ? point : point / 3;
      for (int c = 0; c < 4; ++c)
      {
        rgba[c] = marker.colors[4 * index + c];
      }
      if (triangles)
      {
        rgba[3] *= marker.color[3];
      }
    }
    unsigned char bytes[4];
    color_bytes(rgba, bytes);
    color->SetTypedTuple(i, bytes);
  }
  return color;
}

/// The label arrays of `poly_data` (created empty when missing).
struct LabelArrays
{
  vtkStringArray* text;
  vtkDoubleArray* position;
  vtkDoubleArray* height;
  vtkUnsignedCharArray* color;
};

LabelArrays label_arrays(vtkPolyData* poly_data)
{
  vtkFieldData* field = poly_data->GetFieldData();
  if (!vtkStringArray::SafeDownCast(field->GetAbstractArray(kLabelTextArray)))
  {
    vtkNew<vtkStringArray> text;
    text->SetName(kLabelTextArray);
    field->AddArray(text);
    vtkNew<vtkDoubleArray> position;
    position->SetName(kLabelPositionArray);
    position->SetNumberOfComponents(3);
    field->AddArray(position);
    vtkNew<vtkDoubleArray> height;
    height->SetName(kLabelHeightArray);
    field->AddArray(height);
    vtkNew<vtkUnsignedCharArray> color;
    color->SetName(kLabelColorArray);
    color->SetNumberOfComponents(4);
    field->AddArray(color);
  }
  return { vtkStringArray::SafeDownCast(field->GetAbstractArray(kLabelTextArray)),
    vtkDoubleArray::SafeDownCast(field->GetArray(kLabelPositionArray)),
    vtkDoubleArray::SafeDownCast(field->GetArray(kLabelHeightArray)),
    vtkUnsignedCharArray::SafeDownCast(field->GetArray(kLabelColorArray)) };
}

/// Appends every label of `from` to `to`.
void copy_labels(vtkPolyData* from, vtkPolyData* to)
{
  auto* text =
    vtkStringArray::SafeDownCast(from->GetFieldData()->GetAbstractArray(kLabelTextArray));
  if (!text)
  {
    return;
  }
  const LabelArrays source = label_arrays(from);
  const LabelArrays target = label_arrays(to);
  for (vtkIdType i = 0; i < source.text->GetNumberOfValues(); ++i)
  {
    target.text->InsertNextValue(source.text->GetValue(i));
    target.position->InsertNextTuple(source.position->GetTuple(i));
    target.height->InsertNextValue(source.height->GetValue(i));
    target.color->InsertNextTuple(source.color->GetTuple(i));
  }
}

MeshResourceLoader& mesh_resource_loader()
{
  static MeshResourceLoader loader;
  return loader;
}

std::mutex& mesh_resource_loader_mutex()
{
  static std::mutex mutex;
  return mutex;
}

/// The mesh of a MeshResource marker, scaled by scale (scene units) in the marker's frame;
/// `embedded` tells whether it kept the file's own colours as its scalars.
bool mesh_shape(const Marker& marker, double sx, double sy, double sz, vtkPolyData* out,
  bool* embedded, std::string* error)
{
  MeshResourceLoader loader;
  {
    std::lock_guard<std::mutex> lock(mesh_resource_loader_mutex());
    loader = mesh_resource_loader();
  }
  if (!loader)
  {
    *error = "mesh resource '" + marker.mesh_resource + "': no mesh loader in this process";
    return false;
  }
  if (marker.mesh_resource.empty())
  {
    *error = "a mesh resource marker needs a mesh_resource URI";
    return false;
  }
  vtkNew<vtkPolyData> mesh;
  if (!loader(marker.mesh_resource, mesh, error))
  {
    return false;
  }
  vtkNew<vtkTransform> stretch;
  stretch->Scale(sx, sy, sz);
  vtkNew<vtkTransformPolyDataFilter> scale;
  scale->SetInputData(mesh);
  scale->SetTransform(stretch);
  scale->Update();
  out->DeepCopy(scale->GetOutput());
  vtkDataArray* own = out->GetPointData()->GetScalars();
  *embedded = marker.mesh_use_embedded_materials && own &&
    own->GetDataType() == VTK_UNSIGNED_CHAR && own->GetNumberOfComponents() == 4;
  return true;
}

}

void set_mesh_resource_loader(MeshResourceLoader loader)
{
  std::lock_guard<std::mutex> lock(mesh_resource_loader_mutex());
  mesh_resource_loader() = std::move(loader);
}

bool marker_to_poly_data(
  const Marker& marker, double length_scale, vtkPolyData* poly_data, std::string* error)
{
  const char* where = "marker_to_poly_data";
  if (!poly_data)
  {
    return fail(error, where, "output poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  if (!detail::all_finite(marker.position, 3) || !detail::all_finite(marker.orientation, 4) ||
    !detail::all_finite(marker.scale, 3) || !detail::all_finite(marker.color, 4) ||
    !detail::all_finite(marker.colors.data(), static_cast<int>(marker.colors.size())))
  {
    return fail(error, where, "the pose, scale or colours have a NaN or infinite value");
  }
  const double* q = marker.orientation;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::fabs(norm - 1.0) > 1e-3)
  {
    return fail(error, where,
      "the orientation is not a unit quaternion (norm " + detail::number_text(norm) + ")");
  }
  if (marker.shape == MarkerShape::Text)
  {
    if (!(marker.scale[2] > 0))
    {
      return fail(error, where, "a text marker needs a positive scale.z (its height)");
    }
    poly_data->Initialize();
    const LabelArrays labels = label_arrays(poly_data);
    labels.text->InsertNextValue(marker.text);
    labels.position->InsertNextTuple3(marker.position[0] * length_scale,
      marker.position[1] * length_scale, marker.position[2] * length_scale);
    labels.height->InsertNextValue(marker.scale[2] * length_scale);
    unsigned char rgba[4];
    color_bytes(marker.color, rgba);
    labels.color->InsertNextTypedTuple(rgba);
    poly_data->Modified();
    return true;
  }
  // An arrow with two points goes from the first to the second (RViz's ArrowMarker): its scale
  // is shaft and head diameters and a head length that may be 0; with one point RViz draws
  // nothing and says why.
  const size_t point_count = marker.points.size() / 3;
  const bool arrow_from_two_points = marker.shape == MarkerShape::Arrow && point_count == 2;
  if (marker.shape == MarkerShape::Arrow && point_count != 0 && point_count != 2)
  {
    return fail(error, where,
      "an arrow marker takes two points (start and end) or none, not " +
        std::to_string(point_count));
  }
  if (arrow_from_two_points &&
    !(marker.scale[0] > 0 && marker.scale[1] > 0 && marker.scale[2] >= 0))
  {
    return fail(error, where,
      "an arrow marker with two points needs positive scale.x and scale.y (shaft and head "
      "diameters) and a scale.z (head length) of 0 or more");
  }
  if (marker.shape == MarkerShape::ArrowStrip &&
    !(marker.scale[0] > 0 && marker.scale[1] > 0 && marker.scale[2] >= 0))
  {
    return fail(error, where,
      "an arrow strip needs positive scale.x and scale.y (shaft and head diameters) and a "
      "scale.z (head length) of 0 or more");
  }
  const bool solid = (marker.shape == MarkerShape::Arrow && !arrow_from_two_points) ||
    marker.shape == MarkerShape::Cube || marker.shape == MarkerShape::Sphere ||
    marker.shape == MarkerShape::Cylinder || marker.shape == MarkerShape::CubeList ||
    marker.shape == MarkerShape::SphereList || marker.shape == MarkerShape::MeshResource;
  if (solid && (marker.scale[0] <= 0 || marker.scale[1] <= 0 || marker.scale[2] <= 0))
  {
    return fail(error, where, "a solid marker needs a positive scale on x, y and z");
  }
  const double sx = marker.scale[0] * length_scale, sy = marker.scale[1] * length_scale,
               sz = marker.scale[2] * length_scale;

  vtkNew<vtkPolyData> shape;   // in the marker's frame, scene units
  bool embeddedColors = false; // a mesh keeps its file's colours
  vtkIdType per_point = 1;     // drawn points per marker point (marker_colors)
  switch (marker.shape)
  {
    case MarkerShape::MeshResource:
    {
      std::string reason;
      if (!mesh_shape(marker, sx, sy, sz, shape, &embeddedColors, &reason))
      {
        return fail(error, where, reason);
      }
      break;
    }
    case MarkerShape::Arrow:
      if (arrow_from_two_points)
      {
        if (!detail::all_finite(marker.points.data(), 6))
        {
          return fail(error, where, "the points have a NaN or infinite coordinate");
        }
        const double from[3] = { marker.points[0] * length_scale, marker.points[1] * length_scale,
          marker.points[2] * length_scale };
        const double to[3] = { marker.points[3] * length_scale, marker.points[4] * length_scale,
          marker.points[5] * length_scale };
        if (!arrow_from_points(from, to, sx, sy, sz, shape))
        {
          return fail(error, where, "the two points of an arrow marker are the same point");
        }
        break;
      }
      solid_shape(marker.shape, sx, sy, sz, shape);
      break;
    case MarkerShape::Cube:
    case MarkerShape::Sphere:
    case MarkerShape::Cylinder:
      solid_shape(marker.shape, sx, sy, sz, shape);
      break;
    case MarkerShape::ArrowStrip:
    {
      // RViz's ArrowStripMarker (rviz_default_plugins/.../markers/arrow_strip_marker.cpp): one
      // arrow from each point to the next, sized as a two-point arrow, all in the marker's
      // colour; fewer than two points draw nothing ("Too few points to define an arrow strip").
      if (point_count < 2)
      {
        return fail(error, where,
          "an arrow strip needs two points or more, not " + std::to_string(point_count));
      }
      if (!detail::all_finite(marker.points.data(), static_cast<int>(marker.points.size())))
      {
        return fail(error, where, "the points have a NaN or infinite coordinate");
      }
      vtkNew<vtkAppendPolyData> strip;
      for (size_t i = 0; i + 1 < point_count; ++i)
      {
        const double* p = marker.points.data() + 3 * i;
        const double from[3] = { p[0] * length_scale, p[1] * length_scale, p[2] * length_scale };
        const double to[3] = { p[3] * length_scale, p[4] * length_scale, p[5] * length_scale };
        vtkNew<vtkPolyData> arrow;
        if (!arrow_from_points(from, to, sx, sy, sz, arrow))
        {
          return fail(error, where,
            "points " + std::to_string(i) + " and " + std::to_string(i + 1) +
              " of an arrow strip are the same point");
        }
        strip->AddInputData(arrow);
      }
      strip->Update();
      shape->ShallowCopy(strip->GetOutput());
      break;
    }
    case MarkerShape::TriangleList:
    {
      // RViz scales the triangles' scene node by scale (triangle_list_marker.cpp); it draws
      // nothing for no points or a count not divisible by 3.
      if (point_count == 0 || point_count % 3 != 0)
      {
        return fail(error, where,
          "a triangle list needs its points in threes (a positive multiple of 3), not " +
            std::to_string(point_count));
      }
      std::vector<double> scaled(marker.points);
      for (size_t i = 0; i < scaled.size(); ++i)
      {
        scaled[i] *= marker.scale[i % 3];
      }
      if (!xyz_to_polyline(scaled, length_scale, shape, error))
      {
        return false;
      }
      vtkNew<vtkCellArray> triangles;
      for (vtkIdType i = 0; i + 2 < shape->GetNumberOfPoints(); i += 3)
      {
        const vtkIdType corners[3] = { i, i + 1, i + 2 };
        triangles->InsertNextCell(3, corners);
      }
      shape->SetLines(nullptr);
      shape->SetPolys(triangles);
      break;
    }
    case MarkerShape::CubeList:
    case MarkerShape::SphereList:
    {
      // One solid per point, each centred on its point (RViz's CUBE_LIST / SPHERE_LIST).
      if (marker.points.size() % 3 != 0 ||
        !detail::all_finite(marker.points.data(), static_cast<int>(marker.points.size())))
      {
        return fail(error, where, "the points have a NaN or infinite coordinate");
      }
      vtkNew<vtkPolyData> unit;
      solid_shape(marker.shape == MarkerShape::CubeList ? MarkerShape::Cube : MarkerShape::Sphere,
        sx, sy, sz, unit);
      per_point = unit->GetNumberOfPoints();
      vtkNew<vtkAppendPolyData> all;
      for (size_t i = 0; i + 2 < marker.points.size(); i += 3)
      {
        vtkNew<vtkTransform> at;
        at->Translate(marker.points[i] * length_scale, marker.points[i + 1] * length_scale,
          marker.points[i + 2] * length_scale);
        vtkNew<vtkTransformPolyDataFilter> move;
        move->SetInputData(unit);
        move->SetTransform(at);
        move->Update();
        vtkNew<vtkPolyData> piece;
        piece->DeepCopy(move->GetOutput());
        all->AddInputData(piece);
      }
      if (marker.points.empty())
      {
        break; // no points: nothing drawn, as RViz
      }
      all->Update();
      shape->DeepCopy(all->GetOutput());
      break;
    }
    case MarkerShape::LineList:
    {
      if ((marker.points.size() / 3) % 2 != 0)
      {
        return fail(error, where,
          "a line list needs an even number of points (pairs), not " +
            std::to_string(marker.points.size() / 3));
      }
      if (!xyz_to_polyline(marker.points, length_scale, shape, error))
      {
        return false;
      }
      vtkNew<vtkCellArray> segments;
      for (vtkIdType i = 0; i + 1 < shape->GetNumberOfPoints(); i += 2)
      {
        const vtkIdType pair[2] = { i, i + 1 };
        segments->InsertNextCell(2, pair);
      }
      shape->SetLines(segments);
      break;
    }
    case MarkerShape::LineStrip:
    case MarkerShape::Points:
    {
      if (!xyz_to_polyline(marker.points, length_scale, shape, error))
      {
        return false;
      }
      if (marker.shape == MarkerShape::Points)
      {
        vtkNew<vtkCellArray> vertices;
        for (vtkIdType i = 0; i < shape->GetNumberOfPoints(); ++i)
        {
          vertices->InsertNextCell(1, &i);
        }
        shape->SetLines(nullptr);
        shape->SetVerts(vertices);
      }
      break;
    }
    default:
      return fail(error, where,
        "this marker type is not supported (supported: arrow, cube, "
        "sphere, cylinder, line strip, line list, cube list, sphere "
        "list, points, triangle list, text, mesh resource, arrow strip)");
  }

  vtkNew<vtkTransform> pose;
  pose->Translate(marker.position[0] * length_scale, marker.position[1] * length_scale,
    marker.position[2] * length_scale);
  vtkQuaterniond rotation(q[3] / norm, q[0] / norm, q[1] / norm, q[2] / norm);
  double axis[3];
  const double angle = rotation.GetRotationAngleAndAxis(axis);
  if (angle != 0.0)
  {
    pose->RotateWXYZ(vtkMath::DegreesFromRadians(angle), axis);
  }
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputData(shape);
  place->SetTransform(pose);
  place->Update();

  if (embeddedColors)
  {
    vtkSmartPointer<vtkDataArray> own = place->GetOutput()->GetPointData()->GetScalars();
    own->SetName("Color");
    poly_data->DeepCopy(place->GetOutput());
    poly_data->GetPointData()->SetScalars(own);
    poly_data->Modified();
    return true;
  }
  vtkSmartPointer<vtkUnsignedCharArray> color =
    marker_colors(marker, place->GetOutput()->GetNumberOfPoints(), per_point);
  poly_data->DeepCopy(place->GetOutput());
  poly_data->GetPointData()->SetScalars(color);
  poly_data->Modified();
  return true;
}

bool poly_data_to_marker(
  vtkPolyData* poly_data, double length_scale, Marker* marker, std::string* error)
{
  const char* where = "poly_data_to_marker";
  if (!poly_data || !marker)
  {
    return fail(error, where, poly_data ? "output marker is null" : "input poly data is null");
  }
  Marker out;
  const bool line = poly_data->GetLines() && poly_data->GetLines()->GetNumberOfCells() == 1;
  if (line)
  {
    if (!polyline_to_xyz(poly_data, length_scale, &out.points, error))
    {
      return false;
    }
  }
  else
  {
    vtkNew<vtkPolyData> pointsOnly;
    pointsOnly->SetPoints(poly_data->GetPoints());
    if (!polyline_to_xyz(pointsOnly, length_scale, &out.points, error))
    {
      return false;
    }
  }
  out.shape = line ? MarkerShape::LineStrip : MarkerShape::Points;
  for (double& s : out.scale)
  {
    s = 1.0 / length_scale;
  }
  vtkDataArray* color = poly_data->GetPointData()->GetArray("Color");
  if (color && color->GetNumberOfTuples() > 0 &&
    (color->GetNumberOfComponents() == 3 || color->GetNumberOfComponents() == 4))
  {
    const bool bytes = color->GetDataType() == VTK_UNSIGNED_CHAR;
    for (int c = 0; c < color->GetNumberOfComponents(); ++c)
    {
      const double v = color->GetComponent(0, c);
      out.color[c] = bytes ? v / 255.0 : v;
    }
  }
  *marker = std::move(out);
  return true;
}

bool MarkerSet::add(const std::string& ns, int id, const Marker& marker, std::string* error)
{
  const auto key = std::make_pair(ns, id);
  vtkNew<vtkPolyData> check;
  std::string reason;
  if (!marker_to_poly_data(marker, 1.0, check, &reason))
  {
    this->markers.erase(key);
    if (error)
    {
      *error = "marker (ns '" + ns + "', id " + std::to_string(id) + "): " + reason;
    }
    return false;
  }
  int64_t expires_at = 0;
  if (marker.lifetime > 0 && std::isfinite(marker.lifetime))
  {
    // At least 1 ns later, so that a stamp of 0 (a clock not yet running) still expires.
    expires_at = this->now + std::max<int64_t>(1, std::llround(marker.lifetime * 1e9));
  }
  this->dropped.erase(key);
  Kept kept;
  kept.marker = marker;
  kept.expires_at = expires_at;
  this->markers[key] = std::move(kept);
  return true;
}

bool MarkerSet::apply(const std::vector<Marker>& applied, std::string* error)
{
  bool ok = true;
  for (const Marker& marker : applied)
  {
    std::string reason;
    switch (marker.action)
    {
      case MarkerAction::DeleteAll:
        this->clear();
        continue;
      case MarkerAction::Delete:
        this->remove(marker.ns, marker.id);
        continue;
      case MarkerAction::Add:
        if (this->add(marker.ns, marker.id, marker, &reason))
        {
          continue;
        }
        break;
      case MarkerAction::Unknown:
        reason = "marker (ns '" + marker.ns + "', id " + std::to_string(marker.id) +
          "): unknown action " + std::to_string(marker.action_value);
        break;
    }
    if (ok && error)
    {
      *error = reason;
    }
    ok = false;
  }
  return ok;
}

bool MarkerSet::expire(int64_t now_nanoseconds)
{
  bool expired = false;
  for (auto it = this->markers.begin(); it != this->markers.end();)
  {
    if (it->second.expires_at != 0 && now_nanoseconds >= it->second.expires_at)
    {
      it = this->markers.erase(it);
      expired = true;
    }
    else
    {
      ++it;
    }
  }
  return expired;
}

namespace {

/// `marker` moved by `frame`: its pose (position in metres, orientation) composed after it.
Marker placed_in(const Marker& marker, const FramePose& frame)
{
  Marker out = marker;
  const vtkQuaterniond rotation(
    frame.rotation[3], frame.rotation[0], frame.rotation[1], frame.rotation[2]);
  double matrix[3][3];
  rotation.ToMatrix3x3(matrix);
  vtkMath::Multiply3x3(matrix, marker.position, out.position);
  for (int i = 0; i < 3; ++i)
  {
    out.position[i] += frame.translation[i];
  }
  const vtkQuaterniond own(
    marker.orientation[3], marker.orientation[0], marker.orientation[1], marker.orientation[2]);
  const vtkQuaterniond composed = rotation * own;
  out.orientation[0] = composed.GetX();
  out.orientation[1] = composed.GetY();
  out.orientation[2] = composed.GetZ();
  out.orientation[3] = composed.GetW();
  return out;
}

bool same_pose(const FramePose& a, const FramePose& b)
{
  return std::equal(a.translation, a.translation + 3, b.translation) &&
    std::equal(a.rotation, a.rotation + 4, b.rotation);
}

} // namespace

bool MarkerSet::place(
  Kept& kept, const FrameLookup& lookup, const std::string& fixed_frame, bool* too_old)
{
  const Marker& marker = kept.marker;
  FramePose pose;
  std::string reason;
  // RViz: a frame-locked marker follows the latest transform, the others their stamp.
  const int64_t stamp = marker.frame_locked ? 0 : marker.stamp_nanoseconds;
  const bool found = lookup && lookup(marker.frame_id, stamp, &pose, &reason);
  const bool changed = found != kept.located || (found && !same_pose(pose, kept.frame));
  kept.located = found;
  *too_old = !found && pose.older_than_history && !marker.frame_locked;
  if (found)
  {
    kept.frame = pose;
    kept.status.clear();
  }
  else
  {
    kept.status = "No transform from [" + marker.frame_id + "] to [" + fixed_frame + "]" +
      (reason.empty() ? std::string() : ": " + reason);
  }
  return changed;
}

bool MarkerSet::locate(const FrameLookup& lookup, const std::string& fixed_frame, bool all)
{
  bool changed = !this->placing && !this->markers.empty();
  this->placing = true;
  for (auto it = this->markers.begin(); it != this->markers.end();)
  {
    Kept& kept = it->second;
    if (all || !kept.located || kept.marker.frame_locked)
    {
      bool too_old = false;
      changed = this->place(kept, lookup, fixed_frame, &too_old) || changed;
      if (too_old)
      {
        this->dropped[it->first] = "dropped: its stamp is older than the tf history (" +
          kept.status + "); RViz's tf filter drops it too";
        it = this->markers.erase(it);
        continue;
      }
    }
    ++it;
  }
  return changed;
}

void MarkerSet::unlocate()
{
  this->placing = false;
  this->dropped.clear();
  for (auto& entry : this->markers)
  {
    entry.second.located = false;
    entry.second.status.clear();
  }
}

std::string MarkerSet::status() const
{
  std::string lines;
  if (!this->placing)
  {
    return lines;
  }
  const auto line = [&lines](const std::pair<std::string, int>& key, const std::string& reason) {
    lines += (lines.empty() ? "" : "\n") + std::string("marker (ns '") + key.first + "', id " +
      std::to_string(key.second) + "): " + reason;
  };
  for (const auto& entry : this->markers)
  {
    if (!entry.second.located && !entry.second.status.empty())
    {
      line(entry.first, entry.second.status);
    }
  }
  for (const auto& entry : this->dropped)
  {
    line(entry.first, entry.second);
  }
  return lines;
}

bool MarkerSet::remove(const std::string& ns, int id)
{
  return this->markers.erase(std::make_pair(ns, id)) != 0;
}

bool MarkerSet::to_poly_data(double length_scale, vtkPolyData* poly_data, std::string* error) const
{
  const char* where = "MarkerSet::to_poly_data";
  if (!poly_data)
  {
    return fail(error, where, "output poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  if (this->markers.empty())
  {
    poly_data->Initialize();
    return true;
  }
  vtkNew<vtkAppendPolyData> append;
  vtkNew<vtkPolyData> labels; // the Text markers' labels, in (ns, id) order
  int index = 0;
  for (const auto& entry : this->markers)
  {
    const Kept& kept = entry.second;
    if (this->placing && !kept.located)
    {
      continue; // its frame is not known in the fixed frame (status() says why)
    }
    vtkNew<vtkPolyData> piece;
    std::string reason;
    if (!marker_to_poly_data(this->placing ? placed_in(kept.marker, kept.frame) : kept.marker,
          length_scale, piece, &reason))
    {
      // add() checked it at scale 1; only a scale overflowing to infinity gets here.
      return fail(error, where,
        "marker (ns '" + entry.first.first + "', id " + std::to_string(entry.first.second) +
          "): " + reason);
    }
    copy_labels(piece, labels);
    if (piece->GetNumberOfPoints() == 0)
    {
      ++index;
      continue; // a label, or a list of no points: nothing to append (it has no colour array)
    }
    // Only the arrays every piece has survive the append: keep the colour, drop the rest.
    vtkDataArray* color = piece->GetPointData()->GetArray("Color");
    vtkSmartPointer<vtkDataArray> keep = color;
    piece->GetPointData()->Initialize();
    piece->GetPointData()->SetScalars(keep);
    piece->GetCellData()->Initialize();
    vtkNew<vtkIntArray> markerIndex;
    markerIndex->SetName("MarkerIndex");
    markerIndex->SetNumberOfTuples(piece->GetNumberOfCells());
    markerIndex->FillValue(index++);
    piece->GetCellData()->AddArray(markerIndex);
    append->AddInputData(piece);
  }
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    poly_data->ShallowCopy(append->GetOutput());
  }
  else
  {
    poly_data->Initialize();
  }
  poly_data->GetFieldData()->Initialize();
  copy_labels(labels, poly_data);
  return true;
}

} // namespace convert
} // namespace ros2vtk
