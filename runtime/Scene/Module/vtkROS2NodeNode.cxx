#include "vtkROS2NodeNode.h"

#include "NodeClassRegistry.hpp"
#include "vtkROS2Scene.h"

#include "ros2vtk/tf2/BufferCore.hpp"
#include "ros2vtk/tf2_ros/TransformBroadcaster.hpp"
#include "ros2vtk/tf2_ros/TransformListener.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/wire/ParameterServer.hpp"
#include "ros2vtk/wire/ROSClock.hpp"
#include "ros2vtk/wire/TimeSource.hpp"
#include "ros2vtk/wire/TypeDescriptionService.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkXMLDataElement.h"

#include "Internal/LinkStateMonitor.hpp"
#include "Internal/RateLimitedReport.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace {

/// The order in which Spin calls its children's OnROS2NodeSpin (docs/architecture.md): tf first
/// so that everything after it sees this spin's transforms, then incoming data, parameters,
/// services, actions, and robots last (they read lookups and parameters). Children under any other
/// role (a kind added outside the runtime, connectors) follow, roles sorted by name.
const char* const SpinOrder[] = { vtkROS2NodeNode::Tf2LookupRole, vtkROS2NodeNode::SubscriberRole,
  vtkROS2NodeNode::ParameterRole, vtkROS2NodeNode::ServiceClientRole,
  vtkROS2NodeNode::ServiceServerRole, vtkROS2NodeNode::ActionClientRole,
  vtkROS2NodeNode::ActionServerRole, vtkROS2NodeNode::RobotRole };

std::string IndexKey(const char* role, const std::string& key)
{
  std::string joined = role;
  joined += '\0';
  joined += key;
  return joined;
}

} // namespace

//------------------------------------------------------------------------------
class vtkROS2NodeNode::vtkInternals
{
public:
  std::unique_ptr<ros2vtk::wire::Participant> Participant;
  std::string NodeName;         // as given to Create, kept for scene files after Destroy
  std::string NodeNamespace;    // as given to Create
  bool CreateOnRestore = false; // read from a scene file: Create in OnSceneRestored
  bool Spinning = false;        // Spin ran since Create (SlicerROS2's GetSpinning)
  // The node's clock outlives the participant (GetNodeTime after Destroy still answers); the
  // time source that drives it from use_sim_time and /clock lives with the participant.
  ros2vtk::wire::ROSClock Clock;
  bool UseSimTimeOnCreate = false; // SetUseSimTime before Create, or read from a scene file
  std::unique_ptr<ros2vtk::wire::TimeSource> TimeSource;
  uint64_t Tf2ClockJumps = 0; // Clock.jump_count() when the tf buffer was last cleared
  // Own parameters, tf2: released before the participant they live in.
  std::unique_ptr<ros2vtk::wire::ParameterServer> Parameters;
  // REP 2011 ~/get_type_description; start_type_description_service's value at Create.
  std::unique_ptr<ros2vtk::wire::TypeDescriptionService> TypeDescriptions;
  bool StartTypeDescriptionServiceOnCreate = true;
  std::unique_ptr<ros2vtk::tf2::BufferCore> Tf2Buffer;
  std::unique_ptr<ros2vtk::tf2_ros::TransformListener> Tf2Listener;
  std::unique_ptr<ros2vtk::tf2_ros::TransformBroadcaster> Tf2Broadcasters[2]; // dynamic, static
  uint64_t Tf2RejectionsReported = 0;
  ros2vtk::scene::RateLimitedReport Tf2RejectionReport{ std::chrono::seconds(1) };

  // Children in spin order, rebuilt when the references change (ReferencesVersion). Held, as
  // observers may remove nodes while a spin runs.
  std::vector<vtkSmartPointer<vtkROS2SceneNode>> SpinChildren;
  unsigned long SpinChildrenVersion = ~0ul;
  // role '\0' key -> child; rebuilt when the references (or a child's key) change, kept
  // current by AddChild, so creating N children costs O(N) lookups, not O(N^2) scans.
  std::unordered_map<std::string, vtkROS2SceneNode*> ChildIndex;
  unsigned long ChildIndexVersion = ~0ul;
  uint64_t ChildVisits = 0; // children visited by index rebuilds and lookups (tests count them)
  std::vector<std::string> RoleScratch;
  std::vector<std::pair<vtkROS2SceneNode*, std::function<int()>>> SpinCallbacks; // connectors
  // Link state from spin to spin: LinkStateChangedEvent, and the warning when nobody is found.
  ros2vtk::scene::LinkStateMonitor LinkState{ std::chrono::seconds(5), std::chrono::seconds(60) };

  void ReleaseParticipantObjects()
  {
    // The time source holds a callback in the parameter store: released first.
    this->TimeSource.reset();
    this->TypeDescriptions.reset();
    this->Tf2Listener.reset();
    this->Tf2Broadcasters[0].reset();
    this->Tf2Broadcasters[1].reset();
    this->Parameters.reset();
  }
};

vtkStandardNewMacro(vtkROS2NodeNode);

