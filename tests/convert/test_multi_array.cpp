// std_msgs Int64MultiArray / Float64MultiArray <-> vtkTable and 1-D data arrays.
#include "ros2vtk/convert/MultiArray.hpp"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTypeInt64Array.h>

using namespace ros2vtk::convert;

namespace {

MultiArrayLayout two_d(const std::string& row_label, uint32_t rows, uint32_t row_stride,
  const std::string& col_label, uint32_t cols, uint32_t col_stride, uint32_t offset = 0)
{
  MultiArrayLayout layout;
  layout.dim.push_back({ row_label, rows, row_stride });
  layout.dim.push_back({ col_label, cols, col_stride });
  layout.data_offset = offset;
  return layout;
}

} // namespace

TEST(MultiArray, Int64TwoByThreeBecomesTwoRowThreeColumnTable)
{
  const std::vector<int64_t> data = { 1, 2, 3, 4, 5, 6 };
  vtkNew<vtkTable> table;
  std::string error;
  ASSERT_TRUE(multi_array_to_table(two_d("rows", 2, 6, "cols", 3, 3), data, table, &error))
    << error;
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  ASSERT_EQ(table->GetNumberOfColumns(), 3);
  EXPECT_STREQ(table->GetColumnName(0), "cols_0");
  EXPECT_STREQ(table->GetColumnName(1), "cols_1");
  EXPECT_STREQ(table->GetColumnName(2), "cols_2");
  ASSERT_NE(vtkTypeInt64Array::SafeDownCast(table->GetColumn(0)), nullptr);
  // Row-major: [[1, 2, 3], [4, 5, 6]].
  EXPECT_EQ(table->GetValue(0, 0).ToTypeInt64(), 1);
  EXPECT_EQ(table->GetValue(0, 2).ToTypeInt64(), 3);
  EXPECT_EQ(table->GetValue(1, 0).ToTypeInt64(), 4);
  EXPECT_EQ(table->GetValue(1, 1).ToTypeInt64(), 5);
  EXPECT_EQ(table->GetValue(1, 2).ToTypeInt64(), 6);

  MultiArrayLayout layout;
  std::vector<int64_t> back;
  ASSERT_TRUE(table_to_multi_array(table, &layout, &back, &error)) << error;
  EXPECT_EQ(back, data);
  ASSERT_EQ(layout.dim.size(), 2u);
  EXPECT_EQ(layout.dim[0].label, "rows");
  EXPECT_EQ(layout.dim[0].size, 2u);
  EXPECT_EQ(layout.dim[0].stride, 6u);
  EXPECT_EQ(layout.dim[1].label, "cols"); // recovered from the column names
  EXPECT_EQ(layout.dim[1].size, 3u);
  EXPECT_EQ(layout.dim[1].stride, 3u);
  EXPECT_EQ(layout.data_offset, 0u);
}

TEST(MultiArray, UnlabelledColumnsAreNumbered)
{
  const std::vector<double> data = { 0.5, -1.5, 2.5, 3.5 };
  vtkNew<vtkTable> table;
  ASSERT_TRUE(multi_array_to_table(two_d("", 2, 4, "", 2, 2), data, table, nullptr));
  EXPECT_STREQ(table->GetColumnName(0), "0");
  EXPECT_STREQ(table->GetColumnName(1), "1");
  ASSERT_NE(vtkDoubleArray::SafeDownCast(table->GetColumn(1)), nullptr);
  EXPECT_EQ(table->GetValue(0, 1).ToDouble(), -1.5);
  EXPECT_EQ(table->GetValue(1, 0).ToDouble(), 2.5);

  MultiArrayLayout layout;
  std::vector<double> back;
  ASSERT_TRUE(table_to_multi_array(table, &layout, &back, nullptr));
  EXPECT_EQ(back, data);
  EXPECT_EQ(layout.dim[1].label, "");
}

TEST(MultiArray, OffsetAndPaddedRowStrideAreHonoured)
{
  // offset 1, each row of 3 padded to 4: data = 99 | 1 2 3 -1 | 4 5 6 -1
  const std::vector<int64_t> data = { 99, 1, 2, 3, -1, 4, 5, 6, -1 };
  vtkNew<vtkTable> table;
  std::string error;
  ASSERT_TRUE(multi_array_to_table(two_d("r", 2, 8, "c", 3, 4, 1), data, table, &error)) << error;
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  ASSERT_EQ(table->GetNumberOfColumns(), 3);
  EXPECT_EQ(table->GetValue(0, 0).ToTypeInt64(), 1);
  EXPECT_EQ(table->GetValue(0, 2).ToTypeInt64(), 3);
  EXPECT_EQ(table->GetValue(1, 0).ToTypeInt64(), 4);
  EXPECT_EQ(table->GetValue(1, 2).ToTypeInt64(), 6);
}

