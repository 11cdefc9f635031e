// ros2vtk — a robot's links from joint positions where tf does not place them.
#include "RobotJointStateDriver.hpp"

#include "vtkROS2Message.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2SubscriberNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include "ros2vtk/convert/Units.hpp"
#include "ros2vtk/robot/JointStateKinematics.hpp"
#include "ros2vtk/tf2/TransformStamped.hpp"
#include "ros2vtk/tf2_ros/TransformBroadcaster.hpp"

#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace ros2vtk {
namespace scene {
namespace {
const char* const JointStateType = "sensor_msgs/msg/JointState";
const char* const OwnerAttribute = "ros2vtk.jointStatesOfRobot";
const char* const LinkPoseAttribute =
  "ros2vtk.linkPose"; // a LinkPoseStatus word, read by the display

std::string JoinNames(const std::vector<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
  {
    text += (text.empty() ? "'" : ", '") + name + "'";
  }
  return text;
}
} // namespace

RobotJointStateDriver::RobotJointStateDriver() = default;
RobotJointStateDriver::~RobotJointStateDriver() = default;

//------------------------------------------------------------------------------
bool RobotJointStateDriver::Load(const std::string& urdfXml, std::string* error)
{
  std::unique_ptr<ros2vtk::robot::JointStateKinematics> kinematics =
    ros2vtk::robot::JointStateKinematics::from_urdf(urdfXml, error);
  if (!kinematics)
  {
    return false;
  }
  if (this->Kinematics && this->Kinematics->has_positions())
  {
    for (const std::string& joint : kinematics->joint_names())
    {
      const double value = this->Kinematics->position(joint);
      if (!std::isnan(value))
      {
        kinematics->set_position(joint, value);
      }
    }
  }
  for (const auto& pending : this->PendingPositions)
  {
    using SetResult = ros2vtk::robot::JointStateKinematics::SetResult;
    const SetResult result = kinematics->set_position(pending.first, pending.second);
    if (result != SetResult::Applied && result != SetResult::Clamped)
    {
      this->Warnings.push_back("SetJointPosition('" + pending.first +
        "') before the load: the robot has no such "
        "joint taking a position; ignored");
    }
  }
  this->PendingPositions.clear();
  this->Kinematics = std::move(kinematics);
  this->ReportedUnknownJoints.clear();
  this->LinkStatus.clear();
  this->Placed.clear();
  this->PosesDirty = true;
  this->PublishDue = true;
  this->StaticPublished = false;
  return true;
}

void RobotJointStateDriver::Unload()
{
  this->Kinematics.reset();
  this->LinkStatus.clear();
  this->Placed.clear();
  this->LinkMatricesMillimetres.clear();
  this->PosesDirty = true;
}

//------------------------------------------------------------------------------
std::map<std::string, ros2vtk::robot::LinkReach> RobotJointStateDriver::GetLinkReach() const
{
  return this->Kinematics ? this->Kinematics->tree().link_reach()
                          : std::map<std::string, ros2vtk::robot::LinkReach>{};
}

std::string RobotJointStateDriver::GetRootLink() const
{
  return this->Kinematics ? this->Kinematics->tree().root_link() : std::string();
}

std::vector<std::string> RobotJointStateDriver::GetJointNames() const
{
  return this->Kinematics ? this->Kinematics->joint_names() : std::vector<std::string>();
}

bool RobotJointStateDriver::SetJointPosition(
  const std::string& joint, double value, std::string* why)
{
  using SetResult = ros2vtk::robot::JointStateKinematics::SetResult;
  if (!this->Kinematics)
  {
    if (!std::isfinite(value))
    {
      *why = "joint '" + joint + "': the position is not a finite number";
      return false;
    }
    this->PendingPositions[joint] = value; // applied (and checked) when the robot loads
    return true;
  }
  switch (this->Kinematics->set_position(joint, value))
  {
    case SetResult::Applied:
    case SetResult::Clamped:
      this->PosesDirty = true;
      this->PublishDue = true;
      this->LatestStamp = 0; // set by a script: stamped with the node clock
      return true;
    case SetResult::UnknownJoint:
      *why =
        "no joint '" + joint + "' (joints: " + JoinNames(this->Kinematics->joint_names()) + ")";
      return false;
    case SetResult::NotActuated:
      *why =
        "joint '" + joint + "' takes no position (fixed, or a mimic joint that follows its leader)";
      return false;
    case SetResult::NotFinite:
      *why = "joint '" + joint + "': the position is not a finite number";
      return false;
  }
  return false;
}

double RobotJointStateDriver::GetJointPosition(const std::string& joint) const
{
  auto pending = this->PendingPositions.find(joint);
  if (!this->Kinematics && pending != this->PendingPositions.end())
  {
    return pending->second;
  }
  return this->Kinematics ? this->Kinematics->position(joint)
                          : std::numeric_limits<double>::quiet_NaN();
}

void RobotJointStateDriver::ResetJointPositions()
{
  this->PendingPositions.clear();
  if (this->Kinematics)
  {
    this->Kinematics->reset();
  }
  this->PosesDirty = true;
  this->PublishDue = true;
  this->LatestStamp = 0;
}

//------------------------------------------------------------------------------
bool RobotJointStateDriver::SetJointStatesTopic(
  vtkROS2NodeNode* rosNode, const std::string& topic, const std::string& owner, std::string* error)
{
  this->Owner = owner;
  if (topic == this->Topic && (topic.empty() || this->Subscriber))
  {
    return true;
  }
  this->ReleaseJointStatesTopic(rosNode);
  this->Topic.clear();
  if (topic.empty())
  {
    return true;
  }
  if (!rosNode || !rosNode->IsCreated())
  {
    *error = "the robot's ROS node is not created";
    return false;
  }
  vtkROS2SubscriberNode* subscriber = rosNode->GetSubscriberNodeByTopic(topic.c_str());
  bool owns = false;
  if (!subscriber)
  {
    subscriber = rosNode->CreateAndAddSubscriberNode(JointStateType, topic.c_str());
    owns = subscriber != nullptr;
    if (!subscriber)
    {
      *error = "could not subscribe to '" + topic + "' (see the error above)";
      return false;
    }
    subscriber->SetAttribute(OwnerAttribute, owner.c_str());
  }
  else if (std::string(subscriber->GetROSType()) != JointStateType)
  {
    *error = "'" + topic + "' is subscribed already with type " + subscriber->GetROSType() +
      ", not " + JointStateType;
    return false;
  }
  const char* tag = subscriber->GetAttribute(OwnerAttribute);
  this->Subscriber = subscriber;
  this->OwnsSubscriber =
    owns || (tag && !owner.empty() && owner == tag); // ours, restored with the scene
  this->MessagesSeen = subscriber->GetNumberOfMessages();
  this->Topic = subscriber->GetTopic();
  return true;
}

void RobotJointStateDriver::ReleaseJointStatesTopic(vtkROS2NodeNode* rosNode)
{
  vtkROS2SubscriberNode* subscriber = this->Subscriber;
  if (subscriber && this->OwnsSubscriber && rosNode &&
    rosNode->GetSubscriberNodeByTopic(subscriber->GetTopic()) == subscriber)
  {
    rosNode->RemoveAndDeleteSubscriberNode(subscriber->GetTopic());
  }
  this->Subscriber = nullptr;
  this->OwnsSubscriber = false;
}

void RobotJointStateDriver::SetPublishTf(bool on)
{
  if (on && !this->PublishTf)
  {
    this->PublishDue = true;
    this->StaticPublished = false;
  }
  this->PublishTf = on;
}

//------------------------------------------------------------------------------
void RobotJointStateDriver::ReadJointStates(vtkROS2NodeNode* rosNode)
{
  vtkROS2SubscriberNode* subscriber = this->Subscriber;
  if (!subscriber && !this->Topic.empty() && rosNode)
  {
    // The subscriber went away (removed by a script): follow the topic again.
    const std::string topic = this->Topic;
    this->Topic.clear();
    std::string error;
    if (!this->SetJointStatesTopic(rosNode, topic, this->Owner, &error))
    {
      this->Topic = topic;
      return;
    }
    subscriber = this->Subscriber;
  }
  if (!subscriber || subscriber->GetNumberOfMessages() == this->MessagesSeen)
  {
    return;
  }
  this->MessagesSeen = subscriber->GetNumberOfMessages();
  vtkNew<vtkStringArray> names;
  vtkNew<vtkDoubleArray> positions;
  std::vector<std::string> nameList;
  std::vector<double> positionList;
  uint64_t nonFinite = 0;
  uint64_t refused = 0;
  std::string firstNonFinite;
  // Every message of the latest spin, oldest first: a robot whose joints come from several
  // publishers (each naming some joints) keeps them all.
  for (int i = 0; subscriber->GetNewMessageObject(i, this->Message); ++i)
  {
    names->Reset();
    positions->Reset();
    if (!this->Message->GetFieldAsStringArray("name", names) ||
      !this->Message->GetFieldAsArray("position", positions))
    {
      continue;
    }
    nameList.resize(static_cast<size_t>(names->GetNumberOfValues()));
    for (vtkIdType n = 0; n < names->GetNumberOfValues(); ++n)
    {
      nameList[static_cast<size_t>(n)] = names->GetValue(n);
    }
    positionList.resize(static_cast<size_t>(positions->GetNumberOfValues()));
    for (vtkIdType n = 0; n < positions->GetNumberOfValues(); ++n)
    {
      positionList[static_cast<size_t>(n)] = positions->GetValue(n);
    }
    const ros2vtk::robot::JointStateReport report =
      this->Kinematics->apply_joint_state(nameList, positionList);
    if (!report.accepted)
    {
      ++this->JointStatesRefused;
      ++refused;
      this->LastJointStateError = report.error;
      continue;
    }
    ++this->JointStatesApplied;
    this->PosesDirty = this->PosesDirty || report.applied > 0;
    this->PublishDue = true; // robot_state_publisher broadcasts for every joint state
    const std::int64_t sec = this->Message->GetFieldAsInteger("header.stamp.sec");
    const std::int64_t nanosec = this->Message->GetFieldAsInteger("header.stamp.nanosec");
    this->LatestStamp = sec * 1000000000LL + nanosec;
    for (const std::string& unknown : report.unknown)
    {
      if (this->ReportedUnknownJoints.insert(unknown).second)
      {
        this->Warnings.push_back("joint states on '" + this->Topic + "' name '" + unknown +
          "', which is no joint of this robot taking a position (unknown, fixed or mimic): ignored "
          "(said once)");
      }
    }
    if (!report.not_finite.empty() && firstNonFinite.empty())
    {
      firstNonFinite = report.not_finite.front();
    }
    nonFinite += report.not_finite.size();
  }
  const auto now = RateLimitedReport::Clock::now();
  if (const uint64_t due = this->NonFiniteReport.record(nonFinite, now))
  {
    this->Warnings.push_back("joint states on '" + this->Topic + "': " + std::to_string(due) +
      " positions were NaN or infinite and were ignored (first: joint '" +
      (firstNonFinite.empty() ? std::string("?") : firstNonFinite) + "')");
  }
  if (const uint64_t due = this->RefusedReport.record(refused, now))
  {
    this->Warnings.push_back("joint states on '" + this->Topic + "': " + std::to_string(due) +
      " messages refused: " + this->LastJointStateError);
  }
}

//------------------------------------------------------------------------------
void RobotJointStateDriver::PlaceLinks(
  const LinkNodes& links, const std::string& fixedFrame, const std::string& tfPrefix, bool* changed)
{
  if (this->PosesDirty || fixedFrame != this->PosesFixedFrame)
  {
    const std::map<std::string, Eigen::Isometry3d> poses = this->Kinematics->link_poses();
    // Relative to the fixed frame when it is one of the links; else the root link sits at it.
    Eigen::Isometry3d fixedFromRoot = Eigen::Isometry3d::Identity();
    const std::string& prefix = tfPrefix;
    if (fixedFrame.compare(0, prefix.size(), prefix) == 0)
    {
      auto fixed = poses.find(fixedFrame.substr(prefix.size()));
      if (fixed != poses.end())
      {
        fixedFromRoot = fixed->second.inverse();
      }
    }
    this->LinkMatricesMillimetres.clear();
    for (const auto& entry : poses)
    {
      const Eigen::Isometry3d pose = fixedFromRoot * entry.second;
      std::vector<double>& m = this->LinkMatricesMillimetres[entry.first];
      m.resize(16);
      ros2vtk::convert::isometry_to_elements(
        pose, ros2vtk::convert::kMillimetresPerMetre, m.data());
    }
    this->PosesFixedFrame = fixedFrame;
    this->PosesDirty = false;
  }
  const char* placed = this->Kinematics->has_positions() ? LinkPoseStatus::JointPositions
                                                         : LinkPoseStatus::ZeroConfiguration;
  this->Placed.resize(links.size());
  for (size_t i = 0; i < links.size(); ++i)
  {
    const auto& entry = links[i];
    vtkROS2TransformNode* node = entry.second;
    PlacedLink& last = this->Placed[i];
    if (last.Node != node)
    {
      last = { node, vtkROS2Tf2LookupNode::SafeDownCast(node), nullptr };
    }
    if (!node)
    {
      continue;
    }
    vtkROS2Tf2LookupNode* lookup = last.Lookup;
    const bool tracked = lookup && std::strcmp(lookup->GetLookupStatus(), "ok") == 0;
    const char* status = !lookup ? LinkPoseStatus::FixedFrame
      : tracked                  ? LinkPoseStatus::Tf
                                 : placed;
    if (status != last.Status)
    {
      this->LinkStatus[entry.first] = status;
      // The display draws a link whose lookup is not "ok" as untracked, unless it is posed from
      // joint positions (the zero configuration stays "untracked": nothing arrived). Set before
      // the matrix, whose change makes the display look again.
      const char* current = lookup ? lookup->GetAttribute(LinkPoseAttribute) : nullptr;
      if (lookup && (!current || std::strcmp(current, status) != 0))
      {
        lookup->SetAttribute(LinkPoseAttribute, status);
      }
      last.Status = status;
    }
    if (lookup && !tracked)
    {
      auto matrix = this->LinkMatricesMillimetres.find(entry.first);
      if (matrix != this->LinkMatricesMillimetres.end())
      {
        this->Scratch->DeepCopy(matrix->second.data()); // tf wins: only links tf does not place
        *changed = node->SetMatrixTransformToParent(this->Scratch) || *changed;
      }
    }
  }
}

//------------------------------------------------------------------------------
void RobotJointStateDriver::Broadcast(vtkROS2NodeNode* rosNode, const std::string& tfPrefix)
{
  const std::vector<ros2vtk::robot::LinkTransform> transforms =
    this->Kinematics->joint_transforms();
  const std::int64_t stamp =
    this->LatestStamp != 0 ? this->LatestStamp : rosNode->GetNodeTimeNanoseconds();
  std::vector<ros2vtk::tf2::TransformStamped> moving;
  std::vector<ros2vtk::tf2::TransformStamped> fixed;
  for (const ros2vtk::robot::LinkTransform& link : transforms)
  {
    ros2vtk::tf2::TransformStamped message;
    message.frame_id = tfPrefix + link.parent;
    message.child_frame_id = tfPrefix + link.child;
    message.stamp = stamp;
    message.transform = ros2vtk::tf2::Transform::from_isometry(link.transform);
    (link.is_static ? fixed : moving).push_back(message);
  }
  std::string error;
  if (!this->StaticPublished && !fixed.empty())
  {
    ros2vtk::tf2_ros::TransformBroadcaster* broadcaster = rosNode->GetTf2Broadcaster(true);
    if (!broadcaster || !broadcaster->send(fixed, &error))
    {
      this->Warnings.push_back(
        "could not broadcast the robot's fixed joints on /tf_static: " + error);
    }
  }
  this->StaticPublished = true;
  if (!moving.empty())
  {
    ros2vtk::tf2_ros::TransformBroadcaster* broadcaster = rosNode->GetTf2Broadcaster(false);
    if (!broadcaster || !broadcaster->send(moving, &error))
    {
      this->Warnings.push_back("could not broadcast the robot's joints on /tf: " + error);
    }
  }
  this->PublishDue = false;
}

//------------------------------------------------------------------------------
bool RobotJointStateDriver::Update(vtkROS2NodeNode* rosNode, const LinkNodes& links,
  const std::string& fixedFrame, const std::string& tfPrefix)
{
  if (!this->Kinematics)
  {
    return false;
  }
  this->ReadJointStates(rosNode);
  bool changed = false;
  this->PlaceLinks(links, fixedFrame, tfPrefix, &changed);
  if (this->PublishTf && this->PublishDue && rosNode && rosNode->IsCreated())
  {
    this->Broadcast(rosNode, tfPrefix);
  }
  return changed;
}

std::string RobotJointStateDriver::GetLinkPoseStatus(const std::string& link) const
{
  auto it = this->LinkStatus.find(link);
  return it == this->LinkStatus.end() ? std::string() : it->second;
}

std::vector<std::string> RobotJointStateDriver::TakeWarnings()
{
  std::vector<std::string> warnings;
  warnings.swap(this->Warnings);
  return warnings;
}

} // namespace scene
} // namespace ros2vtk
