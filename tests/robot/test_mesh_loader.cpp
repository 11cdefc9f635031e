// Tests of MeshLoader: each format, colours from the files, and malformed files giving a clear
// error. Expected numbers come from the files' own contents (written by hand, see their
// comments) or from the independent STL reader in robot_test_support.hpp.
#include "ros2vtk/robot/MeshLoader.hpp"

#include "robot_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>

#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace fs = std::filesystem;
using ros2vtk::robot::kVertexColorArray;
using ros2vtk::robot::MeshData;
using ros2vtk::robot::MeshLoader;

namespace {

const std::string kMeshes = ros2vtk_test::data_dir() + "/meshes";

void expect_bounds_near(
  const ros2vtk_test::Bounds& actual, const ros2vtk_test::Bounds& expected, double tolerance)
{
  for (size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(actual[i], expected[i], tolerance) << "bound " << i;
}

TEST(MeshLoader, BinaryStlMatchesTheIndependentlyParsedBounds)
{
  const std::string path = ros2vtk_test::robots_dir() + "/surgical_arm/meshes/base.stl";
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(path, &mesh, &error)) << error;
  expect_bounds_near(
    ros2vtk_test::bounds_of(mesh.polydata), ros2vtk_test::binary_stl_bounds(path), 1e-6);
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 12); // a box: 6 faces x 2 triangles
  EXPECT_FALSE(mesh.has_color);
  EXPECT_FALSE(mesh.has_vertex_colors);
}

TEST(MeshLoader, UpperCaseStlExtension)
{
  const std::string path = ros2vtk_test::robots_dir() + "/surgical_arm/meshes/instrument.STL";
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(path, &mesh, &error)) << error;
  expect_bounds_near(
    ros2vtk_test::bounds_of(mesh.polydata), ros2vtk_test::binary_stl_bounds(path), 1e-6);
}

TEST(MeshLoader, ColladaUnitNodeTransformAndDiffuseColour)
{
  // unit_cube_cm.dae: a cube of side 1 in centimetres, moved to z = 2 cm by its node, Z up,
  // diffuse (0.8, 0.2, 0.1, 1). In metres: x, y in [-0.005, 0.005], z in [0.015, 0.025].
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(ros2vtk_test::data_dir() + "/unit_cube_cm.dae", &mesh, &error))
    << error;
  expect_bounds_near(ros2vtk_test::bounds_of(mesh.polydata),
    { { -0.005, 0.005, -0.005, 0.005, 0.015, 0.025 } }, 1e-7);
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 12); // 6 quads, triangulated
  EXPECT_EQ(mesh.polydata->GetNumberOfPoints(), 8); // identical vertices joined
  ASSERT_TRUE(mesh.has_color);
  EXPECT_NEAR(mesh.color[0], 0.8, 1e-6);
  EXPECT_NEAR(mesh.color[1], 0.2, 1e-6);
  EXPECT_NEAR(mesh.color[2], 0.1, 1e-6);
  EXPECT_NEAR(mesh.color[3], 1.0, 1e-6);
  EXPECT_FALSE(mesh.has_vertex_colors);
}

TEST(MeshLoader, ObjWithTwoMaterialsGivesPerPointColours)
{
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/two_colours.obj", &mesh, &error)) << error;
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 4); // two quads, triangulated
  expect_bounds_near(ros2vtk_test::bounds_of(mesh.polydata), { { 0, 3, 0, 1, 0, 0 } }, 1e-9);
  ASSERT_TRUE(mesh.has_vertex_colors);
  EXPECT_FALSE(mesh.has_color);
  vtkDataArray* colors = mesh.polydata->GetPointData()->GetArray(kVertexColorArray);
  ASSERT_NE(colors, nullptr);
  ASSERT_EQ(colors->GetNumberOfComponents(), 4);
  int red = 0, blue = 0;
  for (vtkIdType i = 0; i < mesh.polydata->GetNumberOfPoints(); ++i)
  {
    const double x = mesh.polydata->GetPoint(i)[0];
    const double r = colors->GetComponent(i, 0), b = colors->GetComponent(i, 2);
    if (x < 1.5)
    {
      EXPECT_EQ(r, 255) << "point " << i;
      EXPECT_EQ(b, 0) << "point " << i;
      ++red;
    }
    else
    {
      EXPECT_EQ(r, 0) << "point " << i;
      EXPECT_EQ(b, 255) << "point " << i;
      ++blue;
    }
  }
  EXPECT_GT(red, 0);
  EXPECT_GT(blue, 0);
}

