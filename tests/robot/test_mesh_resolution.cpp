// Tests of finding a robot's meshes as robot packages are shipped (issue 15, "Mesh resolution"):
// each builds its fixture package in a temp folder — a package.xml deep above the URDF, relative
// meshes of a description that came over the network, robot data without package.xml, upper-case
// extensions and files that exist but cannot be used — then loads a URDF through RobotLoader and
// asserts how many meshes were found and the words the user reads.
#include "ros2vtk/robot/MeshLoader.hpp"
#include "ros2vtk/robot/RobotLoader.hpp"

#include "robot_test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace ros2vtk::robot;

namespace {

class MeshResolution : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("ros2vtk_mesh_resolution_" + std::to_string(seed()));
    fs::create_directories(root_);
    root_ = fs::canonical(root_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  fs::path write(const fs::path& relative, const std::string& content)
  {
    const fs::path path = root_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  fs::path stl(const fs::path& relative, float size = 0.05f)
  {
    ros2vtk_test::write_triangle_stl((root_ / relative).string(), size);
    return root_ / relative;
  }
  void make_package(const fs::path& folder, const std::string& name)
  {
    write(folder / "package.xml",
      "<?xml version=\"1.0\"?>\n<package format=\"3\">\n  <name>" + name +
        "</name>\n  <version>1.0.0</version>\n</package>\n");
  }
  fs::path root_;
};

// A chain of links l0, l1, …, one visual each: a mesh per URI, then `boxes` box visuals.
std::string chain_with_meshes(const std::vector<std::string>& uris, int boxes = 0)
{
  std::string xml = "<?xml version=\"1.0\"?>\n<robot name=\"fixture\">\n";
  const int links = static_cast<int>(uris.size()) + boxes;
  for (int i = 0; i < links; ++i)
  {
    const std::string geometry = i < static_cast<int>(uris.size())
      ? "<mesh filename=\"" + uris[static_cast<size_t>(i)] + "\"/>"
      : std::string("<box size=\"0.1 0.1 0.1\"/>");
    xml += "  <link name=\"l" + std::to_string(i) + "\"><visual><geometry>" + geometry +
      "</geometry></visual></link>\n";
    if (i > 0)
      xml += "  <joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"l" +
        std::to_string(i - 1) + "\"/><child link=\"l" + std::to_string(i) + "\"/></joint>\n";
  }
  return xml + "</robot>\n";
}

bool contains(const std::string& text, const std::string& words)
{
  return text.find(words) != std::string::npos;
}

size_t meshes_loaded(const RobotVisuals& robot)
{
  return robot.mesh_visual_count() - robot.placeholder_count();
}

// ---- 1. the package holding a URDF file, any number of folders up ---------------------------

TEST_F(MeshResolution, PackageXmlFourFoldersAboveTheUrdfIsFound)
{
  // example-robot-data's layout: one package.xml at the top, URDFs in robots/<x>_description/urdf.
  make_package("robot_data", "robot_data");
  stl("robot_data/robots/x_description/meshes/base.stl");
  stl("robot_data/robots/x_description/meshes/arm.STL");
  const fs::path urdf = write("robot_data/robots/x_description/urdf/x.urdf",
    chain_with_meshes({ "package://robot_data/robots/x_description/meshes/base.stl",
      "package://robot_data/robots/x_description/meshes/arm.STL", "../meshes/base.stl" }));
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(urdf.string(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 3u) << robot.summary();
  EXPECT_EQ(robot.summary(), "3 visuals, all 3 meshes loaded");
  EXPECT_EQ(robot.link("l1")->visuals[0].mesh_path,
    (root_ / "robot_data/robots/x_description/meshes/arm.STL").string());
}

TEST_F(MeshResolution, WalkUpStopsAtTheNearestPackageXmlNamingThePackage)
{
  // Two package.xml files name "inner": the nearer one is the package. The outer one names
  // itself too; a URDF may use meshes of the package around its own.
  make_package("ws", "inner");
  stl("ws/meshes/part.stl", 0.5f);
  make_package("ws/src/outer", "outer");
  stl("ws/src/outer/meshes/shell.stl");
  make_package("ws/src/outer/inner_pkg", "inner");
  stl("ws/src/outer/inner_pkg/meshes/part.stl", 0.05f);
  const fs::path urdf = write("ws/src/outer/inner_pkg/urdf/robot.urdf",
    chain_with_meshes({ "package://inner/meshes/part.stl", "package://outer/meshes/shell.stl" }));
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(urdf.string(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 2u) << robot.summary();
  EXPECT_EQ(robot.link("l0")->visuals[0].mesh_path,
    (root_ / "ws/src/outer/inner_pkg/meshes/part.stl").string());
  EXPECT_NEAR(ros2vtk_test::bounds_of(robot.link("l0")->visuals[0].geometry)[1], 0.05, 1e-6)
    << "the nearer package";
  EXPECT_EQ(
    robot.link("l1")->visuals[0].mesh_path, (root_ / "ws/src/outer/meshes/shell.stl").string());
}

TEST_F(MeshResolution, PackageNotFoundListsTheSearchPathAndTheFoldersAboveTheUrdf)
{
  make_package("robot/other_pkg", "other_pkg");
  const fs::path urdf = write("robot/other_pkg/urdf/robot.urdf",
    chain_with_meshes({ "package://ghost/meshes/a.stl", "package://ghost/meshes/b.stl" }));
  fs::create_directories(root_ / "elsewhere");
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "elsewhere").string());
  RobotLoader loader(resolver);
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(urdf.string(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 0u);
  const std::string warning = robot.link("l0")->warnings.at(0);
  EXPECT_TRUE(contains(warning,
    "link 'l0': could not load mesh 'package://ghost/meshes/a.stl': package 'ghost' not "
    "found (looked in mesh search path '" +
      (root_ / "elsewhere").string() + "'; the folders above '" + urdf.string() +
      "' up to the filesystem root (package.xml "
      "in '" +
      (root_ / "robot/other_pkg").string() + "' names another package)"))
    << warning;
  EXPECT_FALSE(contains(warning, "no search path was added")) << warning;
}

// ---- 2. relative meshes of a description from a parameter or topic ----------------------------

TEST_F(MeshResolution, RelativeMeshesOfANetworkDescriptionAreFoundThroughTheMeshSearchPath)
{
  const fs::path a = stl("robot_files/meshes/a.stl");
  const fs::path b = stl("robot_files/meshes/b.STL");
  write("secret.stl", "solid s\nendsolid s\n");
  const std::string xml = chain_with_meshes({ "meshes/a.stl", "../meshes/b.STL", "../secret.stl" });
  RobotLoadOptions no_folder; // a parameter or topic: the description has no folder of its own
  RobotVisuals robot;
  std::string error;

  RobotLoader without{ ResourceResolver() };
  ASSERT_TRUE(without.load_xml(xml, no_folder, &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 0u);
  const std::string warning = robot.link("l0")->warnings.at(0);
  EXPECT_TRUE(contains(warning, "could not load mesh 'meshes/a.stl': no such file (looked for "))
    << warning;
  EXPECT_TRUE(contains(warning,
    "the description has no folder of its own (it came from a parameter or a topic): give "
    "the folder relative mesh paths start from with SetMeshBaseFolder, or add the folder "
    "holding the meshes with AddMeshSearchPath"))
    << warning;

  ResourceResolver resolver;
  resolver.add_search_path((root_ / "robot_files").string());
  RobotLoader with(resolver);
  ASSERT_TRUE(with.load_xml(xml, no_folder, &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 2u) << robot.summary();
  EXPECT_EQ(robot.link("l0")->visuals[0].mesh_path, a.string());
  EXPECT_EQ(robot.link("l1")->visuals[0].mesh_path, b.string());
  // `..` out of the search path still meets the root check (issue 11.10).
  const std::string refused = robot.link("l2")->warnings.at(0);
  EXPECT_TRUE(
    contains(refused, "'" + (root_ / "secret.stl").string() + "' lies outside the allowed roots"))
    << refused;
}

// ---- 3. robot data without package.xml ------------------------------------------------------

TEST_F(MeshResolution, FolderNamedLikeThePackageWithoutPackageXmlIsThePackage)
{
  const fs::path a = stl("assets/arm_meshes/meshes/a.stl");
  stl("assets/arm_meshes/meshes/b.stl");
  const std::string xml =
    chain_with_meshes({ "package://arm_meshes/meshes/a.stl", "package://arm_meshes/meshes/b.stl" });
  for (const fs::path& search_path : { root_ / "assets", root_ / "assets/arm_meshes" })
  {
    ResourceResolver resolver;
    resolver.add_search_path(search_path.string());
    RobotLoader loader(resolver);
    RobotVisuals robot;
    std::string error;
    ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
    EXPECT_EQ(meshes_loaded(robot), 2u) << search_path << ": " << robot.summary();
    EXPECT_EQ(robot.link("l0")->visuals[0].mesh_path, a.string()) << search_path;
  }
}

TEST_F(MeshResolution, FolderNamedLikeThePackageThatWasNotTakenIsNamedInTheMessage)
{
  stl("data/assets/arm_meshes/meshes/a.stl");
  fs::create_directories(root_ / "prefix/share/arm_meshes");
  const std::string xml = chain_with_meshes({ "package://arm_meshes/meshes/a.stl" });
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "data").string()); // the folder is two levels down: not taken
  resolver.set_ament_prefixes({ (root_ / "prefix").string() });
  RobotLoader loader(resolver);
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 0u);
  const std::string warning = robot.link("l0")->warnings.at(0);
  EXPECT_TRUE(contains(warning,
    "'" + (root_ / "data/assets/arm_meshes").string() +
      "' is named like the package but has no package.xml and is neither a mesh search "
      "path nor directly inside one (add it, or the folder holding it, with "
      "AddMeshSearchPath)"))
    << warning;
  EXPECT_TRUE(contains(warning,
    "'" + (root_ / "prefix/share/arm_meshes").string() +
      "' has no package.xml, so it is not an installed package"))
    << warning;
}

// ---- 4. URI forms, upper-case extensions, files that exist but cannot be used ---------------

TEST_F(MeshResolution, UpperCaseExtensionsAndFileUrisLoadUnusableFilesSayWhy)
{
  make_package("parts", "parts");
  stl("parts/meshes/upper.STL");
  fs::copy_file(ros2vtk_test::data_dir() + "/unit_cube_cm.dae", root_ / "parts/meshes/cube.DAE");
  const fs::path note = write("parts/meshes/note.xyz", "not a mesh\n");
  const fs::path empty = write("parts/meshes/empty.stl", "");
  const fs::path lfs = write("parts/meshes/arm.dae",
    "version https://git-lfs.github.com/spec/v1\n"
    "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\n"
    "size 12345\n");
  const std::string xml = chain_with_meshes({ "package://parts/meshes/upper.STL",
    "file://" + (root_ / "parts/meshes/cube.DAE").string(), "package://parts/meshes/note.xyz",
    "package://parts/meshes/empty.stl", "package://parts/meshes/arm.dae" });
  ResourceResolver resolver;
  resolver.add_search_path(root_.string());
  RobotLoader loader(resolver);
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 2u) << robot.summary();
  EXPECT_EQ(robot.link("l0")->visuals[0].kind, VisualKind::Mesh);
  EXPECT_EQ(robot.link("l1")->visuals[0].kind, VisualKind::Mesh);
  const std::vector<std::pair<std::string, std::string>> expected = {
    { "l2", "mesh file '" + note.string() + "': the format '.xyz' is not supported" },
    { "l3", "mesh file '" + empty.string() + "' is empty (0 bytes), so it holds no STL mesh" },
    { "l4", "mesh file '" + lfs.string() + "' is a Git LFS pointer, not the DAE mesh itself" }
  };
  for (const auto& [link, words] : expected)
  {
    const std::string warning = robot.link(link)->warnings.at(0);
    EXPECT_TRUE(contains(warning, words)) << warning;
    EXPECT_FALSE(contains(warning, "Failed to open file")) << warning;
  }
}

// `package:///meshes/x.stl` names no package (exporters write it with an empty package name):
// taken relative to the description, as yourdfpy does; resource_retriever refuses it.
TEST_F(MeshResolution, PackageUriWithoutAPackageNameIsRelativeToTheDescription)
{
  make_package("robots/arm", "arm");
  const fs::path in_package = stl("robots/arm/meshes/base.STL");
  const fs::path beside_urdf = stl("robots/arm/urdf/parts/tool.stl");
  const fs::path urdf = write("robots/arm/urdf/arm.urdf",
    chain_with_meshes({ "package:///meshes/base.STL", "package:///parts/tool.stl",
      "package:///meshes/ghost.stl" }));
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(urdf.string(), &robot, &error)) << error;
  EXPECT_EQ(meshes_loaded(robot), 2u) << robot.summary();
  EXPECT_EQ(robot.link("l0")->visuals[0].mesh_path, in_package.string());  // in the URDF's package
  EXPECT_EQ(robot.link("l1")->visuals[0].mesh_path, beside_urdf.string()); // beside the URDF
  const std::string warning = robot.link("l2")->warnings.at(0);
  EXPECT_TRUE(contains(warning,
    "could not load mesh 'package:///meshes/ghost.stl': no package name after "
    "package://, so 'meshes/ghost.stl' was taken relative to the description: not in "
    "the package of '" +
      urdf.string() + "' ('" + (root_ / "robots/arm/meshes/ghost.stl").string() +
      "'); no such file"))
    << warning;

