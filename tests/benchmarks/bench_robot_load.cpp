// bench_robot_load — time from a robot_description's arrival to all of the robot's links in the
// scene, and the process's memory with 1 and N robots loaded.
//
// "Arrival" is the URDF text in hand, as the robot node's description source hands it over on a
// spin; from there vtkROS2RobotNode::LoadRobotDescription parses it, loads every mesh and builds
// the link transform (tf lookup) and model nodes: the same path the automatic load takes. Each of
// the N robots is its own robot node (own name, own tf prefix) on the default ROS node; they stay
// loaded, so VmRSS after the 1st and the Nth is the memory of 1 and N robots. Robot nodes share
// one mesh cache (MeshCache), so loads 2..N are the cached reload of the same description.
//
// The baseline (--assimp-files, a text file of mesh paths, one per line): assimp's own import of
// the same mesh files with the post-processing flags MeshLoader uses, timed in this process before
// any robot loads, after every file was read once so both sides start from a warm page cache.
// Beside it, RobotLoader alone (no scene nodes, its own mesh cache) reading the meshes on one
// thread and on one thread per core (RobotLoadOptions::mesh_threads), as the robot node does.
//
//   bench_robot_load --urdf FILE [--ament-prefix DIR] [--robots 10] [--assimp-files LIST]
#include "BenchCommon.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/robot/RobotLoader.hpp"

#include <vtkNew.h>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <algorithm>
#include <vector>

namespace {

std::vector<std::string> read_lines(const std::string& path)
{
  std::vector<std::string> lines;
  std::ifstream file(path);
  for (std::string line; std::getline(file, line);)
  {
    if (!line.empty())
      lines.push_back(line);
  }
  return lines;
}

/// assimp's import of every file, as MeshLoader calls it (flags and properties of
/// load_with_assimp): total milliseconds, or -1 when a file cannot be imported.
double assimp_import_ms(const std::vector<std::string>& files)
{
  for (const std::string& path : files) // warm the page cache for both sides
  {
    std::ifstream warm(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(warm)), std::istreambuf_iterator<char>());
  }
  const auto start = bench::Clock::now();
  for (const std::string& path : files)
  {
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    importer.SetPropertyInteger(
      AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene = importer.ReadFile(path,
      aiProcess_ValidateDataStructure | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (!scene)
    {
      std::fprintf(stderr, "bench_robot_load: assimp could not import %s\n", path.c_str());
      return -1;
    }
  }
  return bench::ms_between(start, bench::Clock::now());
}

/// RobotLoader::load_xml alone with a new loader (so an empty mesh cache) and `threads`.
double loader_ms(const std::string& xml, const std::string& folder, unsigned threads)
{
  ros2vtk::robot::RobotLoader loader;
  ros2vtk::robot::RobotLoadOptions options;
  options.base_folder = folder;
  options.mesh_threads = threads;
  ros2vtk::robot::RobotVisuals visuals;
  std::string error;
  const auto start = bench::Clock::now();
  if (!loader.load_xml(xml, options, &visuals, &error))
    return -1;
  return bench::ms_between(start, bench::Clock::now());
}

} // namespace

int main(int argc, char** argv)
{
  std::string urdf_path, assimp_list;
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
    else if (arg == "--assimp-files")
      assimp_list = argv[i + 1];
  }
  std::ifstream file(urdf_path);
  if (urdf_path.empty() || !file || robots < 1)
  {
    std::fprintf(stderr,
      "usage: bench_robot_load --urdf FILE [--ament-prefix DIR] [--robots N] [--assimp-files "
      "LIST]\n");
    return 2;
  }
  const std::string xml((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string folder = std::filesystem::path(urdf_path).parent_path().string();

  const std::vector<std::string> assimp_files =
    assimp_list.empty() ? std::vector<std::string>() : read_lines(assimp_list);
  const double assimp_ms = assimp_files.empty() ? -1 : assimp_import_ms(assimp_files);
  const double loader_one_thread_ms = loader_ms(xml, folder, 1);
  const double loader_threads_ms = loader_ms(xml, folder, 0);

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
    vtkROS2RobotNode* robot = node->CreateAndAddRobotNodeFromTopic(
      name.c_str(), ("/bench_unused/" + name).c_str(), "", (name + "/").c_str());
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
    .number("assimp_files", static_cast<double>(assimp_files.size()))
    .number("assimp_import_ms", assimp_ms)
    .number("loader_one_thread_ms", loader_one_thread_ms)
    .number("loader_threads_ms", loader_threads_ms)
    .number("mesh_threads", std::min(8u, std::max(1u, std::thread::hardware_concurrency())))
    .text("path", "vtkROS2RobotNode::LoadRobotDescription (parse, meshes, link and model nodes)")
    .print();
  return 0;
}
