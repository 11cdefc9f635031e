// Tests of RobotLoader: the shipped surgical arm (every visual, counts, colours, mesh bounds
// against an independent STL reader), URI forms, materials, missing meshes and broken URDFs.
#include "ros2vtk/robot/RobotLoader.hpp"

#include "robot_test_support.hpp"

#include <gtest/gtest.h>

#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <chrono>
#include <memory>

#include <ostream>

#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace ros2vtk::robot;

namespace {

RobotLoader loader_with_shipped_robots()
{
  ResourceResolver resolver;
  resolver.add_search_path(ros2vtk_test::robots_dir());
  return RobotLoader(resolver);
}

void expect_bounds_near(const ros2vtk_test::Bounds& actual, const ros2vtk_test::Bounds& expected,
  double tolerance, const std::string& what)
{
  for (size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(actual[i], expected[i], tolerance) << what << ", bound " << i;
}

// Colours from mesh files come through single-precision floats (assimp), hence the default.
void expect_rgba(const std::array<double, 4>& actual, const std::array<double, 4>& expected,
  const std::string& what, double tolerance = 1e-9)
{
  for (size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(actual[i], expected[i], tolerance) << what << ", channel " << i;
}

// What examples/robots/make_surgical_arm.py writes, restated here by hand.
struct ExpectedVisual
{
  VisualKind kind;
  const char* mesh_file; // under surgical_arm/meshes, or nullptr
  double scale;
  std::array<double, 4> rgba;
};
const std::array<double, 4> kSlate{ { 0.25, 0.28, 0.32, 1.0 } }, kWhite{ { 0.92, 0.92, 0.9, 1.0 } },
  kBlue{ { 0.15, 0.35, 0.75, 1.0 } }, kSteel{ { 0.7, 0.72, 0.75, 1.0 } },
  kSignal{ { 0.95, 0.45, 0.1, 1.0 } };
const std::vector<std::pair<std::string, std::vector<ExpectedVisual>>> kSurgicalArm = {
  { "base_link",
    { { VisualKind::Mesh, "base.stl", 1.0, kSlate },
      { VisualKind::Cylinder, nullptr, 0, kSignal } } },
  { "column_link", { { VisualKind::Mesh, "column.stl", 0.001, kWhite } } },
  { "upper_arm_link",
    { { VisualKind::Sphere, nullptr, 0, kBlue },
      { VisualKind::Mesh, "upper_arm.stl", 1.0, kWhite } } },
  { "forearm_link",
    { { VisualKind::Sphere, nullptr, 0, kBlue },
      { VisualKind::Mesh, "forearm.stl", 0.001, kWhite } } },
  { "wrist_link", { { VisualKind::Mesh, "wrist.stl", 1.0, kSlate } } },
  { "instrument_link", { { VisualKind::Mesh, "instrument.STL", 1.0, kSteel } } },
  { "needle_guide_link", { { VisualKind::Mesh, "needle_guide.stl", 0.001, kSignal } } },
  { "needle_tip", { { VisualKind::Box, nullptr, 0, kSignal } } },
};

TEST(RobotLoader, SurgicalArmLoadsEveryVisualWithItsColourAndMeshBounds)
{
  RobotLoader loader = loader_with_shipped_robots();
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::surgical_arm_urdf(), &robot, &error)) << error;
  EXPECT_EQ(robot.robot_name, "surgical_arm");
  EXPECT_EQ(robot.root_link, "base_link");
  EXPECT_TRUE(robot.warnings().empty()) << robot.warnings().front();
  EXPECT_EQ(robot.placeholder_count(), 0u);
  EXPECT_EQ(robot.visual_count(), 11u);
  ASSERT_EQ(robot.links.size(), kSurgicalArm.size());
  for (size_t l = 0; l < kSurgicalArm.size(); ++l)
  {
    const auto& [link_name, expected] = kSurgicalArm[l];
    const LinkVisuals& link = robot.links[l];
    EXPECT_EQ(link.link, link_name) << "links come parents first";
    ASSERT_EQ(link.visuals.size(), expected.size()) << link_name;
    for (size_t v = 0; v < expected.size(); ++v)
    {
      const std::string what = link_name + " visual " + std::to_string(v);
      const LinkVisual& visual = link.visuals[v];
      EXPECT_EQ(visual.kind, expected[v].kind) << what;
      ASSERT_NE(visual.geometry, nullptr) << what;
      EXPECT_GT(visual.geometry->GetNumberOfPolys(), 0) << what;
      ASSERT_TRUE(visual.has_material_color) << what;
      expect_rgba(visual.material_color, expected[v].rgba, what);
      expect_rgba(visual.display_color(), expected[v].rgba, what);
      if (expected[v].mesh_file)
      {
        const std::string file =
          ros2vtk_test::robots_dir() + "/surgical_arm/meshes/" + expected[v].mesh_file;
        const double s = expected[v].scale;
        EXPECT_EQ(visual.mesh_path, fs::canonical(file).string()) << what;
        EXPECT_EQ(visual.mesh_scale, (std::array<double, 3>{ { s, s, s } })) << what;
        expect_bounds_near(ros2vtk_test::bounds_of(visual.geometry),
          ros2vtk_test::binary_stl_bounds(file, { { s, s, s } }), 1e-6, what);
      }
    }
  }
}

TEST(RobotLoader, SurgicalArmMeshesInMillimetresComeOutInMetres)
{
  RobotLoader loader = loader_with_shipped_robots();
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::surgical_arm_urdf(), &robot, &error)) << error;
  // column.stl is a cylinder of radius 60 mm and length 400 mm, scaled by 0.001 in the URDF.
  const LinkVisual& column = robot.link("column_link")->visuals[0];
  expect_bounds_near(ros2vtk_test::bounds_of(column.geometry),
    { { -0.06, 0.06, -0.06, 0.06, 0.0, 0.4 } }, 1e-4, "column");
}

