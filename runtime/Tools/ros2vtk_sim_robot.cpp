// ros2vtk-sim-robot — plays robot_state_publisher (+ a joint trajectory) for a URDF, on the
// ros2vtk runtime, so demos, examples and benchmarks need no ROS installation:
//   * serves the `robot_description` parameter (and publish_frequency, frame_prefix,
//     ignore_timestamp, use_sim_time) through the standard parameter services;
//   * publishes the URDF on `robot_description` (reliable, transient local, depth 1);
//   * publishes fixed joints on /tf_static and moving joints on /tf, stamped now, with the frame
//     prefix, exactly as robot_state_publisher does; mimic joints follow their leader;
//   * publishes `joint_states` following a smooth trajectory inside the joint limits, or the
//     motion given by --motion FILE: one line per joint, `<joint> <mid> <amplitude> <period s>
//     [<phase rad>]` (rad or m; position = mid + amplitude * sin(2 pi t / period + phase); `#`
//     starts a comment; joints not listed keep the default motion), e.g.
//     examples/robots/surgical_arm/config/needle_insertion.motion.
// Usage: ros2vtk-sim-robot --urdf FILE [--namespace NS] [--rate HZ] [--frame-prefix P]
//                          [--duration S] [--node NAME] [--motion FILE]
#include "ros2vtk/geometry_msgs/msg/transform_stamped.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/robot/KinematicTree.hpp"
#include "ros2vtk/sensor_msgs/msg/joint_state.hpp"
#include "ros2vtk/std_msgs/msg/string.hpp"
#include "ros2vtk/tf2_msgs/msg/tf_message.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/ParameterServer.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "ros2vtk/ros2vtkMessagesRegister.hpp" // ros2vtk_register_ros2vtkMessages_types()

namespace {

using namespace ros2vtk;
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t interrupted = 0;
void on_signal(int)
{
  interrupted = 1;
}

struct Options
{
  std::string urdf_path;
  std::string ns = "/";
  std::string node = "robot_state_publisher";
  std::string frame_prefix;
  std::string motion_path;
  double rate = 50.0;
  double duration = 0.0;
};

bool parse(int argc, char** argv, Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
      return false;
    const std::string value = argv[++i];
    if (arg == "--urdf")
      options.urdf_path = value;
    else if (arg == "--namespace")
      options.ns = value;
    else if (arg == "--node")
      options.node = value;
    else if (arg == "--frame-prefix")
      options.frame_prefix = value;
    else if (arg == "--rate")
      options.rate = std::atof(value.c_str());
    else if (arg == "--duration")
      options.duration = std::atof(value.c_str());
    else if (arg == "--motion")
      options.motion_path = value;
    else
      return false;
  }
  return !options.urdf_path.empty() && options.rate > 0;
}

const wire::MessageTypeSupport& type(const char* name)
{
  const wire::MessageTypeSupport* support = wire::find_message_type(name);
  if (!support)
  {
    std::cerr << "ros2vtk-sim-robot: type " << name << " is not registered\n";
    std::exit(1);
  }
  return *support;
}

builtin_interfaces::msg::Time now_stamp()
{
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
                    .count();
  builtin_interfaces::msg::Time stamp;
  stamp.sec = static_cast<int32_t>(ns / 1000000000);
  stamp.nanosec = static_cast<uint32_t>(ns % 1000000000);
  return stamp;
}

geometry_msgs::msg::TransformStamped to_message(const robot::LinkTransform& link,
  const std::string& prefix, const builtin_interfaces::msg::Time& stamp)
{
  geometry_msgs::msg::TransformStamped message;
  message.header.stamp = stamp;
  message.header.frame_id = prefix + link.parent;
  message.child_frame_id = prefix + link.child;
  const Eigen::Vector3d t = link.transform.translation();
  const Eigen::Quaterniond q(link.transform.rotation());
  message.transform.translation.x = t.x();
  message.transform.translation.y = t.y();
  message.transform.translation.z = t.z();
  message.transform.rotation.x = q.x();
  message.transform.rotation.y = q.y();
  message.transform.rotation.z = q.z();
  message.transform.rotation.w = q.w();
  return message;
}

/// A smooth, bounded motion per actuated joint: mid + amplitude * sin(w t + phase).
struct Trajectory
{
  struct Joint
  {
    std::string name;
    double mid, amplitude, omega, phase;
  };
  std::vector<Joint> joints;

  explicit Trajectory(const robot::KinematicTree& tree)
  {
    size_t i = 0;
    for (const auto& name : tree.actuated_joints())
    {
      const robot::JointInfo* joint = tree.joint(name);
      double lower = -M_PI, upper = M_PI;
      if (joint->has_limits && joint->upper > joint->lower)
      {
        lower = joint->lower;
        upper = joint->upper;
      }
      const double span = upper - lower;
      joints.push_back(
        { name, lower + span / 2, 0.35 * span, 2 * M_PI * 0.1 * (1.0 + 0.13 * i), 0.7 * i });
      ++i;
    }
  }

