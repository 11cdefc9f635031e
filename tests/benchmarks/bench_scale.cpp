// bench_scale — our node on a crowded ROS graph (issue 17, "Scale").
//
//   bench_scale --mode graph --nodes 50 --topics 500 [--spins 500]
//     An rclpy process (scale_peer.py graph) holds 50 nodes and 500 topics. From the creation of
//     our ROS node until GetNodeNamesAndNamespaces / GetTopicNamesAndTypes list every one of them
//     (the discovery time a user waits for on a running lab graph), then the cost of Spin() with
//     that graph known and nothing subscribed (our graph cache must not make spin grow with the
//     graph) and of one graph query.
//   bench_scale --mode subscribers --topics 100 [--spins 500]
//     100 subscriber nodes (std_msgs/String, the mapped String node) on the 100 topics
//     scale_peer.py stream publishes at 100 Hz each: Spin() at 100 Hz, its cost per spin and per
//     message, and the memory one subscriber node costs.
//
// Prints one JSON object. Spins are paced at 100 Hz like a viewer's timer.
#include "BenchCommon.hpp"
#include "ros2vtkNodesRegister.hpp" // the mapped node classes ("String"), as the Python module loads them

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2SubscriberNode.h"

#include <vtkNew.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Options
{
  std::string mode;
  int nodes = 50;
  int topics = 500;
  int spins = 500;
  double wait = 60.0;
};

int count_lines_starting(const std::string& text, const std::string& prefix)
{
  std::istringstream lines(text);
  int count = 0;
  for (std::string line; std::getline(lines, line);)
    count += line.compare(0, prefix.size(), prefix) == 0 ? 1 : 0;
  return count;
}

const auto kPeriod = std::chrono::milliseconds(10); // 100 Hz

/// `spins` paced spins: per-spin milliseconds and items handled.
void timed_spins(
  vtkROS2Logic* logic, int spins, std::vector<double>& spin_ms, std::vector<double>& items)
{
  auto next = bench::Clock::now();
  for (int i = 0; i < spins; ++i)
  {
    next += kPeriod;
    const auto start = bench::Clock::now();
    const int handled = logic->Spin();
    spin_ms.push_back(bench::ms_between(start, bench::Clock::now()));
    items.push_back(handled);
    std::this_thread::sleep_until(next);
  }
}

int run_graph(const Options& o)
{
  vtkNew<vtkROS2Logic> logic;
  const auto created = bench::Clock::now();
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  if (!node)
    return 1;
  const auto deadline = created + std::chrono::duration<double>(o.wait);
  int nodes = 0, topics = 0;
  double discovery_ms = -1, participant_ms = -1, topics_ms = -1, nodes_ms = -1;
  while (bench::Clock::now() < deadline)
  {
    logic->Spin();
    const double now_ms = bench::ms_between(created, bench::Clock::now());
    if (participant_ms < 0 && node->GetNumberOfDiscoveredParticipants() > 0)
      participant_ms = now_ms;
    topics = count_lines_starting(node->GetTopicNamesAndTypes(), "/scale_");
    nodes = count_lines_starting(node->GetNodeNamesAndNamespaces(), "/scale_node_");
    if (topics_ms < 0 && topics >= o.topics)
      topics_ms = now_ms;
    if (nodes_ms < 0 && nodes >= o.nodes)
      nodes_ms = now_ms;
    if (topics >= o.topics && nodes >= o.nodes)
    {
      discovery_ms = bench::ms_between(created, bench::Clock::now());
      break;
    }
    std::this_thread::sleep_for(kPeriod);
  }
  std::vector<double> spin_ms, items, query_ms;
  timed_spins(logic, o.spins, spin_ms, items);
  for (int i = 0; i < 20; ++i)
  {
    const auto start = bench::Clock::now();
    const std::string listing = node->GetTopicNamesAndTypes();
    query_ms.push_back(bench::ms_between(start, bench::Clock::now()));
  }
  bench::JsonObject()
    .text("mode", "graph")
    .number("nodes_seen", nodes)
    .number("topics_seen", topics)
    .number("participants", node->GetNumberOfDiscoveredParticipants())
    .number("discovery_ms", discovery_ms)
    .number("participant_ms", participant_ms)
    .number("topics_ms", topics_ms)
    .number("nodes_ms", nodes_ms)
    .numbers("spin_ms", spin_ms)
    .numbers("query_ms", query_ms)
    .number("rss_mib", bench::rss_mib())
    .print();
  return discovery_ms >= 0 ? 0 : 3;
}

int run_subscribers(const Options& o)
{
  ros2vtk_register_ros2vtkNodes_nodes();
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  if (!node)
    return 1;
  logic->Spin();
  const double rss_before = bench::rss_mib();
  std::vector<vtkROS2SubscriberNode*> subscribers;
  for (int t = 0; t < o.topics; ++t)
  {
    auto* subscriber =
      node->CreateAndAddSubscriberNode("String", ("/scale_stream_" + std::to_string(t)).c_str());
    if (!subscriber)
      return 1;
    subscribers.push_back(subscriber);
  }
  const double rss_after = bench::rss_mib();
  const auto deadline = bench::Clock::now() + std::chrono::duration<double>(o.wait);
  auto all_receiving = [&subscribers] {
    for (auto* s : subscribers)
      if (s->GetNumberOfMessages() == 0)
        return false;
    return true;
  };
  while (bench::Clock::now() < deadline && !all_receiving())
  {
    logic->Spin();
    std::this_thread::sleep_for(kPeriod);
  }
  const bool receiving = all_receiving();
  std::vector<double> spin_ms, items;
  timed_spins(logic, 100, spin_ms, items); // warm-up, not kept
  spin_ms.clear();
  items.clear();
  vtkTypeInt64 before = 0, after = 0;
  for (auto* s : subscribers)
    before += s->GetNumberOfMessages();
  timed_spins(logic, o.spins, spin_ms, items);
  for (auto* s : subscribers)
    after += s->GetNumberOfMessages();
  std::vector<double> per_message_us;
  for (size_t i = 0; i < spin_ms.size(); ++i)
    if (items[i] > 0)
      per_message_us.push_back(1000.0 * spin_ms[i] / items[i]);
  bench::JsonObject()
    .text("mode", "subscribers")
    .number("subscribers", static_cast<double>(subscribers.size()))
    .number("all_receiving", receiving ? 1 : 0)
    .number("messages", static_cast<double>(after - before))
    .numbers("spin_ms", spin_ms)
    .numbers("messages_per_spin", items)
    .numbers("per_message_us", per_message_us)
    .number("rss_before_mib", rss_before)
    .number("rss_after_mib", rss_after)
    .print();
  return receiving ? 0 : 3;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    const char* value = argv[i + 1];
    if (arg == "--mode")
      o.mode = value;
    else if (arg == "--nodes")
      o.nodes = std::atoi(value);
    else if (arg == "--topics")
      o.topics = std::atoi(value);
    else if (arg == "--spins")
      o.spins = std::atoi(value);
    else if (arg == "--wait")
      o.wait = std::atof(value);
  }
  if (o.mode == "graph")
    return run_graph(o);
  if (o.mode == "subscribers")
    return run_subscribers(o);
  std::fprintf(
    stderr, "usage: bench_scale --mode graph|subscribers [--nodes N] [--topics N] [--spins N]\n");
  return 2;
}