TEST(RobotLoader, PrimitivesAndVisualOrigins)
{
  RobotLoader loader = loader_with_shipped_robots();
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::surgical_arm_urdf(), &robot, &error)) << error;
  // base_link's cylinder: radius 0.02, length 0.05, along z, at (0.12, 0.12, 0.125).
  const LinkVisual& cylinder = robot.link("base_link")->visuals[1];
  expect_bounds_near(ros2vtk_test::bounds_of(cylinder.geometry),
    { { -0.02, 0.02, -0.02, 0.02, -0.025, 0.025 } }, 1e-6, "cylinder");
  EXPECT_DOUBLE_EQ(cylinder.origin->GetElement(0, 3), 0.12);
  EXPECT_DOUBLE_EQ(cylinder.origin->GetElement(1, 3), 0.12);
  EXPECT_DOUBLE_EQ(cylinder.origin->GetElement(2, 3), 0.125);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(cylinder.origin->GetElement(r, c), r == c ? 1.0 : 0.0);
  const LinkVisual& sphere = robot.link("upper_arm_link")->visuals[0];
  expect_bounds_near(ros2vtk_test::bounds_of(sphere.geometry),
    { { -0.06, 0.06, -0.06, 0.06, -0.06, 0.06 } }, 1e-3, "sphere");
  const LinkVisual& box = robot.link("needle_tip")->visuals[0];
  expect_bounds_near(ros2vtk_test::bounds_of(box.geometry),
    { { -0.002, 0.002, -0.002, 0.002, -0.002, 0.002 } }, 1e-9, "box");
}

