#include "ros2vtk/convert/PointCloud2.hpp"

#include "ByteOrder.hpp"
#include "Validation.hpp"

#include <vtkAOSDataArrayTemplate.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

/// VTK scalar type holding one value of a PointField datatype (0 when unknown).
int vtk_type_of(uint8_t datatype)
{
  switch (datatype)
  {
    case point_field::kInt8:
      return VTK_SIGNED_CHAR;
    case point_field::kUInt8:
      return VTK_UNSIGNED_CHAR;
    case point_field::kInt16:
      return VTK_SHORT;
    case point_field::kUInt16:
      return VTK_UNSIGNED_SHORT;
    case point_field::kInt32:
      return VTK_INT;
    case point_field::kUInt32:
      return VTK_UNSIGNED_INT;
    case point_field::kFloat32:
      return VTK_FLOAT;
    case point_field::kFloat64:
      return VTK_DOUBLE;
    default:
      return 0;
  }
}

/// PointField datatype for a VTK array type (0 when PointField has none, e.g. 64-bit integers).
uint8_t datatype_of(int vtk_type)
{
  switch (vtk_type)
  {
    case VTK_SIGNED_CHAR:
      return point_field::kInt8;
    case VTK_CHAR:
      return std::numeric_limits<char>::is_signed ? point_field::kInt8 : point_field::kUInt8;
    case VTK_UNSIGNED_CHAR:
      return point_field::kUInt8;
    case VTK_SHORT:
      return point_field::kInt16;
    case VTK_UNSIGNED_SHORT:
      return point_field::kUInt16;
    case VTK_INT:
      return point_field::kInt32;
    case VTK_UNSIGNED_INT:
      return point_field::kUInt32;
    case VTK_FLOAT:
      return point_field::kFloat32;
    case VTK_DOUBLE:
      return point_field::kFloat64;
    default:
      return 0;
  }
}

/// Reads one value of `datatype` at p as double (used for the NaN test and for x, y, z).
template<typename Src>
double load_as_double(const uint8_t* p, bool swap)
{
  return static_cast<double>(detail::load_value<Src>(p, swap));
}

using LoadFn = double (*)(const uint8_t*, bool);

LoadFn loader_for(uint8_t datatype)
{
  switch (datatype)
  {
    case point_field::kInt8:
      return &load_as_double<int8_t>;
    case point_field::kUInt8:
      return &load_as_double<uint8_t>;
    case point_field::kInt16:
      return &load_as_double<int16_t>;
    case point_field::kUInt16:
      return &load_as_double<uint16_t>;
    case point_field::kInt32:
      return &load_as_double<int32_t>;
    case point_field::kUInt32:
      return &load_as_double<uint32_t>;
    case point_field::kFloat32:
      return &load_as_double<float>;
    default:
      return &load_as_double<double>;
  }
}

/// One coordinate for every listed point: dst[3*i + axis] = value * scale. Templated on the
/// source type so the datatype switch happens once per field, not once per point. Returns
/// whether some finite value became non-finite once scaled (an overflow, reported by the caller);
/// checked here, in the same pass, so a valid cloud is read once.
template<typename Src, typename Dst>
bool extract_coordinate(const uint8_t* data, const std::vector<size_t>& points, uint32_t offset,
  bool swap, double scale, int axis, Dst* dst)
{
  bool overflow = false;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const double value =
      static_cast<double>(detail::load_value<Src>(data + points[i] + offset, swap));
    const Dst out = detail::narrow_coordinate<Dst>(value * scale);
    dst[3 * i + axis] = out;
    overflow |= !std::isfinite(out) && std::isfinite(value);
  }
  return overflow;
}

