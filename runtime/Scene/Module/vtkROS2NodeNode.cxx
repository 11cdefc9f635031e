#include "vtkROS2NodeNode.h"

#include "NodeClassRegistry.hpp"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2PublisherNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberGenericNode.h"
#include "vtkROS2SubscriberNode.h"
#include "vtkROS2ParameterNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2ServiceClientNode.h"
#include "vtkROS2ServiceServerNode.h"
#include "vtkROS2Tf2BroadcasterNode.h"
#include "vtkROS2Tf2LookupNode.h"

#include "ros2vtk/tf2/BufferCore.hpp"
#include "ros2vtk/tf2_ros/TransformBroadcaster.hpp"
#include "ros2vtk/tf2_ros/TransformListener.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/wire/ParameterServer.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

#include "RateLimitedReport.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <vector>

namespace
{
const char* const PublisherRole = "publisher";
const char* const SubscriberRole = "subscriber";
const char* const Tf2LookupRole = "tf2Lookup";
const char* const Tf2BroadcasterRole = "tf2Broadcaster";
const char* const ParameterRole = "parameter";
const char* const RobotRole = "robot";
const char* const ServiceClientRole = "serviceClient";
const char* const ServiceServerRole = "serviceServer";

/// The order in which Spin calls its children's OnROS2NodeSpin (docs/architecture.md): tf first
/// so that everything after it sees this spin's transforms, then incoming data, parameters,
/// services, and robots last (they read lookups and parameters). Children under any other
/// role (a kind added outside the runtime, connectors) follow, roles sorted by name.
const char* const SpinOrder[] = { Tf2LookupRole, SubscriberRole, ParameterRole, ServiceClientRole,
  ServiceServerRole, RobotRole };

std::string IndexKey(const char* role, const std::string& key)
{
  std::string joined = role;
  joined += '\0';
  joined += key;
  return joined;
}

/// The nodes referenced under `role` (held, as observers may remove nodes meanwhile).
template <typename NodeType>
std::vector<vtkSmartPointer<NodeType>> Referenced(vtkROS2SceneNode* owner, const char* role)
{
  std::vector<vtkSmartPointer<NodeType>> nodes;
  for (int i = 0; i < owner->GetNumberOfNodeReferences(role); ++i)
  {
    if (auto* node = NodeType::SafeDownCast(owner->GetNthNodeReference(role, i)))
    {
      nodes.emplace_back(node);
    }
  }
  return nodes;
}
} // namespace

//------------------------------------------------------------------------------
class vtkROS2NodeNode::vtkInternals
{
public:
  std::unique_ptr<ros2vtk::wire::Participant> Participant;
  std::string NodeName;      // as given to Create, kept for scene files after Destroy
  std::string NodeNamespace; // as given to Create
  bool CreateOnRestore = false; // read from a scene file: Create in OnSceneRestored
  // Own parameters, tf2: released before the participant they live in.
  std::unique_ptr<ros2vtk::wire::ParameterServer> Parameters;
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

