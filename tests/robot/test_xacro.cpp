// xacro descriptions: expanded by the xacro program from the project's venv (PyPI `xacro`, the
// ros/xacro project), with arguments, properties, macros and `$(find pkg)` includes through an
// ament prefix built here; and the errors a user meets (no xacro, a bad argument, xacro's own).
#include "ros2vtk/robot/RobotLoader.hpp"
#include "ros2vtk/robot/XacroProcessor.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace ros2vtk::robot;

namespace {
void write(const fs::path& path, const std::string& text)
{
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// An ament prefix holding package demo_arm, whose arm.urdf.xacro includes a macro file by
// $(find demo_arm): the layout of every ROS 2 description package.
class Xacro : public ::testing::Test
{
protected:
  void SetUp() override
  {
    this->Root = fs::temp_directory_path() / ("ros2vtk_xacro_" + std::to_string(::getpid()));
    const fs::path prefix = this->Root / "prefix";
    write(prefix / "share/ament_index/resource_index/packages/demo_arm", "");
    write(prefix / "share/demo_arm/urdf/parts.xacro",
      R"(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="boxed_link" params="name size">
    <link name="${name}"><visual><geometry><box size="${size} ${size} ${size}"/></geometry></visual></link>
  </xacro:macro>
</robot>
)");
    this->Arm = prefix / "share/demo_arm/urdf/arm.urdf.xacro";
    write(this->Arm, R"(<?xml version="1.0"?>
<robot name="demo_arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="edge" value="0.25"/>
  <xacro:include filename="$(find demo_arm)/urdf/parts.xacro"/>
  <xacro:boxed_link name="$(arg prefix)base" size="${edge}"/>
  <xacro:boxed_link name="$(arg prefix)tool" size="${edge * 2}"/>
  <joint name="$(arg prefix)joint" type="fixed">
    <parent link="$(arg prefix)base"/><child link="$(arg prefix)tool"/>
    <origin xyz="0 0 ${edge * 4}"/>
  </joint>
</robot>
)");
    // The child process inherits these: $(find) looks in AMENT_PREFIX_PATH, and the venv's
    // xacro is named by ROS2VTK_XACRO (what the Python package sets when it is imported).
    ::setenv("AMENT_PREFIX_PATH", prefix.c_str(), 1);
    const fs::path xacro = fs::path(ROS2VTK_TEST_VENV_PYTHON).parent_path() / "xacro";
    ::setenv("ROS2VTK_XACRO", xacro.c_str(), 1);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(this->Root, ec);
    ::unsetenv("ROS2VTK_XACRO");
  }

  static double edge_of(const LinkVisuals* link)
  {
    double bounds[6];
    link->visuals.at(0).geometry->GetBounds(bounds);
    return bounds[1] - bounds[0];
  }

  fs::path Root;
  fs::path Arm;
};
} // namespace

TEST_F(Xacro, MacrosPropertiesArgumentsAndFindExpandIntoTheRobot)
{
  RobotLoader loader;
  std::string error;
  ASSERT_TRUE(loader.xacro().set_arguments("prefix:=left_", &error)) << error;
  RobotVisuals robot;
  ASSERT_TRUE(loader.load_file(this->Arm.string(), &robot, &error)) << error;
  EXPECT_EQ(robot.robot_name, "demo_arm");
  EXPECT_EQ(robot.root_link, "left_base");
  ASSERT_EQ(robot.links.size(), 2u);
  ASSERT_NE(robot.link("left_tool"), nullptr);
  // The sizes the file computes: edge and edge * 2.
  EXPECT_NEAR(edge_of(robot.link("left_base")), 0.25, 1e-9);
  EXPECT_NEAR(edge_of(robot.link("left_tool")), 0.5, 1e-9);
}

TEST_F(Xacro, WithoutArgumentsTheDefaultsApply)
{
  RobotLoader loader;
  RobotVisuals robot;
  std::string error;
  ASSERT_TRUE(loader.load_file(this->Arm.string(), &robot, &error)) << error;
  EXPECT_NE(robot.link("base"), nullptr);
  EXPECT_NE(robot.link("tool"), nullptr);
}

TEST_F(Xacro, AnArgumentThatIsNotNameAssignValueIsRefused)
{
  XacroProcessor xacro;
  std::string error;
  EXPECT_FALSE(xacro.set_arguments("prefix:=a_ side=left", &error));
  EXPECT_EQ(error, "xacro argument 'side=left' is not name:=value");
  EXPECT_TRUE(xacro.arguments().empty());
}

TEST_F(Xacro, NoXacroInstalledSaysWhereItLookedAndHowToInstall)
{
  RobotLoader loader;
  loader.xacro().set_command((this->Root / "no/such/xacro").string());
  RobotVisuals robot;
  std::string error;
  EXPECT_FALSE(loader.load_file(this->Arm.string(), &robot, &error));
  EXPECT_NE(
    error.find("cannot expand the xacro file '" + this->Arm.string() + "'"), std::string::npos)
    << error;
  EXPECT_NE(error.find("no xacro processor found"), std::string::npos) << error;
  EXPECT_NE(error.find("pip install xacro"), std::string::npos) << error;
}

TEST_F(Xacro, XacrosOwnErrorIsPassedOn)
{
  const fs::path bad = this->Root / "bad.urdf.xacro";
  write(
    bad, R"(<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:nosuch/></robot>)");
  RobotLoader loader;
  RobotVisuals robot;
  std::string error;
  EXPECT_FALSE(loader.load_file(bad.string(), &robot, &error));
  EXPECT_NE(error.find("xacro failed (exit 2)"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown macro name: xacro:nosuch"), std::string::npos) << error;
}

TEST_F(Xacro, AMissingIncludeNamesIt)
{
  const fs::path bad = this->Root / "include.xacro";
  write(bad, R"(<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find no_such_pkg)/urdf/x.xacro"/></robot>)");
  RobotLoader loader;
  RobotVisuals robot;
  std::string error;
  EXPECT_FALSE(loader.load_file(bad.string(), &robot, &error));
  EXPECT_NE(error.find("no_such_pkg"), std::string::npos) << error;
}

TEST(XacroFiles, RecognisedByTheirExtension)
{
  EXPECT_TRUE(XacroProcessor::is_xacro_file("/a/arm.urdf.xacro"));
  EXPECT_TRUE(XacroProcessor::is_xacro_file("arm.XACRO"));
  EXPECT_FALSE(XacroProcessor::is_xacro_file("arm.urdf"));
  EXPECT_FALSE(XacroProcessor::is_xacro_file("xacro"));
}
