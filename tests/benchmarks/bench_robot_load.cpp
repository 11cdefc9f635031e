// bench_robot_load — time from a robot_description's arrival to all of the robot's links in the
// scene, and the process's memory with 1 and N robots loaded.
//
// "Arrival" is the URDF text in hand, as the robot node's description source hands it over on a
// spin; from there vtkROS2RobotNode::LoadRobotDescription parses it, loads every mesh and builds
// the link transform (tf lookup) and model nodes: the same path the automatic load takes. Each of
// the N robots is its own robot node (own name, own tf prefix) on the default ROS node; they stay
// loaded, so VmRSS after the 1st and the Nth is the memory of 1 and N robots.
//
//   bench_robot_load --urdf FILE [--ament-prefix DIR] [--robots 10]
#include "BenchCommon.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2Scene.h"

#include <vtkNew.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  std::string urdf_path;
  int robots = 10;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if (arg == "--urdf")
      urdf_path = argv[i + 1];
    else if (arg == "--ament-prefix") // package:// lookups, as a sourced ROS workspace gives them
      setenv("AMENT_PREFIX_PATH", argv[i + 1], 1);
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
  const std::string folder = std::filesystem::path(urdf_path).parent_path().string();

  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  logic->Spin();
  const double rss_empty = bench::rss_mib();

  std::vector<double> total_ms, node_reported_ms;
  double rss_one = 0;
  int links = 0, models = 0, placeholders = 0;
  std::string warnings;
  for (int r = 0; r < robots; ++r)
  {
    const std::string name = "r" + std::to_string(r);
    // The topic source is never published here: the description is handed over directly.
    vtkROS2RobotNode* robot =
      node->CreateAndAddRobotNodeFromTopic(name.c_str(), ("/bench_unused/" + name).c_str(), "", (name + "/").c_str());
    if (!robot)
      return 1;
    const auto start = bench::Clock::now();
    const bool loaded = robot->LoadRobotDescription(xml.c_str(), folder.c_str());
    const auto end = bench::Clock::now();
    if (!loaded)
    {
      std::fprintf(stderr, "bench_robot_load: %s\n", robot->GetLastError());
      return 1;
    }
    total_ms.push_back(bench::ms_between(start, end));
    node_reported_ms.push_back(1000.0 * robot->GetLastLoadDuration());
    links = robot->GetNumberOfLinks();
    models = robot->GetNumberOfModelNodes();
    placeholders = robot->GetNumberOfPlaceholders();
    warnings = robot->GetWarnings();
    if (r == 0)
      rss_one = bench::rss_mib();
  }
  bench::JsonObject()
    .text("urdf", urdf_path)
    .number("links", links)
    .number("visuals", models)
    .number("placeholders", placeholders)
    .text("warnings", warnings.substr(0, 500))
    .number("robots", robots)
    .numbers("total_ms", total_ms)
    .numbers("node_reported_ms", node_reported_ms)
    .number("rss_empty_mib", rss_empty)
    .number("rss_1_mib", rss_one)
    .number("rss_n_mib", bench::rss_mib())
    .text("path", "vtkROS2RobotNode::LoadRobotDescription (parse, meshes, link and model nodes)")
    .print();
  return 0;
}