  /// Applies a --motion file's lines to the joints they name; false + `error` (file:line: what)
  /// on an unreadable file, a malformed line, an unknown or repeated joint, a period <= 0, or a
  /// motion leaving the joint's limits.
  bool apply(const std::string& path, const robot::KinematicTree& tree, std::string* error)
  {
    std::ifstream file(path);
    if (!file)
    {
      *error = "cannot read the motion file " + path;
      return false;
    }
    std::string line;
    std::map<std::string, int> seen;
    for (int number = 1; std::getline(file, line); ++number)
    {
      const std::string where = path + ":" + std::to_string(number) + ": ";
      line = line.substr(0, line.find('#'));
      std::istringstream fields(line);
      std::string name;
      if (!(fields >> name))
        continue; // blank or comment
      double mid = 0, amplitude = 0, period = 0, phase = 0;
      if (!(fields >> mid >> amplitude >> period))
      {
        *error = where + "expected '<joint> <mid> <amplitude> <period s> [<phase rad>]'";
        return false;
      }
      std::string rest;
      if (!(fields >> phase))
        phase = 0;
      fields.clear();
      if (fields >> rest)
      {
        *error = where + "unexpected '" + rest +
          "' (expected '<joint> <mid> <amplitude> <period s> [<phase rad>]')";
        return false;
      }
      auto joint =
        std::find_if(joints.begin(), joints.end(), [&](const Joint& j) { return j.name == name; });
      if (joint == joints.end())
      {
        *error = where + "'" + name + "' is not an actuated joint of " + tree.robot_name();
        return false;
      }
      if (seen.count(name))
      {
        *error = where + "'" + name + "' was already given on line " + std::to_string(seen[name]);
        return false;
      }
      seen[name] = number;
      if (!(period > 0))
      {
        *error = where + "the period must be > 0 s";
        return false;
      }
      const robot::JointInfo* info = tree.joint(name);
      if (info->has_limits && info->upper > info->lower &&
        (mid - std::abs(amplitude) < info->lower - 1e-9 ||
          mid + std::abs(amplitude) > info->upper + 1e-9))
      {
        std::ostringstream message;
        message << where << "'" << name << "' would move over [" << mid - std::abs(amplitude)
                << ", " << mid + std::abs(amplitude) << "], outside its limits [" << info->lower
                << ", " << info->upper << "]";
        *error = message.str();
        return false;
      }
      *joint = { name, mid, amplitude, 2 * M_PI / period, phase };
    }
    return true;
  }

  void at(double t, std::map<std::string, double>& positions, std::vector<double>& velocities) const
  {
    velocities.clear();
    for (const auto& j : joints)
    {
      positions[j.name] = j.mid + j.amplitude * std::sin(j.omega * t + j.phase);
      velocities.push_back(j.amplitude * j.omega * std::cos(j.omega * t + j.phase));
    }
  }
};

rcl_interfaces::msg::ParameterValue string_value(const std::string& text)
{
  rcl_interfaces::msg::ParameterValue value;
  value.type = rcl_interfaces::msg::ParameterType::PARAMETER_STRING;
  value.string_value = text;
  return value;
}

} // namespace