  void ReleaseParticipantObjects()
  {
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
  auto participant = ros2vtk::wire::Participant::create(nodeName ? nodeName : "",
    nodeNamespace ? nodeNamespace : "", ros2vtk::wire::ParticipantOptions::from_environment(),
    &error);
  if (!participant)
  {
    vtkErrorMacro("Create: cannot create ROS node '" << (nodeName ? nodeName : "(null)")
                                                     << "': " << error);
    return false;
  }
  this->Internals->Participant = std::move(participant);
  this->Internals->Parameters =
    ros2vtk::wire::ParameterServer::create(*this->Internals->Participant, &error);
  if (!this->Internals->Parameters)
  {
    vtkWarningMacro("Create: ROS node '" << nodeName << "' serves no parameters: " << error);
  }
  this->Internals->NodeName = nodeName;
  this->Internals->NodeNamespace = nodeNamespace ? nodeNamespace : "";
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
  // Endpoints first: they live inside the participant.
  for (const char* role : { PublisherRole, SubscriberRole })
  {
    std::vector<vtkSmartPointer<vtkROS2TopicNode>> endpoints;
    for (int i = 0; i < this->GetNumberOfNodeReferences(role); ++i)
    {
      if (auto* endpoint = vtkROS2TopicNode::SafeDownCast(this->GetNthNodeReference(role, i)))
      {
        endpoints.emplace_back(endpoint);
      }
    }
    for (const auto& endpoint : endpoints)
    {
      endpoint->RemoveFromROS2Node();
    }
  }
  // Service endpoints live in the participant too; their nodes stay in the scene.
  for (const auto& client : Referenced<vtkROS2ServiceClientNode>(this, ServiceClientRole))
  {
    client->Detach();
  }
  for (const auto& server : Referenced<vtkROS2ServiceServerNode>(this, ServiceServerRole))
  {
    server->Detach();
  }
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
vtkROS2SceneNode* vtkROS2NodeNode::CreateAndAdd(bool publisher, const char* type, const char* topic)
{
  using ros2vtk::scene::NodeDirection;
  const char* what = publisher ? "CreateAndAddPublisherNode" : "CreateAndAddSubscriberNode";
  if (!this->Scene)
  {
    vtkErrorMacro(<< what << ": add this ROS node to a scene first");
    return nullptr;
  }
  if (!this->Internals->Participant)
  {
    vtkErrorMacro(<< what << ": the ROS node is not created (call Create first)");
    return nullptr;
  }
  if (!type || !topic)
  {
    vtkErrorMacro(<< what << ": type and topic are required");
    return nullptr;
  }
  const char* role = publisher ? PublisherRole : SubscriberRole;
  if (this->FindByTopic<vtkROS2TopicNode>(role, topic))
  {
    vtkErrorMacro(<< what << ": this ROS node already has a " << role << " on '" << topic
                  << "'; remove it first");
    return nullptr;
  }
  const auto resolution = ros2vtk::scene::NodeClassRegistry::instance().resolve(
    publisher ? NodeDirection::Publisher : NodeDirection::Subscriber, type);
  vtkSmartPointer<vtkROS2TopicNode> node;
  if (resolution.mapped_class)
  {
    node.TakeReference(vtkROS2TopicNode::SafeDownCast(resolution.mapped_class->create()));
  }
  else if (resolution.generic_type)
  {
    const char* rosType = resolution.generic_type->ros_type;
    if (publisher)
    {
      auto generic = vtkSmartPointer<vtkROS2PublisherGenericNode>::New();
      node = generic->SetROSType(rosType) ? generic : nullptr;
    }
    else
    {
      auto generic = vtkSmartPointer<vtkROS2SubscriberGenericNode>::New();
      node = generic->SetROSType(rosType) ? generic : nullptr;
    }
  }
  else
  {
    vtkErrorMacro(<< what << ": " << resolution.error);
    return nullptr;
  }
  if (!node)
  {
    vtkErrorMacro(<< what << ": could not create a node for '" << type << "'");
    return nullptr;
  }
  node->SetName(topic);
  this->Scene->AddNode(node);
  if (!node->AddToROS2Node(this->GetID(), topic))
  {
    this->Scene->RemoveNode(node);
    return nullptr;
  }
  return node; // the scene holds it
}

//------------------------------------------------------------------------------
vtkROS2PublisherNode* vtkROS2NodeNode::CreateAndAddPublisherNode(const char* type, const char* topic)
{
  return vtkROS2PublisherNode::SafeDownCast(this->CreateAndAdd(true, type, topic));
}

//------------------------------------------------------------------------------
vtkROS2SubscriberNode* vtkROS2NodeNode::CreateAndAddSubscriberNode(const char* type, const char* topic)
{
  return vtkROS2SubscriberNode::SafeDownCast(this->CreateAndAdd(false, type, topic));
}

//------------------------------------------------------------------------------
template <typename NodeType>
NodeType* vtkROS2NodeNode::FindByTopic(const char* role, const char* topic)
{
  if (!topic)
  {
    return nullptr;
  }
  std::string resolved = topic;
  std::string ignored;
  if (this->Internals->Participant)
  {
    this->Internals->Participant->resolve_name(topic, resolved, &ignored);
  }
  vtkROS2SceneNode* found = this->FindChild(role, resolved);
  return NodeType::SafeDownCast(found ? found : this->FindChild(role, topic));
}

//------------------------------------------------------------------------------
vtkROS2PublisherNode* vtkROS2NodeNode::GetPublisherNodeByTopic(const char* topic)
{
  return this->FindByTopic<vtkROS2PublisherNode>(PublisherRole, topic);
}

//------------------------------------------------------------------------------
vtkROS2SubscriberNode* vtkROS2NodeNode::GetSubscriberNodeByTopic(const char* topic)
{
  return this->FindByTopic<vtkROS2SubscriberNode>(SubscriberRole, topic);
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetNumberOfPublisherNodes()
{
  return this->GetNumberOfNodeReferences(PublisherRole);
}

//------------------------------------------------------------------------------
int vtkROS2NodeNode::GetNumberOfSubscriberNodes()
{
  return this->GetNumberOfNodeReferences(SubscriberRole);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeletePublisherNode(const char* topic)
{
  vtkROS2PublisherNode* node = this->GetPublisherNodeByTopic(topic);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeletePublisherNode: no publisher on '" << (topic ? topic : "(null)")
                                                                    << "'");
    return false;
  }
  node->RemoveFromROS2Node();
  return this->Scene ? this->Scene->RemoveNode(node) : true;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteSubscriberNode(const char* topic)
{
  vtkROS2SubscriberNode* node = this->GetSubscriberNodeByTopic(topic);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteSubscriberNode: no subscriber on '" << (topic ? topic : "(null)")
                                                                      << "'");
    return false;
  }
  node->RemoveFromROS2Node();
  return this->Scene ? this->Scene->RemoveNode(node) : true;
}

//------------------------------------------------------------------------------
namespace
{
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
  // Clear before draining: a sample queued after this point raises the wake-up again.
  this->Internals->Participant->wake_up().clear();
  int handled = 0;
  if (this->Internals->Parameters)
  {
    handled += static_cast<int>(this->Internals->Parameters->process());
  }
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
  return handled;
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
          internals.ChildIndex.emplace(IndexKey(indexedRole.c_str(), child->GetROS2NodeChildKey()), child);
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
    vtkErrorMacro("ReadXML: created ROS node '" << element->GetAttribute("id")
                                                << "' has no ros2NodeName");
    return false;
  }
  this->Internals->CreateOnRestore = created != 0;
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
}

