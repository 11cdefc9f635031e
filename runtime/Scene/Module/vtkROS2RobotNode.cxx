#include "vtkROS2RobotNode.h"

#include "Internal/RobotJointStateDriver.hpp"

#include "vtkROS2ModelNode.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2ParameterNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include "ros2vtk/convert/Units.hpp"
#include "ros2vtk/robot/KinematicTree.hpp"
#include "ros2vtk/robot/RobotLoader.hpp"
#include "ros2vtk/robot/XacroProcessor.hpp"

#include "vtkCallbackCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"
#include "vtkXMLDataElement.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace {
const char* const DescriptionRole = "robotDescription";
const char* const BaseRole = "robotBase";
const char* const LinkRole = "robotLink";
const char* const LinkAttribute = "ros2vtk.link";
const char* const PlaceholderAttribute = "ros2vtk.placeholder";
constexpr double MillimetresPerMetre = ros2vtk::convert::kMillimetresPerMetre;

// Balls (centre, radius) and the smallest ball holding two of them: a robot's workspace.
namespace EnclosingSphere {
struct Ball
{
  Eigen::Vector3d Centre = Eigen::Vector3d::Zero();
  double Radius = 0.0;
  double Extent = 0.0; // added to Radius by Grown(): the link's visuals around its origin
  Ball Grown() const { return { this->Centre, this->Radius + this->Extent, 0.0 }; }
};

Ball Union(const Ball& a, const Ball& b)
{
  const double distance = (b.Centre - a.Centre).norm();
  if (distance + b.Radius <= a.Radius)
  {
    return a;
  }
  if (distance + a.Radius <= b.Radius)
  {
    return b;
  }
  const double radius = (distance + a.Radius + b.Radius) / 2;
  return { a.Centre + (b.Centre - a.Centre) * ((radius - a.Radius) / distance), radius, 0.0 };
}
} // namespace EnclosingSphere

// Visual origin (metres) x uniform m -> mm scale: the model's geometry stays in metres (it is
// shared through the loader's cache) and the matrix brings it into the millimetre scene.
void VisualToLinkMillimetres(vtkMatrix4x4* origin, vtkMatrix4x4* result)
{
  result->Identity();
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      result->SetElement(row, column, origin->GetElement(row, column) * MillimetresPerMetre);
    }
    result->SetElement(row, 3, origin->GetElement(row, 3) * MillimetresPerMetre);
  }
}
} // namespace

//------------------------------------------------------------------------------
class vtkROS2RobotNode::vtkInternals
{
public:
  std::string RobotName;
  std::string Source; // "parameter" | "topic" | "file" | "" (direct loads only)
  std::string ParameterNodeName;
  std::string ParameterName;
  std::string Topic;
  std::string DescriptionFile;
  bool ForceReload = false;
  std::string FixedFrame;
  std::string TfPrefix;
  std::vector<std::string> SearchPaths;
  bool RestrictMeshesToRoots = true;
  std::string MeshBaseFolder;
  std::string XacroArguments;

  // The description source node, and whether this robot created it (then it removes it).
  vtkWeakPointer<vtkROS2SceneNode> SourceNode;
  bool OwnsSourceNode = false;
  unsigned long SourceObserverTag = 0;
  vtkNew<vtkCallbackCommand> SourceObserver;
  bool SourceChanged = true; // check the source on the first spin

  std::string LoadedDescription; // the URDF text of the current robot
  std::string LoadedBaseFolder;
  std::string LastFailedDescription; // refused once: not parsed again on every spin
  bool HasFailedDescription = false; // LastFailedDescription is meaningful ("" can fail too)

  /// Where the description comes from, for messages ("topic '/robot_description'").
  std::string SourceText() const
  {
    if (this->Source == "parameter")
      return "parameter '" + this->ParameterName + "' of '" + this->ParameterNodeName + "'";
    if (this->Source == "topic")
      return "topic '" + this->Topic + "'";
    return "file '" + this->DescriptionFile + "'";
  }
  ros2vtk::robot::RobotVisuals Visuals;
  std::unique_ptr<ros2vtk::robot::RobotLoader> Loader;
  bool Loaded = false;
  bool FramesChanged = false;
  std::string State = "waiting for robot_description";
  std::string LastError;
  int NumberOfLoads = 0;
  double LastLoadDuration = 0.0;

  // What this robot put in the scene. The base and the link nodes it owns are saved with the
  // scene and kept across reloads (a user's placement, and nodes hung under a link, stay); the
  // models are rebuilt from the description each time.
  vtkWeakPointer<vtkROS2TransformNode> Base;
  struct LinkNode
  {
    std::string Link;
    vtkWeakPointer<vtkROS2TransformNode> Node;
    bool Owned; // false: someone else's lookup of the same frames, shared and left in place
  };
  std::vector<LinkNode> Links;
  unsigned long LinksVersion = 1; // bumped by every change of Links (DriverLinks follows it)
  unsigned long DriverLinksVersion = 0;
  std::vector<vtkWeakPointer<vtkROS2ModelNode>> Models;

  // Joint positions -> link poses where tf does not place the links (issue 15).
  ros2vtk::scene::RobotJointStateDriver JointStates;
  ros2vtk::scene::RobotJointStateDriver::LinkNodes DriverLinks; // Links as the driver takes them
  bool PublishTf = false;
  std::string JointStatesTopic; // as asked (kept when the subscriber cannot be made yet)

  /// The loader, made on first use with the mesh search paths (and, for the file source, the
  /// package holding the file).
  ros2vtk::robot::RobotLoader& LoaderForLoads()
  {
    if (!this->Loader)
    {
      this->Loader.reset(new ros2vtk::robot::RobotLoader());
      // Reloads and other robots with the same meshes read no mesh file again.
      this->Loader->set_mesh_cache(ros2vtk::robot::MeshCache::shared());
      this->Loader->resolver().set_restrict_to_roots(this->RestrictMeshesToRoots);
      this->Loader->xacro().set_arguments(this->XacroArguments, nullptr); // checked when set
      for (const std::string& folder : this->SearchPaths)
      {
        this->Loader->resolver().add_search_path(folder);
      }
      if (this->Source == "file")
      {
        this->Loader->resolver().add_package_of(this->DescriptionFile);
      }
    }
    return *this->Loader;
  }