TEST(MultiArray, ZeroStridesMeanDense)
{
  const std::vector<int64_t> data = { 1, 2, 3, 4, 5, 6 };
  vtkNew<vtkTable> table;
  ASSERT_TRUE(multi_array_to_table(two_d("", 3, 0, "", 2, 0), data, table, nullptr));
  ASSERT_EQ(table->GetNumberOfRows(), 3);
  ASSERT_EQ(table->GetNumberOfColumns(), 2);
  EXPECT_EQ(table->GetValue(2, 1).ToTypeInt64(), 6);
  EXPECT_EQ(table->GetValue(1, 0).ToTypeInt64(), 3);
}

TEST(MultiArray, LayoutWithoutDimsIsOneColumn)
{
  MultiArrayLayout layout;
  layout.data_offset = 1;
  vtkNew<vtkTable> table;
  ASSERT_TRUE(multi_array_to_table(layout, std::vector<double>{ 9, 7, 8 }, table, nullptr));
  ASSERT_EQ(table->GetNumberOfColumns(), 1);
  ASSERT_EQ(table->GetNumberOfRows(), 2);
  EXPECT_EQ(table->GetValue(0, 0).ToDouble(), 7);
  EXPECT_EQ(table->GetValue(1, 0).ToDouble(), 8);
}