TEST(RobotLoader, SecondLoadServesEveryMeshFromTheCache)
{
  RobotLoader loader = loader_with_shipped_robots();
  RobotVisuals first, second;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::surgical_arm_urdf(), &first, &error)) << error;
  EXPECT_EQ(loader.mesh_files_read(), 7u); // seven distinct mesh files
  ASSERT_TRUE(loader.load_file(ros2vtk_test::surgical_arm_urdf(), &second, &error)) << error;
  EXPECT_EQ(loader.mesh_files_read(), 7u);
  EXPECT_EQ(second.visual_count(), first.visual_count());
  // Same mesh, different scale: a separate cache entry.
  const std::string base =
    fs::canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes/base.stl").string();
  const std::string xml = "<robot name='r'><link name='a'><visual><geometry><mesh filename='" +
    base + "' scale='2 2 2'/></geometry></visual></link></robot>";
  RobotVisuals scaled;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &scaled, &error)) << error;
  EXPECT_EQ(loader.mesh_files_read(), 8u);
  expect_bounds_near(ros2vtk_test::bounds_of(scaled.links[0].visuals[0].geometry),
    ros2vtk_test::binary_stl_bounds(base, { { 2, 2, 2 } }), 1e-6, "scaled base");
}

TEST(RobotLoader, FileUrisAbsolutePathsAndMirroringScale)
{
  const std::string meshes =
    fs::canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes").string();
  const std::string xml = "<robot name='uris'>"
                          "<link name='a'><visual><geometry><mesh filename='file://" +
    meshes +
    "/base.stl'/></geometry></visual></link>"
    "<link name='b'><visual><geometry><mesh filename='" +
    meshes +
    "/wrist.stl' scale='-1 1 1'/></geometry></visual></link>"
    "<joint name='j' type='fixed'><parent link='a'/><child link='b'/></joint></robot>";
  ResourceResolver resolver;
  resolver.add_allowed_root(meshes); // meshes outside every root are refused by default
  RobotLoader loader{ resolver };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  EXPECT_TRUE(robot.warnings().empty()) << robot.warnings().front();
  expect_bounds_near(ros2vtk_test::bounds_of(robot.link("a")->visuals[0].geometry),
    ros2vtk_test::binary_stl_bounds(meshes + "/base.stl"), 1e-6, "file://");
  expect_bounds_near(ros2vtk_test::bounds_of(robot.link("b")->visuals[0].geometry),
    ros2vtk_test::binary_stl_bounds(meshes + "/wrist.stl", { { -1, 1, 1 } }), 1e-6, "mirrored");
}

TEST(RobotLoader, PackageNamesWithHyphensThroughAmentPrefix)
{
  std::random_device seed;
  const fs::path prefix = fs::temp_directory_path() / ("ros2vtk_hyphen_" + std::to_string(seed()));
  const fs::path package = prefix / "share" / "my-robot-parts";
  fs::create_directories(package / "meshes");
  std::ofstream(package / "package.xml")
    << "<package format='3'><name>my-robot-parts</name></package>";
  const std::string source = ros2vtk_test::robots_dir() + "/surgical_arm/meshes/wrist.stl";
  fs::copy_file(source, package / "meshes" / "wrist.stl");
  ResourceResolver resolver;
  resolver.set_ament_prefixes({ prefix.string() });
  RobotLoader loader(resolver);
  const std::string xml =
    "<robot name='h'><link name='a'><visual><geometry>"
    "<mesh "
    "filename='package://my-robot-parts/meshes/wrist.stl'/></geometry></visual></link></robot>";
  RobotVisuals robot;
  std::string error;
  const bool ok = loader.load_xml(xml, RobotLoadOptions(), &robot, &error);
  fs::remove_all(prefix);
  ASSERT_TRUE(ok) << error;
  EXPECT_TRUE(robot.warnings().empty()) << robot.warnings().front();
  EXPECT_EQ(robot.links[0].visuals[0].kind, VisualKind::Mesh);
  expect_bounds_near(ros2vtk_test::bounds_of(robot.links[0].visuals[0].geometry),
    ros2vtk_test::binary_stl_bounds(source), 1e-6, "hyphenated package");
}