TEST(MeshLoader, ObjWithOneMaterialGivesOneColourAndRecordsTheTexture)
{
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/single_colour.obj", &mesh, &error)) << error;
  expect_bounds_near(
    ros2vtk_test::bounds_of(mesh.polydata), { { 0, 0.5, 0, 0.25, 0, 0.125 } }, 1e-9);
  ASSERT_TRUE(mesh.has_color);
  EXPECT_NEAR(mesh.color[0], 0.0, 1e-9);
  EXPECT_NEAR(mesh.color[1], 0.5, 1e-9);
  EXPECT_NEAR(mesh.color[2], 0.0, 1e-9);
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0], "green_texture.png");
}

TEST(MeshLoader, ObjWithoutMaterialsHasNoColour)
{
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/plain.obj", &mesh, &error)) << error;
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 2); // one quad
  expect_bounds_near(ros2vtk_test::bounds_of(mesh.polydata), { { 0, 1, 0, 1, 0, 0 } }, 1e-9);
  EXPECT_FALSE(mesh.has_color);
  EXPECT_FALSE(mesh.has_vertex_colors);
}

TEST(MeshLoader, ObjWhoseMaterialLibraryIsMissingStillLoadsItsGeometry)
{
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/missing_mtl.obj", &mesh, &error)) << error;
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 1);
  expect_bounds_near(ros2vtk_test::bounds_of(mesh.polydata), { { 0, 1, 0, 2, 0, 0 } }, 1e-9);
}

TEST(MeshLoader, GltfThroughAssimpWithNodeTransformAndBaseColour)
{
  // triangle.gltf: corners (0,0,0), (0.3,0,0), (0,0.2,0.1), node moved by z = 0.5, base colour
  // (0, 0.5, 0.5, 1).
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader::assimp_reads(".gltf"));
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/triangle.gltf", &mesh, &error)) << error;
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 1);
  expect_bounds_near(
    ros2vtk_test::bounds_of(mesh.polydata), { { 0, 0.3, 0, 0.2, 0.5, 0.6 } }, 1e-6);
  ASSERT_TRUE(mesh.has_color);
  EXPECT_NEAR(mesh.color[0], 0.0, 1e-6);
  EXPECT_NEAR(mesh.color[1], 0.5, 1e-6);
  EXPECT_NEAR(mesh.color[2], 0.5, 1e-6);
}

TEST(MeshLoader, PlyVertexColours)
{
  MeshData mesh;
  std::string error;
  ASSERT_TRUE(MeshLoader().load(kMeshes + "/coloured_vertices.ply", &mesh, &error)) << error;
  EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 1);
  expect_bounds_near(ros2vtk_test::bounds_of(mesh.polydata), { { 0, 0.2, 0, 0.3, 0, 0.1 } }, 1e-6);
  ASSERT_TRUE(mesh.has_vertex_colors);
  vtkDataArray* colors = mesh.polydata->GetPointData()->GetArray(kVertexColorArray);
  ASSERT_NE(colors, nullptr);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    const double* p = mesh.polydata->GetPoint(i);
    // The file gives red at the origin, green at x = 0.2, blue at y = 0.3.
    const int expected_channel = p[0] > 0.1 ? 1 : (p[1] > 0.1 ? 2 : 0);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(colors->GetComponent(i, c), c == expected_channel ? 255 : 0)
        << "point " << i << " channel " << c;
    EXPECT_EQ(colors->GetComponent(i, 3), 255);
  }
}

struct BadMesh
{
  const char* file;
  const char* expected_words;
};

void PrintTo(const BadMesh& bad, std::ostream* out)
{
  *out << bad.file;
}

class MalformedMesh : public ::testing::TestWithParam<BadMesh>
{
};