TEST(MultiArray, BadLayoutsAreRejectedAndTableUntouched)
{
  vtkNew<vtkTable> table;
  ASSERT_TRUE(
    multi_array_to_table(two_d("", 1, 1, "", 1, 1), std::vector<int64_t>{ 5 }, table, nullptr));
  std::string error;

  EXPECT_FALSE(multi_array_to_table(
    two_d("rows", 2, 6, "cols", 3, 3), std::vector<int64_t>{ 1, 2, 3, 4, 5 }, table, &error));
  EXPECT_NE(error.find("needs 6 data values but there are 5"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(multi_array_to_table(
    two_d("rows", 2, 6, "cols", 3, 2), std::vector<int64_t>{ 1, 2, 3, 4, 5, 6 }, table, &error));
  EXPECT_NE(error.find("stride 2 smaller than its size 3"), std::string::npos) << error;

  MultiArrayLayout three = two_d("a", 1, 1, "b", 1, 1);
  three.dim.push_back({ "c", 1, 1 });
  error.clear();
  EXPECT_FALSE(multi_array_to_table(three, std::vector<int64_t>{ 1 }, table, &error));
  EXPECT_NE(error.find("3 dimensions"), std::string::npos) << error;

  MultiArrayLayout bare;
  bare.data_offset = 4;
  error.clear();
  EXPECT_FALSE(multi_array_to_table(bare, std::vector<int64_t>{ 1, 2 }, table, &error));
  EXPECT_NE(error.find("data_offset 4"), std::string::npos) << error;

  // 0 rows needs no data, but 4e9 empty columns must not be allocated.
  error.clear();
  EXPECT_FALSE(multi_array_to_table(
    two_d("rows", 0, 0, "cols", 4000000000u, 4000000000u), std::vector<int64_t>{}, table, &error));
  EXPECT_NE(error.find("at most 1024"), std::string::npos) << error;

  EXPECT_EQ(table->GetNumberOfColumns(), 1);
  EXPECT_EQ(table->GetValue(0, 0).ToTypeInt64(), 5);
}

// Issue 11.1: a 60-byte message with a 2^27 x 0 layout allocated 1 GiB (the bounds check was
// skipped for an empty dimension) and a bigger one aborted the process.
TEST(MultiArray, RowsOfZeroColumnsAreRefusedWithoutAllocating)
{
  const MultiArrayLayout layout = two_d("rows", 134217728u, 0, "cols", 0, 0);
  const std::string expected = "134217728 rows of 0 columns";
  std::string error;
  vtkNew<vtkDoubleArray> doubles;
  doubles->InsertNextValue(1.5);
  EXPECT_FALSE(multi_array_to_array(layout, std::vector<double>{}, doubles, &error));
  EXPECT_NE(error.find("multi_array_to_array: layout has " + expected), std::string::npos) << error;
  EXPECT_EQ(doubles->GetNumberOfTuples(), 1); // untouched on failure
  error.clear();
  vtkNew<vtkTypeInt64Array> ints;
  EXPECT_FALSE(multi_array_to_array(
    two_d("rows", 4294967295u, 0, "cols", 0, 7), std::vector<int64_t>{ 1, 2 }, ints, &error));
  EXPECT_NE(error.find("4294967295 rows of 0 columns"), std::string::npos) << error;
  error.clear();
  vtkNew<vtkTable> table;
  EXPECT_FALSE(multi_array_to_table(layout, std::vector<int64_t>{}, table, &error));
  EXPECT_NE(error.find("multi_array_to_table: layout has " + expected), std::string::npos) << error;
  // Huge empty arrays: 0 rows of 4e9 components is capped like table columns.
  error.clear();
  EXPECT_FALSE(multi_array_to_array(
    two_d("rows", 0, 0, "cols", 4000000000u, 4000000000u), std::vector<double>{}, doubles, &error));
  EXPECT_NE(error.find("at most 65536"), std::string::npos) << error;
  // 0 x N stays a valid empty matrix.
  ASSERT_TRUE(
    multi_array_to_array(two_d("rows", 0, 0, "cols", 3, 3), std::vector<double>{}, doubles, &error))
    << error;
  EXPECT_EQ(doubles->GetNumberOfTuples(), 0);
  EXPECT_EQ(doubles->GetNumberOfComponents(), 3);
}

// Found by tests/fuzz: a 0 x 65536 layout (41 bytes on the wire) made a table of 65536 columns,
// added in quadratic time (minutes). Bounded by count: 1024 columns read, 1025 are refused.
TEST(MultiArray, TableColumnsAreBoundedByCount)
{
  vtkNew<vtkTable> table;
  std::string error;
  ASSERT_TRUE(multi_array_to_table(
    two_d("rows", 0, 0, "c", 1024, 1024), std::vector<double>{}, table, &error))
    << error;
  EXPECT_EQ(table->GetNumberOfColumns(), 1024);
  EXPECT_FALSE(multi_array_to_table(
    two_d("rows", 0, 0, "c", 1025, 1025), std::vector<double>{}, table, &error));
  EXPECT_NE(error.find("layout asks for 1025 columns; at most 1024 are taken"), std::string::npos)
    << error;
  EXPECT_EQ(table->GetNumberOfColumns(), 1024); // untouched
}

TEST(MultiArray, EmptyTableKeepsItsColumns)
{
  vtkNew<vtkTable> table;
  ASSERT_TRUE(
    multi_array_to_table(two_d("", 0, 0, "c", 3, 3), std::vector<double>{}, table, nullptr));
  EXPECT_EQ(table->GetNumberOfColumns(), 3);
  EXPECT_EQ(table->GetNumberOfRows(), 0);
}

TEST(MultiArray, TableWithUnsuitableColumnsIsRejected)
{
  std::string error;
  MultiArrayLayout layout;
  std::vector<int64_t> ints;

  vtkNew<vtkTable> fractional;
  vtkNew<vtkDoubleArray> halves;
  halves->SetName("h");
  halves->InsertNextValue(2.0);
  halves->InsertNextValue(1.5);
  fractional->AddColumn(halves);
  EXPECT_FALSE(table_to_multi_array(fractional, &layout, &ints, &error));
  EXPECT_NE(error.find("column 0 ('h')"), std::string::npos) << error;
  EXPECT_NE(error.find("1.5"), std::string::npos) << error;

  // Whole doubles are fine for an Int64MultiArray; and the double overload takes the int column.
  halves->SetValue(1, -3.0);
  ASSERT_TRUE(table_to_multi_array(fractional, &layout, &ints, &error)) << error;
  EXPECT_EQ(ints, (std::vector<int64_t>{ 2, -3 }));

  vtkNew<vtkTable> with_text;
  vtkNew<vtkStringArray> text;
  text->SetName("names");
  text->InsertNextValue("a");
  with_text->AddColumn(text);
  error.clear();
  EXPECT_FALSE(table_to_multi_array(with_text, &layout, &ints, &error));
  EXPECT_NE(error.find("not a numeric data array"), std::string::npos) << error;

  vtkNew<vtkTable> vectors;
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->InsertNextTuple3(1, 2, 3);
  vectors->AddColumn(xyz);
  std::vector<double> doubles;
  error.clear();
  EXPECT_FALSE(table_to_multi_array(vectors, &layout, &doubles, &error));
  EXPECT_NE(error.find("3 components"), std::string::npos) << error;
}

TEST(MultiArray, OneDimToDoubleArrayAndBack)
{
  MultiArrayLayout layout;
  layout.dim.push_back({ "efforts", 3, 3 });
  const std::vector<double> data = { 1.5, -2.5, 3.25 };
  vtkNew<vtkDoubleArray> array;
  std::string error;
  ASSERT_TRUE(multi_array_to_array(layout, data, array, &error)) << error;
  EXPECT_STREQ(array->GetName(), "efforts");
  ASSERT_EQ(array->GetNumberOfTuples(), 3);
  EXPECT_EQ(array->GetNumberOfComponents(), 1);
  EXPECT_EQ(array->GetValue(0), 1.5);
  EXPECT_EQ(array->GetValue(1), -2.5);
  EXPECT_EQ(array->GetValue(2), 3.25);

  MultiArrayLayout back_layout;
  std::vector<double> back;
  ASSERT_TRUE(array_to_multi_array(array, &back_layout, &back, &error)) << error;
  EXPECT_EQ(back, data);
  ASSERT_EQ(back_layout.dim.size(), 1u);
  EXPECT_EQ(back_layout.dim[0].label, "efforts");
  EXPECT_EQ(back_layout.dim[0].size, 3u);
  EXPECT_EQ(back_layout.dim[0].stride, 3u);
  EXPECT_EQ(back_layout.data_offset, 0u);
}

TEST(MultiArray, Int64ArrayKeepsFullPrecision)
{
  const int64_t big = (int64_t{ 1 } << 62) + 1; // not representable as a double
  MultiArrayLayout layout;                      // no dims: the whole data vector
  vtkNew<vtkTypeInt64Array> array;
  ASSERT_TRUE(multi_array_to_array(layout, std::vector<int64_t>{ big, -7 }, array, nullptr));
  ASSERT_EQ(array->GetNumberOfTuples(), 2);
  EXPECT_EQ(array->GetValue(0), big);
  EXPECT_EQ(array->GetValue(1), -7);

  array->SetName("counts");
  MultiArrayLayout back_layout;
  std::vector<int64_t> back;
  ASSERT_TRUE(array_to_multi_array(array, &back_layout, &back, nullptr));
  EXPECT_EQ(back, (std::vector<int64_t>{ big, -7 }));
  EXPECT_EQ(back_layout.dim[0].label, "counts");
}

TEST(MultiArray, TwoDimsBecomeTuplesOfComponents)
{
  // A wrench-like 2 x 3 (two samples of 3 values), second row padded to stride 4.
  const std::vector<double> data = { 1, 2, 3, 0, 4, 5, 6 };
  vtkNew<vtkDoubleArray> array;
  std::string error;
  ASSERT_TRUE(multi_array_to_array(two_d("samples", 2, 8, "xyz", 3, 4), data, array, &error))
    << error;
  ASSERT_EQ(array->GetNumberOfTuples(), 2);
  ASSERT_EQ(array->GetNumberOfComponents(), 3);
  EXPECT_EQ(array->GetComponent(1, 0), 4);
  EXPECT_EQ(array->GetComponent(1, 2), 6);

  MultiArrayLayout layout;
  std::vector<double> back;
  ASSERT_TRUE(array_to_multi_array(array, &layout, &back, &error)) << error;
  EXPECT_EQ(back, (std::vector<double>{ 1, 2, 3, 4, 5, 6 }));
  ASSERT_EQ(layout.dim.size(), 2u);
  EXPECT_EQ(layout.dim[0].size, 2u);
  EXPECT_EQ(layout.dim[0].stride, 6u);
  EXPECT_EQ(layout.dim[1].size, 3u);
  EXPECT_EQ(layout.dim[1].stride, 3u);
}

TEST(MultiArray, ArrayErrors)
{
  std::string error;
  vtkNew<vtkDoubleArray> array;
  MultiArrayLayout layout;
  layout.dim.push_back({ "x", 4, 4 });
  EXPECT_FALSE(multi_array_to_array(layout, std::vector<double>{ 1, 2, 3 }, array, &error));
  EXPECT_NE(error.find("needs 4 data values but there are 3"), std::string::npos) << error;

  vtkNew<vtkDoubleArray> fractional;
  fractional->InsertNextValue(0.25);
  std::vector<int64_t> ints;
  error.clear();
  EXPECT_FALSE(array_to_multi_array(fractional, &layout, &ints, &error));
  EXPECT_NE(error.find("not a whole number"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(array_to_multi_array(nullptr, &layout, &ints, &error));
  EXPECT_NE(error.find("null"), std::string::npos) << error;
}