  /// The frame the links are looked up from: this robot's own, else the scene's (as RViz's
  /// global Fixed Frame places a RobotModel), else the root link.
  std::string EffectiveFixedFrame(const vtkROS2Scene* scene) const
  {
    if (!this->FixedFrame.empty())
      return this->FixedFrame;
    if (scene && scene->GetFixedFrame()[0] != '\0')
      return scene->GetFixedFrame();
    return this->TfPrefix + this->Visuals.root_link;
  }
  /// EffectiveFixedFrame(scene) == frame, without building the string: asked at every spin.
  bool IsEffectiveFixedFrame(const vtkROS2Scene* scene, const std::string& frame) const
  {
    if (!this->FixedFrame.empty())
      return frame == this->FixedFrame;
    if (scene && scene->GetFixedFrame()[0] != '\0')
      return frame == scene->GetFixedFrame();
    const std::string& root = this->Visuals.root_link;
    return frame.size() == this->TfPrefix.size() + root.size() &&
      frame.compare(0, this->TfPrefix.size(), this->TfPrefix) == 0 &&
      frame.compare(this->TfPrefix.size(), std::string::npos, root) == 0;
  }
  std::string LoadedFixedFrame; // EffectiveFixedFrame() of the last load
};

vtkStandardNewMacro(vtkROS2RobotNode);

//------------------------------------------------------------------------------
vtkROS2RobotNode::vtkROS2RobotNode()
  : Internals(new vtkInternals)
{
  this->Internals->SourceObserver->SetClientData(this->Internals.get());
  this->Internals->SourceObserver->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void*) {
      static_cast<vtkInternals*>(clientData)->SourceChanged = true;
    });
}

//------------------------------------------------------------------------------
vtkROS2RobotNode::~vtkROS2RobotNode() = default;

//------------------------------------------------------------------------------
void vtkROS2RobotNode::SetRobotName(const char* robotName)
{
  this->Internals->RobotName = robotName ? robotName : "";
  this->ROS2NodeChildKeyChanged();
  this->SetName(("ros2:robot:" + this->Internals->RobotName).c_str());
}

const char* vtkROS2RobotNode::GetRobotName() const
{
  return this->Internals->RobotName.c_str();
}

const char* vtkROS2RobotNode::GetDescriptionSource() const
{
  return this->Internals->Source.c_str();
}

const char* vtkROS2RobotNode::GetParameterNodeName() const
{
  return this->Internals->ParameterNodeName.c_str();
}

const char* vtkROS2RobotNode::GetParameterName() const
{
  return this->Internals->ParameterName.c_str();
}

const char* vtkROS2RobotNode::GetDescriptionTopic() const
{
  return this->Internals->Topic.c_str();
}

const char* vtkROS2RobotNode::GetDescriptionFile() const
{
  return this->Internals->DescriptionFile.c_str();
}