TEST_P(MalformedMesh, FailsWithAMessageNamingTheFile)
{
  const std::string path = kMeshes + "/" + GetParam().file;
  MeshData mesh;
  std::string error;
  EXPECT_FALSE(MeshLoader().load(path, &mesh, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(GetParam().expected_words), std::string::npos) << error;
  EXPECT_EQ(mesh.polydata, nullptr);
}

INSTANTIATE_TEST_SUITE_P(MeshLoader, MalformedMesh,
  ::testing::Values(BadMesh{ "empty.stl", "STL" }, BadMesh{ "truncated.stl", "STL" },
    BadMesh{ "garbage.dae", "is not well-formed XML" },
    BadMesh{ "mystery.notamesh", "not supported" },
    BadMesh{ "bad_header.ply", "line 6: unknown keyword 'prop/rty'" },
    BadMesh{ "truncated_body.ply", "does not match its header: line 11: 2 values" },
    BadMesh{ "does_not_exist.stl", "does not exist" },
    // Found by tests/fuzz: SIGBUS inside assimp 5.2 before the body check.
    BadMesh{ "extra_face_value.ply", "line 17: a face with no vertex indices" },
    // Found by tests/fuzz: assimp asked for 400 MB before the Collada check.
    BadMesh{ "corrupt_index_list.dae", "line 49: <p> holds '6" }));

// A PLY or Collada file written by the test, with the part of the message that says what is wrong.
struct WrittenMesh
{
  const char* name;
  std::string bytes;
  const char* expected_words; ///< nullptr: the file loads
};

void PrintTo(const WrittenMesh& written, std::ostream* out)
{
  *out << written.name;
}

std::string ply_header(const std::string& format, int vertices, int faces)
{
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
    std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

// Little- or big-endian bytes of a float or int32, as a PLY body holds them.
template<typename T>
std::string binary(T value, bool big_endian)
{
  std::string bytes(sizeof(T), '\0');
  std::memcpy(&bytes[0], &value, sizeof(T));
  if (big_endian) // this machine is little-endian (x86-64)
    std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

std::string binary_triangle(bool big_endian, int last_index, bool cut)
{
  std::string body;
  const float corners[3][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  for (const auto& corner : corners)
    for (float axis : corner)
      body += binary(axis, big_endian);
  body += std::string(1, '\3') + binary(0, big_endian) + binary(1, big_endian) +
    binary(last_index, big_endian);
  return cut ? body.substr(0, body.size() - 2) : body;
}

std::string collada(const std::string& positions_count, const std::string& accessor_count,
  const std::string& triangles_count, const std::string& indices)
{
  return R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count=")" +
    positions_count + R"(">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count=")" +
    accessor_count + R"(" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count=")" +
    triangles_count + R"("><input semantic="VERTEX" source="#v" offset="0"/><p>)" + indices +
    R"(</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

class CheckedMesh : public ::testing::TestWithParam<WrittenMesh>
{
};

TEST_P(CheckedMesh, LoadsOrNamesWhatIsWrong)
{
  const fs::path folder =
    fs::temp_directory_path() / ("ros2vtk_checked_" + std::to_string(std::random_device()()));
  fs::create_directories(folder);
  const std::string path = (folder / GetParam().name).string();
  std::ofstream(path, std::ios::binary) << GetParam().bytes;
  MeshData mesh;
  std::string error;
  const bool loaded = MeshLoader().load(path, &mesh, &error);
  fs::remove_all(folder);
  if (!GetParam().expected_words)
  {
    ASSERT_TRUE(loaded) << error;
    EXPECT_EQ(mesh.polydata->GetNumberOfPolys(), 1);
    return;
  }
  EXPECT_FALSE(loaded);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(GetParam().expected_words), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(MeshLoader, CheckedMesh,
  ::testing::Values(WrittenMesh{ "ascii_good.ply",
                      ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", nullptr },
    WrittenMesh{ "ascii_index_out_of_range.ply",
      ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
      "line 13: vertex index 3 is outside [0, 3)" },
    WrittenMesh{ "ascii_not_a_number.ply",
      ply_header("ascii", 3, 1) + "0 0 0\n1 0x1p3 0\n0 1 0\n3 0 1 2\n",
      "line 11: the value '0x1p3' of 'y' is not a number of its type" },
    WrittenMesh{ "ascii_count_beyond_file.ply", ply_header("ascii", 3, 999999) + "0 0 0\n",
      "the element 'face' announces 999999 records" },
    WrittenMesh{ "ascii_missing_records.ply",
      ply_header("ascii", 3, 2) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      "the body ends after 1 of 2 'face' records" },
    // Found by tests/fuzz: assimp 5.2's post-processing ended in SIGBUS on a face without indices.
    WrittenMesh{ "ascii_empty_face.ply", ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n0\n",
      "line 13: a face with no vertex indices" },
    WrittenMesh{ "binary_le_good.ply",
      ply_header("binary_little_endian", 3, 1) + binary_triangle(false, 2, false), nullptr },
    WrittenMesh{ "binary_be_good.ply",
      ply_header("binary_big_endian", 3, 1) + binary_triangle(true, 2, false), nullptr },
    WrittenMesh{ "binary_index_out_of_range.ply",
      ply_header("binary_little_endian", 3, 1) + binary_triangle(false, -1, false),
      "vertex index -1 is outside [0, 3)" },
    WrittenMesh{ "binary_cut.ply",
      ply_header("binary_big_endian", 3, 1) + binary_triangle(true, 2, true),
      "the body ends inside 'face' record 0 of 1" },
    WrittenMesh{ "good.dae", collada("9", "3", "1", "0 1 2"), nullptr },
    WrittenMesh{ "array_count.dae", collada("90000000", "3", "1", "0 1 2"),
      "<float_array> announces 90000000 values but holds 9" },
    WrittenMesh{ "accessor_beyond_array.dae", collada("9", "30000000", "1", "0 1 2"),
      "<accessor> reads 30000000 x 3 values from '#pa', which holds 9" },
    WrittenMesh{ "triangle_count.dae", collada("9", "3", "5000000", "0 1 2"),
      "<triangles> holds 3 indices where its count and inputs announce 15000000" },
    // Found by the mutation test: assimp 5.2 crashed on an array without its count.
    WrittenMesh{ "array_without_count.dae",
      replaced(collada("9", "3", "1", "0 1 2"), "count=\"9\"", "couPPnt=\"9\""),
      "<float_array> has no count" },
    WrittenMesh{ "index_not_a_number.dae", collada("9", "3", "1", "0 1 -2"),
      "<p> holds '-2', which is not an index" },
    // Numbers decided without strtold (plain decimals, short indices) and with it (exponents,
    // long digit strings) must agree with what strtold reads whole and finite.
    WrittenMesh{ "floats_plain_and_exponent.dae",
      replaced(
        collada("9", "3", "1", "0 1 2"), "0 0 0 1 0 0 0 1 0", "+.5 -0. 0 1e0 0 0 -1.5E-3 1 0"),
      nullptr },
    WrittenMesh{ "float_exponent_overflow.dae",
      replaced(collada("9", "3", "1", "0 1 2"), "0 0 0 1 0 0 0 1 0", "0 0 0 1 0 0 0 1e99999 0"),
      "holds '1e99999', which is not a number of its kind" },
    WrittenMesh{ "float_two_points.dae",
      replaced(collada("9", "3", "1", "0 1 2"), "0 0 0 1 0 0 0 1 0", "0 0 0 1.2.3 0 0 0 1 0"),
      "holds '1.2.3', which is not a number of its kind" },
    WrittenMesh{ "float_sign_alone.dae",
      replaced(collada("9", "3", "1", "0 1 2"), "0 0 0 1 0 0 0 1 0", "0 0 0 - 0 0 0 1 0"),
      "holds '-', which is not a number of its kind" },
    WrittenMesh{
      "index_long_digits.dae", collada("9", "3", "1", "0 00000000000000000000001 2"), nullptr },
    WrittenMesh{ "index_beyond_int.dae", collada("9", "3", "1", "0 1 2147483648"),
      "<p> holds '2147483648', which is not an index" }),
  [](const ::testing::TestParamInfo<WrittenMesh>& param_info) {
    std::string name = param_info.param.name;
    std::replace(name.begin(), name.end(), '.', '_');
    return name;
  });

// Mutated copies of good files (bytes overwritten, files cut short, bytes inserted) must load or
// fail with a message, never crash or hang; run under AddressSanitizer this found the crashes
// that keep PLY and OBJ away from VTK's readers. Collada is in since its arrays and counts are
// checked before assimp reads them.
class MutatedMesh : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MutatedMesh, LoadsOrFailsWithAMessage)
{
  const std::string source = GetParam();
  std::ifstream in(source, std::ios::binary);
  const std::string original(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(original.empty()) << source;
  std::random_device seed;
  const fs::path folder = fs::temp_directory_path() / ("ros2vtk_mutated_" + std::to_string(seed()));
  fs::create_directories(folder);
  const std::string path = (folder / ("mutated" + fs::path(source).extension().string())).string();
  std::mt19937 random(20261123); // fixed: the same mutations on every run
  int loaded = 0;
  for (int round = 0; round < 150; ++round)
  {
    std::string bytes = original;
    switch (round % 3)
    {
      case 0:
        for (int k = 0; k < 4; ++k)
          bytes[random() % bytes.size()] = static_cast<char>(random());
        break;
      case 1:
        bytes.resize(random() % bytes.size());
        break;
      default:
        bytes.insert(
          random() % bytes.size(), std::string(1 + random() % 8, static_cast<char>(random())));
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    MeshData mesh;
    std::string error;
    if (MeshLoader().load(path, &mesh, &error))
    {
      ++loaded;
      ASSERT_NE(mesh.polydata, nullptr) << "round " << round;
      EXPECT_GT(mesh.polydata->GetNumberOfPolys(), 0) << "round " << round;
    }
    else
    {
      EXPECT_NE(error.find(path), std::string::npos) << "round " << round << ": " << error;
    }
  }
  fs::remove_all(folder);
  RecordProperty("loaded", loaded);
}

INSTANTIATE_TEST_SUITE_P(MeshLoader, MutatedMesh,
  ::testing::Values(ros2vtk_test::robots_dir() + "/surgical_arm/meshes/wrist.stl",
    kMeshes + "/coloured_vertices.ply", kMeshes + "/two_colours.obj", kMeshes + "/triangle.gltf",
    ros2vtk_test::data_dir() + "/unit_cube_cm.dae"),
  [](const ::testing::TestParamInfo<std::string>& param_info) {
    return fs::path(param_info.param).extension().string().substr(1);
  });

} // namespace
