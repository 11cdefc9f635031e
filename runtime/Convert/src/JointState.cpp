#include "ros2vtk/convert/JointState.hpp"

#include "Validation.hpp"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

vtkSmartPointer<vtkDoubleArray> double_column(const char* name, const std::vector<double>& values)
{
  auto column = vtkSmartPointer<vtkDoubleArray>::New();
  column->SetName(name);
  column->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), column->GetPointer(0));
  return column;
}

/// Reads a numeric column (absent -> empty vector).
bool read_double_column(
  vtkTable* table, const char* name, std::vector<double>* values, std::string* error)
{
  vtkAbstractArray* column = table->GetColumnByName(name);
  values->clear();
  if (!column)
  {
    return true;
  }
  vtkDataArray* numbers = vtkDataArray::SafeDownCast(column);
  if (!numbers || numbers->GetNumberOfComponents() != 1)
  {
    return fail(error, "table_to_joint_state",
      std::string("column '") + name + "' must be a one-component numeric array");
  }
  values->resize(static_cast<size_t>(numbers->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < numbers->GetNumberOfTuples(); ++i)
  {
    (*values)[static_cast<size_t>(i)] = numbers->GetComponent(i, 0);
  }
  return true;
}

} // namespace

bool joint_state_to_table(const std::vector<std::string>& name, const std::vector<double>& position,
  const std::vector<double>& velocity, const std::vector<double>& effort, vtkTable* table,
  std::string* error)
{
  const char* where = "joint_state_to_table";
  if (!table)
  {
    return fail(error, where, "output table is null");
  }
  const size_t joints = std::max({ name.size(), position.size(), velocity.size(), effort.size() });
  const struct
  {
    const char* label;
    size_t size;
  } arrays[] = { { "name", name.size() }, { "position", position.size() },
    { "velocity", velocity.size() }, { "effort", effort.size() } };
  for (const auto& array : arrays)
  {
    if (array.size != 0 && array.size != joints)
    {
      return fail(error, where,
        std::string(array.label) + " has " + std::to_string(array.size) +
          " entries but another array has " + std::to_string(joints) +
          " (each array must match or be empty)");
    }
  }
  table->Initialize();
  if (!name.empty())
  {
    auto names = vtkSmartPointer<vtkStringArray>::New();
    names->SetName("name");
    names->SetNumberOfValues(static_cast<vtkIdType>(name.size()));
    for (size_t i = 0; i < name.size(); ++i)
    {
      names->SetValue(static_cast<vtkIdType>(i), name[i]);
    }
    table->AddColumn(names);
  }
  if (!position.empty())
  {
    table->AddColumn(double_column("position", position));
  }
  if (!velocity.empty())
  {
    table->AddColumn(double_column("velocity", velocity));
  }
  if (!effort.empty())
  {
    table->AddColumn(double_column("effort", effort));
  }
  table->Modified();
  return true;
}

bool table_to_joint_state(vtkTable* table, JointStateArrays* arrays, std::string* error)
{
  const char* where = "table_to_joint_state";
  if (!table || !arrays)
  {
    return fail(error, where, table ? "output arrays are null" : "input table is null");
  }
  JointStateArrays result;
  if (vtkAbstractArray* column = table->GetColumnByName("name"))
  {
    vtkStringArray* names = vtkStringArray::SafeDownCast(column);
    if (!names)
    {
      return fail(error, where, "column 'name' must be a vtkStringArray");
    }
    result.name.reserve(static_cast<size_t>(names->GetNumberOfValues()));
    for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i)
    {
      result.name.push_back(names->GetValue(i));
    }
  }
  if (!read_double_column(table, "position", &result.position, error) ||
    !read_double_column(table, "velocity", &result.velocity, error) ||
    !read_double_column(table, "effort", &result.effort, error))
  {
    return false;
  }
  *arrays = std::move(result);
  return true;
}

} // namespace convert
} // namespace ros2vtk
