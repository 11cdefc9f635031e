// bench_robot_load — time from a robot_description's arrival to all of the robot's links in the
// scene, and the process's memory with 1 and N robots loaded.
//
// "Arrival" is the URDF text in hand (as a subscriber hands it over); from there each load runs
// ros2vtk::robot::RobotLoader::load_xml (parse, read and convert every mesh) with a fresh loader
// (so no mesh cache is shared between robots: the conservative case) and then puts the links into
// the scene as tests/benchmarks/RobotScene.hpp does (tf lookup + model nodes, as the demo does
// until vtkROS2RobotNode lands). The robots stay loaded, so VmRSS after the 1st and the Nth load
// is the memory of 1 and N robots.
//
//   bench_robot_load --urdf FILE [--ament-prefix DIR] [--robots 10]
#include "BenchCommon.hpp"
#include "RobotScene.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include <vtkNew.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  std::string urdf_path;
  std::string ament_prefix;
  int robots = 10;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if (arg == "--urdf")
      urdf_path = argv[i + 1];
    else if (arg == "--ament-prefix")
      ament_prefix = argv[i + 1];
    else if (arg == "--robots")
      robots = std::atoi(argv[i + 1]);
  }
  std::ifstream file(urdf_path);
  if (urdf_path.empty() || !file || robots < 1)
  {
    std::fprintf(stderr, "usage: bench_robot_load --urdf FILE [--ament-prefix DIR] [--robots N]\n");
    return 2;
  }
  const std::string xml((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());

  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  logic->Spin();
  const double rss_empty = bench::rss_mib();

  std::vector<double> load_ms, scene_ms, total_ms;
  std::vector<std::unique_ptr<ros2vtk::robot::RobotVisuals>> kept; // robots stay loaded
  double rss_one = 0;
  size_t links = 0, visuals = 0, placeholders = 0;
  for (int r = 0; r < robots; ++r)
  {
    ros2vtk::robot::ResourceResolver resolver = ros2vtk::robot::ResourceResolver::from_environment();
    if (!ament_prefix.empty())
      resolver.set_ament_prefixes({ ament_prefix });
    ros2vtk::robot::RobotLoader loader(resolver);
    ros2vtk::robot::RobotLoadOptions load_options;
    load_options.base_folder = std::filesystem::path(urdf_path).parent_path().string();
    auto robot = std::make_unique<ros2vtk::robot::RobotVisuals>();
    std::string error;
    const auto start = bench::Clock::now();
    if (!loader.load_xml(xml, load_options, robot.get(), &error))
    {
      std::fprintf(stderr, "bench_robot_load: %s\n", error.c_str());
      return 1;
    }
    const auto loaded = bench::Clock::now();
    const auto added = bench::add_robot_to_scene(node, logic->GetScene(), *robot, "r" + std::to_string(r) + "/");
    const auto end = bench::Clock::now();
    load_ms.push_back(bench::ms_between(start, loaded));
    scene_ms.push_back(bench::ms_between(loaded, end));
    total_ms.push_back(bench::ms_between(start, end));
    links = robot->links.size();
    visuals = robot->visual_count();
    placeholders = robot->placeholder_count();
    (void)added;
    kept.push_back(std::move(robot));
    if (r == 0)
      rss_one = bench::rss_mib();
  }
  bench::JsonObject()
    .text("urdf", urdf_path)
    .number("links", static_cast<double>(links))
    .number("visuals", static_cast<double>(visuals))
    .number("placeholders", static_cast<double>(placeholders))
    .number("robots", robots)
    .numbers("load_ms", load_ms)
    .numbers("scene_ms", scene_ms)
    .numbers("total_ms", total_ms)
    .number("rss_empty_mib", rss_empty)
    .number("rss_1_mib", rss_one)
    .number("rss_n_mib", bench::rss_mib())
    .text("path", "RobotLoader::load_xml + tf lookup/model nodes (vtkROS2RobotNode not yet available)")
    .print();
  return 0;
}
