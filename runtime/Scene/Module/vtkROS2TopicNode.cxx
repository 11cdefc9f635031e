#include "vtkROS2TopicNode.h"

#include "vtkROS2NodeNode.h"

#include "NodeClassRegistry.hpp"
#include "vtkROS2Scene.h"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/QoS.hpp"

#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

//------------------------------------------------------------------------------
class vtkROS2TopicNode::vtkInternals
{
public:
  std::string Topic;
  ros2vtk::wire::QoS QoS;
};

//------------------------------------------------------------------------------
vtkROS2TopicNode::vtkROS2TopicNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2TopicNode::~vtkROS2TopicNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::AddToROS2Node(const char* nodeID, const char* topic)
{
  if (this->IsAddedToROS2Node())
  {
    vtkErrorMacro("AddToROS2Node: already added on topic '" << this->Internals->Topic
                                                            << "'; call RemoveFromROS2Node first");
    return false;
  }
  if (!this->Scene)
  {
    vtkErrorMacro("AddToROS2Node: add this node to the scene of the ROS node first");
    return false;
  }
  auto* rosNode = vtkROS2NodeNode::SafeDownCast(this->Scene->GetNodeByID(nodeID));
  if (!rosNode)
  {
    vtkErrorMacro("AddToROS2Node: '" << (nodeID ? nodeID : "(null)")
                                     << "' is not a vtkROS2NodeNode of this scene");
    return false;
  }
  ros2vtk::wire::Participant* participant = rosNode->GetParticipant();
  if (!participant)
  {
    vtkErrorMacro("AddToROS2Node: ROS node '" << nodeID << "' is not created (call Create first)");
    return false;
  }
  if (!this->HasMessageTypeSupport())
  {
    vtkErrorMacro("AddToROS2Node: the message type is not set");
    return false;
  }
  std::string resolved;
  std::string error;
  if (!topic || !participant->resolve_name(topic, resolved, &error))
  {
    vtkErrorMacro("AddToROS2Node: invalid topic '" << (topic ? topic : "(null)") << "': " << error);
    return false;
  }
  if (!this->CreateEndpoint(*participant, resolved, this->Internals->QoS, &error))
  {
    vtkErrorMacro("AddToROS2Node: cannot create the endpoint on '" << resolved << "': " << error);
    return false;
  }
  this->Internals->Topic = resolved;
  this->SetNodeReferenceID(ROS2NodeReferenceRole, nodeID);
  const char* role = this->GetROS2NodeReferenceRole();
  bool listed = false;
  for (int i = 0; i < rosNode->GetNumberOfNodeReferences(role); ++i)
  {
    listed = listed || std::string(rosNode->GetNthNodeReferenceID(role, i)) == this->GetID();
  }
  if (!listed)
  {
    rosNode->AddNodeReferenceID(role, this->GetID());
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::RemoveFromROS2Node()
{
  if (!this->IsAddedToROS2Node())
  {
    return false;
  }
  this->DestroyEndpoint();
  if (vtkROS2SceneNode* rosNode = this->GetNodeReference(ROS2NodeReferenceRole))
  {
    rosNode->RemoveNodeReferenceID(this->GetROS2NodeReferenceRole(), this->GetID());
  }
  this->SetNodeReferenceID(ROS2NodeReferenceRole, nullptr);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::IsAddedToROS2Node() const
{
  return this->HasEndpoint();
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2TopicNode::GetROS2Node() const
{
  return this->IsAddedToROS2Node()
    ? vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole))
    : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkROS2TopicNode::GetTopic() const
{
  return this->Internals->Topic.c_str();
}

//------------------------------------------------------------------------------
const char* vtkROS2TopicNode::GetROSType() const
{
  return this->HasMessageTypeSupport() ? this->GetMessageTypeSupport().ros_type : "";
}

//------------------------------------------------------------------------------
const ros2vtk::wire::QoS& vtkROS2TopicNode::GetQoS() const
{
  return this->Internals->QoS;
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetQoS(const ros2vtk::wire::QoS& qos)
{
  if (qos == this->Internals->QoS)
  {
    return true;
  }
  this->Internals->QoS = qos;
  this->Modified();
  return this->RecreateEndpoint();
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::RecreateEndpoint()
{
  if (!this->IsAddedToROS2Node())
  {
    return true;
  }
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  ros2vtk::wire::Participant* participant = rosNode ? rosNode->GetParticipant() : nullptr;
  this->DestroyEndpoint();
  std::string error;
  if (!participant ||
    !this->CreateEndpoint(*participant, this->Internals->Topic, this->Internals->QoS, &error))
  {
    vtkErrorMacro("cannot re-create the endpoint on '" << this->Internals->Topic
                                                       << "' with the new QoS: " << error);
    if (rosNode)
    {
      rosNode->RemoveNodeReferenceID(this->GetROS2NodeReferenceRole(), this->GetID());
    }
    this->SetNodeReferenceID(ROS2NodeReferenceRole, nullptr);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetQoSProfile(const char* profile)
{
  ros2vtk::wire::QoS qos;
  if (!profile || !ros2vtk::wire::QoS::from_name(profile, qos))
  {
    vtkErrorMacro("SetQoSProfile: unknown profile '"
      << (profile ? profile : "(null)") << "'; known: " << ros2vtk::wire::QoS::profile_names());
    return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetReliability(const char* reliability)
{
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  if (!ros2vtk::wire::QoS::parse(reliability, qos.reliability))
  {
    vtkErrorMacro("SetReliability: unknown value '" << (reliability ? reliability : "(null)")
                                                    << "'; use reliable or best_effort");
    return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetDurability(const char* durability)
{
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  if (!ros2vtk::wire::QoS::parse(durability, qos.durability))
  {
    vtkErrorMacro("SetDurability: unknown value '" << (durability ? durability : "(null)")
                                                   << "'; use volatile or transient_local");
    return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetHistory(const char* history)
{
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  if (!ros2vtk::wire::QoS::parse(history, qos.history))
  {
    vtkErrorMacro("SetHistory: unknown value '" << (history ? history : "(null)")
                                                << "'; use keep_last or keep_all");
    return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetHistoryDepth(int depth)
{
  if (depth < 1)
  {
    vtkErrorMacro("SetHistoryDepth: depth must be at least 1, got " << depth);
    return false;
  }
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  qos.depth = static_cast<uint32_t>(depth);
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
const char* vtkROS2TopicNode::GetReliability() const
{
  return ros2vtk::wire::QoS::name_of(this->Internals->QoS.reliability);
}

//------------------------------------------------------------------------------
const char* vtkROS2TopicNode::GetDurability() const
{
  return ros2vtk::wire::QoS::name_of(this->Internals->QoS.durability);
}

//------------------------------------------------------------------------------
const char* vtkROS2TopicNode::GetHistory() const
{
  return ros2vtk::wire::QoS::name_of(this->Internals->QoS.history);
}

//------------------------------------------------------------------------------
int vtkROS2TopicNode::GetHistoryDepth() const
{
  return static_cast<int>(this->Internals->QoS.depth);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetQoSReliability(int reliability)
{
  using Reliability = ros2vtk::wire::QoS::Reliability;
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  switch (reliability)
  {
    case ReliabilitySystemDefault:
      qos.reliability = ros2vtk::wire::QoS::default_profile().reliability;
      break;
    case Reliable:
      qos.reliability = Reliability::Reliable;
      break;
    case BestEffort:
      qos.reliability = Reliability::BestEffort;
      break;
    default:
      vtkErrorMacro("SetQoSReliability: unknown value "
        << reliability << "; use ReliabilitySystemDefault (0), Reliable (1) or BestEffort (2)");
      return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
int vtkROS2TopicNode::GetQoSReliability() const
{
  return this->Internals->QoS.reliability == ros2vtk::wire::QoS::Reliability::BestEffort
    ? BestEffort
    : Reliable;
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::SetQoSDurability(int durability)
{
  using Durability = ros2vtk::wire::QoS::Durability;
  ros2vtk::wire::QoS qos = this->Internals->QoS;
  switch (durability)
  {
    case DurabilitySystemDefault:
      qos.durability = ros2vtk::wire::QoS::default_profile().durability;
      break;
    case TransientLocal:
      qos.durability = Durability::TransientLocal;
      break;
    case Volatile:
      qos.durability = Durability::Volatile;
      break;
    default:
      vtkErrorMacro("SetQoSDurability: unknown value "
        << durability << "; use DurabilitySystemDefault (0), TransientLocal (1) or Volatile (2)");
      return false;
  }
  return this->SetQoS(qos);
}

//------------------------------------------------------------------------------
int vtkROS2TopicNode::GetQoSDurability() const
{
  return this->Internals->QoS.durability == ros2vtk::wire::QoS::Durability::TransientLocal
    ? TransientLocal
    : Volatile;
}

//------------------------------------------------------------------------------
std::string vtkROS2TopicNode::GetQoSDescription() const
{
  return this->Internals->QoS.to_string();
}

//------------------------------------------------------------------------------
void vtkROS2TopicNode::OnRemovedFromScene()
{
  this->RemoveFromROS2Node();
  this->Superclass::OnRemovedFromScene();
}

//------------------------------------------------------------------------------
void vtkROS2TopicNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute("topic", this->Internals->Topic.c_str());
  element->SetAttribute("rosType", this->GetROSType());
  element->SetAttribute("reliability", this->GetReliability());
  element->SetAttribute("durability", this->GetDurability());
  element->SetAttribute("history", this->GetHistory());
  element->SetIntAttribute("historyDepth", this->GetHistoryDepth());
  element->SetIntAttribute("scaleLengths", this->ScaleLengths ? 1 : 0);
}

//------------------------------------------------------------------------------
bool vtkROS2TopicNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  const char* rosType = element->GetAttribute("rosType");
  if (this->HasMessageTypeSupport() && rosType && *rosType &&
    std::string(rosType) != this->GetMessageTypeSupport().ros_type)
  {
    vtkErrorMacro("ReadXML: node '" << element->GetAttribute("id") << "' has ROS type '" << rosType
                                    << "' but " << this->GetClassName() << " carries '"
                                    << this->GetMessageTypeSupport().ros_type << "'");
    return false;
  }
  const char* topic = element->GetAttribute("topic");
  this->Internals->Topic = topic ? topic : "";

  ros2vtk::wire::QoS qos;
  int depth = static_cast<int>(qos.depth);
  int scale = 1;
  element->GetScalarAttribute("historyDepth", depth);
  element->GetScalarAttribute("scaleLengths", scale);
  const char* reliability = element->GetAttribute("reliability");
  const char* durability = element->GetAttribute("durability");
  const char* history = element->GetAttribute("history");
  if ((reliability && !ros2vtk::wire::QoS::parse(reliability, qos.reliability)) ||
    (durability && !ros2vtk::wire::QoS::parse(durability, qos.durability)) ||
    (history && !ros2vtk::wire::QoS::parse(history, qos.history)) || depth < 1)
  {
    vtkErrorMacro("ReadXML: invalid QoS in node '" << element->GetAttribute("id") << "'");
    return false;
  }
  qos.depth = static_cast<uint32_t>(depth);
  this->Internals->QoS = qos;
  this->ScaleLengths = scale != 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2TopicNode::OnSceneRestored()
{
  this->Superclass::OnSceneRestored();
  const char* savedNode = this->GetNodeReferenceID(ROS2NodeReferenceRole);
  if (!savedNode || this->Internals->Topic.empty())
  {
    return;
  }
  const std::string nodeID = savedNode;
  this->SetNodeReferenceID(ROS2NodeReferenceRole, nullptr);
  this->AddToROS2Node(nodeID.c_str(), this->Internals->Topic.c_str());
}

//------------------------------------------------------------------------------
void vtkROS2TopicNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Topic: " << this->Internals->Topic << "\n";
  os << indent << "ROSType: " << this->GetROSType() << "\n";
  os << indent << "QoS: " << this->Internals->QoS.to_string() << "\n";
  os << indent << "ScaleLengths: " << this->ScaleLengths << "\n";
  os << indent << "AddedToROS2Node: " << this->IsAddedToROS2Node() << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2NodeNode::CreateAndAddTopicNode(bool publisher, const char* type,
  const char* topic, vtkROS2TopicNode* (*newGeneric)(const char* rosType))
{
  using ros2vtk::scene::NodeDirection;
  const char* what = publisher ? "CreateAndAddPublisherNode" : "CreateAndAddSubscriberNode";
  if (!this->CheckReadyFor(what))
  {
    return nullptr;
  }
  if (!type || !topic)
  {
    vtkErrorMacro(<< what << ": type and topic are required");
    return nullptr;
  }
  const char* role = publisher ? PublisherRole : SubscriberRole;
  if (this->FindChildByName(role, topic))
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
    node.TakeReference(newGeneric(resolution.generic_type->ros_type));
  }
  else if (std::string(type).find('/') != std::string::npos)
  {
    // A full type name nothing registers: the generic subscriber learns it from the topic's
    // publisher, the generic publisher from its subscriptions (REP 2011 type description;
    // issue 13). Both refuse a text that is no type name.
    node.TakeReference(newGeneric(type));
    if (!node)
    {
      vtkErrorMacro(<< what << ": " << resolution.error);
      return nullptr;
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