//------------------------------------------------------------------------------
// tf2, parameters and spin callbacks
//------------------------------------------------------------------------------
namespace
{
std::string AbsoluteNodeName(const char* name)
{
  std::string value = name ? name : "";
  return !value.empty() && value[0] != '/' ? "/" + value : value;
}

} // namespace

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
    vtkWarningMacro("tf2: rejected " << due << " transform(s): " << internals.Tf2Listener->last_rejection());
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
    broadcaster = ros2vtk::tf2_ros::TransformBroadcaster::create(*this->Internals->Participant, isStatic, &error);
    if (!broadcaster)
    {
      vtkErrorMacro("tf2: cannot publish on " << (isStatic ? "/tf_static" : "/tf") << ": " << error);
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
template <typename NodeType>
NodeType* vtkROS2NodeNode::FindByFrames(const char* role, const char* parentFrame, const char* childFrame)
{
  if (!parentFrame || !childFrame)
  {
    return nullptr;
  }
  return NodeType::SafeDownCast(this->FindChild(role, std::string(parentFrame) + '\n' + childFrame));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::CheckReadyFor(const char* what)
{
  if (!this->Scene)
  {
    vtkErrorMacro(<< what << ": add this ROS node to a scene first");
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
vtkROS2Tf2LookupNode* vtkROS2NodeNode::CreateAndAddTf2LookupNode(const char* parentFrame, const char* childFrame)
{
  if (!this->CheckReadyFor("CreateAndAddTf2LookupNode") || !this->GetTf2Buffer())
  {
    return nullptr;
  }
  if (!parentFrame || !*parentFrame || !childFrame || !*childFrame)
  {
    vtkErrorMacro("CreateAndAddTf2LookupNode: parent and child frames are required");
    return nullptr;
  }
  if (this->FindByFrames<vtkROS2Tf2LookupNode>(Tf2LookupRole, parentFrame, childFrame))
  {
    vtkErrorMacro("CreateAndAddTf2LookupNode: " << parentFrame << " <- " << childFrame << " exists already");
    return nullptr;
  }
  vtkNew<vtkROS2Tf2LookupNode> node;
  node->SetParentID(parentFrame);
  node->SetChildID(childFrame);
  node->SetName((std::string("ros2:tf2lookup:") + parentFrame + "To" + childFrame).c_str());
  this->Scene->AddNode(node);
  this->AddChild(Tf2LookupRole, node);
  // A first lookup right away, so data already in the buffer shows without waiting for a spin.
  node->UpdateFromBuffer(*this->Internals->Tf2Buffer);
  return node;
}

//------------------------------------------------------------------------------
vtkROS2Tf2LookupNode* vtkROS2NodeNode::GetTf2LookupNodeByParentChild(const char* parentFrame, const char* childFrame)
{
  return this->FindByFrames<vtkROS2Tf2LookupNode>(Tf2LookupRole, parentFrame, childFrame);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2LookupNode(const char* parentFrame, const char* childFrame)
{
  vtkROS2Tf2LookupNode* node = this->GetTf2LookupNodeByParentChild(parentFrame, childFrame);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2LookupNode: no lookup " << (parentFrame ? parentFrame : "") << " <- "
                                                             << (childFrame ? childFrame : ""));
    return false;
  }
  return this->RemoveChild(Tf2LookupRole, node);
}

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode* vtkROS2NodeNode::CreateAndAddTf2BroadcasterNode(const char* parentFrame,
                                                                           const char* childFrame)
{
  if (!this->CheckReadyFor("CreateAndAddTf2BroadcasterNode"))
  {
    return nullptr;
  }
  if (!parentFrame || !*parentFrame || !childFrame || !*childFrame)
  {
    vtkErrorMacro("CreateAndAddTf2BroadcasterNode: parent and child frames are required");
    return nullptr;
  }
  if (this->FindByFrames<vtkROS2Tf2BroadcasterNode>(Tf2BroadcasterRole, parentFrame, childFrame))
  {
    vtkErrorMacro("CreateAndAddTf2BroadcasterNode: " << parentFrame << " <- " << childFrame << " exists already");
    return nullptr;
  }
  vtkNew<vtkROS2Tf2BroadcasterNode> node;
  node->SetParentID(parentFrame);
  node->SetChildID(childFrame);
  node->SetName((std::string("ros2:tf2broadcaster:") + parentFrame + "To" + childFrame).c_str());
  this->Scene->AddNode(node);
  this->AddChild(Tf2BroadcasterRole, node);
  return node;
}

//------------------------------------------------------------------------------
vtkROS2Tf2BroadcasterNode* vtkROS2NodeNode::GetTf2BroadcasterNodeByParentChild(const char* parentFrame,
                                                                               const char* childFrame)
{
  return this->FindByFrames<vtkROS2Tf2BroadcasterNode>(Tf2BroadcasterRole, parentFrame, childFrame);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteTf2BroadcasterNode(const char* parentFrame, const char* childFrame)
{
  vtkROS2Tf2BroadcasterNode* node = this->GetTf2BroadcasterNodeByParentChild(parentFrame, childFrame);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteTf2BroadcasterNode: no broadcaster " << (parentFrame ? parentFrame : "")
                                                                       << " <- " << (childFrame ? childFrame : ""));
    return false;
  }
  return this->RemoveChild(Tf2BroadcasterRole, node);
}

//------------------------------------------------------------------------------
vtkROS2ParameterNode* vtkROS2NodeNode::CreateAndAddParameterNode(const char* monitoredNodeName)
{
  if (!this->CheckReadyFor("CreateAndAddParameterNode"))
  {
    return nullptr;
  }
  const std::string remote = AbsoluteNodeName(monitoredNodeName);
  if (remote.empty())
  {
    vtkErrorMacro("CreateAndAddParameterNode: the monitored node name is required");
    return nullptr;
  }
  if (this->GetParameterNodeByNode(remote.c_str()))
  {
    vtkErrorMacro("CreateAndAddParameterNode: " << remote << " is monitored already");
    return nullptr;
  }
  vtkNew<vtkROS2ParameterNode> node;
  node->SetName(("ros2:param:" + remote).c_str());
  this->Scene->AddNode(node);
  if (!node->Attach(this, remote))
  {
    this->Scene->RemoveNode(node);
    return nullptr;
  }
  this->AddChild(ParameterRole, node);
  return node;
}

//------------------------------------------------------------------------------
vtkROS2ParameterNode* vtkROS2NodeNode::GetParameterNodeByNode(const char* monitoredNodeName)
{
  return vtkROS2ParameterNode::SafeDownCast(this->FindChild(ParameterRole, AbsoluteNodeName(monitoredNodeName)));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteParameterNode(const char* monitoredNodeName)
{
  vtkROS2ParameterNode* node = this->GetParameterNodeByNode(monitoredNodeName);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteParameterNode: " << AbsoluteNodeName(monitoredNodeName) << " is not monitored");
    return false;
  }
  return this->RemoveChild(ParameterRole, node);
}

//------------------------------------------------------------------------------
namespace
{
template <typename Fill>
bool SetOwnParameter(ros2vtk::wire::ParameterServer* server, const char* name, uint8_t type, Fill fill,
                     std::string* error)
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

#define ROS2VTK_SET_OWN_PARAMETER(TYPE_ID, FIELD)                                                    \
  std::string error;                                                                                \
  if (!SetOwnParameter(this->Internals->Parameters.get(), name, TYPE_ID,                            \
        [&](ros2vtk::rcl_interfaces::msg::ParameterValue& v) { v.FIELD = value; }, &error))         \
  {                                                                                                 \
    vtkErrorMacro("SetParameter '" << (name ? name : "") << "': " << error);                       \
    return false;                                                                                   \
  }                                                                                                 \
  return true;

bool vtkROS2NodeNode::SetParameterAsBool(const char* name, bool value) { ROS2VTK_SET_OWN_PARAMETER(ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_BOOL, bool_value) }
bool vtkROS2NodeNode::SetParameterAsInteger(const char* name, vtkTypeInt64 value) { ROS2VTK_SET_OWN_PARAMETER(ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_INTEGER, integer_value) }
bool vtkROS2NodeNode::SetParameterAsDouble(const char* name, double value) { ROS2VTK_SET_OWN_PARAMETER(ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_DOUBLE, double_value) }
bool vtkROS2NodeNode::SetParameterAsString(const char* name, const char* text)
{
  const std::string value = text ? text : "";
  ROS2VTK_SET_OWN_PARAMETER(ros2vtk::rcl_interfaces::msg::ParameterType::PARAMETER_STRING, string_value)
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
  const auto* value = this->Internals->Parameters && name ? this->Internals->Parameters->store().get(name) : nullptr;
  return std::string(name ? name : "") + " (" + ros2vtk::wire::parameter_type_name(value ? value->type : 0) +
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
// robots
//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::AddRobotNode(const char* what, const char* robotName, const char* fixedFrame,
  const char* tfPrefix, const std::function<bool(vtkROS2RobotNode*)>& attach)
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
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNode(const char* robotName, const char* parameterNodeName,
  const char* parameterName, const char* fixedFrame, const char* tfPrefix)
{
  const std::string remote = AbsoluteNodeName(parameterNodeName);
  const std::string parameter = parameterName && *parameterName ? parameterName : "robot_description";
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
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNodeFromTopic(const char* robotName, const char* topic,
  const char* fixedFrame, const char* tfPrefix)
{
  const std::string name = topic && *topic ? topic : "/robot_description";
  return this->AddRobotNode("CreateAndAddRobotNodeFromTopic", robotName, fixedFrame, tfPrefix,
    [&](vtkROS2RobotNode* robot) { return robot->AttachToTopic(this, name); });
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2NodeNode::CreateAndAddRobotNodeFromFile(const char* robotName, const char* urdfFile,
  const char* fixedFrame, const char* tfPrefix)
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
  return robotName ? vtkROS2RobotNode::SafeDownCast(this->FindChild(RobotRole, robotName)) : nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteRobotNode(const char* robotName)
{
  vtkROS2RobotNode* robot = this->GetRobotNodeByName(robotName);
  if (!robot)
  {
    vtkErrorMacro("RemoveAndDeleteRobotNode: no robot '" << (robotName ? robotName : "(null)") << "'");
    return false;
  }
  return this->RemoveChild(RobotRole, robot);
}

//------------------------------------------------------------------------------
// Services
//------------------------------------------------------------------------------
namespace
{
/// The node under `role` whose service name (as given or resolved) is `service`.
template <typename NodeType>
NodeType* FindByService(vtkROS2NodeNode* owner, const char* role, const char* service)
{
  if (!service || !*service)
  {
    return nullptr;
  }
  std::string resolved;
  if (owner->GetParticipant())
  {
    owner->GetParticipant()->resolve_name(service, resolved, nullptr);
  }
  vtkROS2SceneNode* found = resolved.empty() ? nullptr : owner->FindChild(role, resolved);
  return NodeType::SafeDownCast(found ? found : owner->FindChild(role, service));
}

/// Creates a service node of class NodeType, adds it to the scene and attaches it; nullptr and
/// `error` when it cannot be attached (the node is removed again).
template <typename NodeType>
NodeType* AddServiceNode(vtkROS2NodeNode* owner, vtkROS2Scene* scene, const char* role, const char* prefix,
  const char* type, const char* service)
{
  vtkNew<NodeType> node;
  node->SetName((std::string(prefix) + service).c_str());
  scene->AddNode(node);
  if (!node->Attach(owner, type, service))
  {
    scene->RemoveNode(node);
    return nullptr;
  }
  owner->AddChild(role, node);
  return node;
}
}

//------------------------------------------------------------------------------
vtkROS2ServiceClientNode* vtkROS2NodeNode::CreateAndAddServiceClientNode(const char* type, const char* service)
{
  if (!this->CheckReadyFor("CreateAndAddServiceClientNode"))
  {
    return nullptr;
  }
  if (!type || !service || !*service)
  {
    vtkErrorMacro("CreateAndAddServiceClientNode: type and service name are required");
    return nullptr;
  }
  if (this->GetServiceClientNodeByService(service))
  {
    vtkErrorMacro("CreateAndAddServiceClientNode: this node has a client of " << service << " already");
    return nullptr;
  }
  return AddServiceNode<vtkROS2ServiceClientNode>(this, this->Scene, ServiceClientRole, "ros2:client:", type, service);
}

//------------------------------------------------------------------------------
vtkROS2ServiceClientNode* vtkROS2NodeNode::GetServiceClientNodeByService(const char* service)
{
  return FindByService<vtkROS2ServiceClientNode>(this, ServiceClientRole, service);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteServiceClientNode(const char* service)
{
  vtkROS2ServiceClientNode* node = this->GetServiceClientNodeByService(service);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteServiceClientNode: no client of " << (service ? service : ""));
    return false;
  }
  return this->RemoveChild(ServiceClientRole, node);
}

//------------------------------------------------------------------------------
vtkROS2ServiceServerNode* vtkROS2NodeNode::CreateAndAddServiceServerNode(const char* type, const char* service)
{
  if (!this->CheckReadyFor("CreateAndAddServiceServerNode"))
  {
    return nullptr;
  }
  if (!type || !service || !*service)
  {
    vtkErrorMacro("CreateAndAddServiceServerNode: type and service name are required");
    return nullptr;
  }
  if (this->GetServiceServerNodeByService(service))
  {
    vtkErrorMacro("CreateAndAddServiceServerNode: this node serves " << service << " already");
    return nullptr;
  }
  return AddServiceNode<vtkROS2ServiceServerNode>(this, this->Scene, ServiceServerRole, "ros2:server:", type, service);
}

//------------------------------------------------------------------------------
vtkROS2ServiceServerNode* vtkROS2NodeNode::GetServiceServerNodeByService(const char* service)
{
  return FindByService<vtkROS2ServiceServerNode>(this, ServiceServerRole, service);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteServiceServerNode(const char* service)
{
  vtkROS2ServiceServerNode* node = this->GetServiceServerNodeByService(service);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteServiceServerNode: no server of " << (service ? service : ""));
    return false;
  }
  return this->RemoveChild(ServiceServerRole, node);
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