  // From the network: the search path, as for any relative mesh path.
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "robots/arm").string());
  RobotLoader network(resolver);
  RobotVisuals received;
  ASSERT_TRUE(network.load_xml(
    chain_with_meshes({ "package:///meshes/base.STL" }), RobotLoadOptions(), &received, &error))
    << error;
  EXPECT_EQ(meshes_loaded(received), 1u) << received.summary();
  EXPECT_EQ(received.link("l0")->visuals[0].mesh_path, in_package.string());
}

TEST_F(MeshResolution, MeshFileThatCannotBeOpenedSaysWhy)
{
  // A file this process may not read: mode 000 for a normal user; root reads those, so then a
  // link to a write-only kernel setting, which root cannot read either.
  const fs::path locked = root_ / "locked.stl";
  if (geteuid() != 0)
  {
    ros2vtk_test::write_triangle_stl(locked.string());
    fs::permissions(locked, fs::perms::none);
  }
  else
  {
    ASSERT_TRUE(fs::exists("/proc/sys/vm/drop_caches")) << "needs a file root cannot read";
    fs::create_symlink("/proc/sys/vm/drop_caches", locked);
  }
  MeshData mesh;
  std::string error;
  EXPECT_FALSE(MeshLoader().load(locked.string(), &mesh, &error));
  EXPECT_EQ(error, "mesh file '" + locked.string() + "' cannot be opened: Permission denied");
}

