// ros2vtk — URDF joint tree and robot_state_publisher-style transforms.
#include "ros2vtk/robot/KinematicTree.hpp"

#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ros2vtk {
namespace robot {
namespace {

Eigen::Isometry3d to_isometry(const urdf::Pose& pose)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  double x = 0, y = 0, z = 0, w = 1;
  pose.rotation.getQuaternion(x, y, z, w);
  result.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return result;
}

JointInfo::Type to_type(int urdf_type)
{
  switch (urdf_type)
  {
    case urdf::Joint::REVOLUTE:
      return JointInfo::Type::Revolute;
    case urdf::Joint::CONTINUOUS:
      return JointInfo::Type::Continuous;
    case urdf::Joint::PRISMATIC:
      return JointInfo::Type::Prismatic;
    case urdf::Joint::FLOATING:
      return JointInfo::Type::Floating;
    case urdf::Joint::PLANAR:
      return JointInfo::Type::Planar;
    default:
      return JointInfo::Type::Fixed;
  }
}

} // namespace

std::unique_ptr<KinematicTree> KinematicTree::from_urdf(
  const std::string& urdf_xml, std::string* error)
{
  if (urdf_xml.find_first_not_of(" \t\r\n") == std::string::npos)
  {
    if (error)
      *error = "URDF is empty";
    return nullptr;
  }
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model)
  {
    if (error)
      *error = "URDF failed to parse (urdfdom rejected it: malformed XML, a missing <robot>, a "
               "joint naming an unknown link, or a tree with several roots)";
    return nullptr;
  }
  auto tree = std::unique_ptr<KinematicTree>(new KinematicTree());
  tree->robot_name_ = model->getName();
  tree->root_link_ = model->getRoot() ? model->getRoot()->name : std::string();
  // Depth-first from the root, so parents come before children (URDF order is arbitrary). An
  // explicit stack (link, next child joint), not recursion: descriptions come from the network
  // and a chain of 10 000+ links overflowed the stack (issue 11.2).
  struct Pending
  {
    urdf::LinkConstSharedPtr link;
    size_t next_joint;
  };
  std::vector<Pending> pending;
  if (model->getRoot())
  {
    tree->links_.push_back(model->getRoot()->name);
    pending.push_back({ model->getRoot(), 0 });
  }
  while (!pending.empty())
  {
    Pending& top = pending.back();
    if (top.next_joint == top.link->child_joints.size())
    {
      pending.pop_back();
      continue;
    }
    const urdf::JointConstSharedPtr joint = top.link->child_joints[top.next_joint++];
    JointInfo info;
    info.name = joint->name;
    info.type = to_type(joint->type);
    info.parent_link = joint->parent_link_name;
    info.child_link = joint->child_link_name;
    info.origin = to_isometry(joint->parent_to_joint_origin_transform);
    info.axis = Eigen::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z);
    if (info.axis.norm() > 0)
      info.axis.normalize();
    if (joint->limits &&
      (info.type == JointInfo::Type::Revolute || info.type == JointInfo::Type::Prismatic))
    {
      info.has_limits = true;
      info.lower = joint->limits->lower;
      info.upper = joint->limits->upper;
    }
    if (joint->mimic)
    {
      info.mimic_joint = joint->mimic->joint_name;
      info.mimic_multiplier = joint->mimic->multiplier;
      info.mimic_offset = joint->mimic->offset;
    }
    tree->joint_index_[info.name] = tree->joints_.size();
    tree->joints_.push_back(info);
    urdf::LinkConstSharedPtr child = model->getLink(joint->child_link_name);
    if (child)
    {
      tree->links_.push_back(child->name);
      pending.push_back({ std::move(child), 0 }); // `top` is not used after this
    }
  }
  return tree;
}

std::vector<std::string> KinematicTree::link_names() const
{
  return links_;
}

std::vector<std::string> KinematicTree::actuated_joints() const
{
  std::vector<std::string> names;
  for (const auto& joint : joints_)
  {
    if (joint.is_moving() && joint.mimic_joint.empty() && joint.type != JointInfo::Type::Floating &&
      joint.type != JointInfo::Type::Planar)
      names.push_back(joint.name);
  }
  return names;
}

const JointInfo* KinematicTree::joint(const std::string& name) const
{
  auto it = joint_index_.find(name);
  return it == joint_index_.end() ? nullptr : &joints_[it->second];
}

Eigen::Isometry3d joint_motion(const JointInfo& joint, double q)
{
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  switch (joint.type)
  {
    case JointInfo::Type::Revolute:
    case JointInfo::Type::Continuous:
      motion.linear() = Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
      break;
    case JointInfo::Type::Prismatic:
      motion.translation() = q * joint.axis;
      break;
    default:
      break;
  }
  return motion;
}

