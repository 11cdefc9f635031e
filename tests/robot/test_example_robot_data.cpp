// Real third-party robots: PyPI's example-robot-data 6.0.0 (URDFs with package://example-robot-data
// URIs; STL, Collada and OBJ+MTL meshes), installed into the project's venv by scripts/setup.sh.
// The package's share folder follows the ament layout, so AMENT_PREFIX_PATH=<cmeel.prefix>
// resolves its URIs. A missing venv or package is a failure, never a silent skip.
#include "ros2vtk/robot/RobotLoader.hpp"

#include "robot_test_support.hpp"

#include <gtest/gtest.h>

#include <ostream>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace fs = std::filesystem;
using namespace ros2vtk::robot;

namespace {

// <venv site-packages>/cmeel.prefix, or "" with `why` saying what to do.
std::string example_robot_data_prefix(std::string* why)
{
  const char* from_env = std::getenv("ROS2VTK_VENV_PYTHON");
  const std::string python = from_env && *from_env ? from_env : ROS2VTK_TEST_VENV_PYTHON;
  if (!fs::exists(python))
  {
    *why = "the project's venv python '" + python +
      "' does not exist (ROS2VTK_VENV_PYTHON); run scripts/setup.sh to create the venv with "
      "example-robot-data";
    return {};
  }
  const std::string command =
    "'" + python + "' -c \"import sysconfig; print(sysconfig.get_paths()['purelib'])\"";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string site_packages;
  char buffer[4096];
  while (pipe && fgets(buffer, sizeof(buffer), pipe.get()))
    site_packages += buffer;
  while (!site_packages.empty() && (site_packages.back() == '\n' || site_packages.back() == '\r'))
    site_packages.pop_back();
  const fs::path prefix = fs::path(site_packages) / "cmeel.prefix";
  if (site_packages.empty() || !fs::exists(prefix / "share/example-robot-data/package.xml"))
  {
    *why = "example-robot-data is not installed in the venv of '" + python + "' (looked for " +
      (prefix / "share/example-robot-data/package.xml").string() +
      "); run scripts/setup.sh (it installs scripts/requirements-ros.txt, which pins "
      "example-robot-data==6.0.0)";
    return {};
  }
  return prefix.string();
}

struct ThirdPartyRobot
{
  const char* urdf; // under share/example-robot-data/robots
  size_t visuals;   // <visual> elements in the file (counted by hand with grep)
  const char* mesh_format;
};

void PrintTo(const ThirdPartyRobot& robot, std::ostream* out)
{
  *out << robot.urdf;
}

class ExampleRobotData : public ::testing::TestWithParam<ThirdPartyRobot>
{
};

TEST_P(ExampleRobotData, LoadsWithNoMissingMesh)
{
  std::string why;
  const std::string prefix = example_robot_data_prefix(&why);
  ASSERT_FALSE(prefix.empty()) << why;
  ResourceResolver resolver;
  resolver.set_ament_prefixes({ prefix });
  RobotLoader loader(resolver);
  RobotVisuals robot;
  std::string error;
  const std::string urdf = prefix + "/share/example-robot-data/robots/" + GetParam().urdf;
  ASSERT_TRUE(loader.load_file(urdf, &robot, &error)) << error;
  const auto warnings = robot.warnings();
  EXPECT_TRUE(warnings.empty()) << warnings.size() << " warnings, first: " << warnings.front();
  EXPECT_EQ(robot.placeholder_count(), 0u);
  EXPECT_EQ(robot.visual_count(), GetParam().visuals);
  size_t meshes_of_format = 0;
  for (const auto& link : robot.links)
    for (const auto& visual : link.visuals)
    {
      ASSERT_NE(visual.geometry, nullptr) << link.link;
      EXPECT_GT(visual.geometry->GetNumberOfPolys(), 0) << link.link;
      if (visual.kind == VisualKind::Mesh &&
        fs::path(visual.mesh_path).extension() == GetParam().mesh_format)
        ++meshes_of_format;
      // Metres: every link of these robots is between a millimetre and two metres across.
      const auto b = ros2vtk_test::bounds_of(visual.geometry);
      const double extent = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
      EXPECT_GT(extent, 0.001) << link.link << " " << visual.mesh_uri;
      EXPECT_LT(extent, 2.0) << link.link << " " << visual.mesh_uri;
    }
  EXPECT_GT(meshes_of_format, 0u) << "expected " << GetParam().mesh_format << " meshes";
}

// Issue 15: the package.xml of example-robot-data is four folders above its URDFs
// (share/example-robot-data/robots/<x>_description/urdf/<x>.urdf); walking up from the file
// finds it with no AMENT_PREFIX_PATH, no search path and nothing else set up.
TEST_P(ExampleRobotData, LoadsFromItsFileAloneWithNoPackageLocationsSet)
{
  std::string why;
  const std::string prefix = example_robot_data_prefix(&why);
  ASSERT_FALSE(prefix.empty()) << why;
  RobotLoader loader{ ResourceResolver() };
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(
    prefix + "/share/example-robot-data/robots/" + GetParam().urdf, &robot, &error))
    << error;
  EXPECT_EQ(robot.placeholder_count(), 0u) << robot.summary();
  EXPECT_EQ(robot.visual_count(), GetParam().visuals);
  EXPECT_EQ(robot.summary(),
    std::to_string(GetParam().visuals) + " visuals, all " +
      std::to_string(robot.mesh_visual_count()) + " meshes loaded");
}

