#include "ros2vtk/convert/Values.hpp"

#include "Validation.hpp"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>

#include <cmath>

namespace ros2vtk {
namespace convert {

using detail::fail;

bool values_to_array(const double* values, size_t count, vtkDoubleArray* array, std::string* error)
{
  const char* where = "values_to_array";
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
  array->SetNumberOfValues(static_cast<vtkIdType>(count));
  for (size_t i = 0; i < count; ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  array->Modified();
  return true;
}

bool array_to_values(vtkDataArray* array, size_t count, double* values, std::string* error)
{
  const char* where = "array_to_values";
  if (!array || (count > 0 && !values))
  {
    return fail(error, where, array ? "output values pointer is null" : "input array is null");
  }
  const int components = array->GetNumberOfComponents();
  const size_t available = static_cast<size_t>(array->GetNumberOfTuples()) * components;
  if (available != count)
  {
    return fail(error, where,
      "array holds " + std::to_string(available) + " values, expected exactly " +
        std::to_string(count));
  }
  for (size_t i = 0; i < count; ++i)
  {
    const double value =
      array->GetComponent(static_cast<vtkIdType>(i / components), static_cast<int>(i % components));
    if (!std::isfinite(value))
    {
      return fail(error, where, "value " + std::to_string(i) + " is NaN or infinite");
    }
  }
  for (size_t i = 0; i < count; ++i)
  {
    values[i] =
      array->GetComponent(static_cast<vtkIdType>(i / components), static_cast<int>(i % components));
  }
  return true;
}

} // namespace convert
} // namespace ros2vtk
