// ros2vtk-topic — `ros2 topic`-like command line on the ros2vtk wire layer, with no ROS install:
//   ros2vtk-topic list [--wait S]                       topics and types seen on the graph
//   ros2vtk-topic nodes [--wait S]                      node names seen on the graph
//   ros2vtk-topic types                                 message types this build knows
//   ros2vtk-topic echo TOPIC TYPE [--count N] [--timeout S] [--qos PROFILE]
//   ros2vtk-topic pub TOPIC TYPE YAML [--count N] [--rate HZ] [--qos PROFILE] [--wait-matched N]
// Echo prints each message as YAML followed by `---`, as `ros2 topic echo` does. A full type name
// (pkg/msg/Type) this build does not know is learnt from the publisher's ~/get_type_description.
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"
#include "ros2vtk/wire/Subscription.hpp"
#include "ros2vtk/wire/TypeDescriptionClient.hpp"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "ros2vtk/ros2vtkMessagesRegister.hpp" // ros2vtk_register_ros2vtkMessages_types()

namespace {

using namespace ros2vtk::wire;
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t interrupted = 0;

void on_signal(int)
{
  interrupted = 1;
}

struct Options
{
  std::vector<std::string> positional;
  long count = -1;
  double rate = 1.0;
  double timeout = -1.0;
  double wait = 2.0;
  long wait_matched = 0;
  std::string qos = "default";
  std::string node = "ros2vtk_topic";
  std::string node_namespace = "/";
};

int usage()
{
  std::cerr << "usage: ros2vtk-topic list|nodes|types|echo TOPIC TYPE|pub TOPIC TYPE YAML\n"
               "       [--count N] [--rate HZ] [--timeout S] [--wait S] [--qos PROFILE]\n"
               "       [--wait-matched N] [--node NAME] [--namespace NS]\n"
               "TOPIC is resolved as rclpy does (relative, ~/private, {node}, {ns}).\n";
  return 2;
}

bool parse(int argc, char** argv, Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc)
      {
        std::cerr << "ros2vtk-topic: " << name << " needs a value\n";
        return nullptr;
      }
      return argv[++i];
    };
    const char* v = nullptr;
    if (arg == "--count" && (v = value("--count")))
      options.count = std::atol(v);
    else if (arg == "--rate" && (v = value("--rate")))
      options.rate = std::atof(v);
    else if (arg == "--timeout" && (v = value("--timeout")))
      options.timeout = std::atof(v);
    else if (arg == "--wait" && (v = value("--wait")))
      options.wait = std::atof(v);
    else if (arg == "--wait-matched" && (v = value("--wait-matched")))
      options.wait_matched = std::atol(v);
    else if (arg == "--qos" && (v = value("--qos")))
      options.qos = v;
    else if (arg == "--node" && (v = value("--node")))
      options.node = v;
    else if (arg == "--namespace" && (v = value("--namespace")))
      options.node_namespace = v;
    else if (arg.rfind("--", 0) == 0)
      return false;
    else
      options.positional.push_back(arg);
  }
  return !options.positional.empty();
}

const MessageTypeSupport* find_type_or_explain(const std::string& name)
{
  const MessageTypeSupport* type = find_message_type(name);
  if (!type)
  {
    std::cerr << "ros2vtk-topic: unknown message type '" << name << "'. Known types:\n";
    for (const auto& known : registered_message_types())
    {
      std::cerr << "  " << known << "\n";
    }
  }
  return type;
}

std::unique_ptr<Participant> make_participant(const Options& options)
{
  std::string error;
  auto participant = Participant::create(
    options.node, options.node_namespace, ParticipantOptions::from_environment(), &error);
  if (!participant)
  {
    std::cerr << "ros2vtk-topic: " << error << "\n";
  }
  return participant;
}

