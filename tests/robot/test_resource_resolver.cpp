// Tests of ResourceResolver: package:// through every lookup, file://, absolute and relative
// paths, and the refusals (unknown schemes, escaping the roots, over-size files).
#include "ros2vtk/robot/ResourceResolver.hpp"

#include "robot_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

namespace fs = std::filesystem;
using ros2vtk::robot::PackageSearchReport;
using ros2vtk::robot::ResolvedResource;
using ros2vtk::robot::ResourceResolver;

namespace {

// A fresh folder per test, removed afterwards.
class ResolverTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("ros2vtk_resolver_" + std::to_string(seed()));
    fs::create_directories(root_);
    root_ = fs::canonical(root_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  fs::path write(const fs::path& relative, const std::string& content = "solid x\nendsolid x\n")
  {
    const fs::path path = root_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  fs::path make_package(const fs::path& folder, const std::string& name)
  {
    write(folder / "package.xml",
      "<?xml version=\"1.0\"?>\n<package format=\"3\">\n  <name>" + name +
        "</name>\n  <version>1.0.0</version>\n</package>\n");
    return root_ / folder;
  }
  fs::path root_;
};

std::string canonical(const fs::path& path)
{
  return fs::canonical(path).string();
}

TEST(ResourceResolver, FindsPackageBySearchPathUsingTheNameInPackageXml)
{
  // The shipped arm's folder is "surgical_arm", its package.xml says "ros2vtk_surgical_arm".
  ResourceResolver resolver;
  resolver.add_search_path(ros2vtk_test::robots_dir());
  const ResolvedResource found =
    resolver.resolve("package://ros2vtk_surgical_arm/meshes/base.stl", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes/base.stl"));
}

TEST_F(ResolverTest, FindsHyphenatedPackageThroughAmentPrefix)
{
  make_package("prefix/share/example-robot-parts", "example_robot_parts_xml_name");
  const fs::path mesh = write("prefix/share/example-robot-parts/robots/arm/meshes/link.stl");
  ResourceResolver resolver;
  resolver.set_ament_prefixes({ (root_ / "prefix").string() });
  const auto found =
    resolver.resolve("package://example-robot-parts/robots/arm/meshes/link.stl", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
}

TEST_F(ResolverTest, AddsThePackageHoldingAUrdfFile)
{
  make_package("src/tool_description", "tool_description");
  const fs::path mesh = write("src/tool_description/meshes/jaw.stl");
  const fs::path urdf = write("src/tool_description/urdf/xacro/tool.urdf", "<robot name=\"t\"/>");
  ResourceResolver resolver;
  EXPECT_EQ(resolver.add_package_of(urdf.string()), (root_ / "src/tool_description").string());
  const auto found = resolver.resolve("package://tool_description/meshes/jaw.stl", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
}

// Issue 15: the walk used to stop three folders above the file.
TEST_F(ResolverTest, FindsThePackageHoldingAUrdfFileAnyNumberOfFoldersUp)
{
  make_package("deep", "deep");
  const fs::path mesh = write("deep/meshes/m.stl");
  const fs::path urdf = write("deep/a/b/c/robot.urdf", "<robot name=\"r\"/>");
  ResourceResolver resolver;
  EXPECT_EQ(resolver.find_package("deep"), "");
  EXPECT_EQ(resolver.add_package_of(urdf.string()), (root_ / "deep").string());
  EXPECT_EQ(resolver.find_package("deep"), (root_ / "deep").string());
  const auto found = resolver.resolve("package://deep/meshes/m.stl", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
}

TEST_F(ResolverTest, AddsNoPackageWhenNoFolderAboveTheFileHasPackageXml)
{
  const fs::path urdf = write("loose/a/robot.urdf", "<robot name=\"r\"/>");
  ResourceResolver resolver;
  EXPECT_EQ(resolver.add_package_of(urdf.string()), "");
  PackageSearchReport report;
  EXPECT_EQ(resolver.find_package("loose", &report), "");
  ASSERT_EQ(report.looked_in.size(), 1u);
  EXPECT_EQ(report.looked_in[0],
    "the folders above '" + urdf.string() + "' up to the filesystem root (no package.xml there)");
}

TEST_F(ResolverTest, ReadsAmentPrefixPathFromTheEnvironment)
{
  make_package("install_a/share/other_pkg", "other_pkg");
  make_package("install_b/share/my-pkg", "my-pkg");
  const fs::path mesh = write("install_b/share/my-pkg/meshes/a.STL");
  const std::string value = (root_ / "install_a").string() + ":" + (root_ / "install_b").string();
  ASSERT_EQ(setenv("AMENT_PREFIX_PATH", value.c_str(), 1), 0);
  ASSERT_EQ(unsetenv("ROS_PACKAGE_PATH"), 0);
  const ResourceResolver resolver = ResourceResolver::from_environment();
  unsetenv("AMENT_PREFIX_PATH");
  const auto found = resolver.resolve("package://my-pkg/meshes/a.STL", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
}

TEST_F(ResolverTest, FindsNestedPackageOnRosPackagePath)
{
  make_package("ws/src/group/deep-pkg", "deep-pkg");
  make_package("ws/src/group/deep-pkg-other", "deep-pkg-other");
  const fs::path mesh = write("ws/src/group/deep-pkg/meshes/m.stl");
  ResourceResolver resolver;
  resolver.set_ros_package_path({ (root_ / "ws").string() });
  const auto found = resolver.resolve("package://deep-pkg/meshes/m.stl", "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
  EXPECT_EQ(
    resolver.find_package("deep-pkg-other"), (root_ / "ws/src/group/deep-pkg-other").string());
}

TEST_F(ResolverTest, SkipsFoldersMarkedColconIgnore)
{
  make_package("ws/ignored/pkg", "hidden_pkg");
  write("ws/ignored/COLCON_IGNORE", "");
  ResourceResolver resolver;
  resolver.set_ros_package_path({ (root_ / "ws").string() });
  EXPECT_EQ(resolver.find_package("hidden_pkg"), "");
}

TEST_F(ResolverTest, MissingPackageNamesTheUriAndWhereItLooked)
{
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "nothing_here").string());
  resolver.set_ament_prefixes({ (root_ / "prefix").string() });
  const auto found = resolver.resolve("package://no-such-pkg/meshes/a.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("'package://no-such-pkg/meshes/a.stl'"), std::string::npos)
    << found.error;
  EXPECT_NE(found.error.find("package 'no-such-pkg' not found"), std::string::npos) << found.error;
  EXPECT_NE(found.error.find((root_ / "nothing_here").string()), std::string::npos) << found.error;
  EXPECT_NE(found.error.find((root_ / "prefix/share/no-such-pkg").string()), std::string::npos)
    << found.error;
}

TEST(ResourceResolver, MissingPackageWithNoLocationsSaysSo)
{
  ResourceResolver resolver;
  const auto found = resolver.resolve("package://pkg/a.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("AMENT_PREFIX_PATH and ROS_PACKAGE_PATH are empty"), std::string::npos)
    << found.error;
}

TEST_F(ResolverTest, MissingFileNamesTheUriAndThePathTried)
{
  make_package("pkgs/arm", "arm");
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "pkgs").string());
  const auto found = resolver.resolve("package://arm/meshes/gone.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("'package://arm/meshes/gone.stl'"), std::string::npos) << found.error;
  EXPECT_NE(found.error.find((root_ / "pkgs/arm/meshes/gone.stl").string()), std::string::npos)
    << found.error;
}

TEST_F(ResolverTest, FileUrisAndAbsolutePaths)
{
  const fs::path mesh = write("with space/mesh.stl");
  ResourceResolver resolver;
  resolver.add_allowed_root(root_.string());
  auto found = resolver.resolve("file://" + (root_ / "with%20space/mesh.stl").string(), "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
  found = resolver.resolve("file://localhost" + mesh.string(), "");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
  found = resolver.resolve(mesh.string(), "/somewhere/else");
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, mesh.string());
  found = resolver.resolve("file://relative/mesh.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("absolute path"), std::string::npos) << found.error;
}

TEST(ResourceResolver, RelativePathsWithParentFolderFromTheBaseFolder)
{
  ResourceResolver resolver;
  const std::string base = ros2vtk_test::robots_dir() + "/surgical_arm/urdf";
  // ../meshes leaves the URDF's folder: allowed once the robot's folder is a root.
  EXPECT_FALSE(resolver.resolve("../meshes/forearm.stl", base).ok);
  resolver.add_allowed_root(ros2vtk_test::robots_dir() + "/surgical_arm");
  const auto found = resolver.resolve("../meshes/forearm.stl", base);
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_EQ(found.path, canonical(ros2vtk_test::robots_dir() + "/surgical_arm/meshes/forearm.stl"));
}

TEST(ResourceResolver, RefusesUnknownSchemesAndSaysWhatIsSupported)
{
  ResourceResolver resolver;
  for (const std::string uri : { "http://example.org/robot/mesh.stl", "model://arm/meshes/a.dae",
         "https://example.org/x.stl" })
  {
    const auto found = resolver.resolve(uri, "");
    ASSERT_FALSE(found.ok) << uri;
    EXPECT_NE(found.error.find("'" + uri + "'"), std::string::npos) << found.error;
    EXPECT_NE(found.error.find("is not supported"), std::string::npos) << found.error;
    EXPECT_NE(found.error.find("package://"), std::string::npos) << found.error;
    EXPECT_NE(found.error.find("file://"), std::string::npos) << found.error;
  }
}

TEST(ResourceResolver, RefusesEmptyAndIncompleteUris)
{
  ResourceResolver resolver;
  resolver.add_search_path(ros2vtk_test::robots_dir());
  EXPECT_FALSE(resolver.resolve("", "").ok);
  auto found = resolver.resolve("package://ros2vtk_surgical_arm", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("no file path"), std::string::npos) << found.error;
  found = resolver.resolve("package:///", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(
    found.error.find("no package name and no file path after package://"), std::string::npos)
    << found.error;
  // A folder named like the package is a package in a search path: "." and ".." are not names.
  found = resolver.resolve("package://../surgical_arm/meshes/base.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("'..' is not a package name"), std::string::npos) << found.error;
  // A folder is not a mesh.
  found = resolver.resolve("package://ros2vtk_surgical_arm/meshes", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("not a regular file"), std::string::npos) << found.error;
}

TEST_F(ResolverTest, RootCheckRefusesPathsEscapingTheRoots)
{
  make_package("robots/arm", "arm");
  write("robots/arm/meshes/ok.stl");
  const fs::path secret = write("secret.stl");
  write("robots2/near_miss.stl");
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "robots").string());
  const std::string base = (root_ / "robots/arm/urdf").string();

  // Switched off (the explicit opt-out): the escaping paths resolve.
  EXPECT_TRUE(resolver.restrict_to_roots()) << "on by default";
  resolver.set_restrict_to_roots(false);
  EXPECT_TRUE(resolver.resolve("../../../secret.stl", base).ok);
  EXPECT_TRUE(resolver.resolve("package://arm/../../secret.stl", "").ok);

  resolver.set_restrict_to_roots(true);
  EXPECT_TRUE(resolver.resolve("../meshes/ok.stl", base).ok);
  EXPECT_TRUE(resolver.resolve("package://arm/meshes/ok.stl", "").ok);
  auto found = resolver.resolve("../../../secret.stl", base);
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("outside the allowed roots"), std::string::npos) << found.error;
  EXPECT_NE(found.error.find(secret.string()), std::string::npos) << found.error;
  found = resolver.resolve("package://arm/../../secret.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("outside its package folder"), std::string::npos) << found.error;
  // A sibling folder whose name starts like the root is not inside it.
  found = resolver.resolve((root_ / "robots2/near_miss.stl").string(), "");
  ASSERT_FALSE(found.ok) << "robots2 must not count as inside robots";
  // file:// and absolute paths are checked too; an added root lets them through.
  EXPECT_FALSE(resolver.resolve("file://" + secret.string(), "").ok);
  resolver.add_allowed_root(root_.string());
  EXPECT_TRUE(resolver.resolve("file://" + secret.string(), "").ok);
}

TEST_F(ResolverTest, RootCheckFollowsSymlinks)
{
  make_package("robots/arm", "arm");
  const fs::path outside = write("outside/real.stl");
  fs::create_directories(root_ / "robots/arm/meshes");
  fs::create_symlink(outside, root_ / "robots/arm/meshes/link.stl");
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "robots").string());
  resolver.set_restrict_to_roots(true);
  const auto found = resolver.resolve("package://arm/meshes/link.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find(outside.string()), std::string::npos) << found.error;
}

TEST_F(ResolverTest, RefusesFilesOverTheSizeLimit)
{
  EXPECT_EQ(ResourceResolver().max_file_bytes(), 200ull * 1024 * 1024);
  const fs::path big = write("big.stl", std::string(4096, 'x'));
  const fs::path small = write("small.stl", std::string(100, 'x'));
  ResourceResolver resolver;
  resolver.add_allowed_root(root_.string());
  resolver.set_max_file_bytes(1000);
  auto found = resolver.resolve(big.string(), "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("4096 bytes"), std::string::npos) << found.error;
  EXPECT_NE(found.error.find("limit of 1000 bytes"), std::string::npos) << found.error;
  EXPECT_TRUE(resolver.resolve(small.string(), "").ok);
}

// Issue 11.10: with no set-up at all (a description from the network, no URDF file), nothing
// outside the package roots is read: not through `..` in a package URI, not by file:// or an
// absolute path; the URDF file's folder (the base folder) is a root.
TEST_F(ResolverTest, ByDefaultMeshesOutsideThePackageRootsAreRefused)
{
  make_package("ws/pkg", "pkg");
  write("ws/pkg/meshes/ok.stl");
  const fs::path outside = write("outside/x.stl");
  const fs::path beside_urdf = write("robot_files/mesh.stl");
  ResourceResolver resolver;
  resolver.add_search_path((root_ / "ws").string());
  EXPECT_TRUE(resolver.resolve("package://pkg/meshes/ok.stl", "").ok);
  auto found = resolver.resolve("package://pkg/../../outside/x.stl", "");
  ASSERT_FALSE(found.ok);
  EXPECT_NE(found.error.find("outside its package folder"), std::string::npos) << found.error;
  for (const std::string& uri :
    { "file://" + outside.string(), outside.string(), std::string("file:///etc/hostname") })
  {
    found = resolver.resolve(uri, "");
    ASSERT_FALSE(found.ok) << uri;
    EXPECT_TRUE(found.error.find("outside the allowed roots") != std::string::npos ||
      found.error.find("no such file") != std::string::npos)
      << found.error;
  }
  EXPECT_TRUE(resolver.resolve("mesh.stl", (root_ / "robot_files").string()).ok);
  EXPECT_TRUE(resolver.resolve(beside_urdf.string(), (root_ / "robot_files").string()).ok);
  EXPECT_FALSE(resolver.resolve("../outside/x.stl", (root_ / "robot_files").string()).ok);
  resolver.set_restrict_to_roots(false); // the explicit opt-out
  EXPECT_TRUE(resolver.resolve("package://pkg/../../outside/x.stl", "").ok);
  EXPECT_TRUE(resolver.resolve("file://" + outside.string(), "").ok);
}

} // namespace