std::vector<LinkTransform> KinematicTree::joint_transforms(
  const std::map<std::string, double>& positions) const
{
  auto position_of = [&](const JointInfo& joint) {
    const std::string& leader = joint.mimic_joint.empty() ? joint.name : joint.mimic_joint;
    auto it = positions.find(leader);
    const double q = it == positions.end() ? 0.0 : it->second;
    return joint.mimic_joint.empty() ? q : joint.mimic_multiplier * q + joint.mimic_offset;
  };
  std::vector<LinkTransform> result;
  result.reserve(joints_.size());
  for (const auto& joint : joints_)
  {
    LinkTransform transform;
    transform.parent = joint.parent_link;
    transform.child = joint.child_link;
    transform.is_static = !joint.is_moving();
    transform.transform = joint.origin * joint_motion(joint, position_of(joint));
    result.push_back(transform);
  }
  return result;
}

std::map<std::string, Eigen::Isometry3d> KinematicTree::link_poses(
  const std::map<std::string, double>& positions) const
{
  std::map<std::string, Eigen::Isometry3d> poses;
  poses[root_link_] = Eigen::Isometry3d::Identity();
  // joints_ is in depth-first order, so each parent's pose is known before its children.
  for (const auto& transform : joint_transforms(positions))
  {
    poses[transform.child] = poses[transform.parent] * transform.transform;
  }
  return poses;
}

std::map<std::string, LinkReach> KinematicTree::link_reach() const
{
  // What is known of each link's frame over all joint positions, from the root down:
  // Fixed: its pose (`pose`); Turning: its origin fixed at pose.translation(), its orientation
  // pose.linear() turned about the root-frame `axis` through that origin; Free: its origin within
  // `reach` (orientation unknown).
  enum class Known
  {
    Fixed,
    Turning,
    Free
  };
  struct Frame
  {
    Known known = Known::Fixed;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    LinkReach reach;
  };
  auto travel = [this](const JointInfo& joint) {
    if (joint.type != JointInfo::Type::Prismatic)
      return 0.0;
    const JointInfo* leader = joint.mimic_joint.empty() ? &joint : this->joint(joint.mimic_joint);
    const double led = leader ? std::max(std::abs(leader->lower), std::abs(leader->upper)) : 0.0;
    return joint.mimic_joint.empty()
      ? led * joint.axis.norm()
      : (std::abs(joint.mimic_multiplier) * led + std::abs(joint.mimic_offset)) * joint.axis.norm();
  };
  auto turns = [](const JointInfo& joint) {
    return joint.type == JointInfo::Type::Revolute || joint.type == JointInfo::Type::Continuous;
  };
  std::map<std::string, Frame> frames;
  frames[root_link_] = Frame{};
  // joints_ is in depth-first order, so each parent is known before its children.
  for (const auto& joint : joints_)
  {
    const Frame parent = frames[joint.parent_link];
    Frame child;
    const double moved = travel(joint);
    if (parent.known == Known::Free)
    {
      child.known = Known::Free;
      child.reach.centre = parent.reach.centre;
      child.reach.radius = parent.reach.radius + joint.origin.translation().norm() + moved;
    }
    else
    {
      // Where the joint's origin is: fixed for a Fixed parent; on a circle about the parent's
      // axis for a Turning one (its centre fixed, its radius the offset across the axis).
      const Eigen::Vector3d offset = parent.pose.linear() * joint.origin.translation();
      const Eigen::Vector3d along =
        parent.known == Known::Turning ? parent.axis * parent.axis.dot(offset) : offset;
      const Eigen::Vector3d centre = parent.pose.translation() + along;
      const double across = (offset - along).norm() < 1e-9 ? 0.0 : (offset - along).norm();
      const Eigen::Isometry3d pose = parent.pose * joint.origin;
      if (across == 0.0 && moved == 0.0 && parent.known == Known::Fixed && turns(joint))
      {
        child.known = Known::Turning; // origin in place, turning about the joint's axis
        child.pose = pose;
        child.axis = (pose.linear() * joint.axis).normalized();
      }
      else if (across == 0.0 && moved == 0.0 && !turns(joint) &&
        joint.type != JointInfo::Type::Prismatic)
      {
        child.known = parent.known; // fixed (or floating, planar: at their origin) joint
        child.pose = pose;
        child.axis = parent.axis;
      }
      else
      {
        child.known = Known::Free;
      }
      child.reach.centre = centre;
      child.reach.radius = across + moved;
    }
    if (child.known != Known::Free)
    {
      child.reach.centre = child.pose.translation();
      child.reach.radius = 0.0;
    }
    frames[joint.child_link] = child;
  }
  std::map<std::string, LinkReach> reach;
  for (const auto& entry : frames)
  {
    reach[entry.first] = entry.second.reach;
  }
  return reach;
}

} // namespace robot
} // namespace ros2vtk