TEST(RobotLoader, MissingMeshIsAWarningAndAPlaceholderWhileTheRestLoads)
{
  RobotLoader loader = loader_with_shipped_robots();
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::data_dir() + "/missing_mesh.urdf", &robot, &error))
    << error;
  ASSERT_EQ(robot.links.size(), 3u);
  EXPECT_EQ(robot.placeholder_count(), 1u);

  const LinkVisuals* forearm = robot.link("forearm_link");
  ASSERT_NE(forearm, nullptr);
  ASSERT_EQ(forearm->visuals.size(), 2u);
  const LinkVisual& missing = forearm->visuals[0];
  EXPECT_EQ(missing.kind, VisualKind::Placeholder);
  expect_bounds_near(ros2vtk_test::bounds_of(missing.geometry),
    { { -0.005, 0.005, -0.005, 0.005, -0.005, 0.005 } }, 1e-9, "placeholder");
  ASSERT_EQ(forearm->warnings.size(), 1u);
  const std::string& warning = forearm->warnings[0];
  EXPECT_EQ(warning.rfind("link 'forearm_link': could not load mesh "
                          "'package://ros2vtk_surgical_arm/meshes/does_not_exist.stl': ",
              0),
    0u)
    << warning;
  EXPECT_NE(warning.find("no such file"), std::string::npos) << warning;
  EXPECT_EQ(forearm->visuals[1].kind, VisualKind::Sphere);
  expect_rgba(forearm->visuals[1].display_color(), { { 0.1, 0.8, 0.2, 1 } }, "green sphere");

  // The other links load: an OBJ with two materials and a scaled DAE keeping its own colour.
  const LinkVisual& obj = robot.link("base_link")->visuals[0];
  EXPECT_EQ(obj.kind, VisualKind::Mesh);
  EXPECT_TRUE(obj.has_vertex_colors);
  EXPECT_TRUE(robot.link("base_link")->warnings.empty());
  const LinkVisual& dae = robot.link("tool_link")->visuals[0];
  EXPECT_EQ(dae.kind, VisualKind::Mesh);
  expect_bounds_near(ros2vtk_test::bounds_of(dae.geometry),
    { { -0.01, 0.01, -0.01, 0.01, 0.03, 0.05 } }, 1e-7, "DAE x2");
  EXPECT_FALSE(dae.has_material_color);
  ASSERT_TRUE(dae.has_mesh_color);
  expect_rgba(dae.display_color(), { { 0.8, 0.2, 0.1, 1.0 } }, "DAE colour", 1e-6);
}

TEST(RobotLoader, MaterialsNamedAtRobotLevelInlineReusedTexturedAndAbsent)
{
  const std::string xml = R"(<robot name="materials">
    <material name="red"><color rgba="1 0 0 1"/></material>
    <link name="a"><visual><geometry><box size="1 1 1"/></geometry><material name="red"/></visual></link>
    <link name="b"><visual><geometry><box size="1 1 1"/></geometry>
      <material name="custom"><color rgba="0.1 0.2 0.3 0.4"/></material></visual></link>
    <link name="c"><visual><geometry><box size="1 1 1"/></geometry><material name="custom"/></visual></link>
    <link name="d"><visual><geometry><box size="1 1 1"/></geometry>
      <material name="wood"><texture filename="package://p/textures/wood.png"/></material></visual></link>
    <link name="e"><visual><geometry><box size="1 1 1"/></geometry>
      <material name="black"><color rgba="0 0 0 1"/></material></visual></link>
    <link name="f"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
    <joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>
    <joint name="bc" type="fixed"><parent link="b"/><child link="c"/></joint>
    <joint name="cd" type="fixed"><parent link="c"/><child link="d"/></joint>
    <joint name="de" type="fixed"><parent link="d"/><child link="e"/></joint>
    <joint name="ef" type="fixed"><parent link="e"/><child link="f"/></joint>
  </robot>)";
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  auto visual = [&](const char* link) {
    return robot.link(link)->visuals.at(0);
  };
  EXPECT_EQ(visual("a").material_name, "red");
  expect_rgba(visual("a").material_color, { { 1, 0, 0, 1 } }, "robot-level");
  expect_rgba(visual("b").material_color, { { 0.1, 0.2, 0.3, 0.4 } }, "inline");
  ASSERT_TRUE(visual("c").has_material_color);
  expect_rgba(visual("c").material_color, { { 0.1, 0.2, 0.3, 0.4 } }, "reused by name");
  EXPECT_FALSE(visual("d").has_material_color);
  EXPECT_EQ(visual("d").material_texture, "package://p/textures/wood.png");
  ASSERT_TRUE(visual("e").has_material_color) << "an explicit black is a colour";
  expect_rgba(visual("e").material_color, { { 0, 0, 0, 1 } }, "black");
  EXPECT_FALSE(visual("f").has_material_color);
  expect_rgba(visual("f").display_color(), { { 0.7, 0.7, 0.7, 1.0 } }, "default grey");
}

