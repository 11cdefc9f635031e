#include "ros2vtk/convert/MultiArray.hpp"

#include "Validation.hpp"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTypeInt64Array.h>
#include <vtkVariant.h>

#include <cmath>
#include <limits>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

/// A multi-array layout reduced to a row-major grid: element (i, j) = data[offset + i*row_stride +
/// j].
struct Grid
{
  uint64_t rows = 0;
  uint64_t cols = 1;
  uint64_t row_stride = 1;
  uint64_t offset = 0;
  std::string row_label;
  std::string col_label;
};

bool resolve_grid(const MultiArrayLayout& layout, size_t data_size, const char* where,
  uint64_t max_columns, Grid* grid, std::string* error)
{
  Grid g;
  g.offset = layout.data_offset;
  switch (layout.dim.size())
  {
    case 0:
      if (g.offset > data_size)
      {
        return fail(error, where,
          "data_offset " + std::to_string(g.offset) + " is beyond the " +
            std::to_string(data_size) + " data values");
      }
      g.rows = data_size - g.offset;
      break;
    case 1:
    {
      const MultiArrayDimension& d = layout.dim[0];
      if (d.stride != 0 && d.stride < d.size)
      {
        return fail(error, where,
          "dim[0] ('" + d.label + "') has stride " + std::to_string(d.stride) +
            " smaller than its size " + std::to_string(d.size));
      }
      g.rows = d.size;
      g.row_label = d.label;
      break;
    }
    case 2:
    {
      const MultiArrayDimension& r = layout.dim[0];
      const MultiArrayDimension& c = layout.dim[1];
      if (c.stride != 0 && c.stride < c.size)
      {
        return fail(error, where,
          "dim[1] ('" + c.label + "') has stride " + std::to_string(c.stride) +
            " smaller than its size " + std::to_string(c.size));
      }
      g.rows = r.size;
      g.cols = c.size;
      g.row_stride = c.stride != 0 ? c.stride : c.size;
      g.row_label = r.label;
      g.col_label = c.label;
      break;
    }
    default:
      return fail(error, where,
        "layout has " + std::to_string(layout.dim.size()) +
          " dimensions; only 0, 1 or 2 map to VTK arrays and tables");
  }
  // Bounded before anything is allocated from these numbers: the sizes come off the wire.
  if (g.cols > max_columns)
  {
    return fail(error, where,
      "layout asks for " + std::to_string(g.cols) + " columns; at most " +
        std::to_string(max_columns) + " are taken");
  }
  if (g.cols == 0 && g.rows > 0)
  {
    // VTK holds no row without values (a data array has at least one component, a table's
    // rows are its columns' values): N x 0 would become N allocated values from no data.
    return fail(error, where,
      "layout has " + std::to_string(g.rows) + " rows of 0 columns (dim[1] size 0); a VTK " +
        "array or table cannot hold rows without values (send 0 rows for an empty matrix)");
  }
  if (g.rows > 0 && g.cols > 0)
  {
    const uint64_t last = g.offset + (g.rows - 1) * g.row_stride + (g.cols - 1);
    if (last >= data_size)
    {
      return fail(error, where,
        "layout (" + std::to_string(g.rows) + " x " + std::to_string(g.cols) + ", offset " +
          std::to_string(g.offset) + ", row stride " + std::to_string(g.row_stride) + ") needs " +
          std::to_string(last + 1) + " data values but there are " + std::to_string(data_size));
    }
  }
  *grid = std::move(g);
  return true;
}

template<typename T>
struct ArrayFor;
template<>
struct ArrayFor<int64_t>
{
  using type = vtkTypeInt64Array;
};
template<>
struct ArrayFor<double>
{
  using type = vtkDoubleArray;
};

std::string column_name(const std::string& label, uint64_t j)
{
  return label.empty() ? std::to_string(j) : label + "_" + std::to_string(j);
}

/// The dim[1] label that column_name() would have used, or "" when the names do not follow it.
std::string recover_column_label(vtkTable* table)
{
  const vtkIdType cols = table->GetNumberOfColumns();
  if (cols == 0)
  {
    return "";
  }
  const char* first = table->GetColumnName(0);
  const std::string first_name = first ? first : "";
  const std::string suffix = "_0";
  std::string label;
  if (first_name.size() > suffix.size() &&
    first_name.compare(first_name.size() - suffix.size(), suffix.size(), suffix) == 0)
  {
    label = first_name.substr(0, first_name.size() - suffix.size());
  }
  for (vtkIdType j = 0; j < cols; ++j)
  {
    const char* name = table->GetColumnName(j);
    if (!name || column_name(label, static_cast<uint64_t>(j)) != name)
    {
      return "";
    }
  }
  return label;
}

