// ros2vtk — joint positions -> link poses, with limits and mimic joints.
#include "ros2vtk/robot/JointStateKinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ros2vtk {
namespace robot {

std::unique_ptr<JointStateKinematics> JointStateKinematics::from_urdf(
  const std::string& urdf_xml, std::string* error)
{
  std::unique_ptr<KinematicTree> tree = KinematicTree::from_urdf(urdf_xml, error);
  if (!tree)
  {
    return nullptr;
  }
  return std::unique_ptr<JointStateKinematics>(new JointStateKinematics(std::move(tree)));
}

JointStateKinematics::JointStateKinematics(std::unique_ptr<KinematicTree> tree)
  : tree_(std::move(tree))
  , actuated_(tree_->actuated_joints())
{
  this->reset();
}

double JointStateKinematics::clamp_into_limits(
  const JointInfo& joint, double value, bool* clamped) const
{
  double result = value;
  const bool bounded =
    joint.type == JointInfo::Type::Revolute || joint.type == JointInfo::Type::Prismatic;
  if (bounded && joint.has_limits && joint.lower < joint.upper)
  {
    result = std::min(std::max(value, joint.lower), joint.upper);
  }
  if (clamped)
  {
    *clamped = result != value;
  }
  return result;
}

void JointStateKinematics::reset()
{
  positions_.clear();
  for (const std::string& name : actuated_)
  {
    positions_[name] = clamp_into_limits(*tree_->joint(name), 0.0, nullptr);
  }
  has_positions_ = false;
}

JointStateKinematics::SetResult JointStateKinematics::set_position(
  const std::string& joint, double value)
{
  const JointInfo* info = tree_->joint(joint);
  if (!info)
  {
    return SetResult::UnknownJoint;
  }
  auto slot = positions_.find(joint);
  if (slot == positions_.end())
  {
    return SetResult::NotActuated;
  }
  if (!std::isfinite(value))
  {
    return SetResult::NotFinite;
  }
  bool clamped = false;
  slot->second = clamp_into_limits(*info, value, &clamped);
  has_positions_ = true;
  return clamped ? SetResult::Clamped : SetResult::Applied;
}

double JointStateKinematics::effective_position(const JointInfo& joint) const
{
  // Follow mimic chains (a mimics b mimics c); a loop or a missing leader ends at 0.
  double multiplier = 1.0;
  double offset = 0.0;
  const JointInfo* current = &joint;
  for (size_t hops = 0; hops <= tree_->joints().size(); ++hops)
  {
    if (current->mimic_joint.empty())
    {
      auto it = positions_.find(current->name);
      const double q = it == positions_.end() ? 0.0 : it->second;
      return multiplier * q + offset;
    }
    // q(current) = m * q(leader) + o, so q(joint) = M * (m * q(leader) + o) + O.
    offset += multiplier * current->mimic_offset;
    multiplier *= current->mimic_multiplier;
    current = tree_->joint(current->mimic_joint);
    if (!current)
    {
      return 0.0;
    }
  }
  return 0.0;
}

double JointStateKinematics::position(const std::string& joint) const
{
  const JointInfo* info = tree_->joint(joint);
  return info ? effective_position(*info) : std::numeric_limits<double>::quiet_NaN();
}

JointStateReport JointStateKinematics::apply_joint_state(
  const std::vector<std::string>& names, const std::vector<double>& positions)
{
  JointStateReport report;
  if (names.size() != positions.size())
  {
    report.error = "JointState has " + std::to_string(names.size()) + " names but " +
      std::to_string(positions.size()) + " positions (they must match one to one); message ignored";
    return report;
  }
  report.accepted = true;
  for (size_t i = 0; i < names.size(); ++i)
  {
    switch (set_position(names[i], positions[i]))
    {
      case SetResult::Applied:
        ++report.applied;
        break;
      case SetResult::Clamped:
        ++report.applied;
        report.clamped.push_back(names[i]);
        break;
      case SetResult::NotFinite:
        report.not_finite.push_back(names[i]);
        break;
      case SetResult::UnknownJoint:
      case SetResult::NotActuated:
        report.unknown.push_back(names[i]);
        break;
    }
  }
  return report;
}

std::vector<LinkTransform> JointStateKinematics::joint_transforms() const
{
  std::vector<LinkTransform> result;
  result.reserve(tree_->joints().size());
  for (const JointInfo& joint : tree_->joints())
  {
    LinkTransform transform;
    transform.parent = joint.parent_link;
    transform.child = joint.child_link;
    transform.is_static = !joint.is_moving();
    transform.transform = joint.origin * joint_motion(joint, effective_position(joint));
    result.push_back(transform);
  }
  return result;
}

std::map<std::string, Eigen::Isometry3d> JointStateKinematics::link_poses() const
{
  std::map<std::string, Eigen::Isometry3d> poses;
  poses[tree_->root_link()] = Eigen::Isometry3d::Identity();
  // The tree's joints come parents first, so each parent's pose is known before its children.
  for (const LinkTransform& transform : joint_transforms())
  {
    poses[transform.child] = poses[transform.parent] * transform.transform;
  }
  return poses;
}

} // namespace robot
} // namespace ros2vtk