TEST(RobotLoader, VisualOriginRotation)
{
  const std::string xml = R"(<robot name="r"><link name="a"><visual>
      <origin xyz="1 2 3" rpy="0 0 1.5707963267948966"/><geometry><sphere radius="0.1"/></geometry>
    </visual></link></robot>)";
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  const vtkMatrix4x4* m = robot.links[0].visuals[0].origin;
  // A quarter turn about z: x -> y, y -> -x.
  const double expected[4][4] = { { 0, -1, 0, 1 }, { 1, 0, 0, 2 }, { 0, 0, 1, 3 }, { 0, 0, 0, 1 } };
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(m->GetElement(r, c), expected[r][c], 1e-12) << r << "," << c;
}

TEST(RobotLoader, ZeroScaleAndBadPrimitivesArePlaceholdersWithWarnings)
{
  const std::string base =
    fs::canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes/base.stl").string();
  const std::string xml = "<robot name='r'><link name='a'>"
                          "<visual><geometry><mesh filename='" +
    base +
    "' scale='1 0 1'/></geometry></visual>"
    "<visual><geometry><sphere radius='-1'/></geometry></visual>"
    "<visual><geometry><box size='0.1 0.1 0.1'/></geometry></visual>"
    "</link></robot>";
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  const LinkVisuals& link = robot.links[0];
  ASSERT_EQ(link.visuals.size(), 3u);
  EXPECT_EQ(link.visuals[0].kind, VisualKind::Placeholder);
  EXPECT_EQ(link.visuals[1].kind, VisualKind::Placeholder);
  EXPECT_EQ(link.visuals[2].kind, VisualKind::Box);
  ASSERT_EQ(link.warnings.size(), 2u);
  EXPECT_NE(link.warnings[0].find("scale"), std::string::npos) << link.warnings[0];
  EXPECT_NE(link.warnings[1].find("sphere radius must be positive"), std::string::npos)
    << link.warnings[1];
}

struct BrokenUrdf
{
  const char* file;
  const char* expected_words;
};

void PrintTo(const BrokenUrdf& broken, std::ostream* out)
{
  *out << broken.file;
}

class MalformedUrdf : public ::testing::TestWithParam<BrokenUrdf>
{
};