INSTANTIATE_TEST_SUITE_P(RobotLoader, ExampleRobotData,
  ::testing::Values(ThirdPartyRobot{ "ur_description/urdf/ur5_robot.urdf", 7, ".dae" },
    ThirdPartyRobot{ "panda_description/urdf/panda.urdf", 11, ".dae" },
    ThirdPartyRobot{ "go1_description/urdf/go1.urdf", 39, ".dae" },
    ThirdPartyRobot{ "laikago_description/urdf/laikago.urdf", 17, ".obj" }),
  [](const ::testing::TestParamInfo<ThirdPartyRobot>& param_info) {
    std::string name = fs::path(param_info.param.urdf).stem().string();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)))
        c = '_';
    return name;
  });

TEST(ExampleRobotDataPanda, ColladaVisualsMatchTheCollisionStlsInMetres)
{
  // Franka's visual meshes are Collada (metres, Z up); its collision meshes are binary STLs of
  // the same shapes. Bounds of the loaded DAE against the STL read by the test's own parser
  // check units, up axis and node transforms on real third-party files.
  std::string why;
  const std::string prefix = example_robot_data_prefix(&why);
  ASSERT_FALSE(prefix.empty()) << why;
  ResourceResolver resolver;
  resolver.set_ament_prefixes({ prefix });
  RobotLoader loader(resolver);
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(
    prefix + "/share/example-robot-data/robots/panda_description/urdf/panda.urdf", &robot, &error))
    << error;
  size_t compared = 0;
  for (const auto& link : robot.links)
    for (const auto& visual : link.visuals)
    {
      const fs::path dae(visual.mesh_path);
      if (dae.extension() != ".dae" || dae.parent_path().filename() != "visual")
        continue;
      const fs::path stl =
        dae.parent_path().parent_path() / "collision" / (dae.stem().string() + ".stl");
      if (!fs::exists(stl))
        continue;
      const auto expected = ros2vtk_test::binary_stl_bounds(stl.string());
      const auto actual = ros2vtk_test::bounds_of(visual.geometry);
      // The collision meshes are simplified (link5's differs by 5.5 mm); a wrong unit (x100) or
      // a Y-up rotation moves these bounds by several centimetres.
      for (size_t i = 0; i < 6; ++i)
        EXPECT_NEAR(actual[i], expected[i], 0.01)
          << link.link << " " << dae.filename() << " bound " << i;
      ++compared;
    }
  EXPECT_GE(compared, 9u)
    << "links 0-7, hand and fingers have a DAE visual and an STL collision mesh";
}

} // namespace
