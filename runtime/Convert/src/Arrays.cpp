// ros2vtk — numeric ROS arrays <-> vtkMatrix3x3 and one-component VTK arrays (Arrays.hpp).
#include "ros2vtk/convert/Arrays.hpp"

#include "Validation.hpp"

#include <vtkDataArray.h>
#include <vtkMatrix3x3.h>

#include <cmath>

namespace ros2vtk {
namespace convert {

using detail::fail;

bool values_to_matrix3x3(const double* values, vtkMatrix3x3* matrix, std::string* error)
{
  const char* where = "values_to_matrix3x3";
  if (!matrix || !values)
  {
    return fail(error, where, matrix ? "values pointer is null" : "output matrix is null");
  }
  if (!detail::all_finite(values, 9))
  {
    return fail(error, where, "a matrix element is NaN or infinite");
  }
  matrix->DeepCopy(values);
  matrix->Modified();
  return true;
}

bool matrix3x3_to_values(vtkMatrix3x3* matrix, double* values, std::string* error)
{
  const char* where = "matrix3x3_to_values";
  if (!matrix || !values)
  {
    return fail(error, where, matrix ? "output values pointer is null" : "input matrix is null");
  }
  const double* elements = matrix->GetData();
  if (!detail::all_finite(elements, 9))
  {
    return fail(error, where, "a matrix element is NaN or infinite");
  }
  for (int i = 0; i < 9; ++i)
  {
    values[i] = elements[i];
  }
  return true;
}

bool numbers_to_array(const double* values, size_t count, vtkDataArray* array, std::string* error)
{
  const char* where = "numbers_to_array";
  if (!array)
  {
    return fail(error, where, "output array is null");
  }
  if (count > 0 && !values)
  {
    return fail(error, where, "values pointer is null");
  }
  for (size_t i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return fail(error, where, "value " + std::to_string(i) + " is NaN or infinite");
    }
  }
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(static_cast<vtkIdType>(count));
  for (size_t i = 0; i < count; ++i)
  {
    array->SetTuple1(static_cast<vtkIdType>(i), values[i]);
  }
  array->Modified();
  return true;
}

bool array_to_numbers(
  vtkDataArray* array, const NumberLimits& limits, std::vector<double>* values, std::string* error)
{
  const char* where = "array_to_numbers";
  if (!array || !values)
  {
    return fail(error, where, array ? "output values pointer is null" : "input array is null");
  }
  const int components = array->GetNumberOfComponents();
  const vtkIdType tuples = array->GetNumberOfTuples();
  std::vector<double> out;
  out.reserve(static_cast<size_t>(tuples) * static_cast<size_t>(components));
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      const double value = array->GetComponent(t, c);
      const std::string index = std::to_string(out.size());
      if (!std::isfinite(value))
      {
        return fail(error, where, "value " + index + " is NaN or infinite");
      }
      if (value < limits.lowest || value > limits.highest)
      {
        return fail(error, where,
          "value " + index + " (" + detail::number_text(value) + ") is outside [" +
            detail::number_text(limits.lowest) + ", " + detail::number_text(limits.highest) + "]");
      }
      if (limits.integral && std::trunc(value) != value)
      {
        return fail(error, where,
          "value " + index + " (" + detail::number_text(value) + ") is not an integer");
      }
      out.push_back(value);
    }
  }
  *values = std::move(out);
  return true;
}

} // namespace convert
} // namespace ros2vtk