// ---- 5. one summary line per load; per-link status -------------------------------------------

TEST(MeshResolutionSummary, OneLineForTheLoadAndAStatusPerLink)
{
  const std::string xml =
    chain_with_meshes({ "package://ghost/meshes/m0.stl", "package://ghost/meshes/m1.stl",
                        "package://ghost/meshes/m2.stl", "package://ghost/meshes/m3.stl" },
      1);
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_xml(xml, RobotLoadOptions(), &robot, &error)) << error;
  EXPECT_EQ(robot.visual_count(), 5u);
  EXPECT_EQ(robot.mesh_visual_count(), 4u);
  EXPECT_EQ(robot.placeholder_count(), 4u);
  const std::string summary = robot.summary();
  EXPECT_EQ(
    summary.rfind(
      "5 visuals, 4 of 4 meshes missing (4 warnings, 1 cause); first: link 'l0': could not load "
      "mesh 'package://ghost/meshes/m0.stl': package 'ghost' not found: no package locations are "
      "set",
      0),
    0u)
    << summary;
  EXPECT_EQ(summary.find('\n'), std::string::npos) << "one line";
  EXPECT_EQ(robot.link("l4")->status(), "ok");
  EXPECT_EQ(robot.link("l2")->status().rfind(
              "1 of 1 visuals are placeholders: link 'l2': could not load mesh "
              "'package://ghost/meshes/m2.stl': package 'ghost' not found",
              0),
    0u)
    << robot.link("l2")->status();
}

} // namespace