int main(int argc, char** argv)
{
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ros2vtk_register_ros2vtkMessages_types();
  Options options;
  if (!parse(argc, argv, options))
  {
    std::cerr << "usage: ros2vtk-sim-robot --urdf FILE [--namespace NS] [--rate HZ] "
                 "[--frame-prefix P] [--duration S] [--node NAME] [--motion FILE]\n";
    return 2;
  }
  std::ifstream file(options.urdf_path);
  if (!file)
  {
    std::cerr << "ros2vtk-sim-robot: cannot read " << options.urdf_path << "\n";
    return 1;
  }
  std::stringstream buffer;
  buffer << file.rdbuf();
  std::string urdf = buffer.str();
  std::string error;
  auto tree = robot::KinematicTree::from_urdf(urdf, &error);
  if (!tree)
  {
    std::cerr << "ros2vtk-sim-robot: " << options.urdf_path << ": " << error << "\n";
    return 1;
  }
  Trajectory trajectory(*tree);
  if (!options.motion_path.empty() && !trajectory.apply(options.motion_path, *tree, &error))
  {
    std::cerr << "ros2vtk-sim-robot: " << error << "\n";
    return 1;
  }

  auto participant = wire::Participant::create(
    options.node, options.ns, wire::ParticipantOptions::from_environment(), &error);
  if (!participant)
  {
    std::cerr << "ros2vtk-sim-robot: " << error << "\n";
    return 1;
  }
  auto parameters = wire::ParameterServer::create(*participant, &error);
  auto description = participant->create_publisher(
    type("std_msgs/msg/String"), "robot_description", wire::QoS::transient_local(1), &error);
  auto tf = participant->create_publisher(type("tf2_msgs/msg/TFMessage"), "/tf",
    wire::QoS{ wire::QoS::History::KeepLast, 100, wire::QoS::Reliability::Reliable,
      wire::QoS::Durability::Volatile },
    &error);
  auto tf_static = participant->create_publisher(
    type("tf2_msgs/msg/TFMessage"), "/tf_static", wire::QoS::transient_local(1), &error);
  auto joint_states = participant->create_publisher(
    type("sensor_msgs/msg/JointState"), "joint_states", wire::QoS{}, &error);
  if (!parameters || !description || !tf || !tf_static || !joint_states)
  {
    std::cerr << "ros2vtk-sim-robot: " << error << "\n";
    return 1;
  }

  wire::ParameterStore& store = parameters->store();
  rcl_interfaces::msg::ParameterValue frequency;
  frequency.type = rcl_interfaces::msg::ParameterType::PARAMETER_DOUBLE;
  frequency.double_value = options.rate;
  rcl_interfaces::msg::ParameterValue off;
  off.type = rcl_interfaces::msg::ParameterType::PARAMETER_BOOL;
  store.declare("robot_description", string_value(urdf), nullptr);
  store.declare("publish_frequency", frequency, nullptr);
  store.declare("frame_prefix", string_value(options.frame_prefix), nullptr);
  store.declare("ignore_timestamp", off, nullptr);
  store.declare("use_sim_time", off, nullptr);
  // Like robot_state_publisher: an unparsable or empty new description is refused.
  store.set_validator([](const rcl_interfaces::msg::Parameter& parameter) -> std::string {
    if (parameter.name != "robot_description")
      return std::string();
    std::string reason;
    return robot::KinematicTree::from_urdf(parameter.value.string_value, &reason) ? std::string()
                                                                                  : reason;
  });

  auto publish_description = [&]() {
    std_msgs::msg::String message;
    message.data = urdf;
    description->publish(&message);
    tf2_msgs::msg::TFMessage statics;
    const auto stamp = now_stamp();
    for (const auto& link : tree->joint_transforms({}))
    {
      if (link.is_static)
        statics.transforms.push_back(to_message(link, options.frame_prefix, stamp));
    }
    tf_static->publish(&statics);
  };
  publish_description();
  std::cout << "ros2vtk-sim-robot: " << tree->robot_name() << " (" << tree->joints().size()
            << " joints, " << tree->actuated_joints().size() << " actuated) as "
            << participant->fully_qualified_name() << " at " << options.rate << " Hz" << std::endl;

  std::map<std::string, double> positions;
  std::vector<double> velocities;
  const auto start = Clock::now();
  const auto period =
    std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.rate));
  auto next = start;
  while (!interrupted)
  {
    const double t = std::chrono::duration<double>(Clock::now() - start).count();
    if (options.duration > 0 && t >= options.duration)
      break;
    parameters->process();
    const rcl_interfaces::msg::ParameterValue* current = store.get("robot_description");
    if (current && current->string_value != urdf)
    {
      urdf = current->string_value;
      tree = robot::KinematicTree::from_urdf(urdf, &error);
      trajectory = Trajectory(*tree);
      // The motion file's joints that the new robot has (others are its own business).
      if (!options.motion_path.empty() && !trajectory.apply(options.motion_path, *tree, &error))
      {
        trajectory = Trajectory(*tree);
        std::cout << "ros2vtk-sim-robot: the new robot gets the default motion: " << error
                  << std::endl;
      }
      positions.clear();
      publish_description();
      std::cout << "ros2vtk-sim-robot: new robot_description: " << tree->robot_name() << std::endl;
    }
    trajectory.at(t, positions, velocities);
    const auto stamp = now_stamp();
    sensor_msgs::msg::JointState state;
    state.header.stamp = stamp;
    for (size_t i = 0; i < trajectory.joints.size(); ++i)
    {
      state.name.push_back(trajectory.joints[i].name);
      state.position.push_back(positions[trajectory.joints[i].name]);
      state.velocity.push_back(velocities[i]);
    }
    joint_states->publish(&state);
    tf2_msgs::msg::TFMessage moving;
    for (const auto& link : tree->joint_transforms(positions))
    {
      if (!link.is_static)
        moving.transforms.push_back(to_message(link, options.frame_prefix, stamp));
    }
    tf->publish(&moving);
    next += period;
    std::this_thread::sleep_until(next);
  }
  return 0;
}