//------------------------------------------------------------------------------
vtkROS2NodeNode::vtkROS2NodeNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2NodeNode::~vtkROS2NodeNode()
{
  // Endpoints were released when the node left its scene (OnRemovedFromScene); endpoints can
  // only be attached to a node of their own scene, so none can outlive the participant here.
  this->Internals->ReleaseParticipantObjects();
  this->Internals->Participant.reset();
  this->Internals->Spinning = false;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::SetLogLevel(int severity)
{
  ros2vtk::wire::Rosout* rosout =
    this->Internals->Participant ? this->Internals->Participant->rosout() : nullptr;
  if (!rosout || severity < 10 || severity > 50 || severity % 10 != 0)
  {
    vtkErrorMacro("SetLogLevel: " << (rosout ? "severity must be 10, 20, 30, 40 or 50"
                                             : "the ROS node is not created or has no /rosout"));
    return false;
  }
  rosout->set_level(static_cast<ros2vtk::wire::LogSeverity>(severity));
  return true;
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetLogLevel()
{
  ros2vtk::wire::Rosout* rosout =
    this->Internals->Participant ? this->Internals->Participant->rosout() : nullptr;
  return rosout ? static_cast<int>(rosout->level()) : 0;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::Create(const char* nodeName, const char* nodeNamespace)
{
  if (this->Internals->Participant)
  {
    vtkErrorMacro("Create: ROS node '" << this->Internals->Participant->fully_qualified_name()
                                       << "' already exists; call Destroy first");
    return false;
  }
  std::string error;
  auto participant =
    ros2vtk::wire::Participant::create(nodeName ? nodeName : "", nodeNamespace ? nodeNamespace : "",
      ros2vtk::wire::ParticipantOptions::from_environment(), &error);
  if (!participant)
  {
    vtkErrorMacro(
      "Create: cannot create ROS node '" << (nodeName ? nodeName : "(null)") << "': " << error);
    return false;
  }
  this->Internals->Participant = std::move(participant);
  this->Internals->LinkState.start(std::chrono::steady_clock::now());
  this->Internals->Parameters =
    ros2vtk::wire::ParameterServer::create(*this->Internals->Participant, &error);
  if (!this->Internals->Parameters)
  {
    vtkWarningMacro("Create: ROS node '" << nodeName << "' serves no parameters: " << error);
  }
  this->Internals->NodeName = nodeName;
  this->Internals->NodeNamespace = nodeNamespace ? nodeNamespace : "";
  if (this->Internals->Parameters)
  {
    this->StartTimeSource();
  }
  this->StartTypeDescriptionService();
  if (!*this->GetName())
  {
    this->SetName(nodeName);
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::Destroy()
{
  if (!this->Internals->Participant)
  {
    return false;
  }
  // Children whose endpoints live inside the participant release them first (topic and
  // service nodes); the nodes stay in the scene.
  std::vector<vtkSmartPointer<vtkROS2SceneNode>> children;
  this->GetNodeReferenceRoleList(this->Internals->RoleScratch);
  for (const auto& role : this->Internals->RoleScratch)
  {
    for (int i = 0; i < this->GetNumberOfNodeReferences(role.c_str()); ++i)
    {
      if (vtkROS2SceneNode* child = this->GetNthNodeReference(role.c_str(), i))
      {
        children.emplace_back(child);
      }
    }
  }
  for (const auto& child : children)
  {
    child->OnROS2NodeDestroyed(this);
  }
  // Kept for a later Create and for scene files, whoever switched it last (a peer may have).
  this->Internals->UseSimTimeOnCreate = this->Internals->Clock.is_sim_time_active();
  this->Internals->ReleaseParticipantObjects();
  this->Internals->Participant.reset();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
// vtkROS2SceneNode's accessor lives here so that the base class needs no subclass header.
vtkROS2NodeNode* vtkROS2SceneNode::GetROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::IsCreated() const
{
  return this->Internals->Participant != nullptr;
}

//------------------------------------------------------------------------------
ros2vtk::wire::Participant* vtkROS2NodeNode::GetParticipant() const
{
  return this->Internals->Participant.get();
}

//------------------------------------------------------------------------------
const char* vtkROS2NodeNode::GetROS2NodeName() const
{
  return this->Internals->NodeName.c_str();
}

//------------------------------------------------------------------------------
const char* vtkROS2NodeNode::GetROS2NodeNamespace() const
{
  if (this->Internals->Participant)
  {
    return this->Internals->Participant->node_namespace().c_str();
  }
  return this->Internals->NodeNamespace.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::OnRemovedFromScene()
{
  this->Destroy();
  this->Superclass::OnRemovedFromScene();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2NodeNode::FindChildByName(const char* role, const char* name)
{
  if (!name || !*name)
  {
    return nullptr;
  }
  std::string resolved = name;
  std::string ignored;
  if (this->Internals->Participant)
  {
    this->Internals->Participant->resolve_name(name, resolved, &ignored);
  }
  vtkROS2SceneNode* found = this->FindChild(role, resolved);
  return found ? found : this->FindChild(role, name);
}

//------------------------------------------------------------------------------
namespace {
std::string JoinClassNames(ros2vtk::scene::NodeDirection direction)
{
  std::string joined;
  for (const auto* info : ros2vtk::scene::NodeClassRegistry::instance().classes(direction))
  {
    joined += (joined.empty() ? "" : " ") + info->class_name;
  }
  return joined;
}
} // namespace

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetRegisteredROS2PublisherNodes() const
{
  return JoinClassNames(ros2vtk::scene::NodeDirection::Publisher);
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetRegisteredROS2SubscriberNodes() const
{
  return JoinClassNames(ros2vtk::scene::NodeDirection::Subscriber);
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::Spin()
{
  if (!this->Internals->Participant)
  {
    return 0;
  }
  this->Internals->Spinning = true;
  // Clear before draining: a sample queued after this point raises the wake-up again.
  // Only a spin after something was queued looks into the node's own services' queues: most
  // spins of a robot scene bring only tf, which the DDS thread already put in the buffer.
  const bool queued = this->Internals->Participant->wake_up().clear();
  int handled = 0;
  if (this->Internals->Parameters)
  {
    handled += static_cast<int>(queued ? this->Internals->Parameters->process()
                                       : this->Internals->Parameters->publish_events());
  }
  if (queued && this->Internals->TimeSource)
  {
    handled += static_cast<int>(this->Internals->TimeSource->process());
  }
  if (queued && this->Internals->TypeDescriptions)
  {
    handled += static_cast<int>(this->Internals->TypeDescriptions->process());
  }
  this->ClearTf2BufferOnClockJump();
  handled += this->SpinTf2Listener();
  if (this->Internals->SpinChildrenVersion != this->GetReferencesVersion())
  {
    this->CollectSpinChildren();
  }
  // By index: a child's hook may add children (a robot its lookups); they spin next time.
  const auto& children = this->Internals->SpinChildren;
  for (size_t i = 0, n = children.size(); i < n; ++i)
  {
    handled += children[i]->OnROS2NodeSpin(this);
  }
  if (!this->Internals->SpinCallbacks.empty())
  {
    // Copy: a callback may add or remove callbacks.
    const auto callbacks = this->Internals->SpinCallbacks;
    for (const auto& callback : callbacks)
    {
      handled += callback.second();
    }
  }
  this->UpdateLinkState();
  return handled;
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::UpdateLinkState()
{
  if (!this->Internals->Participant)
  {
    return; // a callback destroyed the node
  }
  const auto now = std::chrono::steady_clock::now();
  if (this->Internals->LinkState.update(this->GetNumberOfDiscoveredParticipants(), now))
  {
    this->InvokeEvent(LinkStateChangedEvent, const_cast<char*>(this->GetLinkState()));
  }
  if (!this->Internals->Participant)
  {
    return; // an observer destroyed it
  }
  const double alone = this->Internals->LinkState.alone_report_due(now);
  if (alone < 0)
  {
    return; // the usual case, checked without looking at the children
  }
  // Only a node that waits for or sends something (it has children: this spin's list) says so.
  if (this->Internals->SpinChildren.empty())
  {
    return;
  }
  this->Internals->LinkState.alone_reported(now);
  std::string topics;
  for (int i = 0, n = this->GetNumberOfNodeReferences(SubscriberRole); i < n; ++i)
  {
    if (vtkROS2SceneNode* subscriber = this->GetNthNodeReference(SubscriberRole, i))
    {
      topics +=
        (topics.empty() ? " (nothing can arrive on " : ", ") + subscriber->GetROS2NodeChildKey();
    }
  }
  if (!topics.empty())
  {
    topics += ")";
  }
  vtkWarningMacro("ROS node " << this->Internals->Participant->fully_qualified_name()
                              << " has seen no other ROS 2 "
                              << "participant for " << static_cast<int>(alone) << " s" << topics
                              << ": " << this->GetNoPeersAdvice());
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetNoPeersAdvice() const
{
  if (!this->Internals->Participant || this->GetNumberOfDiscoveredParticipants() > 0)
  {
    return std::string();
  }
  // The settings the participant was created with come from the environment (Create).
  const auto options = ros2vtk::wire::ParticipantOptions::from_environment();
  const int firstPort = 7400 + 250 * options.domain_id;
  std::ostringstream advice;
  advice << "it uses ROS_DOMAIN_ID=" << options.domain_id;
  if (!options.discovery_servers.empty())
  {
    advice << " and the discovery server(s) ROS_DISCOVERY_SERVER=" << options.discovery_servers
           << "; check that a server runs there, started with the id of its position in the list "
              "(fastdds discovery -i 0 for the first), that no firewall drops its port";
  }
  else
  {
    switch (options.range)
    {
      case ros2vtk::wire::DiscoveryRange::Localhost:
        advice << " and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, so it looks only on this computer";
        break;
      case ros2vtk::wire::DiscoveryRange::Off:
        advice << " and ROS_AUTOMATIC_DISCOVERY_RANGE=OFF, so it looks for nobody";
        break;
      case ros2vtk::wire::DiscoveryRange::Subnet:
        advice << " and ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET (multicast)";
        break;
    }
    if (!options.static_peers.empty())
    {
      advice << ", with ROS_STATIC_PEERS=";
      for (size_t i = 0; i < options.static_peers.size(); ++i)
      {
        advice << (i ? ";" : "") << options.static_peers[i];
      }
    }
    advice << "; check that the other side uses the same domain and range, that multicast reaches "
              "it (if the network drops multicast: ROS_STATIC_PEERS or ROS_DISCOVERY_SERVER)";
  }
  advice << ", and that no firewall drops UDP ports " << firstPort << "-" << firstPort + 249
         << " (docs/networking.md)";
  return advice.str();
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::GetSpinning() const
{
  return this->Internals->Participant && this->Internals->Spinning;
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::WarnIfNotSpinning(const char* context) const
{
  if (!this->GetSpinning())
  {
    vtkWarningMacro("Node " << this->GetROS2NodeName() << " is not spinning (yet) when "
                            << (context ? context : ""));
  }
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::AddSpinCallback(vtkROS2SceneNode* owner, std::function<int()> callback)
{
  this->Internals->SpinCallbacks.emplace_back(owner, std::move(callback));
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::RemoveSpinCallbacks(vtkROS2SceneNode* owner)
{
  auto& callbacks = this->Internals->SpinCallbacks;
  callbacks.erase(std::remove_if(callbacks.begin(), callbacks.end(),
                    [owner](const auto& entry) { return entry.first == owner; }),
    callbacks.end());
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::CollectSpinChildren()
{
  vtkInternals& internals = *this->Internals;
  std::vector<vtkSmartPointer<vtkROS2SceneNode>> children;
  auto collect = [&](const char* role) {
    for (int i = 0; i < this->GetNumberOfNodeReferences(role); ++i)
    {
      if (vtkROS2SceneNode* child = this->GetNthNodeReference(role, i))
      {
        children.emplace_back(child);
      }
    }
  };
  for (const char* role : SpinOrder)
  {
    collect(role);
  }
  this->GetNodeReferenceRoleList(internals.RoleScratch);
  for (const auto& role : internals.RoleScratch)
  {
    if (std::find_if(std::begin(SpinOrder), std::end(SpinOrder),
          [&](const char* known) { return role == known; }) == std::end(SpinOrder))
    {
      collect(role.c_str());
    }
  }
  internals.SpinChildren.swap(children);
  internals.SpinChildrenVersion = this->GetReferencesVersion();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2NodeNode::FindChild(const char* role, const std::string& key)
{
  vtkInternals& internals = *this->Internals;
  if (internals.ChildIndexVersion != this->GetReferencesVersion())
  {
    internals.ChildIndex.clear();
    this->GetNodeReferenceRoleList(internals.RoleScratch);
    for (const auto& indexedRole : internals.RoleScratch)
    {
      for (int i = 0; i < this->GetNumberOfNodeReferences(indexedRole.c_str()); ++i)
      {
        ++internals.ChildVisits;
        if (vtkROS2SceneNode* child = this->GetNthNodeReference(indexedRole.c_str(), i))
        {
          internals.ChildIndex.emplace(
            IndexKey(indexedRole.c_str(), child->GetROS2NodeChildKey()), child);
        }
      }
    }
    internals.ChildIndexVersion = this->GetReferencesVersion();
  }
  ++internals.ChildVisits;
  auto found = internals.ChildIndex.find(IndexKey(role, key));
  return found == internals.ChildIndex.end() ? nullptr : found->second;
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::AddChild(const char* role, vtkROS2SceneNode* child)
{
  vtkInternals& internals = *this->Internals;
  const bool indexCurrent = internals.ChildIndexVersion == this->GetReferencesVersion();
  child->SetNodeReferenceID(ROS2NodeReferenceRole, this->GetID());
  this->AddNodeReferenceID(role, child->GetID());
  if (indexCurrent)
  {
    internals.ChildIndex.emplace(IndexKey(role, child->GetROS2NodeChildKey()), child);
    internals.ChildIndexVersion = this->GetReferencesVersion();
  }
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveChild(const char* role, vtkROS2SceneNode* child)
{
  this->RemoveNodeReferenceID(role, child->GetID());
  return this->Scene ? this->Scene->RemoveNode(child) : true;
}

//------------------------------------------------------------------------------
vtkTypeUInt64 vtkROS2NodeNode::GetNumberOfChildVisits() const
{
  return this->Internals->ChildVisits;
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetWakeUpFileDescriptor()
{
  return this->Internals->Participant ? this->Internals->Participant->wake_up().fd() : -1;
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute("ros2NodeName", this->Internals->NodeName.c_str());
  element->SetAttribute("ros2NodeNamespace", this->Internals->NodeNamespace.c_str());
  element->SetIntAttribute("created", this->IsCreated() ? 1 : 0);
  element->SetIntAttribute("useSimTime", this->GetUseSimTime() ? 1 : 0);
  if (!this->Internals->StartTypeDescriptionServiceOnCreate)
  {
    // Written only when off, so files of nodes with the default stay as they were.
    element->SetIntAttribute("startTypeDescriptionService", 0);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  const char* name = element->GetAttribute("ros2NodeName");
  const char* nodeNamespace = element->GetAttribute("ros2NodeNamespace");
  this->Internals->NodeName = name ? name : "";
  this->Internals->NodeNamespace = nodeNamespace ? nodeNamespace : "";
  int created = 0;
  element->GetScalarAttribute("created", created);
  if (created && this->Internals->NodeName.empty())
  {
    vtkErrorMacro(
      "ReadXML: created ROS node '" << element->GetAttribute("id") << "' has no ros2NodeName");
    return false;
  }
  this->Internals->CreateOnRestore = created != 0;
  int useSimTime = 0;
  element->GetScalarAttribute("useSimTime", useSimTime);
  this->Internals->UseSimTimeOnCreate = useSimTime != 0;
  int startTypeDescriptionService = 1;
  element->GetScalarAttribute("startTypeDescriptionService", startTypeDescriptionService);
  this->Internals->StartTypeDescriptionServiceOnCreate = startTypeDescriptionService != 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::OnSceneRestored()
{
  this->Superclass::OnSceneRestored();
  const bool create = this->Internals->CreateOnRestore;
  this->Internals->CreateOnRestore = false;
  if (create && !this->IsCreated())
  {
    this->Create(this->Internals->NodeName.c_str(), this->Internals->NodeNamespace.c_str());
  }
  // Restored lookups need /tf and /tf_static, which CreateAndAddTf2LookupNode would subscribe.
  if (this->IsCreated() && this->GetNumberOfNodeReferences(Tf2LookupRole) > 0)
  {
    this->GetTf2Buffer();
  }
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ROS2NodeName: " << this->Internals->NodeName << "\n";
  os << indent << "ROS2NodeNamespace: " << this->Internals->NodeNamespace << "\n";
  os << indent << "Created: " << this->IsCreated() << "\n";
  os << indent << "UseSimTime: " << this->GetUseSimTime() << "\n";
}

//------------------------------------------------------------------------------
// tf2, parameters and spin callbacks
//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::AbsoluteNodeName(const char* name)
{
  std::string value = name ? name : "";
  return !value.empty() && value[0] != '/' ? "/" + value : value;
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::SpinTf2Listener()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Tf2Listener)
  {
    return 0;
  }
  const int handled = static_cast<int>(internals.Tf2Listener->process());
  const uint64_t rejected = internals.Tf2Listener->rejected_count();
  // At most one line a second, however many bad transforms arrive (1 kHz senders).
  const uint64_t due = internals.Tf2RejectionReport.record(
    rejected - internals.Tf2RejectionsReported, ros2vtk::scene::RateLimitedReport::Clock::now());
  internals.Tf2RejectionsReported = rejected;
  if (due > 0)
  {
    vtkWarningMacro(
      "tf2: rejected " << due << " transform(s): " << internals.Tf2Listener->last_rejection());
  }
  return handled;
}

//------------------------------------------------------------------------------
ros2vtk::tf2::BufferCore* vtkROS2NodeNode::GetTf2Buffer()
{
  if (!this->Internals->Participant)
  {
    return nullptr;
  }
  if (!this->Internals->Tf2Listener)
  {
    if (!this->Internals->Tf2Buffer)
    {
      this->Internals->Tf2Buffer.reset(new ros2vtk::tf2::BufferCore());
    }
    std::string error;
    this->Internals->Tf2Listener = ros2vtk::tf2_ros::TransformListener::create(
      *this->Internals->Participant, *this->Internals->Tf2Buffer, &error);
    if (!this->Internals->Tf2Listener)
    {
      vtkErrorMacro("tf2: cannot subscribe to /tf and /tf_static: " << error);
      return nullptr;
    }
  }
  return this->Internals->Tf2Buffer.get();
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::LookupFramePose(const std::string& targetFrame, const std::string& frame,
  vtkTypeInt64 stampNanoseconds, double translation[3], double rotation[4], std::string* error,
  bool* olderThanHistory)
{
  if (olderThanHistory)
  {
    *olderThanHistory = false;
  }
  ros2vtk::tf2::BufferCore* buffer = this->GetTf2Buffer();
  if (!buffer)
  {
    if (error)
    {
      *error =
        "ROS node '" + std::string(this->GetROS2NodeName()) + "' is not created (no tf buffer)";
    }
    return false;
  }
  const ros2vtk::tf2::LookupResult result =
    buffer->lookup_transform(targetFrame, frame, stampNanoseconds);
  if (!result)
  {
    if (error)
    {
      *error = result.message;
    }
    if (olderThanHistory)
    {
      *olderThanHistory = result.error == ros2vtk::tf2::Tf2Error::BackwardExtrapolation;
    }
    return false;
  }
  const ros2vtk::tf2::Transform& transform = result.transform;
  translation[0] = transform.translation.x();
  translation[1] = transform.translation.y();
  translation[2] = transform.translation.z();
  rotation[0] = transform.rotation.x();
  rotation[1] = transform.rotation.y();
  rotation[2] = transform.rotation.z();
  rotation[3] = transform.rotation.w();
  return true;
}

//------------------------------------------------------------------------------
ros2vtk::tf2_ros::TransformBroadcaster* vtkROS2NodeNode::GetTf2Broadcaster(bool isStatic)
{
  if (!this->Internals->Participant)
  {
    return nullptr;
  }
  auto& broadcaster = this->Internals->Tf2Broadcasters[isStatic ? 1 : 0];
  if (!broadcaster)
  {
    std::string error;
    broadcaster = ros2vtk::tf2_ros::TransformBroadcaster::create(
      *this->Internals->Participant, isStatic, &error);
    if (!broadcaster)
    {
      vtkErrorMacro(
        "tf2: cannot publish on " << (isStatic ? "/tf_static" : "/tf") << ": " << error);
    }
  }
  return broadcaster.get();
}

//------------------------------------------------------------------------------
ros2vtk::wire::ParameterServer* vtkROS2NodeNode::GetParameterServer() const
{
  return this->Internals->Parameters.get();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2NodeNode::FindChildByFrames(
  const char* role, const char* parentFrame, const char* childFrame)
{
  if (!parentFrame || !childFrame)
  {
    return nullptr;
  }
  return this->FindChild(role, std::string(parentFrame) + '\n' + childFrame);
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2NodeNode::FindChildByID(const char* role, const char* nodeID)
{
  if (!nodeID || !this->Scene)
  {
    return nullptr;
  }
  for (int i = 0; i < this->GetNumberOfNodeReferences(role); ++i)
  {
    vtkROS2SceneNode* child = this->GetNthNodeReference(role, i);
    if (child && child->GetID() && std::string(child->GetID()) == nodeID)
    {
      return child;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::AdoptChild(
  const char* role, vtkROS2SceneNode* child, const char* name, const std::function<bool()>& attach)
{
  child->SetName(name);
  this->Scene->AddNode(child);
  if (!attach())
  {
    this->Scene->RemoveNode(child);
    return false;
  }
  this->AddChild(role, child);
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::AdoptKeyedChild(const char* what, const char* role, vtkROS2SceneNode* child,
  const char* type, const char* key, const char* argument, const char* duplicate,
  const char* namePrefix, const std::function<bool()>& attach)
{
  if (!this->CheckReadyFor(what))
  {
    return false;
  }
  if (!type || !key || !*key)
  {
    vtkErrorMacro(<< what << ": type and " << argument << " name are required");
    return false;
  }
  if (this->FindChildByName(role, key))
  {
    vtkErrorMacro(<< what << ": " << duplicate << key << " already");
    return false;
  }
  return this->AdoptChild(role, child, (std::string(namePrefix) + key).c_str(), attach);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveKeyedChild(
  const char* what, const char* role, const char* key, const char* missing)
{
  vtkROS2SceneNode* child = this->FindChildByName(role, key);
  if (!child)
  {
    vtkErrorMacro(<< what << ": " << missing << (key ? key : ""));
    return false;
  }
  return this->RemoveChild(role, child);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::CheckReadyFor(const char* what)
{
  if (!this->Scene)
  {
    if (!this->GetLeftSceneBecause().empty())
    {
      vtkErrorMacro(<< what
                    << ": this ROS node is in no scene any more: " << this->GetLeftSceneBecause());
    }
    else
    {
      vtkErrorMacro(<< what << ": add this ROS node to a scene first");
    }
    return false;
  }
  if (!this->Internals->Participant)
  {
    vtkErrorMacro(<< what << ": the ROS node is not created (call Create first)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
namespace {
template<typename Fill>
bool SetOwnParameter(ros2vtk::wire::ParameterServer* server, const char* name, uint8_t type,
  Fill fill, std::string* error)
{
  if (!server)
  {
    *error = "the ROS node is not created";
    return false;
  }
  if (!name || !*name)
  {
    *error = "a parameter needs a name";
    return false;
  }
  ros2vtk::rcl_interfaces::msg::Parameter parameter;
  parameter.name = name;
  parameter.value.type = type;
  fill(parameter.value);
  ros2vtk::wire::ParameterStore& store = server->store();
  if (!store.has(name))
  {
    return store.declare(name, parameter.value, error);
  }
  const auto results = store.set_parameters({ parameter });
  if (!results.front().successful)
  {
    *error = results.front().reason;
    return false;
  }
  return true;
}
} // namespace

#define ROS2VTK_SET_OWN_PARAMETER(TYPE_ID, FIELD)                                                  \
  std::string error;                                                                               \
  if (!SetOwnParameter(                                                                            \
        this->Internals->Parameters.get(), name, TYPE_ID,                                          \
        [&](ros2vtk::rcl_interfaces::msg::ParameterValue& v) { v.FIELD = value; }, &error))        \
  {                                                                                                \
    vtkErrorMacro("SetParameter '" << (name ? name : "") << "': " << error);                       \
    return false;                                                                                  \
  }                                                                                                \
  return true;

bool vtkROS2NodeNode::SetParameterAsBool(const char* name, bool value)
{
  ROS2VTK_SET_OWN_PARAMETER(ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_BOOL, bool_value)
}
bool vtkROS2NodeNode::SetParameterAsInteger(const char* name, vtkTypeInt64 value)
{
  ROS2VTK_SET_OWN_PARAMETER(
    ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_INTEGER, integer_value)
}
bool vtkROS2NodeNode::SetParameterAsDouble(const char* name, double value)
{
  ROS2VTK_SET_OWN_PARAMETER(
    ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_DOUBLE, double_value)
}
bool vtkROS2NodeNode::SetParameterAsString(const char* name, const char* text)
{
  const std::string value = text ? text : "";
  ROS2VTK_SET_OWN_PARAMETER(
    ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_STRING, string_value)
}

//------------------------------------------------------------------------------
namespace {
/// The elements of a one-component array as T, each checked by `convert` (false: the element
/// is refused); the error names the first refused element.
template<typename T, typename Convert>
bool ArrayElements(
  vtkDataArray* values, const char* kind, Convert convert, std::vector<T>* out, std::string* error)
{
  if (!values || values->GetNumberOfComponents() != 1)
  {
    *error = std::string("a ") + kind + " array needs one value per element";
    return false;
  }
  out->clear();
  out->reserve(static_cast<size_t>(values->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    T value{};
    if (!convert(values, i, &value))
    {
      std::ostringstream reason;
      reason << "element " << i << " (" << values->GetTuple1(i) << ") is not a " << kind;
      *error = reason.str();
      return false;
    }
    out->push_back(value);
  }
  return true;
}

bool WholeNumber(vtkDataArray* values, vtkIdType i, double low, double high, int64_t* out)
{
  const int type = values->GetDataType();
  if (type == VTK_TYPE_INT64 || type == VTK_LONG_LONG || type == VTK_ID_TYPE ||
    (type == VTK_LONG && sizeof(long) == 8))
  {
    *out = values->GetVariantValue(i).ToTypeInt64();
    return static_cast<double>(*out) >= low && static_cast<double>(*out) <= high;
  }
  const double value = values->GetTuple1(i);
  if (!std::isfinite(value) || value != std::floor(value) || value < low || value > high)
  {
    return false;
  }
  *out = static_cast<int64_t>(value);
  return true;
}
} // namespace

namespace {
bool AnyNumber(vtkDataArray* a, vtkIdType i, double* out)
{
  *out = a->GetTuple1(i);
  return true;
}
bool NonZero(vtkDataArray* a, vtkIdType i, bool* out)
{
  *out = a->GetTuple1(i) != 0.0;
  return true;
}
bool Int64(vtkDataArray* a, vtkIdType i, int64_t* out)
{
  return WholeNumber(a, i, -9223372036854775808.0, 9223372036854775807.0, out);
}
bool Byte(vtkDataArray* a, vtkIdType i, uint8_t* out)
{
  int64_t whole = 0;
  if (!WholeNumber(a, i, 0.0, 255.0, &whole))
  {
    return false;
  }
  *out = static_cast<uint8_t>(whole);
  return true;
}

/// Reads the elements of a one-component vtkDataArray as T, each checked by `convert`.
template<typename T, typename Convert>
auto NumericElements(const char* kind, Convert convert)
{
  return [kind, convert](vtkDataArray* values, std::vector<T>* out, std::string* error) {
    return ArrayElements<T>(values, kind, convert, out, error);
  };
}

bool StringElements(vtkStringArray* values, std::vector<std::string>* out, std::string* error)
{
  if (!values)
  {
    *error = "a string array is required";
    return false;
  }
  out->clear();
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    out->push_back(values->GetValue(i));
  }
  return true;
}

using ros2vtk::rcl_interfaces::msg::ParameterType;
using ros2vtk::rcl_interfaces::msg::ParameterValue;

/// The array setters (SetParameterAs*Array) in one: the elements `read` from `values` become
/// the ParameterValue's `field` of `type`; a refusal is reported on `self` (vtkErrorMacro's text).
template<typename T, typename Values, typename Read>
bool SetArrayParameter(vtkObject* self, ros2vtk::wire::ParameterServer* server, const char* name,
  uint8_t type, std::vector<T> ParameterValue::*field, Values* values, Read read)
{
  std::vector<T> elements;
  std::string error;
  if (!read(values, &elements, &error) ||
    !SetOwnParameter(
      server, name, type, [&](ParameterValue& value) { value.*field = elements; }, &error))
  {
    vtkErrorWithObjectMacro(self, "SetParameter '" << (name ? name : "") << "': " << error);
    return false;
  }
  return true;
}
} // namespace

bool vtkROS2NodeNode::SetParameterAsBoolArray(const char* name, vtkDataArray* values)
{
  return SetArrayParameter(this, this->Internals->Parameters.get(), name,
    ParameterType::PARAMETER_BOOL_ARRAY, &ParameterValue::bool_array_value, values,
    NumericElements<bool>("bool", NonZero));
}
bool vtkROS2NodeNode::SetParameterAsIntegerArray(const char* name, vtkDataArray* values)
{
  return SetArrayParameter(this, this->Internals->Parameters.get(), name,
    ParameterType::PARAMETER_INTEGER_ARRAY, &ParameterValue::integer_array_value, values,
    NumericElements<int64_t>("64-bit whole number", Int64));
}
bool vtkROS2NodeNode::SetParameterAsDoubleArray(const char* name, vtkDataArray* values)
{
  return SetArrayParameter(this, this->Internals->Parameters.get(), name,
    ParameterType::PARAMETER_DOUBLE_ARRAY, &ParameterValue::double_array_value, values,
    NumericElements<double>("number", AnyNumber));
}
bool vtkROS2NodeNode::SetParameterAsByteArray(const char* name, vtkDataArray* values)
{
  return SetArrayParameter(this, this->Internals->Parameters.get(), name,
    ParameterType::PARAMETER_BYTE_ARRAY, &ParameterValue::byte_array_value, values,
    NumericElements<uint8_t>("byte (0..255)", Byte));
}
bool vtkROS2NodeNode::SetParameterAsStringArray(const char* name, vtkStringArray* values)
{
  return SetArrayParameter(this, this->Internals->Parameters.get(), name,
    ParameterType::PARAMETER_STRING_ARRAY, &ParameterValue::string_array_value, values,
    StringElements);
}
#undef ROS2VTK_SET_OWN_PARAMETER

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::SetParameterValueSizeLimit(vtkTypeInt64 bytes)
{
  if (!this->Internals->Parameters || bytes < 0)
  {
    vtkErrorMacro("SetParameterValueSizeLimit: needs a created node and a limit >= 0");
    return false;
  }
  this->Internals->Parameters->store().set_value_size_limit(static_cast<size_t>(bytes));
  return true;
}

vtkTypeInt64 vtkROS2NodeNode::GetParameterValueSizeLimit()
{
  return this->Internals->Parameters
    ? static_cast<vtkTypeInt64>(this->Internals->Parameters->store().value_size_limit())
    : -1;
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::PrintOwnParameter(const char* name)
{
  const auto* value =
    this->Internals->Parameters && name ? this->Internals->Parameters->store().get(name) : nullptr;
  return std::string(name ? name : "") + " (" +
    ros2vtk::wire::parameter_type_name(value ? value->type : 0) +
    "): " + (value ? ros2vtk::wire::parameter_value_to_string(*value) : std::string("not set"));
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetNumberOfDiscoveredParticipants() const
{
  return this->Internals->Participant
    ? static_cast<int>(this->Internals->Participant->remote_participant_count())
    : 0;
}

vtkTypeInt64 vtkROS2NodeNode::GetNumberOfDroppedParticipants() const
{
  return this->Internals->Participant
    ? static_cast<vtkTypeInt64>(this->Internals->Participant->dropped_participant_count())
    : 0;
}

const char* vtkROS2NodeNode::GetLinkState() const
{
  if (!this->Internals->Participant)
  {
    return "not created";
  }
  return this->GetNumberOfDiscoveredParticipants() > 0 ? "peers" : "no peers";
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetNodeNamesAndNamespaces()
{
  std::string lines;
  if (this->Internals->Participant)
  {
    for (const auto& node : this->Internals->Participant->node_names_and_namespaces())
    {
      lines += (node.second == "/" ? "/" + node.first : node.second + "/" + node.first) + "\n";
    }
  }
  return lines;
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetTopicNamesAndTypes()
{
  std::string lines;
  if (this->Internals->Participant)
  {
    for (const auto& topic : this->Internals->Participant->topic_names_and_types())
    {
      lines += topic.name;
      for (const auto& type : topic.types)
      {
        lines += " " + type;
      }
      lines += "\n";
    }
  }
  return lines;
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetPublisherNodeNames(const char* topic)
{
  std::string lines;
  if (this->Internals->Participant && topic)
  {
    for (const auto& name : this->Internals->Participant->publisher_node_names(topic))
    {
      lines += name + "\n";
    }
  }
  return lines;
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetTf2FramesAsYAML()
{
  ros2vtk::tf2::BufferCore* buffer = this->GetTf2Buffer();
  if (!buffer)
  {
    return std::string();
  }
  // The delay is measured to the node's clock (kLatestTime, 0, would leave it out).
  const ros2vtk::tf2::TimePoint now = this->GetNodeTimeNanoseconds();
  return buffer->all_frames_as_yaml(now != ros2vtk::tf2::kLatestTime ? now : 1);
}

//------------------------------------------------------------------------------
std::string vtkROS2NodeNode::GetRegisteredServiceTypes() const
{
  std::string names;
  for (const auto& name : ros2vtk::wire::registered_service_types())
  {
    names += (names.empty() ? "" : " ") + name;
  }
  return names;
}

//------------------------------------------------------------------------------
// Simulated time
//------------------------------------------------------------------------------
void vtkROS2NodeNode::StartTimeSource()
{
  vtkInternals& internals = *this->Internals;
  ros2vtk::wire::ParameterStore& store = internals.Parameters->store();
  std::string error;
  if (internals.UseSimTimeOnCreate && !store.has(ros2vtk::wire::TimeSource::kUseSimTimeParameter))
  {
    // Declared with the requested value, as rclpy's parameter_overrides would: the node never
    // stamps a wall-clock time before switching.
    ros2vtk::rcl_interfaces::msg::ParameterValue on;
    on.type = ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_BOOL;
    on.bool_value = true;
    store.declare(ros2vtk::wire::TimeSource::kUseSimTimeParameter, on, &error);
  }
  internals.TimeSource =
    ros2vtk::wire::TimeSource::create(*internals.Participant, store, internals.Clock, &error);
  if (!internals.TimeSource)
  {
    vtkWarningMacro(
      "Create: ROS node '" << internals.NodeName << "' has no use_sim_time: " << error);
  }
  internals.Parameters->set_clock(&internals.Clock);
  // A switch made here comes before this participant's first tf data: nothing to report. A
  // buffer kept from before a Destroy may hold the other time base, so it is cleared quietly.
  if (internals.Tf2ClockJumps != internals.Clock.jump_count() && internals.Tf2Buffer)
  {
    internals.Tf2Buffer->clear();
  }
  internals.Tf2ClockJumps = internals.Clock.jump_count();
}

//------------------------------------------------------------------------------
void vtkROS2NodeNode::ClearTf2BufferOnClockJump()
{
  vtkInternals& internals = *this->Internals;
  const uint64_t jumps = internals.Clock.jump_count();
  if (jumps == internals.Tf2ClockJumps)
  {
    return;
  }
  internals.Tf2ClockJumps = jumps;
  // tf2_ros::Buffer clears itself on a change of time source or a jump back: transforms
  // stamped in the other time base (or before a replay restarted) would otherwise win every
  // "latest" lookup. Static transforms survive (StaticCache::clear).
  if (internals.Tf2Buffer)
  {
    internals.Tf2Buffer->clear();
    vtkWarningMacro("tf2: the ROS clock of node "
      << internals.NodeName << " changed source or jumped back in time: tf buffer cleared");
  }
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::SetUseSimTime(bool useSimTime)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Participant)
  {
    internals.UseSimTimeOnCreate = useSimTime;
    this->Modified();
    return true;
  }
  if (!internals.TimeSource)
  {
    vtkErrorMacro(
      "SetUseSimTime: ROS node '" << internals.NodeName << "' has no use_sim_time parameter");
    return false;
  }
  // Through the parameter store, so the switch is the same as one made by another node through
  // the parameter services (a parameter event is published, the time source follows).
  if (!this->SetParameterAsBool(ros2vtk::wire::TimeSource::kUseSimTimeParameter, useSimTime))
  {
    return false;
  }
  if (!internals.TimeSource->last_error().empty())
  {
    vtkErrorMacro("SetUseSimTime: " << internals.TimeSource->last_error());
    return false;
  }
  internals.UseSimTimeOnCreate = useSimTime;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::GetUseSimTime() const
{
  return this->Internals->Participant ? this->Internals->Clock.is_sim_time_active()
                                      : this->Internals->UseSimTimeOnCreate;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::GetSimTimeReceived() const
{
  return this->Internals->Clock.has_sim_time();
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2NodeNode::GetNodeTimeNanoseconds() const
{
  return static_cast<vtkTypeInt64>(this->Internals->Clock.now());
}

//------------------------------------------------------------------------------
double vtkROS2NodeNode::GetNodeTime() const
{
  // Divided, not multiplied by 1e-9: the quotient is the double nearest the exact time.
  return static_cast<double>(this->GetNodeTimeNanoseconds()) / 1e9;
}

//------------------------------------------------------------------------------
// Type description service (REP 2011)
//------------------------------------------------------------------------------
void vtkROS2NodeNode::StartTypeDescriptionService()
{
  vtkInternals& internals = *this->Internals;
  std::string error;
  // As rclpy: the read-only parameter decides, declared with the value asked for before Create.
  const bool enabled = internals.Parameters
    ? ros2vtk::wire::TypeDescriptionService::enabled(
        internals.Parameters->store(), internals.StartTypeDescriptionServiceOnCreate, &error)
    : internals.StartTypeDescriptionServiceOnCreate;
  if (!error.empty())
  {
    vtkWarningMacro("Create: ROS node '" << internals.NodeName << "': " << error);
  }
  if (!enabled)
  {
    return;
  }
  internals.TypeDescriptions =
    ros2vtk::wire::TypeDescriptionService::create(*internals.Participant, &error);
  if (!internals.TypeDescriptions)
  {
    vtkWarningMacro("Create: ROS node '" << internals.NodeName
                                         << "' serves no ~/get_type_description: " << error);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::SetStartTypeDescriptionService(bool start)
{
  if (this->Internals->Participant)
  {
    vtkErrorMacro("SetStartTypeDescriptionService: parameter "
      << ros2vtk::wire::TypeDescriptionService::kEnableParameter << " is read-only once ROS node '"
      << this->Internals->NodeName << "' is created");
    return false;
  }
  this->Internals->StartTypeDescriptionServiceOnCreate = start;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::GetStartTypeDescriptionService() const
{
  return this->Internals->Participant ? this->Internals->TypeDescriptions != nullptr
                                      : this->Internals->StartTypeDescriptionServiceOnCreate;
}