TEST_P(MalformedUrdf, FailsWithAMessageNamingTheProblem)
{
  const std::string path = ros2vtk_test::data_dir() + "/malformed/" + GetParam().file;
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  EXPECT_FALSE(loader.load_file(path, &robot, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(GetParam().expected_words), std::string::npos) << error;
  EXPECT_TRUE(robot.links.empty());
}

INSTANTIATE_TEST_SUITE_P(RobotLoader, MalformedUrdf,
  ::testing::Values(BrokenUrdf{ "unclosed_tags.urdf", "XML" },
    BrokenUrdf{ "joint_to_unknown_link.urdf", "no_such_link" },
    BrokenUrdf{ "no_robot_element.urdf", "robot" },
    BrokenUrdf{ "unknown_joint_type.urdf", "telescopic" },
    BrokenUrdf{ "does_not_exist.urdf", "no such file" }));

TEST(RobotLoader, VisualsDroppedByUrdfdomAreReportedNotLostSilently)
{
  // urdfdom accepts the URDF but drops every visual of a link once one fails to parse.
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(ros2vtk_test::data_dir() + "/dropped_visual.urdf", &robot, &error))
    << error;
  const LinkVisuals& link = robot.links.at(0);
  EXPECT_TRUE(link.visuals.empty());
  ASSERT_EQ(link.warnings.size(), 1u);
  EXPECT_NE(link.warnings[0].find("link 'base_link': urdfdom dropped 2 of its 2 visuals"),
    std::string::npos)
    << link.warnings[0];
  ASSERT_FALSE(robot.urdf_warnings.empty());
  EXPECT_NE(robot.urdf_warnings[0].find("[0.1 0.1]"), std::string::npos) << robot.urdf_warnings[0];
  EXPECT_EQ(robot.warnings().size(), robot.urdf_warnings.size() + 1);
}

// Issue 11.2: the link walk recursed once per link; ~7000 links overflowed the stack.
TEST(RobotLoader, ChainOfTenThousandLinksFromAFileLoadsRootFirst)
{
  const int links = 10000;
  const fs::path file =
    fs::temp_directory_path() / ("ros2vtk_chain_" + std::to_string(::getpid()) + ".urdf");
  std::ofstream(file) << ros2vtk_test::chain_urdf(links);
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  const bool loaded = loader.load_file(file.string(), &robot, &error);
  fs::remove(file);
  ASSERT_TRUE(loaded) << error;
  ASSERT_EQ(robot.links.size(), static_cast<size_t>(links));
  EXPECT_EQ(robot.root_link, "link_9999");
  EXPECT_EQ(robot.links.front().link, "link_9999");
  EXPECT_EQ(robot.links[1].link, "link_9998");
  EXPECT_EQ(robot.links.back().link, "link_0");
}

