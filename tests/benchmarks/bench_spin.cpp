// bench_spin — cost of one vtkROS2Logic::Spin() with N simulated robots publishing tf.
//
// C++ rather than Python so the figure is our spin alone: a Python loop would add the wrapper
// call and the interpreter's own jitter to every sample. Each Spin() takes every pending message
// (tf of all robots), updates every robot link's transform (the tf lookup nodes of each
// vtkROS2RobotNode, which its model nodes hang under) and fires their observers (a counting
// callback stands in for a viewer's; rendering is excluded). The robots are ros2vtk-sim-robot
// processes the driver starts in namespaces /robot1 .. /robotN with frame prefixes robot1/ ..
// robotN/; each becomes a robot node through CreateAndAddRobotNodeFromTopic, as users do.
// --robots 0 spins the ROS node alone (nothing to take, nothing to update): the floor of one
// Spin() on this machine at this rate, which the robot rows are read against.
//
// --between busy waits for the next spin in a loop reading the clock instead of sleeping: the
// same spins with the same messages, but the core never idles between them, so the caches and
// TLBs are as warm as the spin's own work leaves them. Read beside the sleeping rows, it says
// how much of a spin is this machine's wake-up from idle rather than instructions.
//
//   bench_spin --robots N [--spins 1000] [--rate 50] [--wait 30] [--between sleep|busy]
//
// Prints one JSON object: spin_ms (per spin), messages (per spin), links, tracked, ...
#include "BenchCommon.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2TransformNode.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

#include <sys/resource.h>
#include <time.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Options
{
  int robots = 1;
  int spins = 1000;
  double rate = 50.0;
  double wait = 30.0;
  bool busy = false;  ///< --between busy or flush
  bool flush = false; ///< --between flush
};

bool parse(int argc, char** argv, Options& o)
{
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    const char* value = argv[i + 1];
    if (arg == "--robots")
      o.robots = std::atoi(value);
    else if (arg == "--spins")
      o.spins = std::atoi(value);
    else if (arg == "--rate")
      o.rate = std::atof(value);
    else if (arg == "--wait")
      o.wait = std::atof(value);
    else if (arg == "--between" &&
      (std::string(value) == "sleep" || std::string(value) == "busy" ||
        std::string(value) == "flush"))
    {
      o.busy = std::string(value) != "sleep";
      o.flush = std::string(value) == "flush";
    }
    else
      return false;
  }
  return o.robots >= 0 && o.spins > 0 && o.rate > 0;
}

void count_event(vtkObject*, unsigned long, void* client_data, void*)
{
  ++*static_cast<long*>(client_data);
}

void wait_until(bench::Clock::time_point next, bool busy)
{
  if (!busy)
  {
    std::this_thread::sleep_until(next);
    return;
  }
  while (bench::Clock::now() < next)
  {
  }
}

// Writes one byte per cache line of a buffer larger than the last-level cache, touching as many
// pages as the TLBs hold many times over: the spin that follows finds its data in memory only,
// as after an idle period in which the core's caches were given to others.
void evict_caches(std::vector<unsigned char>& buffer)
{
  for (size_t i = 0; i < buffer.size(); i += 64)
    buffer[i] = static_cast<unsigned char>(buffer[i] + 1);
}