/// Reads one value of a numeric array as T. double: any numeric value. int64: integer arrays
/// exactly; floating arrays only when the value is a finite whole number in range.
bool read_value(vtkDataArray* array, vtkIdType index, int component, double* value, std::string*)
{
  *value = array->GetComponent(index, component);
  return true;
}

bool read_value(
  vtkDataArray* array, vtkIdType index, int component, int64_t* value, std::string* reason)
{
  const int type = array->GetDataType();
  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    const double v = array->GetComponent(index, component);
    // 2^63 is exactly representable; int64 holds [-2^63, 2^63).
    if (!std::isfinite(v) || std::floor(v) != v || v < -9223372036854775808.0 ||
      v >= 9223372036854775808.0)
    {
      *reason = "value " + detail::number_text(v) + " at row " + std::to_string(index) +
        " is not a whole number that fits int64";
      return false;
    }
    *value = static_cast<int64_t>(v);
    return true;
  }
  const vtkVariant variant =
    array->GetVariantValue(index * array->GetNumberOfComponents() + component);
  if ((type == VTK_UNSIGNED_LONG_LONG || type == VTK_UNSIGNED_LONG) &&
    variant.ToTypeUInt64() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max()))
  {
    *reason = "value at row " + std::to_string(index) + " does not fit int64";
    return false;
  }
  *value = variant.ToTypeInt64();
  return true;
}

template<typename T>
bool grid_to_table(
  const MultiArrayLayout& layout, const std::vector<T>& data, vtkTable* table, std::string* error)
{
  const char* where = "multi_array_to_table";
  if (!table)
  {
    return fail(error, where, "output table is null");
  }
  Grid g;
  if (!resolve_grid(layout, data.size(), where, kMaxTableColumns, &g, error))
  {
    return false;
  }
  std::vector<vtkSmartPointer<typename ArrayFor<T>::type>> columns;
  columns.reserve(g.cols);
  for (uint64_t j = 0; j < g.cols; ++j)
  {
    auto column = vtkSmartPointer<typename ArrayFor<T>::type>::New();
    column->SetName(column_name(g.col_label, j).c_str());
    column->SetNumberOfValues(static_cast<vtkIdType>(g.rows));
    auto* values = column->GetPointer(0); // vtkTypeInt64 may be long long, int64_t long
    for (uint64_t i = 0; i < g.rows; ++i)
    {
      values[i] = data[g.offset + i * g.row_stride + j];
    }
    columns.push_back(column);
  }
  table->Initialize();
  for (const auto& column : columns)
  {
    table->AddColumn(column);
  }
  table->Modified();
  return true;
}

template<typename T>
bool table_to_grid(
  vtkTable* table, MultiArrayLayout* layout, std::vector<T>* data, std::string* error)
{
  const char* where = "table_to_multi_array";
  if (!table || !layout || !data)
  {
    return fail(error, where, table ? "output layout or data is null" : "input table is null");
  }
  const vtkIdType rows = table->GetNumberOfRows();
  const vtkIdType cols = table->GetNumberOfColumns();
  if (static_cast<uint64_t>(rows) * static_cast<uint64_t>(cols) >
    std::numeric_limits<uint32_t>::max())
  {
    return fail(error, where, "table is too large for a multi-array (uint32 sizes)");
  }
  std::vector<T> values(static_cast<size_t>(rows * cols));
  for (vtkIdType j = 0; j < cols; ++j)
  {
    vtkDataArray* column = vtkDataArray::SafeDownCast(table->GetColumn(j));
    const char* name = table->GetColumnName(j);
    const std::string column_text =
      "column " + std::to_string(j) + (name ? std::string(" ('") + name + "')" : std::string());
    if (!column)
    {
      return fail(error, where, column_text + " is not a numeric data array");
    }
    if (column->GetNumberOfComponents() != 1)
    {
      return fail(error, where,
        column_text + " has " + std::to_string(column->GetNumberOfComponents()) +
          " components; table columns must have 1");
    }
    if (column->GetNumberOfTuples() != rows)
    {
      return fail(error, where,
        column_text + " has " + std::to_string(column->GetNumberOfTuples()) +
          " values but the table has " + std::to_string(rows) + " rows");
    }
    for (vtkIdType i = 0; i < rows; ++i)
    {
      std::string reason;
      if (!read_value(column, i, 0, &values[static_cast<size_t>(i * cols + j)], &reason))
      {
        return fail(error, where, column_text + ": " + reason);
      }
    }
  }
  MultiArrayLayout result;
  result.dim.resize(2);
  result.dim[0].label = "rows";
  result.dim[0].size = static_cast<uint32_t>(rows);
  result.dim[0].stride = static_cast<uint32_t>(rows * cols);
  result.dim[1].label = recover_column_label(table);
  result.dim[1].size = static_cast<uint32_t>(cols);
  result.dim[1].stride = static_cast<uint32_t>(cols);
  result.data_offset = 0;
  *layout = std::move(result);
  *data = std::move(values);
  return true;
}