template<typename Dst>
bool extract_coordinate_any(uint8_t datatype, const uint8_t* data,
  const std::vector<size_t>& points, uint32_t offset, bool swap, double scale, int axis, Dst* dst)
{
  switch (datatype)
  {
    case point_field::kInt8:
      return extract_coordinate<int8_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kUInt8:
      return extract_coordinate<uint8_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kInt16:
      return extract_coordinate<int16_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kUInt16:
      return extract_coordinate<uint16_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kInt32:
      return extract_coordinate<int32_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kUInt32:
      return extract_coordinate<uint32_t>(data, points, offset, swap, scale, axis, dst);
    case point_field::kFloat32:
      return extract_coordinate<float>(data, points, offset, swap, scale, axis, dst);
    default:
      return extract_coordinate<double>(data, points, offset, swap, scale, axis, dst);
  }
}

/// Copies a field's raw values (count per point, N bytes each) into a VTK array's memory.
template<int N>
void copy_field_values(const uint8_t* data, const std::vector<size_t>& points, uint32_t offset,
  uint32_t count, bool swap, uint8_t* dst)
{
  for (size_t i = 0; i < points.size(); ++i)
  {
    const uint8_t* src = data + points[i] + offset;
    for (uint32_t c = 0; c < count; ++c)
    {
      detail::copy_value<N>(src + c * N, dst, swap);
      dst += N;
    }
  }
}

void copy_field_values_any(size_t size, const uint8_t* data, const std::vector<size_t>& points,
  uint32_t offset, uint32_t count, bool swap, uint8_t* dst)
{
  switch (size)
  {
    case 1:
      copy_field_values<1>(data, points, offset, count, swap, dst);
      break;
    case 2:
      copy_field_values<2>(data, points, offset, count, swap, dst);
      break;
    case 4:
      copy_field_values<4>(data, points, offset, count, swap, dst);
      break;
    default:
      copy_field_values<8>(data, points, offset, count, swap, dst);
      break;
  }
}

std::string field_names(const std::vector<PointField>& fields)
{
  std::string names;
  for (const PointField& field : fields)
  {
    names += names.empty() ? "" : ", ";
    names += "'" + field.name + "'";
  }
  return names.empty() ? "none" : names;
}

/// Checks every field against point_step and returns the x, y, z fields.
bool check_fields(
  const PointCloud2Layout& layout, const char* where, const PointField* xyz[3], std::string* error)
{
  xyz[0] = xyz[1] = xyz[2] = nullptr;
  for (const PointField& field : layout.fields)
  {
    const size_t size = point_field_size(field.datatype);
    if (size == 0)
    {
      return fail(error, where,
        "field '" + field.name + "' has unknown datatype " + std::to_string(field.datatype) +
          " (PointField knows INT8=1, UINT8=2, INT16=3, UINT16=4, INT32=5, UINT32=6, FLOAT32=7, "
          "FLOAT64=8)");
    }
    if (field.count == 0)
    {
      return fail(error, where, "field '" + field.name + "' has count 0");
    }
    const uint64_t end = static_cast<uint64_t>(field.offset) + size * field.count;
    if (end > layout.point_step)
    {
      return fail(error, where,
        "field '" + field.name + "' (offset " + std::to_string(field.offset) + ", " +
          std::to_string(size * field.count) + " bytes) reaches past point_step " +
          std::to_string(layout.point_step));
    }
    const char* axes[3] = { "x", "y", "z" };
    for (int axis = 0; axis < 3; ++axis)
    {
      if (field.name == axes[axis])
      {
        if (field.count != 1)
        {
          return fail(error, where, "field '" + field.name + "' must have count 1");
        }
        xyz[axis] = &field;
      }
    }
  }
  if (!xyz[0] || !xyz[1] || !xyz[2])
  {
    return fail(error, where,
      "cloud needs fields 'x', 'y' and 'z' (fields: " + field_names(layout.fields) + ")");
  }
  return true;
}

} // namespace

