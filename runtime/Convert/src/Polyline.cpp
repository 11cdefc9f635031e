// ros2vtk — flat x/y/z positions <-> a vtkPolyData with one polyline cell (Polyline.hpp).
#include "ros2vtk/convert/Polyline.hpp"

#include "Validation.hpp"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>

namespace ros2vtk {
namespace convert {

using detail::fail;

bool xyz_to_polyline(
  const std::vector<double>& xyz, double length_scale, vtkPolyData* polyline, std::string* error)
{
  const char* where = "xyz_to_polyline";
  if (!polyline)
  {
    return fail(error, where, "output poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  if (xyz.size() % 3 != 0)
  {
    return fail(error, where, std::to_string(xyz.size()) + " coordinates are not x, y, z triples");
  }
  for (size_t i = 0; i < xyz.size(); ++i)
  {
    if (!std::isfinite(xyz[i]) || !std::isfinite(xyz[i] * length_scale))
    {
      return fail(error, where,
        "point " + std::to_string(i / 3) + " has a NaN, infinite or too large coordinate");
    }
  }
  const vtkIdType count = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(
      i, xyz[3 * i] * length_scale, xyz[3 * i + 1] * length_scale, xyz[3 * i + 2] * length_scale);
  }
  vtkNew<vtkCellArray> lines;
  if (count >= 2)
  {
    lines->InsertNextCell(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      lines->InsertCellPoint(i);
    }
  }
  polyline->Initialize();
  polyline->SetPoints(points);
  polyline->SetLines(lines);
  polyline->Modified();
  return true;
}

bool polyline_to_xyz(
  vtkPolyData* polyline, double length_scale, std::vector<double>* xyz, std::string* error)
{
  const char* where = "polyline_to_xyz";
  if (!polyline || !xyz)
  {
    return fail(error, where, polyline ? "output vector is null" : "input poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  vtkPoints* points = polyline->GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  vtkNew<vtkIdList> ids;
  vtkCellArray* lines = polyline->GetLines();
  const vtkIdType lineCount = lines ? lines->GetNumberOfCells() : 0;
  if (lineCount > 1)
  {
    return fail(error, where,
      "the poly data has " + std::to_string(lineCount) + " line cells, a path is one");
  }
  if (lineCount == 1)
  {
    lines->GetCellAtId(0, ids);
  }
  else
  {
    ids->SetNumberOfIds(pointCount);
    for (vtkIdType i = 0; i < pointCount; ++i)
    {
      ids->SetId(i, i);
    }
  }
  std::vector<double> out;
  out.reserve(3 * static_cast<size_t>(ids->GetNumberOfIds()));
  for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
  {
    const vtkIdType id = ids->GetId(i);
    if (id < 0 || id >= pointCount)
    {
      return fail(error, where, "line cell point id " + std::to_string(id) + " is not a point");
    }
    double p[3];
    points->GetPoint(id, p);
    if (!detail::all_finite(p, 3))
    {
      return fail(error, where, "point " + std::to_string(id) + " is NaN or infinite");
    }
    out.push_back(p[0] / length_scale);
    out.push_back(p[1] / length_scale);
    out.push_back(p[2] / length_scale);
  }
  *xyz = std::move(out);
  return true;
}

} // namespace convert
} // namespace ros2vtk