template<typename T>
bool grid_to_array(const MultiArrayLayout& layout, const std::vector<T>& data,
  typename ArrayFor<T>::type* array, std::string* error)
{
  const char* where = "multi_array_to_array";
  if (!array)
  {
    return fail(error, where, "output array is null");
  }
  Grid g;
  if (!resolve_grid(layout, data.size(), where, kMaxArrayComponents, &g, error))
  {
    return false;
  }
  array->SetNumberOfComponents(static_cast<int>(g.cols));
  array->SetNumberOfTuples(static_cast<vtkIdType>(g.rows));
  auto* out = array->GetPointer(0);
  for (uint64_t i = 0; i < g.rows; ++i)
  {
    for (uint64_t j = 0; j < g.cols; ++j)
    {
      out[i * g.cols + j] = data[g.offset + i * g.row_stride + j];
    }
  }
  if (!g.row_label.empty())
  {
    array->SetName(g.row_label.c_str());
  }
  array->Modified();
  return true;
}

template<typename T>
bool array_to_grid(
  vtkDataArray* array, MultiArrayLayout* layout, std::vector<T>* data, std::string* error)
{
  const char* where = "array_to_multi_array";
  if (!array || !layout || !data)
  {
    return fail(error, where, array ? "output layout or data is null" : "input array is null");
  }
  const vtkIdType tuples = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  if (static_cast<uint64_t>(tuples) * static_cast<uint64_t>(components) >
    std::numeric_limits<uint32_t>::max())
  {
    return fail(error, where, "array is too large for a multi-array (uint32 sizes)");
  }
  std::vector<T> values(static_cast<size_t>(tuples) * static_cast<size_t>(components));
  for (vtkIdType i = 0; i < tuples; ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      std::string reason;
      if (!read_value(array, i, c, &values[static_cast<size_t>(i * components + c)], &reason))
      {
        return fail(error, where, reason);
      }
    }
  }
  MultiArrayLayout result;
  const char* name = array->GetName();
  const uint32_t n = static_cast<uint32_t>(tuples);
  const uint32_t k = static_cast<uint32_t>(components);
  result.dim.push_back({ name ? name : "", n, n * k });
  if (components > 1)
  {
    result.dim.push_back({ "components", k, k });
  }
  *layout = std::move(result);
  *data = std::move(values);
  return true;
}

} // namespace

bool multi_array_to_table(const MultiArrayLayout& layout, const std::vector<int64_t>& data,
  vtkTable* table, std::string* error)
{
  return grid_to_table(layout, data, table, error);
}

bool multi_array_to_table(const MultiArrayLayout& layout, const std::vector<double>& data,
  vtkTable* table, std::string* error)
{
  return grid_to_table(layout, data, table, error);
}

bool table_to_multi_array(
  vtkTable* table, MultiArrayLayout* layout, std::vector<int64_t>* data, std::string* error)
{
  return table_to_grid(table, layout, data, error);
}

bool table_to_multi_array(
  vtkTable* table, MultiArrayLayout* layout, std::vector<double>* data, std::string* error)
{
  return table_to_grid(table, layout, data, error);
}

bool multi_array_to_array(const MultiArrayLayout& layout, const std::vector<int64_t>& data,
  vtkTypeInt64Array* array, std::string* error)
{
  return grid_to_array(layout, data, array, error);
}

bool multi_array_to_array(const MultiArrayLayout& layout, const std::vector<double>& data,
  vtkDoubleArray* array, std::string* error)
{
  return grid_to_array(layout, data, array, error);
}

bool array_to_multi_array(
  vtkDataArray* array, MultiArrayLayout* layout, std::vector<int64_t>* data, std::string* error)
{
  return array_to_grid(array, layout, data, error);
}

bool array_to_multi_array(
  vtkDataArray* array, MultiArrayLayout* layout, std::vector<double>* data, std::string* error)
{
  return array_to_grid(array, layout, data, error);
}

} // namespace convert
} // namespace ros2vtk