void vtkROS2RobotNode::Reload()
{
  this->Internals->ForceReload = true;
  this->Internals->SourceChanged = true;
  this->Internals->Loader.reset(); // meshes are read again too
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::SetFixedFrame(const char* frame)
{
  const std::string value = frame ? frame : "";
  if (value != this->Internals->FixedFrame)
  {
    this->Internals->FixedFrame = value;
    this->Internals->FramesChanged = this->Internals->Loaded;
    this->Modified();
  }
}

const char* vtkROS2RobotNode::GetFixedFrame() const
{
  return this->Internals->FixedFrame.c_str();
}

void vtkROS2RobotNode::SetTfPrefix(const char* prefix)
{
  const std::string value = prefix ? prefix : "";
  if (value != this->Internals->TfPrefix)
  {
    this->Internals->TfPrefix = value;
    this->Internals->FramesChanged = this->Internals->Loaded;
    this->Modified();
  }
}

const char* vtkROS2RobotNode::GetTfPrefix() const
{
  return this->Internals->TfPrefix.c_str();
}

void vtkROS2RobotNode::AddMeshSearchPath(const char* folder)
{
  if (!folder || !*folder)
  {
    vtkErrorMacro("AddMeshSearchPath: a folder is required");
    return;
  }
  this->Internals->SearchPaths.emplace_back(folder);
  if (this->Internals->Loader)
  {
    this->Internals->Loader->resolver().add_search_path(folder);
  }
}

void vtkROS2RobotNode::SetRestrictMeshesToRoots(bool on)
{
  this->Internals->RestrictMeshesToRoots = on;
  if (this->Internals->Loader)
  {
    this->Internals->Loader->resolver().set_restrict_to_roots(on);
  }
  this->Modified();
}

bool vtkROS2RobotNode::GetRestrictMeshesToRoots() const
{
  return this->Internals->RestrictMeshesToRoots;
}

void vtkROS2RobotNode::SetMeshBaseFolder(const char* folder)
{
  this->Internals->MeshBaseFolder = folder ? folder : "";
}

const char* vtkROS2RobotNode::GetMeshBaseFolder() const
{
  return this->Internals->MeshBaseFolder.c_str();
}

bool vtkROS2RobotNode::SetXacroArguments(const char* arguments)
{
  vtkInternals& internals = *this->Internals;
  ros2vtk::robot::XacroProcessor check;
  std::string error;
  if (!check.set_arguments(arguments ? arguments : "", &error))
  {
    vtkErrorMacro("SetXacroArguments: " << error);
    return false;
  }
  internals.XacroArguments = arguments ? arguments : "";
  if (internals.Loader)
  {
    internals.Loader->xacro().set_arguments(internals.XacroArguments, nullptr);
  }
  if (internals.Source == "file")
  {
    internals.SourceChanged = true;
  }
  this->Modified();
  return true;
}

const char* vtkROS2RobotNode::GetXacroArguments() const
{
  return this->Internals->XacroArguments.c_str();
}

//------------------------------------------------------------------------------
const char* vtkROS2RobotNode::GetRobotState() const
{
  return this->Internals->State.c_str();
}

bool vtkROS2RobotNode::IsLoaded() const
{
  return this->Internals->Loaded;
}

const char* vtkROS2RobotNode::GetLastError() const
{
  return this->Internals->LastError.c_str();
}

std::string vtkROS2RobotNode::GetWarnings() const
{
  std::string all;
  for (const std::string& warning : this->Internals->Visuals.warnings())
  {
    all += warning + "\n";
  }
  return all;
}

std::string vtkROS2RobotNode::GetLoadSummary() const
{
  return this->Internals->Loaded ? this->Internals->Visuals.summary() : std::string();
}

std::string vtkROS2RobotNode::GetLinkStatus(const char* link) const
{
  const ros2vtk::robot::LinkVisuals* visuals = this->Internals->Visuals.link(link ? link : "");
  return visuals ? visuals->status() : std::string();
}

int vtkROS2RobotNode::GetNumberOfLoads() const
{
  return this->Internals->NumberOfLoads;
}

double vtkROS2RobotNode::GetLastLoadDuration() const
{
  return this->Internals->LastLoadDuration;
}

int vtkROS2RobotNode::GetNumberOfLinks() const
{
  return static_cast<int>(this->Internals->Links.size());
}

std::string vtkROS2RobotNode::GetLinkNames() const
{
  std::string names;
  for (const auto& link : this->Internals->Links)
  {
    names += (names.empty() ? "" : " ") + link.Link;
  }
  return names;
}

vtkROS2TransformNode* vtkROS2RobotNode::GetLinkTransformNode(const char* link)
{
  for (const auto& entry : this->Internals->Links)
  {
    if (link && entry.Link == link)
    {
      return entry.Node;
    }
  }
  return nullptr;
}

int vtkROS2RobotNode::GetNumberOfLinksTracked()
{
  int tracked = 0;
  for (const auto& entry : this->Internals->Links)
  {
    vtkROS2TransformNode* node = entry.Node;
    auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(node);
    if (node && (!lookup || std::string(lookup->GetLookupStatus()) == "ok"))
    {
      ++tracked;
    }
  }
  return tracked;
}

vtkROS2TransformNode* vtkROS2RobotNode::GetBaseTransformNode()
{
  return this->Internals->Base;
}

int vtkROS2RobotNode::GetNumberOfModelNodes() const
{
  return static_cast<int>(this->Internals->Models.size());
}

vtkROS2ModelNode* vtkROS2RobotNode::GetNthModelNode(int n)
{
  if (n < 0 || n >= this->GetNumberOfModelNodes())
  {
    return nullptr;
  }
  return this->Internals->Models[static_cast<size_t>(n)];
}

int vtkROS2RobotNode::GetNumberOfPlaceholders() const
{
  return this->Internals->Loaded ? static_cast<int>(this->Internals->Visuals.placeholder_count())
                                 : 0;
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::GetWorkspaceSphere(double sphere[4])
{
  vtkInternals& internals = *this->Internals;
  const std::map<std::string, ros2vtk::robot::LinkReach> reach =
    internals.JointStates.GetLinkReach();
  if (!internals.Loaded || reach.empty())
  {
    return false;
  }
  // Each link's ball (root frame, mm), grown by the furthest point of its visuals from its origin.
  std::map<std::string, EnclosingSphere::Ball> balls;
  for (const auto& entry : reach)
  {
    balls[entry.first] = { entry.second.centre * MillimetresPerMetre,
      entry.second.radius * MillimetresPerMetre };
  }
  for (vtkROS2ModelNode* model : internals.Models)
  {
    const char* link = model ? model->GetAttribute(LinkAttribute) : nullptr;
    auto ball = link ? balls.find(link) : balls.end();
    if (ball == balls.end() || !model->GetPolyData() ||
      model->GetPolyData()->GetNumberOfPoints() == 0)
    {
      continue;
    }
    double bounds[6];
    model->GetPolyData()->GetBounds(bounds);                     // metres, in the visual's frame
    vtkMatrix4x4* modelToLink = model->GetMatrixModelToParent(); // -> link frame, mm
    double extent = 0.0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const double point[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
        bounds[4 + ((corner >> 2) & 1)], 1.0 };
      double inLink[4];
      modelToLink->MultiplyPoint(point, inLink);
      extent = std::max(extent, Eigen::Vector3d(inLink[0], inLink[1], inLink[2]).norm());
    }
    ball->second.Extent = std::max(ball->second.Extent, extent);
  }
  EnclosingSphere::Ball all = balls.begin()->second.Grown();
  for (const auto& entry : balls)
  {
    all = EnclosingSphere::Union(all, entry.second.Grown());
  }
  // Into the world: the root link's pose now (the fixed frame's origin until it is known).
  vtkROS2TransformNode* root =
    this->GetLinkTransformNode(internals.JointStates.GetRootLink().c_str());
  vtkNew<vtkMatrix4x4> rootToWorld;
  if (root)
  {
    root->GetMatrixTransformToWorld(rootToWorld);
  }
  const double centre[4] = { all.Centre.x(), all.Centre.y(), all.Centre.z(), 1.0 };
  double world[4];
  rootToWorld->MultiplyPoint(centre, world);
  for (int axis = 0; axis < 3; ++axis)
  {
    sphere[axis] = world[axis];
  }
  sphere[3] = all.Radius;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::SetJointStatesTopic(const char* topic)
{
  vtkInternals& internals = *this->Internals;
  const std::string value = topic ? topic : "";
  std::string error;
  if (!internals.JointStates.SetJointStatesTopic(
        this->GetROS2Node(), value, internals.RobotName, &error))
  {
    vtkErrorMacro(
      "robot '" << internals.RobotName << "': SetJointStatesTopic('" << value << "'): " << error);
    return false;
  }
  internals.JointStatesTopic = internals.JointStates.GetJointStatesTopic();
  this->Modified();
  return true;
}

const char* vtkROS2RobotNode::GetJointStatesTopic() const
{
  return this->Internals->JointStatesTopic.c_str();
}

bool vtkROS2RobotNode::SetJointPosition(const char* joint, double value)
{
  std::string why;
  if (!this->Internals->JointStates.SetJointPosition(joint ? joint : "", value, &why))
  {
    vtkErrorMacro("robot '" << this->Internals->RobotName << "': SetJointPosition: " << why);
    return false;
  }
  return true;
}

double vtkROS2RobotNode::GetJointPosition(const char* joint) const
{
  return this->Internals->JointStates.GetJointPosition(joint ? joint : "");
}

std::string vtkROS2RobotNode::GetJointNames() const
{
  std::string names;
  for (const std::string& joint : this->Internals->JointStates.GetJointNames())
  {
    names += (names.empty() ? "" : " ") + joint;
  }
  return names;
}

void vtkROS2RobotNode::ResetJointPositions()
{
  this->Internals->JointStates.ResetJointPositions();
}

void vtkROS2RobotNode::SetPublishTf(bool on)
{
  if (on != this->Internals->PublishTf)
  {
    this->Internals->PublishTf = on;
    this->Internals->JointStates.SetPublishTf(on);
    this->Modified();
  }
}

bool vtkROS2RobotNode::GetPublishTf() const
{
  return this->Internals->PublishTf;
}

std::string vtkROS2RobotNode::GetLinkPoseStatus(const char* link) const
{
  return this->Internals->JointStates.GetLinkPoseStatus(link ? link : "");
}

std::string vtkROS2RobotNode::GetLinkPoseSummary() const
{
  using Status = ros2vtk::scene::LinkPoseStatus;
  const char* const order[] = { Status::Tf, Status::FixedFrame, Status::JointPositions,
    Status::ZeroConfiguration };
  std::map<std::string, int> counts;
  int links = 0;
  for (const vtkInternals::LinkNode& entry : this->Internals->Links)
  {
    const std::string status = this->Internals->JointStates.GetLinkPoseStatus(entry.Link);
    if (!status.empty())
    {
      ++counts[status];
      ++links;
    }
  }
  if (links == 0)
  {
    return std::string();
  }
  std::string summary = std::to_string(links) + (links == 1 ? " link:" : " links:");
  const char* separator = " ";
  for (const char* status : order)
  {
    auto it = counts.find(status);
    if (it != counts.end())
    {
      summary += separator + std::to_string(it->second) + " " + status;
      separator = ", ";
    }
  }
  return summary;
}

vtkTypeInt64 vtkROS2RobotNode::GetNumberOfJointStatesApplied() const
{
  return this->Internals->JointStates.GetNumberOfJointStatesApplied();
}

vtkTypeInt64 vtkROS2RobotNode::GetNumberOfJointStatesRefused() const
{
  return this->Internals->JointStates.GetNumberOfJointStatesRefused();
}

const char* vtkROS2RobotNode::GetLastJointStateError() const
{
  return this->Internals->JointStates.GetLastJointStateError().c_str();
}

//------------------------------------------------------------------------------
int vtkROS2RobotNode::OnROS2NodeSpin(vtkROS2NodeNode* rosNode)
{
  // First: a changed fixed frame reloads here, so UpdateLinkPoses' LoadedFixedFrame is current.
  const int loaded = this->CheckForNewDescription();
  return loaded + this->UpdateLinkPoses(rosNode);
}

//------------------------------------------------------------------------------
int vtkROS2RobotNode::UpdateLinkPoses(vtkROS2NodeNode* rosNode)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Loaded)
  {
    return 0;
  }
  if (!internals.JointStatesTopic.empty() && internals.JointStates.GetJointStatesTopic().empty())
  {
    // Asked before the ROS node could subscribe (a restored scene): subscribe now.
    std::string error;
    if (!internals.JointStates.SetJointStatesTopic(
          rosNode, internals.JointStatesTopic, internals.RobotName, &error))
    {
      vtkErrorMacro("robot '" << internals.RobotName << "': joint states topic '"
                              << internals.JointStatesTopic << "': " << error);
      internals.JointStatesTopic.clear(); // said once
    }
  }
  // The driver's list of link nodes is rebuilt only when the links changed (a load, a restore):
  // a spin allocates nothing, and does not compare the two lists link by link either.
  ros2vtk::scene::RobotJointStateDriver::LinkNodes& links = internals.DriverLinks;
  if (internals.DriverLinksVersion != internals.LinksVersion)
  {
    internals.DriverLinksVersion = internals.LinksVersion;
    links.clear();
    for (const vtkInternals::LinkNode& entry : internals.Links)
    {
      links.emplace_back(entry.Link, entry.Node);
    }
  }
  const bool changed = internals.JointStates.Update(
    rosNode, links, internals.LoadedFixedFrame, internals.TfPrefix); // current: see OnROS2NodeSpin
  for (const std::string& warning : internals.JointStates.TakeWarnings())
  {
    vtkWarningMacro("robot '" << internals.RobotName << "': " << warning);
  }
  return changed ? 1 : 0;
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2RobotNode::GetROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::AttachToParameter(
  vtkROS2NodeNode* rosNode, const std::string& remoteNode, const std::string& parameterName)
{
  vtkInternals& internals = *this->Internals;
  vtkROS2ParameterNode* parameters = rosNode->GetParameterNodeByNode(remoteNode.c_str());
  internals.OwnsSourceNode = parameters == nullptr;
  if (!parameters)
  {
    parameters = rosNode->CreateAndAddParameterNode(remoteNode.c_str());
  }
  if (!parameters || !parameters->AddParameter(parameterName.c_str()))
  {
    return false;
  }
  internals.Source = "parameter";
  internals.ParameterNodeName = parameters->GetMonitoredNodeName();
  internals.ParameterName = parameterName;
  this->FollowSource(rosNode, parameters);
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::AttachToTopic(vtkROS2NodeNode* rosNode, const std::string& topic)
{
  vtkInternals& internals = *this->Internals;
  vtkROS2SubscriberNode* subscriber = rosNode->GetSubscriberNodeByTopic(topic.c_str());
  internals.OwnsSourceNode = subscriber == nullptr;
  if (!subscriber)
  {
    // robot_state_publisher publishes the description once, reliable + transient local (as RViz 2
    // subscribes): a late joiner still gets it.
    subscriber = rosNode->CreateAndAddSubscriberNode("std_msgs/msg/String", topic.c_str());
    if (!subscriber || !subscriber->SetQoSProfile("transient_local"))
    {
      return false;
    }
  }
  else if (std::string(subscriber->GetROSType()) != "std_msgs/msg/String")
  {
    vtkErrorMacro("CreateAndAddRobotNode: " << topic << " is subscribed already with type "
                                            << subscriber->GetROSType()
                                            << ", not std_msgs/msg/String");
    return false;
  }
  internals.Source = "topic";
  internals.Topic = subscriber->GetTopic();
  this->FollowSource(rosNode, subscriber);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::FollowSource(vtkROS2NodeNode* rosNode, vtkROS2SceneNode* source)
{
  vtkInternals& internals = *this->Internals;
  internals.SourceNode = source;
  internals.SourceObserverTag =
    source->AddObserver(vtkCommand::ModifiedEvent, internals.SourceObserver);
  this->SetNodeReferenceID(ROS2NodeReferenceRole, rosNode->GetID());
  this->SetNodeReferenceID(DescriptionRole, source->GetID());
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::AttachToFile(vtkROS2NodeNode* rosNode, const std::string& urdfFile)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path path = fs::absolute(fs::path(urdfFile), error).lexically_normal();
  if (error || !fs::is_regular_file(path, error))
  {
    vtkErrorMacro("CreateAndAddRobotNodeFromFile: no URDF file '" << urdfFile << "'");
    return false;
  }
  this->Internals->Source = "file";
  this->Internals->DescriptionFile = path.string();
  this->FollowFile(rosNode);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::FollowFile(vtkROS2NodeNode* rosNode)
{
  vtkInternals& internals = *this->Internals;
  internals.Loader.reset(); // made again with the package holding the file (package:// URIs)
  internals.SourceChanged = true;
  this->SetNodeReferenceID(ROS2NodeReferenceRole, rosNode->GetID());
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::ReadDescriptionFile(std::string& description)
{
  vtkInternals& internals = *this->Internals;
  std::string error;
  if (internals.LoaderForLoads().read_urdf_file(internals.DescriptionFile, &description, &error))
  {
    return true;
  }
  if (internals.LastError != error)
  {
    vtkErrorMacro("robot '" << internals.RobotName << "': " << error);
  }
  internals.LastError = error;
  internals.State = "failed: " + error;
  this->Modified();
  return false;
}

//------------------------------------------------------------------------------
int vtkROS2RobotNode::CheckForNewDescription()
{
  vtkInternals& internals = *this->Internals;
  // The scene's fixed frame, used when the robot has none, may have changed since the load.
  internals.FramesChanged = internals.FramesChanged ||
    (internals.Loaded && !internals.IsEffectiveFixedFrame(this->Scene, internals.LoadedFixedFrame));
  if (internals.FramesChanged && internals.Loaded)
  {
    // New prefix or fixed frame: rebuild the nodes from the description already parsed.
    internals.FramesChanged = false;
    const std::string description = internals.LoadedDescription;
    this->LoadRobotDescription(description.c_str(), internals.LoadedBaseFolder.c_str());
    return 1;
  }
  if (!internals.SourceChanged || (!internals.SourceNode && internals.Source != "file"))
  {
    return 0;
  }
  internals.SourceChanged = false;
  const bool force = internals.ForceReload;
  internals.ForceReload = false;
  std::string description;
  std::string baseFolder = internals.MeshBaseFolder;
  if (internals.Source == "file")
  {
    if (!this->ReadDescriptionFile(description))
    {
      return 1;
    }
    if (baseFolder.empty())
    {
      baseFolder = std::filesystem::path(internals.DescriptionFile).parent_path().string();
    }
  }
  else if (auto* parameters = vtkROS2ParameterNode::SafeDownCast(internals.SourceNode))
  {
    if (!parameters->IsParameterSet(internals.ParameterName.c_str(), /*noWarning=*/true))
    {
      return 0;
    }
    const std::string type = parameters->GetParameterType(internals.ParameterName.c_str());
    if (type != "string")
    {
      // Say what arrived (issue 11.8) instead of waiting for a string forever; once per value.
      const std::string what =
        "the " + internals.SourceText() + " is a " + type + ", not a URDF string";
      if (internals.LastError != what)
      {
        internals.LastError = what;
        internals.State = "failed: " + what;
        vtkErrorMacro("robot '" << internals.RobotName << "': " << what);
        this->Modified();
      }
      return 0;
    }
    description = parameters->GetParameterAsString(internals.ParameterName.c_str());
  }
  else if (auto* subscriber = vtkROS2SubscriberNode::SafeDownCast(internals.SourceNode))
  {
    if (!subscriber->GetLastMessageStringField("data", description))
    {
      return 0;
    }
  }
  const bool unchanged = (internals.Loaded && description == internals.LoadedDescription) ||
    (internals.HasFailedDescription && description == internals.LastFailedDescription);
  if (unchanged && !force)
  {
    return 0;
  }
  if (description.find_first_not_of(" \t\r\n") == std::string::npos)
  {
    // An empty description is an error that says what arrived (issue 11.8: the robot waited
    // forever); a robot already shown stays.
    internals.LastFailedDescription = description;
    internals.HasFailedDescription = true;
    internals.LastError = "the robot description from the " + internals.SourceText() +
      " is empty (" + std::to_string(description.size()) + " bytes" +
      (description.empty() ? "" : ", all white space") + ")";
    internals.State = "failed: " + internals.LastError;
    vtkErrorMacro("robot '" << internals.RobotName << "': " << internals.LastError);
    this->Modified();
    return 1;
  }
  this->LoadRobotDescription(description.c_str(), baseFolder.c_str());
  return 1;
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::LoadRobotDescription(const char* urdfXml, const char* baseFolder)
{
  vtkInternals& internals = *this->Internals;
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (!this->Scene || !rosNode || !rosNode->IsCreated())
  {
    vtkErrorMacro("LoadRobotDescription: the robot node must belong to a created ROS node");
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  ros2vtk::robot::RobotLoadOptions options;
  options.base_folder = baseFolder ? baseFolder : "";
  ros2vtk::robot::RobotVisuals visuals;
  std::string error;
  const std::string description = urdfXml ? urdfXml : "";
  if (!internals.LoaderForLoads().load_xml(description, options, &visuals, &error))
  {
    // The robot already shown (if any) stays; the bad description is not parsed again.
    internals.LastFailedDescription = description;
    internals.HasFailedDescription = true;
    internals.LastError = error;
    internals.State = "failed: " + error;
    vtkErrorMacro("robot '" << internals.RobotName << "': robot_description refused: " << error);
    this->Modified();
    return false;
  }
  std::string kinematicsError;
  if (!internals.JointStates.Load(description, &kinematicsError))
  {
    // urdfdom accepted the visuals, so this should not happen; the robot still shows, at tf only.
    vtkWarningMacro("robot '" << internals.RobotName << "': no kinematics: " << kinematicsError);
    internals.JointStates.Unload();
  }
  this->RemoveModels();
  internals.Visuals = std::move(visuals);
  internals.LoadedDescription = description;
  internals.LoadedBaseFolder = options.base_folder;
  internals.LastFailedDescription.clear();
  internals.HasFailedDescription = false;
  internals.LastError.clear();

  vtkROS2Scene* scene = this->Scene;
  const std::string& name = internals.RobotName;
  if (!internals.Base)
  {
    vtkNew<vtkROS2TransformNode> base;
    base->SetName((name + ":base").c_str());
    scene->AddNode(base);
    internals.Base = base;
    this->SetNodeReferenceID(BaseRole, base->GetID());
  }
  vtkROS2TransformNode* base = internals.Base;

  // Link nodes of the previous load (or of a restored scene) are kept for links that are still
  // there with the same frames; the others go before any new lookup is made.
  const std::string fixedFrame = internals.EffectiveFixedFrame(scene);
  internals.LoadedFixedFrame = fixedFrame;
  std::set<std::string> links;
  for (const ros2vtk::robot::LinkVisuals& link : internals.Visuals.links)
  {
    links.insert(link.link);
  }
  std::vector<vtkInternals::LinkNode> previous;
  previous.swap(internals.Links);
  ++internals.LinksVersion;
  std::vector<vtkInternals::LinkNode> kept;
  for (const vtkInternals::LinkNode& entry : previous)
  {
    if (!entry.Owned || !entry.Node)
    {
      continue;
    }
    const std::string frame = internals.TfPrefix + entry.Link;
    auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(entry.Node);
    const bool framesMatch = frame == fixedFrame
      ? lookup == nullptr
      : lookup && fixedFrame == lookup->GetParentID() && frame == lookup->GetChildID();
    if (links.count(entry.Link) && framesMatch)
    {
      kept.push_back(entry);
    }
    else
    {
      this->RemoveLinkNode(entry.Node);
    }
  }

  vtkNew<vtkMatrix4x4> modelToLink;
  for (const ros2vtk::robot::LinkVisuals& link : internals.Visuals.links)
  {
    const std::string frame = internals.TfPrefix + link.link;
    vtkSmartPointer<vtkROS2TransformNode> linkNode;
    bool owned = true;
    auto reused = std::find_if(kept.begin(), kept.end(),
      [&link](const vtkInternals::LinkNode& entry) { return entry.Link == link.link; });
    if (reused != kept.end())
    {
      linkNode = reused->Node.GetPointer();
    }
    else if (frame == fixedFrame)
    {
      linkNode = vtkSmartPointer<vtkROS2TransformNode>::New(); // the fixed frame itself: identity
      scene->AddNode(linkNode);
    }
    else if ((linkNode = rosNode->GetTf2LookupNodeByParentChild(fixedFrame.c_str(), frame.c_str())))
    {
      owned = false; // someone's lookup already: shared, left in place on unload
    }
    else
    {
      linkNode = rosNode->CreateAndAddTf2LookupNode(fixedFrame.c_str(), frame.c_str());
    }
    if (!linkNode)
    {
      continue; // CreateAndAddTf2LookupNode said why
    }
    if (owned && reused == kept.end())
    {
      linkNode->SetName((name + ":" + link.link).c_str());
      linkNode->SetAttribute(LinkAttribute, link.link.c_str());
      linkNode->SetParentTransformNodeID(base->GetID());
      this->AddNodeReferenceID(LinkRole, linkNode->GetID());
    }
    internals.Links.push_back({ link.link, linkNode.GetPointer(), owned });
    ++internals.LinksVersion;
    for (size_t i = 0; i < link.visuals.size(); ++i)
    {
      const ros2vtk::robot::LinkVisual& visual = link.visuals[i];
      vtkNew<vtkROS2ModelNode> model;
      model->SetSaveWithScene(false); // geometry comes from the description, not the scene file
      std::ostringstream modelName;
      modelName << name << ":" << link.link << ":visual" << i;
      model->SetName(modelName.str().c_str());
      model->SetPolyData(visual.geometry);
      VisualToLinkMillimetres(visual.origin, modelToLink);
      model->SetMatrixModelToParent(modelToLink);
      const auto color = visual.display_color();
      model->SetColor(color[0], color[1], color[2]);
      model->SetOpacity(color[3]);
      // A mesh coloured per vertex (Collada, PLY, OBJ) shows its colours unless the URDF gives
      // a material, as in RViz 2.
      model->SetScalarVisibility(visual.has_vertex_colors && !visual.has_material_color);
      model->SetAttribute("ros2vtk.robot", name.c_str());
      model->SetAttribute(LinkAttribute, link.link.c_str());
      if (!visual.mesh_path.empty())
      {
        model->SetAttribute("ros2vtk.meshFile", visual.mesh_path.c_str());
      }
      if (visual.kind == ros2vtk::robot::VisualKind::Placeholder)
      {
        // Stands in for a mesh that did not load; the display layer draws it as such.
        model->SetAttribute(PlaceholderAttribute, "1");
      }
      scene->AddNode(model);
      model->SetParentTransformNodeID(linkNode->GetID());
      internals.Models.emplace_back(model.GetPointer());
    }
  }
  // One line per load, not one per visual: a description whose meshes all name an unknown
  // package would otherwise repeat the same cause for every visual. Every warning stays in
  // GetWarnings(), and each link's in GetLinkStatus().
  if (!internals.Visuals.warnings().empty())
  {
    vtkWarningMacro("robot '" << name << "': " << internals.Visuals.summary());
  }
  internals.Loaded = true;
  internals.FramesChanged = false;
  internals.State = "loaded";
  ++internals.NumberOfLoads;
  internals.LastLoadDuration =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Modified();
  this->InvokeEvent(RobotLoadedEvent);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::RemoveModels()
{
  vtkInternals& internals = *this->Internals;
  for (const auto& model : internals.Models)
  {
    if (model && this->Scene && model->GetScene() == this->Scene)
    {
      this->Scene->RemoveNode(model);
    }
  }
  internals.Models.clear();
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::RemoveLinkNode(vtkROS2TransformNode* node)
{
  if (!node)
  {
    return;
  }
  this->RemoveNodeReferenceID(LinkRole, node->GetID());
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(node);
  if (lookup && rosNode &&
    rosNode->GetTf2LookupNodeByParentChild(lookup->GetParentID(), lookup->GetChildID()) == lookup)
  {
    rosNode->RemoveAndDeleteTf2LookupNode(lookup->GetParentID(), lookup->GetChildID());
  }
  else if (this->Scene && node->GetScene() == this->Scene)
  {
    this->Scene->RemoveNode(node);
  }
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::Unload()
{
  vtkInternals& internals = *this->Internals;
  this->RemoveModels();
  for (const vtkInternals::LinkNode& entry : internals.Links)
  {
    if (entry.Owned)
    {
      this->RemoveLinkNode(entry.Node);
    }
  }
  internals.Links.clear();
  ++internals.LinksVersion;
  if (vtkROS2TransformNode* base = internals.Base)
  {
    this->RemoveNodeReferenceIDs(BaseRole);
    if (this->Scene && base->GetScene() == this->Scene)
    {
      this->Scene->RemoveNode(base);
    }
  }
  internals.Base = nullptr;
  internals.JointStates.Unload();
  internals.Loaded = false;
  internals.State = "waiting for robot_description";
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::ReleaseSource()
{
  vtkInternals& internals = *this->Internals;
  vtkROS2SceneNode* source = internals.SourceNode;
  if (source)
  {
    source->RemoveObserver(internals.SourceObserverTag);
  }
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  // Only while the ROS node still holds it: when a whole scene is cleared, the source may have
  // left before the robot (asking to remove it again would report an error nobody made).
  if (source && internals.OwnsSourceNode && rosNode)
  {
    if (internals.Source == "parameter")
    {
      if (rosNode->GetParameterNodeByNode(internals.ParameterNodeName.c_str()) == source)
      {
        rosNode->RemoveAndDeleteParameterNode(internals.ParameterNodeName.c_str());
      }
    }
    else if (rosNode->GetSubscriberNodeByTopic(internals.Topic.c_str()) == source)
    {
      rosNode->RemoveAndDeleteSubscriberNode(internals.Topic.c_str());
    }
  }
  internals.SourceNode = nullptr;
  internals.OwnsSourceNode = false;
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::OnRemovedFromScene()
{
  // Everything this robot built goes with it (RemoveAndDeleteRobotNode, or the scene closing).
  this->Unload();
  this->Internals->JointStates.ReleaseJointStatesTopic(this->GetROS2Node());
  this->ReleaseSource();
  this->Superclass::OnRemovedFromScene();
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  const vtkInternals& internals = *this->Internals;
  element->SetAttribute("robotName", internals.RobotName.c_str());
  element->SetAttribute("descriptionSource", internals.Source.c_str());
  element->SetAttribute("parameterNode", internals.ParameterNodeName.c_str());
  element->SetAttribute("parameterName", internals.ParameterName.c_str());
  element->SetAttribute("topic", internals.Topic.c_str());
  element->SetAttribute("descriptionFile", internals.DescriptionFile.c_str());
  element->SetIntAttribute("ownsSource", internals.OwnsSourceNode ? 1 : 0);
  element->SetAttribute("fixedFrame", internals.FixedFrame.c_str());
  element->SetAttribute("tfPrefix", internals.TfPrefix.c_str());
  element->SetAttribute("meshBaseFolder", internals.MeshBaseFolder.c_str());
  element->SetAttribute("xacroArguments", internals.XacroArguments.c_str());
  element->SetAttribute("jointStatesTopic", internals.JointStatesTopic.c_str());
  element->SetIntAttribute("publishTf", internals.PublishTf ? 1 : 0);
  for (const std::string& folder : internals.SearchPaths)
  {
    vtkNew<vtkXMLDataElement> path; // one element each: folders may hold spaces
    path->SetName("MeshSearchPath");
    path->SetAttribute("folder", folder.c_str());
    element->AddNestedElement(path);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2RobotNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  vtkInternals& internals = *this->Internals;
  auto text = [element](const char* name) {
    const char* value = element->GetAttribute(name);
    return std::string(value ? value : "");
  };
  internals.RobotName = text("robotName");
  internals.Source = text("descriptionSource");
  internals.ParameterNodeName = text("parameterNode");
  internals.ParameterName = text("parameterName");
  internals.Topic = text("topic");
  internals.DescriptionFile = text("descriptionFile");
  internals.FixedFrame = text("fixedFrame");
  internals.TfPrefix = text("tfPrefix");
  internals.MeshBaseFolder = text("meshBaseFolder");
  internals.XacroArguments = text("xacroArguments");
  internals.JointStatesTopic =
    text("jointStatesTopic"); // subscribed on the first spin after the load
  int publishTf = 0;
  element->GetScalarAttribute("publishTf", publishTf);
  internals.PublishTf = publishTf != 0;
  internals.JointStates.SetPublishTf(internals.PublishTf);
  int owns = 0;
  element->GetScalarAttribute("ownsSource", owns);
  internals.OwnsSourceNode = owns != 0;
  const bool known = internals.Source == "parameter" || internals.Source == "topic" ||
    (internals.Source == "file" && !internals.DescriptionFile.empty());
  if (internals.RobotName.empty() || !known)
  {
    vtkErrorMacro("ReadXML: robot node '" << text("id")
                                          << "' needs a robotName and a descriptionSource "
                                          << "(parameter, topic, or file with a descriptionFile)");
    return false;
  }
  internals.SearchPaths.clear();
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* child = element->GetNestedElement(i);
    const char* folder = child->GetAttribute("folder");
    if (child->GetName() && std::string(child->GetName()) == "MeshSearchPath" && folder && *folder)
    {
      internals.SearchPaths.emplace_back(folder);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::OnSceneRestored()
{
  this->Superclass::OnSceneRestored();
  vtkInternals& internals = *this->Internals;
  // The base and link nodes came back with the scene; the models come back with the description,
  // which the source (the parameter fetched again, the transient-local topic) delivers anew.
  internals.Base = vtkROS2TransformNode::SafeDownCast(this->GetNodeReference(BaseRole));
  internals.Links.clear();
  ++internals.LinksVersion;
  for (int i = 0; i < this->GetNumberOfNodeReferences(LinkRole); ++i)
  {
    auto* node = vtkROS2TransformNode::SafeDownCast(this->GetNthNodeReference(LinkRole, i));
    const char* link = node ? node->GetAttribute(LinkAttribute) : nullptr;
    if (link && *link)
    {
      internals.Links.push_back({ link, node, true });
      ++internals.LinksVersion;
    }
  }
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  vtkROS2SceneNode* source = this->GetNodeReference(DescriptionRole);
  const bool fromFile = internals.Source == "file";
  if (!rosNode || !rosNode->IsCreated() || (!source && !fromFile))
  {
    vtkErrorMacro("robot '" << internals.RobotName
                            << "': restored without its ROS node or description source; "
                            << "it will not load");
    return;
  }
  if (fromFile)
  {
    this->FollowFile(rosNode);
  }
  else
  {
    this->FollowSource(rosNode, source);
  }
}

//------------------------------------------------------------------------------
void vtkROS2RobotNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& internals = *this->Internals;
  os << indent << "RobotName: " << internals.RobotName << "\n";
  os << indent << "DescriptionSource: " << internals.Source << "\n";
  if (internals.Source == "parameter")
  {
    os << indent << "Parameter: " << internals.ParameterNodeName << " " << internals.ParameterName
       << "\n";
  }
  else if (internals.Source == "topic")
  {
    os << indent << "Topic: " << internals.Topic << "\n";
  }
  else if (internals.Source == "file")
  {
    os << indent << "File: " << internals.DescriptionFile << "\n";
  }
  os << indent << "FixedFrame: " << internals.FixedFrame << "\n";
  os << indent << "TfPrefix: " << internals.TfPrefix << "\n";
  os << indent << "State: " << internals.State << "\n";
  os << indent << "JointStatesTopic: " << internals.JointStatesTopic << "\n";
  os << indent << "PublishTf: " << (internals.PublishTf ? "on" : "off") << "\n";
  os << indent << "Links: " << internals.Links.size() << ", models: " << internals.Models.size()
     << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::AddRobotNode(const char* what, const char* robotName,
  const char* fixedFrame, const char* tfPrefix,
  const std::function<bool(vtkROS2RobotNode*)>& attach)
{
  if (!this->CheckReadyFor(what))
  {
    return nullptr;
  }
  if (!robotName || !*robotName)
  {
    vtkErrorMacro(<< what << ": a robot name is required");
    return nullptr;
  }
  if (this->GetRobotNodeByName(robotName))
  {
    vtkErrorMacro(<< what << ": robot '" << robotName << "' exists already on this ROS node");
    return nullptr;
  }
  vtkNew<vtkROS2RobotNode> robot;
  robot->SetRobotName(robotName);
  robot->SetFixedFrame(fixedFrame);
  robot->SetTfPrefix(tfPrefix);
  this->Scene->AddNode(robot);
  this->AddChild(RobotRole, robot);
  if (!attach(robot))
  {
    this->RemoveAndDeleteRobotNode(robotName);
    return nullptr;
  }
  return robot;
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNode(const char* robotName,
  const char* parameterNodeName, const char* parameterName, const char* fixedFrame,
  const char* tfPrefix)
{
  const std::string remote = AbsoluteNodeName(parameterNodeName);
  const std::string parameter =
    parameterName && *parameterName ? parameterName : "robot_description";
  if (remote.empty())
  {
    vtkErrorMacro("CreateAndAddRobotNode: the node serving the description is required "
                  "(e.g. /robot_state_publisher)");
    return nullptr;
  }
  return this->AddRobotNode("CreateAndAddRobotNode", robotName, fixedFrame, tfPrefix,
    [&](vtkROS2RobotNode* robot) { return robot->AttachToParameter(this, remote, parameter); });
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNodeFromTopic(
  const char* robotName, const char* topic, const char* fixedFrame, const char* tfPrefix)
{
  const std::string name = topic && *topic ? topic : "/robot_description";
  return this->AddRobotNode("CreateAndAddRobotNodeFromTopic", robotName, fixedFrame, tfPrefix,
    [&](vtkROS2RobotNode* robot) { return robot->AttachToTopic(this, name); });
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNodeFromFile(
  const char* robotName, const char* urdfFile, const char* fixedFrame, const char* tfPrefix)
{
  if (!urdfFile || !*urdfFile)
  {
    vtkErrorMacro("CreateAndAddRobotNodeFromFile: a URDF file is required");
    return nullptr;
  }
  return this->AddRobotNode("CreateAndAddRobotNodeFromFile", robotName, fixedFrame, tfPrefix,
    [&](vtkROS2RobotNode* robot) { return robot->AttachToFile(this, urdfFile); });
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::GetRobotNodeByName(const char* robotName)
{
  return robotName ? vtkROS2RobotNode::SafeDownCast(this->FindChild(RobotRole, robotName))
                   : nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteRobotNode(const char* robotName)
{
  vtkROS2RobotNode* robot = this->GetRobotNodeByName(robotName);
  if (!robot)
  {
    vtkErrorMacro(
      "RemoveAndDeleteRobotNode: no robot '" << (robotName ? robotName : "(null)") << "'");
    return false;
  }
  return this->RemoveChild(RobotRole, robot);
}
