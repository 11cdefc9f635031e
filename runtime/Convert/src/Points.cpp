#include "ros2vtk/convert/Points.hpp"

#include "Validation.hpp"

#include <vtkDataArray.h>
#include <vtkPoints.h>
#include <vtkType.h>

#include <cmath>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

template<typename T>
struct VtkTypeOf;
template<>
struct VtkTypeOf<float>
{
  static constexpr int value = VTK_FLOAT;
};
template<>
struct VtkTypeOf<double>
{
  static constexpr int value = VTK_DOUBLE;
};

template<typename T>
bool finite_triple(const T* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

/// A finite coordinate that is not finite once scaled into T (1e37 m is a float, 1e40 mm is not).
template<typename T>
bool overflows(T value, double scale)
{
  return std::isfinite(value) && !detail::finite_in<T>(value * scale);
}

template<typename T>
bool to_points(const T* xyz, size_t count, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  const char* where = "xyz_to_points";
  if (!points)
  {
    return fail(error, where, "output points are null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  if (count > 0 && !xyz)
  {
    return fail(error, where, "xyz pointer is null");
  }
  // The policy is about the sender's NaN points; a finite coordinate that overflows once scaled
  // is an error whatever the policy (issue 11.9).
  for (size_t i = 0; i < 3 * count; ++i)
  {
    if (overflows(xyz[i], length_scale))
    {
      return fail(error, where,
        "point " + std::to_string(i / 3) + ": coordinate " + detail::number_text(xyz[i]) +
          " is not finite once scaled by " + detail::number_text(length_scale));
    }
  }
  size_t kept = count;
  if (policy != NonFinitePoints::Keep)
  {
    kept = 0;
    for (size_t i = 0; i < count; ++i)
    {
      if (finite_triple(xyz + 3 * i))
      {
        ++kept;
      }
      else if (policy == NonFinitePoints::Reject)
      {
        return fail(
          error, where, "point " + std::to_string(i) + " has a NaN or infinite coordinate");
      }
    }
  }
  points->SetDataType(VtkTypeOf<T>::value);
  points->SetNumberOfPoints(static_cast<vtkIdType>(kept));
  T* out = static_cast<T*>(points->GetData()->GetVoidPointer(0));
  for (size_t i = 0; i < count; ++i)
  {
    const T* p = xyz + 3 * i;
    if (kept != count && !finite_triple(p))
    {
      continue;
    }
    out[0] = detail::narrow_coordinate<T>(p[0] * length_scale);
    out[1] = detail::narrow_coordinate<T>(p[1] * length_scale);
    out[2] = detail::narrow_coordinate<T>(p[2] * length_scale);
    out += 3;
  }
  points->Modified();
  return true;
}

template<typename T>
bool vector_to_points(const std::vector<T>& xyz, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  if (xyz.size() % 3 != 0)
  {
    return fail(error, "xyz_to_points",
      std::to_string(xyz.size()) + " values is not a whole number of x, y, z triples");
  }
  return to_points(xyz.data(), xyz.size() / 3, length_scale, policy, points, error);
}

template<typename T>
bool from_points(vtkPoints* points, double length_scale, std::vector<T>* xyz, std::string* error)
{
  const char* where = "points_to_xyz";
  if (!points || !xyz)
  {
    return fail(error, where, points ? "output vector is null" : "input points are null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  const vtkIdType count = points->GetNumberOfPoints();
  xyz->resize(static_cast<size_t>(count) * 3);
  double p[3];
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      (*xyz)[static_cast<size_t>(i) * 3 + c] = static_cast<T>(p[c] / length_scale);
    }
  }
  return true;
}

} // namespace

bool xyz_to_points(const float* xyz, size_t count, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  return to_points(xyz, count, length_scale, policy, points, error);
}

bool xyz_to_points(const double* xyz, size_t count, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  return to_points(xyz, count, length_scale, policy, points, error);
}

bool xyz_to_points(const std::vector<float>& xyz, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  return vector_to_points(xyz, length_scale, policy, points, error);
}

bool xyz_to_points(const std::vector<double>& xyz, double length_scale, NonFinitePoints policy,
  vtkPoints* points, std::string* error)
{
  return vector_to_points(xyz, length_scale, policy, points, error);
}

bool points_to_xyz(
  vtkPoints* points, double length_scale, std::vector<float>* xyz, std::string* error)
{
  return from_points(points, length_scale, xyz, error);
}

bool points_to_xyz(
  vtkPoints* points, double length_scale, std::vector<double>* xyz, std::string* error)
{
  return from_points(points, length_scale, xyz, error);
}

} // namespace convert
} // namespace ros2vtk