// Meshes are read several at a time (RobotLoadOptions::mesh_threads); what a load gives must not
// depend on it: the same visuals in document order, the same warnings, each distinct file (and
// scale) read once, however many visuals name it and whether it loads or not.
TEST(RobotLoader, MeshesReadOnSeveralThreadsGiveTheSameRobotAsOneThread)
{
  const std::string meshes = fs::canonical(ros2vtk_test::data_dir() + "/meshes").string();
  const std::string arm =
    fs::canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes").string();
  const std::vector<std::pair<std::string, std::string>> visuals = {
    { arm + "/base.stl", "1 1 1" },
    { arm + "/column.stl", "0.001 0.001 0.001" },
    { meshes + "/two_colours.obj", "1 1 1" },
    { meshes + "/truncated.stl", "1 1 1" },
    { arm + "/base.stl", "1 1 1" },
    { arm + "/base.stl", "2 2 2" },
    { ros2vtk_test::data_dir() + "/unit_cube_cm.dae", "2 2 2" },
    { meshes + "/garbage.dae", "1 1 1" },
    { meshes + "/coloured_vertices.ply", "1 1 1" },
    { meshes + "/truncated.stl", "1 1 1" },
    { arm + "/upper_arm.stl", "1 1 1" },
    { meshes + "/no_such_file.stl", "1 1 1" },
    { arm + "/forearm.stl", "0.001 0.001 0.001" },
    { meshes + "/single_colour.obj", "1 1 1" },
  };
  std::string xml = "<robot name='many'>";
  for (size_t i = 0; i < visuals.size(); ++i)
  {
    xml += "<link name='l" + std::to_string(i) + "'><visual><geometry><mesh filename='" +
      visuals[i].first + "' scale='" + visuals[i].second + "'/></geometry></visual></link>";
    if (i > 0)
      xml += "<joint name='j" + std::to_string(i) + "' type='fixed'><parent link='l" +
        std::to_string(i - 1) + "'/><child link='l" + std::to_string(i) + "'/></joint>";
  }
  xml += "</robot>";

  RobotLoadOptions one_thread, four_threads;
  one_thread.mesh_threads = 1;
  four_threads.mesh_threads = 4;
  RobotLoader sequential = loader_with_shipped_robots(), parallel = loader_with_shipped_robots();
  sequential.resolver().add_search_path(ros2vtk_test::data_dir());
  parallel.resolver().add_search_path(ros2vtk_test::data_dir());
  RobotVisuals a, b;
  std::string error;
  ASSERT_TRUE(sequential.load_xml(xml, one_thread, &a, &error)) << error;
  ASSERT_TRUE(parallel.load_xml(xml, four_threads, &b, &error)) << error;

  // Distinct (file, scale) pairs that load: base x1, base x2, column, two_colours, unit_cube,
  // coloured_vertices, upper_arm, forearm, single_colour.
  EXPECT_EQ(sequential.mesh_files_read(), 9u);
  EXPECT_EQ(parallel.mesh_files_read(), 9u);
  EXPECT_EQ(a.placeholder_count(), 4u); // truncated (twice), garbage, no_such_file
  EXPECT_EQ(a.summary(), b.summary());
  ASSERT_EQ(a.links.size(), b.links.size());
  for (size_t i = 0; i < a.links.size(); ++i)
  {
    const std::string what = a.links[i].link + " (" + visuals.at(i).first + ")";
    ASSERT_EQ(a.links[i].link, b.links[i].link);
    EXPECT_EQ(a.links[i].warnings, b.links[i].warnings) << what;
    ASSERT_EQ(a.links[i].visuals.size(), 1u) << what;
    ASSERT_EQ(b.links[i].visuals.size(), 1u) << what;
    const LinkVisual& x = a.links[i].visuals[0];
    const LinkVisual& y = b.links[i].visuals[0];
    EXPECT_EQ(x.kind, y.kind) << what;
    EXPECT_EQ(x.mesh_path, y.mesh_path) << what;
    EXPECT_EQ(x.geometry->GetNumberOfPoints(), y.geometry->GetNumberOfPoints()) << what;
    EXPECT_EQ(x.geometry->GetNumberOfCells(), y.geometry->GetNumberOfCells()) << what;
    expect_bounds_near(
      ros2vtk_test::bounds_of(y.geometry), ros2vtk_test::bounds_of(x.geometry), 0.0, what);
    EXPECT_EQ(x.has_mesh_color, y.has_mesh_color) << what;
    expect_rgba(y.display_color(), x.display_color(), what, 0.0);
    EXPECT_EQ(x.has_vertex_colors, y.has_vertex_colors) << what;
  }
  // A file that does not load is reported on every visual that names it, with the same reason.
  ASSERT_EQ(a.links[3].warnings.size(), 1u);
  ASSERT_EQ(a.links[9].warnings.size(), 1u);
  EXPECT_EQ(a.links[3].warnings[0].substr(a.links[3].warnings[0].find(": could not load")),
    a.links[9].warnings[0].substr(a.links[9].warnings[0].find(": could not load")));
  // Sharing a mesh file does not share its polydata object: each visual has its own.
  EXPECT_NE(b.links[0].visuals[0].geometry.Get(), b.links[4].visuals[0].geometry.Get());
  EXPECT_EQ(
    b.links[0].visuals[0].geometry->GetPoints(), b.links[4].visuals[0].geometry->GetPoints());
}

TEST(RobotLoader, EmptyUrdfTextIsAnError)
{
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  EXPECT_FALSE(loader.load_xml("  \n", RobotLoadOptions(), &robot, &error));
  EXPECT_NE(error.find("empty"), std::string::npos) << error;
}

} // namespace