size_t point_field_size(uint8_t datatype)
{
  switch (datatype)
  {
    case point_field::kInt8:
    case point_field::kUInt8:
      return 1;
    case point_field::kInt16:
    case point_field::kUInt16:
      return 2;
    case point_field::kInt32:
    case point_field::kUInt32:
    case point_field::kFloat32:
      return 4;
    case point_field::kFloat64:
      return 8;
    default:
      return 0;
  }
}

bool point_cloud2_to_poly_data(const PointCloud2Layout& layout, const uint8_t* data,
  size_t data_size, double length_scale, NonFinitePoints policy, vtkPolyData* poly_data,
  std::string* error)
{
  const char* where = "point_cloud2_to_poly_data";
  if (!poly_data)
  {
    return fail(error, where, "output poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  const PointField* xyz[3];
  if (!check_fields(layout, where, xyz, error))
  {
    return false;
  }
  const uint64_t row_bytes = static_cast<uint64_t>(layout.width) * layout.point_step;
  if (layout.row_step < row_bytes)
  {
    return fail(error, where,
      "row_step " + std::to_string(layout.row_step) + " is smaller than width " +
        std::to_string(layout.width) + " x point_step " + std::to_string(layout.point_step));
  }
  const uint64_t needed = static_cast<uint64_t>(layout.row_step) * layout.height;
  if (needed > data_size)
  {
    return fail(error, where,
      "data has " + std::to_string(data_size) + " bytes but row_step " +
        std::to_string(layout.row_step) + " x height " + std::to_string(layout.height) + " needs " +
        std::to_string(needed));
  }
  const uint64_t total = static_cast<uint64_t>(layout.width) * layout.height;
  if (total > 0 && !data)
  {
    return fail(error, where, "data pointer is null");
  }
  const bool swap = layout.is_bigendian != detail::host_is_big_endian();

  const bool float_points = xyz[0]->datatype == point_field::kFloat32 &&
    xyz[1]->datatype == point_field::kFloat32 && xyz[2]->datatype == point_field::kFloat32;
  // Byte offset of every point that is kept: the one per-cloud allocation all fields reuse.
  std::vector<size_t> points;
  points.reserve(static_cast<size_t>(total));
  const LoadFn load[3] = { loader_for(xyz[0]->datatype), loader_for(xyz[1]->datatype),
    loader_for(xyz[2]->datatype) };
  const uint32_t rows = layout.width == 0 ? 0 : layout.height; // width 0: nothing to visit
  for (uint32_t row = 0; row < rows; ++row)
  {
    for (uint32_t col = 0; col < layout.width; ++col)
    {
      const size_t base =
        static_cast<size_t>(row) * layout.row_step + static_cast<size_t>(col) * layout.point_step;
      if (policy != NonFinitePoints::Keep)
      {
        const uint8_t* p = data + base;
        const bool finite = std::isfinite(load[0](p + xyz[0]->offset, swap)) &&
          std::isfinite(load[1](p + xyz[1]->offset, swap)) &&
          std::isfinite(load[2](p + xyz[2]->offset, swap));
        if (!finite)
        {
          if (policy == NonFinitePoints::Reject)
          {
            return fail(error, where,
              "point " + std::to_string(static_cast<uint64_t>(row) * layout.width + col) +
                " (row " + std::to_string(row) + ", column " + std::to_string(col) +
                ") has a NaN or infinite coordinate");
          }
          continue;
        }
      }
      points.push_back(base);
    }
  }
  const vtkIdType count = static_cast<vtkIdType>(points.size());

  auto vtk_points = vtkSmartPointer<vtkPoints>::New();
  vtk_points->SetDataType(float_points ? VTK_FLOAT : VTK_DOUBLE);
  vtk_points->SetNumberOfPoints(count);
  void* coordinates = vtk_points->GetData()->GetVoidPointer(0);
  bool overflow = false;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (float_points)
    {
      overflow |= extract_coordinate_any(xyz[axis]->datatype, data, points, xyz[axis]->offset, swap,
        length_scale, axis, static_cast<float*>(coordinates));
    }
    else
    {
      overflow |= extract_coordinate_any(xyz[axis]->datatype, data, points, xyz[axis]->offset, swap,
        length_scale, axis, static_cast<double*>(coordinates));
    }
  }

  // The policy above is about the sender's NaN points; a finite coordinate that overflows once
  // scaled (1e306 m as float64, 1e37 m as float32 into mm) is an error whatever the policy
  // (issue 11.9). The extraction said whether there is one; only then is the cloud read again
  // to name the first.
  if (overflow)
  {
    const auto* out_float = static_cast<const float*>(coordinates);
    const auto* out_double = static_cast<const double*>(coordinates);
    for (size_t i = 0; i < points.size(); ++i)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        const double out = float_points ? out_float[3 * i + axis] : out_double[3 * i + axis];
        const double in = load[axis](data + points[i] + xyz[axis]->offset, swap);
        if (!std::isfinite(out) && std::isfinite(in))
        {
          return fail(error, where,
            "point at byte " + std::to_string(points[i]) + ": " + xyz[axis]->name + " = " +
              detail::number_text(in) + " is not finite once scaled by " +
              detail::number_text(length_scale) + (float_points ? " into float32" : ""));
        }
      }
    }
  }

  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  for (const PointField& field : layout.fields)
  {
    if (&field == xyz[0] || &field == xyz[1] || &field == xyz[2])
    {
      continue;
    }
    auto array = vtkSmartPointer<vtkDataArray>::Take(
      vtkDataArray::CreateDataArray(vtk_type_of(field.datatype)));
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(static_cast<int>(field.count));
    array->SetNumberOfTuples(count);
    copy_field_values_any(point_field_size(field.datatype), data, points, field.offset, field.count,
      swap, static_cast<uint8_t*>(array->GetVoidPointer(0)));
    arrays.push_back(array);
  }

  // One vertex cell per point (fixed cell size 1, connectivity 0 .. n-1) so the cloud renders.
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(count);
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + count, vtkIdType{ 0 });
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  vertices->SetData(1, connectivity);

  poly_data->Initialize();
  poly_data->SetPoints(vtk_points);
  poly_data->SetVerts(vertices);
  for (const auto& array : arrays)
  {
    poly_data->GetPointData()->AddArray(array);
  }
  poly_data->Modified();
  return true;
}