void sleep_seconds(double seconds)
{
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (!interrupted && Clock::now() < end)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

int list_topics(const Options& options)
{
  auto participant = make_participant(options);
  if (!participant)
    return 1;
  sleep_seconds(options.wait);
  for (const auto& topic : participant->topic_names_and_types())
  {
    std::cout << topic.name << " [";
    for (size_t i = 0; i < topic.types.size(); ++i)
    {
      std::cout << (i ? ", " : "") << topic.types[i];
    }
    std::cout << "]\n";
  }
  return 0;
}

int list_nodes(const Options& options)
{
  auto participant = make_participant(options);
  if (!participant)
    return 1;
  sleep_seconds(options.wait);
  for (const auto& node : participant->node_names_and_namespaces())
  {
    std::cout << (node.second == "/" ? "/" + node.first : node.second + "/" + node.first) << "\n";
  }
  return 0;
}

int echo(const Options& options)
{
  if (options.positional.size() != 3)
    return usage();
  const std::string& type_name = options.positional[2];
  // A full type name nothing registers is learnt from the topic's publisher (issue 13).
  const bool learn = !find_message_type(type_name) && type_name.find("/msg/") != std::string::npos;
  const MessageTypeSupport* type = learn ? nullptr : find_type_or_explain(type_name);
  if (!type && !learn)
    return 1;
  QoS qos;
  if (!QoS::from_name(options.qos, qos))
  {
    std::cerr << "ros2vtk-topic: unknown QoS profile '" << options.qos << "'\n";
    return 1;
  }
  auto participant = make_participant(options);
  if (!participant)
    return 1;
  std::string error;
  const auto deadline = Clock::now() + std::chrono::duration<double>(options.timeout);
  if (learn)
  {
    std::string topic;
    if (!participant->resolve_name(options.positional[1], topic, &error))
    {
      std::cerr << "ros2vtk-topic: " << error << "\n";
      return 1;
    }
    RuntimeTypeResolver resolver(*participant, topic, type_name);
    std::string said;
    while (!interrupted && resolver.poll() != RuntimeTypeResolver::State::Ready)
    {
      if (resolver.status() != said)
      {
        said = resolver.status();
        std::cerr << "ros2vtk-topic: " << said << std::endl;
      }
      if (resolver.state() == RuntimeTypeResolver::State::Failed)
        return 1;
      if (options.timeout >= 0 && Clock::now() >= deadline)
      {
        std::cerr << "ros2vtk-topic: timeout: " << resolver.status() << "\n";
        return 3;
      }
      sleep_seconds(0.05);
    }
    type = resolver.type();
    if (!type)
      return 1;
  }
  auto subscription = participant->create_subscription(*type, options.positional[1], qos, &error);
  if (!subscription)
  {
    std::cerr << "ros2vtk-topic: " << error << "\n";
    return 1;
  }
  long printed = 0;
  uint64_t rejected_reported = 0;
  std::vector<MessagePtr> messages;
  while (!interrupted && (options.count < 0 || printed < options.count))
  {
    if (options.timeout >= 0 && Clock::now() >= deadline)
    {
      std::cerr << "ros2vtk-topic: timeout after " << printed << " messages\n";
      return 3;
    }
    participant->wake_up().wait_for(50);
    participant->wake_up().clear();
    messages.clear();
    subscription->take(messages);
    for (const auto& message : messages)
    {
      if (options.count >= 0 && printed >= options.count)
        break;
      std::cout << to_yaml(*type, message.get()) << "---" << std::endl;
      ++printed;
    }
    if (subscription->rejected_count() > rejected_reported)
    {
      rejected_reported = subscription->rejected_count();
      std::cerr << "ros2vtk-topic: rejected " << rejected_reported
                << " malformed sample(s): " << subscription->last_rejection() << std::endl;
    }
  }
  return 0;
}

int pub(const Options& options)
{
  if (options.positional.size() != 4)
    return usage();
  const MessageTypeSupport* type = find_type_or_explain(options.positional[2]);
  if (!type)
    return 1;
  QoS qos;
  if (!QoS::from_name(options.qos, qos))
  {
    std::cerr << "ros2vtk-topic: unknown QoS profile '" << options.qos << "'\n";
    return 1;
  }
  void* message = type->create();
  std::string error;
  if (!from_yaml(*type, options.positional[3], message, &error))
  {
    std::cerr << "ros2vtk-topic: " << error << "\n";
    type->destroy(message);
    return 1;
  }
  auto participant = make_participant(options);
  if (!participant)
    return 1;
  auto publisher = participant->create_publisher(*type, options.positional[1], qos, &error);
  if (!publisher)
  {
    std::cerr << "ros2vtk-topic: " << error << "\n";
    return 1;
  }
  const auto match_deadline = Clock::now() + std::chrono::duration<double>(options.wait);
  while (!interrupted &&
    publisher->matched_subscriptions() < static_cast<size_t>(options.wait_matched) &&
    Clock::now() < match_deadline)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const auto period = std::chrono::duration<double>(options.rate > 0 ? 1.0 / options.rate : 0.0);
  auto next = Clock::now();
  for (long sent = 0; !interrupted && (options.count < 0 || sent < options.count); ++sent)
  {
    publisher->publish(message);
    std::cout << "published #" << sent + 1 << std::endl;
    next += std::chrono::duration_cast<Clock::duration>(period);
    std::this_thread::sleep_until(next);
  }
  // Let reliable / transient-local deliveries complete before the writer goes away.
  sleep_seconds(options.timeout > 0 ? options.timeout : 0.5);
  type->destroy(message);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ros2vtk_register_ros2vtkMessages_types();
  Options options;
  if (!parse(argc, argv, options))
    return usage();
  const std::string& verb = options.positional[0];
  if (verb == "list")
    return list_topics(options);
  if (verb == "nodes")
    return list_nodes(options);
  if (verb == "types")
  {
    for (const auto& name : registered_message_types())
      std::cout << name << "\n";
    return 0;
  }
  if (verb == "echo")
    return echo(options);
  if (verb == "pub")
    return pub(options);
  return usage();
}