TEST(RobotLoader, LoadersSharingAMeshCacheReadEachMeshOnceUntilTheFileChanges)
{
  // Two robot nodes of a scene: two loaders, one cache (as vtkROS2RobotNode does).
  const auto cache = std::make_shared<MeshCache>();
  RobotLoader first_loader = loader_with_shipped_robots();
  RobotLoader second_loader = loader_with_shipped_robots();
  first_loader.set_mesh_cache(cache);
  second_loader.set_mesh_cache(cache);
  RobotVisuals first, second;
  std::string error;
  ASSERT_TRUE(first_loader.load_file(ros2vtk_test::surgical_arm_urdf(), &first, &error)) << error;
  EXPECT_EQ(first_loader.mesh_files_read(), 7u);
  EXPECT_EQ(cache->size(), 7u);
  ASSERT_TRUE(second_loader.load_file(ros2vtk_test::surgical_arm_urdf(), &second, &error)) << error;
  EXPECT_EQ(second_loader.mesh_files_read(), 0u);
  EXPECT_EQ(second.placeholder_count(), 0u);

  // A mesh file that changes is read again.
  const fs::path folder =
    fs::temp_directory_path() / ("ros2vtk_mesh_cache_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string mesh = (folder / "part.stl").string();
  ros2vtk_test::write_triangle_stl(mesh, 0.05f);
  const std::string xml =
    "<robot name='r'><link name='a'><visual><geometry><mesh filename='part.stl'/>"
    "</geometry></visual></link></robot>";
  RobotLoadOptions options;
  options.base_folder = folder.string(); // as a URDF file in that folder would
  RobotVisuals part;
  ASSERT_TRUE(first_loader.load_xml(xml, options, &part, &error)) << error;
  ASSERT_EQ(part.placeholder_count(), 0u) << part.links[0].warnings.at(0);
  ASSERT_TRUE(second_loader.load_xml(xml, options, &part, &error)) << error;
  EXPECT_EQ(first_loader.mesh_files_read() + second_loader.mesh_files_read(), 8u);
  ros2vtk_test::write_triangle_stl(mesh, 0.5f);
  fs::last_write_time(mesh, fs::last_write_time(mesh) + std::chrono::seconds(1)); // coarse clocks
  ASSERT_TRUE(second_loader.load_xml(xml, options, &part, &error)) << error;
  EXPECT_EQ(second_loader.mesh_files_read(), 1u); // its first read: the rest came from the cache
  EXPECT_NEAR(ros2vtk_test::bounds_of(part.links[0].visuals[0].geometry)[1], 0.5, 1e-6);
  fs::remove_all(folder);
}

TEST(MeshCacheTest, TheLeastRecentlyUsedMeshesGoFirstWhenOverTheBound)
{
  auto mesh_of_points = [](int points) {
    MeshData mesh;
    mesh.polydata = vtkSmartPointer<vtkPolyData>::New();
    auto coordinates = vtkSmartPointer<vtkPoints>::New();
    for (int i = 0; i < points; ++i)
      coordinates->InsertNextPoint(i, 0, 0);
    mesh.polydata->SetPoints(coordinates);
    return mesh;
  };
  const MeshData sample = mesh_of_points(20000);
  const size_t one = size_t(sample.polydata->GetActualMemorySize()) * 1024;
  MeshCache cache(one * 2 + one / 2); // room for two
  cache.insert("a", mesh_of_points(20000));
  cache.insert("b", mesh_of_points(20000));
  MeshData found;
  ASSERT_TRUE(cache.find("a", &found)); // a is now the most recently used
  cache.insert("c", mesh_of_points(20000));
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_TRUE(cache.find("a", &found));
  EXPECT_FALSE(cache.find("b", &found));
  EXPECT_TRUE(cache.find("c", &found));
  EXPECT_LE(cache.bytes(), one * 2 + one / 2);
  cache.insert("huge", mesh_of_points(200000)); // bigger than the whole cache: not kept
  EXPECT_FALSE(cache.find("huge", &found));
  EXPECT_EQ(cache.size(), 2u);
}