bool point_cloud2_to_poly_data(const PointCloud2Layout& layout, const std::vector<uint8_t>& data,
  double length_scale, NonFinitePoints policy, vtkPolyData* poly_data, std::string* error)
{
  return point_cloud2_to_poly_data(
    layout, data.data(), data.size(), length_scale, policy, poly_data, error);
}

bool poly_data_to_point_cloud2(vtkPolyData* poly_data, double length_scale,
  PointCloud2Layout* layout, std::vector<uint8_t>* data, std::string* error)
{
  const char* where = "poly_data_to_point_cloud2";
  if (!poly_data || !layout || !data)
  {
    return fail(
      error, where, poly_data ? "output layout or data is null" : "input poly data is null");
  }
  if (!detail::check_length_scale(length_scale, where, error))
  {
    return false;
  }
  vtkPoints* vtk_points = poly_data->GetPoints();
  const vtkIdType count = vtk_points ? vtk_points->GetNumberOfPoints() : 0;
  const bool double_points = vtk_points && vtk_points->GetDataType() == VTK_DOUBLE;
  const uint8_t coordinate_type = double_points ? point_field::kFloat64 : point_field::kFloat32;

  // Lay the fields out one after the other, each aligned to its value size.
  PointCloud2Layout result;
  std::vector<vtkDataArray*> sources; // parallel to result.fields after x, y, z
  size_t alignment = 1;
  uint32_t offset = 0;
  auto add_field = [&](const std::string& name, uint8_t datatype, uint32_t values) {
    const uint32_t size = static_cast<uint32_t>(point_field_size(datatype));
    offset = (offset + size - 1) / size * size;
    result.fields.push_back({ name, offset, datatype, values });
    offset += size * values;
    alignment = std::max<size_t>(alignment, size);
  };
  add_field("x", coordinate_type, 1);
  add_field("y", coordinate_type, 1);
  add_field("z", coordinate_type, 1);
  vtkPointData* point_data = poly_data->GetPointData();
  for (int a = 0; a < point_data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = point_data->GetArray(a);
    const uint8_t datatype = array ? datatype_of(array->GetDataType()) : 0;
    const char* name = array ? array->GetName() : nullptr;
    if (datatype == 0 || !name || !*name || array->GetNumberOfTuples() != count ||
      std::string(name) == "x" || std::string(name) == "y" || std::string(name) == "z")
    {
      continue; // cannot be described by a PointField (see header)
    }
    add_field(name, datatype, static_cast<uint32_t>(array->GetNumberOfComponents()));
    sources.push_back(array);
  }
  const uint64_t point_step = (offset + alignment - 1) / alignment * alignment;
  const uint64_t row_step = point_step * static_cast<uint64_t>(count);
  if (row_step > std::numeric_limits<uint32_t>::max())
  {
    return fail(error, where, "cloud is too large for PointCloud2 (row_step exceeds uint32)");
  }
  result.height = 1;
  result.width = static_cast<uint32_t>(count);
  result.point_step = static_cast<uint32_t>(point_step);
  result.row_step = static_cast<uint32_t>(row_step);
  result.is_bigendian = detail::host_is_big_endian();

  std::vector<uint8_t> bytes(static_cast<size_t>(row_step), 0);
  bool dense = true;
  double p[3];
  // The usual storage read directly; any other array type through its virtual GetPoint.
  auto* float_data =
    vtk_points ? vtkAOSDataArrayTemplate<float>::FastDownCast(vtk_points->GetData()) : nullptr;
  auto* double_data =
    vtk_points ? vtkAOSDataArrayTemplate<double>::FastDownCast(vtk_points->GetData()) : nullptr;
  const float* float_source = float_data ? float_data->GetPointer(0) : nullptr;
  const double* double_source = double_data ? double_data->GetPointer(0) : nullptr;
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (float_source)
    {
      p[0] = float_source[3 * i];
      p[1] = float_source[3 * i + 1];
      p[2] = float_source[3 * i + 2];
    }
    else if (double_source)
    {
      p[0] = double_source[3 * i];
      p[1] = double_source[3 * i + 1];
      p[2] = double_source[3 * i + 2];
    }
    else
    {
      vtk_points->GetPoint(i, p);
    }
    dense = dense && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    uint8_t* out = bytes.data() + static_cast<size_t>(i) * point_step;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double value = p[axis] / length_scale;
      if (double_points)
      {
        std::memcpy(out + result.fields[axis].offset, &value, sizeof(double));
      }
      else
      {
        const float narrow = static_cast<float>(value);
        std::memcpy(out + result.fields[axis].offset, &narrow, sizeof(float));
      }
    }
  }
  for (size_t s = 0; s < sources.size(); ++s)
  {
    const PointField& field = result.fields[3 + s];
    const size_t value_bytes = point_field_size(field.datatype) * field.count;
    const uint8_t* src = static_cast<const uint8_t*>(sources[s]->GetVoidPointer(0));
    for (vtkIdType i = 0; i < count; ++i)
    {
      std::memcpy(bytes.data() + static_cast<size_t>(i) * point_step + field.offset,
        src + static_cast<size_t>(i) * value_bytes, value_bytes);
    }
  }
  result.is_dense = dense;
  *layout = std::move(result);
  *data = std::move(bytes);
  return true;
}

} // namespace convert
} // namespace ros2vtk
