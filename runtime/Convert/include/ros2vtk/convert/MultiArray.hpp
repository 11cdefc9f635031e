// ros2vtk — std_msgs *MultiArray fields (layout + int64 or float64 data) <-> vtkTable and
// 1-D VTK data arrays.
//
// ROS layout convention (std_msgs/MultiArrayLayout): element [i][j] of a 2-D array is
// data[data_offset + dim[1].stride * i + j]; dim[0] counts rows, dim[1] columns. Publishers often
// leave strides at 0: a stride of 0 is read as "dense" (dim[1].stride = dim[1].size). A non-zero
// stride smaller than the size it spans is rejected.
//
// Table side: one column per ROS column, all of one type (vtkTypeInt64Array for Int64MultiArray,
// vtkDoubleArray for Float64MultiArray), named "<label>_<j>" when dim[1] has a label and "<j>"
// otherwise (j = 0, 1, ...). Going back, the label is recovered when every column is named that
// way, dim[0] is labelled "rows".
// Layouts with 0 dims (a bare data vector) or 1 dim become one column.
//
// No values are scaled: a multi-array carries no units.
// Every function returns false with a message on bad input and leaves its output untouched.
#ifndef ros2vtk_convert_MultiArray_hpp
#define ros2vtk_convert_MultiArray_hpp

#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkTable;
class vtkTypeInt64Array;

namespace ros2vtk {
namespace convert {

/// std_msgs/MultiArrayDimension.
struct MultiArrayDimension
{
  std::string label;
  uint32_t size = 0;
  uint32_t stride = 0;
};

/// std_msgs/MultiArrayLayout.
struct MultiArrayLayout
{
  std::vector<MultiArrayDimension> dim;
  uint32_t data_offset = 0;
};

/// A table gets one vtkDataArray per column, an array one component per column; a layout of 0
/// rows but 4e9 columns passes every bounds check against the data, so the column count is
/// capped: for tables at 1024, because vtkTable adds columns in linear time each (a 41-byte
/// message of 0 x 65536 took minutes: found by tests/fuzz), for arrays at 65536 components. A
/// layout of N rows and 0 columns is refused for both (VTK cannot hold it without allocating N
/// values that no data backs).
constexpr uint64_t kMaxTableColumns = 1024;
constexpr uint64_t kMaxArrayComponents = 65536;

/// Int64MultiArray / Float64MultiArray -> vtkTable (layout with 0, 1 or 2 dims; more is an
/// error). Fails when an index the layout names lies beyond the data, on a stride that cannot
/// hold its dimension, or beyond kMaxTableColumns columns. The table's columns are replaced.
bool multi_array_to_table(const MultiArrayLayout& layout, const std::vector<int64_t>& data,
  vtkTable* table, std::string* error);
bool multi_array_to_table(const MultiArrayLayout& layout, const std::vector<double>& data,
  vtkTable* table, std::string* error);

/// vtkTable -> 2-D layout (dim[0] rows, dim[1] columns, dense strides, data_offset 0) + data in
/// row-major order. Every column must be a one-component numeric vtkDataArray with the table's
/// row count. For int64 data, floating-point columns must hold whole numbers in int64 range.
/// Non-finite values are rejected for int64 and passed through for double.
bool table_to_multi_array(
  vtkTable* table, MultiArrayLayout* layout, std::vector<int64_t>* data, std::string* error);
bool table_to_multi_array(
  vtkTable* table, MultiArrayLayout* layout, std::vector<double>* data, std::string* error);

/// Int64MultiArray / Float64MultiArray -> 1-D array: with 0 or 1 dims a one-component array
/// (named from dim[0].label when there is one); with 2 dims an array of dim[0].size tuples of
/// dim[1].size components (strides honoured). The array's contents are replaced.
bool multi_array_to_array(const MultiArrayLayout& layout, const std::vector<int64_t>& data,
  vtkTypeInt64Array* array, std::string* error);
bool multi_array_to_array(const MultiArrayLayout& layout, const std::vector<double>& data,
  vtkDoubleArray* array, std::string* error);

/// Data array -> multi-array. One component: one dim {array name, n, n}; k > 1 components: two
/// dims {name, n, n*k}, {"components", k, k}. Any numeric array type is accepted (int64 output
/// applies the same whole-number rule as table_to_multi_array).
bool array_to_multi_array(
  vtkDataArray* array, MultiArrayLayout* layout, std::vector<int64_t>* data, std::string* error);
bool array_to_multi_array(
  vtkDataArray* array, MultiArrayLayout* layout, std::vector<double>* data, std::string* error);

} // namespace convert
} // namespace ros2vtk

#endif
