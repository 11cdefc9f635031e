#include "vtkROS2ParameterNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/wire/ParameterClient.hpp"
#include "ros2vtk/wire/ParameterStore.hpp"
#include "ros2vtk/wire/Participant.hpp"

#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLDataElement.h"

#include <set>
#include <sstream>

vtkStandardNewMacro(vtkROS2ParameterNode);

namespace {
namespace rcl = ::ros2vtk::rcl_interfaces::msg;
}

//------------------------------------------------------------------------------
class vtkROS2ParameterNode::vtkInternals
{
public:
  std::string RemoteNode;
  std::set<std::string> Names; // kept here too, so a scene file restores them before attaching
  std::unique_ptr<ros2vtk::wire::ParameterClient> Client;
};

//------------------------------------------------------------------------------
vtkROS2ParameterNode::vtkROS2ParameterNode()
  : Internals(new vtkInternals)
{
}

vtkROS2ParameterNode::~vtkROS2ParameterNode() = default;

//------------------------------------------------------------------------------
void vtkROS2ParameterNode::OnRemovedFromScene()
{
  this->Internals->Client.reset();
}

//------------------------------------------------------------------------------
void vtkROS2ParameterNode::OnROS2NodeDestroyed(vtkROS2NodeNode*)
{
  this->Internals->Client.reset();
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::Attach(vtkROS2NodeNode* rosNode, const std::string& remoteNode)
{
  if (!rosNode || !rosNode->GetParticipant())
  {
    vtkErrorMacro("parameter node for " << remoteNode << ": the ROS node is not created");
    return false;
  }
  std::string error;
  auto client =
    ros2vtk::wire::ParameterClient::create(*rosNode->GetParticipant(), remoteNode, &error);
  if (!client)
  {
    vtkErrorMacro("parameter node for " << remoteNode << ": " << error);
    return false;
  }
  this->Internals->RemoteNode = client->remote_node();
  for (const auto& name : this->Internals->Names)
  {
    client->add(name);
  }
  this->Internals->Client = std::move(client);
  this->SetNodeReferenceID(ROS2NodeReferenceRole, rosNode->GetID());
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ParameterNode::OnSceneRestored()
{
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (rosNode && rosNode->GetParticipant() && !this->Internals->Client &&
    !this->Internals->RemoteNode.empty())
  {
    this->Attach(rosNode, this->Internals->RemoteNode);
  }
}

//------------------------------------------------------------------------------
int vtkROS2ParameterNode::ProcessParameterUpdates()
{
  if (!this->Internals->Client)
  {
    return 0;
  }
  const bool wasReady = this->IsMonitoredNodeReady();
  const std::set<std::string> changed = this->Internals->Client->process();
  if (!changed.empty() || wasReady != this->IsMonitoredNodeReady())
  {
    this->Modified();
  }
  if (!changed.empty())
  {
    this->InvokeEvent(ParameterModifiedEvent);
  }
  return static_cast<int>(changed.size());
}

//------------------------------------------------------------------------------
const char* vtkROS2ParameterNode::GetMonitoredNodeName() const
{
  return this->Internals->RemoteNode.c_str();
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::IsMonitoredNodeReady() const
{
  return this->Internals->Client &&
    this->Internals->Client->state() == ros2vtk::wire::ParameterClient::State::Ready;
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::AddParameter(const char* name)
{
  if (!name || !*name)
  {
    vtkErrorMacro("AddParameter: empty parameter name");
    return false;
  }
  this->Internals->Names.insert(name);
  if (this->Internals->Client)
  {
    this->Internals->Client->add(name);
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::RemoveParameter(const char* name)
{
  if (!name || !this->Internals->Names.erase(name))
  {
    vtkErrorMacro("RemoveParameter: '" << (name ? name : "") << "' is not followed");
    return false;
  }
  if (this->Internals->Client)
  {
    this->Internals->Client->remove(name);
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkROS2ParameterNode::GetParameterNames() const
{
  std::string names;
  for (const auto& name : this->Internals->Names)
  {
    names += (names.empty() ? "" : " ") + name;
  }
  return names;
}

//------------------------------------------------------------------------------
namespace {
const rcl::ParameterValue* Find(
  const std::unique_ptr<ros2vtk::wire::ParameterClient>& client, const char* name)
{
  return client && name ? client->value(name) : nullptr;
}

using ParameterType = ros2vtk::rcl_interfaces::msg::ParameterType;

/// Copies a parameter's array into a VTK array (the typed-array getters), element by element
/// through `convert`.
template<typename ArrayType, typename Values, typename Convert>
bool FillArray(ArrayType* array, const Values& values, Convert convert)
{
  if (!array)
  {
    return false;
  }
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), convert(values[i]));
  }
  return true;
}
const auto Same = [](const auto& value) {
  return value;
};
} // namespace

#define ROS2VTK_PARAMETER_VALUE(name, expected, fallback)                                          \
  const rcl::ParameterValue* value = Find(this->Internals->Client, name);                          \
  if (!value || value->type != (expected))                                                         \
  {                                                                                                \
    vtkErrorMacro(                                                                                 \
      "parameter '" << (name ? name : "") << "' of " << this->Internals->RemoteNode << " is "      \
                    << (value ? ros2vtk::wire::parameter_type_name(value->type) : "not set")       \
                    << ", not " << ros2vtk::wire::parameter_type_name(expected));                  \
    return fallback;                                                                               \
  }

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::IsParameterSet(const char* name, bool noWarning) const
{
  const bool set = Find(this->Internals->Client, name) != nullptr;
  if (!set && !noWarning)
  {
    vtkWarningMacro("parameter '" << (name ? name : "") << "' of " << this->Internals->RemoteNode
                                  << " is not set (yet)");
  }
  return set;
}

//------------------------------------------------------------------------------
std::string vtkROS2ParameterNode::GetParameterType(const char* name) const
{
  // "" for a parameter this node has never seen, as SlicerROS2 answers; "not set" for one the
  // monitored node reports without a value.
  const rcl::ParameterValue* value = Find(this->Internals->Client, name);
  return value ? ros2vtk::wire::parameter_type_name(value->type) : std::string();
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::GetParameterAsBool(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_BOOL, false)
  return value->bool_value;
}

vtkTypeInt64 vtkROS2ParameterNode::GetParameterAsInteger(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_INTEGER, 0)
  return value->integer_value;
}

double vtkROS2ParameterNode::GetParameterAsDouble(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_DOUBLE, 0.0)
  return value->double_value;
}

std::string vtkROS2ParameterNode::GetParameterAsString(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_STRING, std::string())
  return value->string_value;
}

bool vtkROS2ParameterNode::GetParameterAsByteArray(
  const char* name, vtkUnsignedCharArray* values) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_BYTE_ARRAY, false)
  return FillArray(values, value->byte_array_value, Same);
}