// CPU time of the calling thread: beside the wall time of a spin, it says how long the spin ran
// and how long it waited (descheduled, or blocked on a lock a DDS thread held).
double thread_cpu_ms()
{
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// Voluntary plus involuntary context switches of the calling thread so far.
long thread_switches()
{
  rusage usage{};
  getrusage(RUSAGE_THREAD, &usage);
  return usage.ru_nvcsw + usage.ru_nivcsw;
}

bool all_loaded(const std::vector<vtkROS2RobotNode*>& robots)
{
  for (auto* robot : robots)
    if (!robot->IsLoaded())
      return false;
  return true;
}

size_t links_of(const std::vector<vtkROS2RobotNode*>& robots)
{
  size_t links = 0;
  for (auto* robot : robots)
    links += static_cast<size_t>(robot->GetNumberOfLinks());
  return links;
}

size_t tracked_of(const std::vector<vtkROS2RobotNode*>& robots)
{
  size_t tracked = 0;
  for (auto* robot : robots)
    tracked += static_cast<size_t>(robot->GetNumberOfLinksTracked());
  return tracked;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  if (!parse(argc, argv, options))
  {
    std::fprintf(stderr,
      "usage: bench_spin --robots N [--spins N] [--rate HZ] [--wait S] [--between sleep|busy]\n");
    return 2;
  }
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  if (!node)
  {
    std::fprintf(stderr, "bench_spin: no default ROS node\n");
    return 1;
  }
  std::vector<vtkROS2RobotNode*> robots; // owned by the scene
  for (int i = 1; i <= options.robots; ++i)
  {
    const std::string name = "robot" + std::to_string(i);
    auto* robot = node->CreateAndAddRobotNodeFromTopic(
      name.c_str(), ("/" + name + "/robot_description").c_str(), "", (name + "/").c_str());
    if (!robot)
      return 1;
    robots.push_back(robot);
  }

  // Wait until every robot is loaded and every link tracked (discovery, description, first tf).
  const auto period = std::chrono::duration_cast<bench::Clock::duration>(
    std::chrono::duration<double>(1.0 / options.rate));
  const auto wait_end = bench::Clock::now() + std::chrono::duration<double>(options.wait);
  while (bench::Clock::now() < wait_end)
  {
    logic->Spin();
    if (all_loaded(robots) && tracked_of(robots) == links_of(robots))
      break;
    std::this_thread::sleep_for(period);
  }
  const size_t links = links_of(robots);
  const size_t tracked = tracked_of(robots);
  // Observers on every link transform (what a viewer hooks to move the actors).
  long observed = 0;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(count_event);
  observer->SetClientData(&observed);
  size_t models = 0;
  for (auto* robot : robots)
  {
    std::istringstream names(robot->GetLinkNames());
    std::string link;
    while (names >> link)
      if (auto* transform = robot->GetLinkTransformNode(link.c_str()))
        transform->AddObserver(vtkCommand::ModifiedEvent, observer);
    models += static_cast<size_t>(robot->GetNumberOfModelNodes());
  }
  // One second of warm-up spins so caches and queues are in their steady state.
  auto next = bench::Clock::now();
  for (int i = 0; i < static_cast<int>(options.rate); ++i)
  {
    next += period;
    logic->Spin();
    wait_until(next, options.busy);
  }

  std::vector<unsigned char> eviction(options.flush ? size_t(64) << 20 : 0);
  std::vector<double> spin_ms;
  std::vector<double> spin_cpu_ms;
  std::vector<double> switched; // 1 where the thread was switched out during the spin
  std::vector<double> messages;
  spin_ms.reserve(options.spins);
  spin_cpu_ms.reserve(options.spins);
  switched.reserve(options.spins);
  messages.reserve(options.spins);
  const long observed_before = observed;
  next = bench::Clock::now();
  for (int i = 0; i < options.spins; ++i)
  {
    next += period;
    if (options.flush)
      evict_caches(eviction);
    const long switches_before = thread_switches();
    const double cpu_before = thread_cpu_ms();
    const auto start = bench::Clock::now();
    const int handled = logic->Spin();
    const auto end = bench::Clock::now();
    const double cpu_after = thread_cpu_ms();
    spin_ms.push_back(bench::ms_between(start, end));
    spin_cpu_ms.push_back(cpu_after - cpu_before);
    switched.push_back(thread_switches() != switches_before ? 1.0 : 0.0);
    messages.push_back(handled);
    wait_until(next, options.busy);
  }
  const size_t tracked_end = tracked_of(robots);

  bench::JsonObject()
    .number("robots", options.robots)
    .number("links", static_cast<double>(links))
    .number("models", static_cast<double>(models))
    .number("tracked_before", static_cast<double>(tracked))
    .number("tracked_after", static_cast<double>(tracked_end))
    .number("observer_calls", static_cast<double>(observed - observed_before))
    .number("logic_mean_spin_ms", logic->GetMeanSpinDuration())
    .text("between_spins",
      options.flush    ? "flush"
        : options.busy ? "busy"
                       : "sleep")
    .text("driven_by", "vtkROS2RobotNode (CreateAndAddRobotNodeFromTopic)")
    .numbers("spin_ms", spin_ms)
    .numbers("spin_cpu_ms", spin_cpu_ms)
    .numbers("switched", switched)
    .numbers("messages", messages)
    .print();
  return tracked == links ? 0 : 3;
}