bool vtkROS2ParameterNode::GetParameterAsVectorOfBools(const char* name, vtkIntArray* values) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_BOOL_ARRAY, false)
  return FillArray(values, value->bool_array_value, [](bool item) { return item ? 1 : 0; });
}

bool vtkROS2ParameterNode::GetParameterAsVectorOfIntegers(
  const char* name, vtkTypeInt64Array* values) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_INTEGER_ARRAY, false)
  return FillArray(values, value->integer_array_value, Same);
}

bool vtkROS2ParameterNode::GetParameterAsVectorOfDoubles(
  const char* name, vtkDoubleArray* values) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_DOUBLE_ARRAY, false)
  return FillArray(values, value->double_array_value, Same);
}

bool vtkROS2ParameterNode::GetParameterAsVectorOfStrings(
  const char* name, vtkStringArray* values) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_STRING_ARRAY, false)
  return FillArray(values, value->string_array_value, Same);
}

std::vector<int> vtkROS2ParameterNode::GetParameterAsVectorOfBools(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_BOOL_ARRAY, std::vector<int>())
  return std::vector<int>(value->bool_array_value.begin(), value->bool_array_value.end());
}

std::vector<vtkTypeInt64> vtkROS2ParameterNode::GetParameterAsVectorOfIntegers(
  const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_INTEGER_ARRAY, std::vector<vtkTypeInt64>())
  return std::vector<vtkTypeInt64>(
    value->integer_array_value.begin(), value->integer_array_value.end());
}

std::vector<double> vtkROS2ParameterNode::GetParameterAsVectorOfDoubles(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_DOUBLE_ARRAY, std::vector<double>())
  return value->double_array_value;
}

std::vector<std::string> vtkROS2ParameterNode::GetParameterAsVectorOfStrings(const char* name) const
{
  ROS2VTK_PARAMETER_VALUE(name, ParameterType::PARAMETER_STRING_ARRAY, std::vector<std::string>())
  return value->string_array_value;
}

#undef ROS2VTK_PARAMETER_VALUE

//------------------------------------------------------------------------------
std::string vtkROS2ParameterNode::PrintParameter(const char* name) const
{
  const rcl::ParameterValue* value = Find(this->Internals->Client, name);
  std::ostringstream text;
  text << (name ? name : "") << " (" << ros2vtk::wire::parameter_type_name(value ? value->type : 0)
       << "): "
       << (value ? ros2vtk::wire::parameter_value_to_string(*value) : std::string("not set"));
  return text.str();
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2ParameterNode::GetROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(ROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
void vtkROS2ParameterNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetAttribute("monitoredNode", this->Internals->RemoteNode.c_str());
  element->SetAttribute("parameters", this->GetParameterNames().c_str());
}

//------------------------------------------------------------------------------
bool vtkROS2ParameterNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  if (const char* node = element->GetAttribute("monitoredNode"))
  {
    this->Internals->RemoteNode = node;
  }
  if (const char* names = element->GetAttribute("parameters"))
  {
    std::istringstream list(names);
    std::string name;
    while (list >> name)
    {
      this->Internals->Names.insert(name);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ParameterNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MonitoredNode: " << this->Internals->RemoteNode << "\n";
  os << indent << "Ready: " << this->IsMonitoredNodeReady() << "\n";
  for (const auto& name : this->Internals->Names)
  {
    os << indent << this->PrintParameter(name.c_str()) << "\n";
  }
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
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
  return vtkROS2ParameterNode::SafeDownCast(
    this->FindChild(ParameterRole, AbsoluteNodeName(monitoredNodeName)));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteParameterNode(const char* monitoredNodeName)
{
  vtkROS2ParameterNode* node = this->GetParameterNodeByNode(monitoredNodeName);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteParameterNode: " << AbsoluteNodeName(monitoredNodeName)
                                                   << " is not monitored");
    return false;
  }
  return this->RemoveChild(ParameterRole, node);
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteParameterNodeByNodeID(const char* nodeID)
{
  vtkROS2SceneNode* node = this->FindChildByID(ParameterRole, nodeID);
  if (!node)
  {
    vtkErrorMacro("RemoveAndDeleteParameterNodeByNodeID: "
      << (nodeID ? nodeID : "(null)") << " is not a parameter node of this node");
    return false;
  }
  return this->RemoveChild(ParameterRole, node);
}

//------------------------------------------------------------------------------
vtkROS2ParameterNode* vtkROS2NodeNode::GetParameterNodeByNodeID(const char* nodeID)
{
  return vtkROS2ParameterNode::SafeDownCast(this->FindChildByID(ParameterRole, nodeID));
}
