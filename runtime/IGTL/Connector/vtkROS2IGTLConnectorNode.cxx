// ros2vtk — OpenIGTLink connector node (vtkROS2IGTLConnectorNode.h). The sockets, framing and
// codecs are plain C++ (ros2vtk::IGTL); this file maps scene nodes to messages and back.
#include "vtkROS2IGTLConnectorNode.h"

#include "ros2vtk/igtl/Codec.hpp"
#include "ros2vtk/igtl/Endpoint.hpp"

#include "NodeClassRegistry.hpp"
#include "vtkROS2ModelNode.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberImageNode.h"
#include "vtkROS2SubscriberPointCloud2Node.h"
#include "vtkROS2SubscriberPointCloudNode.h"
#include "vtkROS2SubscriberPoseArrayNode.h"
#include "vtkROS2SubscriberStringNode.h"
#include "vtkROS2Tf2BroadcasterNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkTransformCollection.h>
#include <vtkWeakPointer.h>
#include <vtkXMLDataElement.h>

#include <chrono>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <set>

namespace igtl = ros2vtk::igtl;

namespace {

igtl::Matrix to_array(vtkMatrix4x4* m)
{
  igtl::Matrix out;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[4 * r + c] = m->GetElement(r, c);
    }
  }
  return out;
}

void from_array(const igtl::Matrix& in, vtkMatrix4x4* m)
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m->SetElement(r, c, in[4 * r + c]);
    }
  }
}

// Text as an XML attribute value.
std::string xml_escape(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

double wall_seconds()
{
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// VTK scalar type → IMAGE scalar type (0: not one Slicer reads safely).
bool to_igtl_scalar(int vtkType, igtl::ScalarType& type)
{
  switch (vtkType)
  {
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      type = igtl::ScalarType::Int8;
      return true;
    case VTK_UNSIGNED_CHAR:
      type = igtl::ScalarType::UInt8;
      return true;
    case VTK_SHORT:
      type = igtl::ScalarType::Int16;
      return true;
    case VTK_UNSIGNED_SHORT:
      type = igtl::ScalarType::UInt16;
      return true;
    case VTK_FLOAT:
      type = igtl::ScalarType::Float32;
      return true;
    case VTK_DOUBLE:
      type = igtl::ScalarType::Float64;
      return true;
    default:
      return false;
  }
}

int to_vtk_scalar(igtl::ScalarType type)
{
  switch (type)
  {
    case igtl::ScalarType::Int8:
      return VTK_SIGNED_CHAR;
    case igtl::ScalarType::UInt8:
      return VTK_UNSIGNED_CHAR;
    case igtl::ScalarType::Int16:
      return VTK_SHORT;
    case igtl::ScalarType::UInt16:
      return VTK_UNSIGNED_SHORT;
    case igtl::ScalarType::Float32:
      return VTK_FLOAT;
    case igtl::ScalarType::Float64:
      return VTK_DOUBLE;
  }
  return VTK_UNSIGNED_CHAR;
}

} // namespace

//------------------------------------------------------------------------------
class vtkROS2IGTLConnectorNode::vtkInternals
{
public:
  struct Route
  {
    std::string parent, child; // tf
    std::string topic, type;   // topic
    vtkWeakPointer<vtkROS2Tf2BroadcasterNode> broadcaster;
    vtkWeakPointer<vtkROS2PublisherNode> publisher;
  };
  struct SentModel
  {
    vtkMTimeType polyTime = 0;
    igtl::Matrix matrix{};
  };

  igtl::Endpoint Endpoint;
  std::string Host = "127.0.0.1";
  std::string State = "off";
  std::string LastError;
  std::deque<std::string> Log;
  vtkWeakPointer<vtkROS2NodeNode> ROSNode;
  vtkNew<vtkMatrix4x4> WorldToSlicer;
  vtkNew<vtkMatrix4x4> SlicerToWorld;
  std::map<std::string, SentModel> SentModels;      // by model node ID
  std::map<std::string, vtkTypeInt64> SentMessages; // subscriber node ID → count sent
  std::map<std::string, Route> Routes;              // by device name
  std::map<std::string, std::string> ReceivedNodes; // device (type-qualified) → node ID
  std::set<std::string> ReceivedNodeIDs;
  std::map<std::string, vtkSmartPointer<vtkImageData>> ReceivedImages;
  std::map<std::string, std::string> ReceivedStrings;
  std::set<std::string> Warned;
  vtkTypeInt64 BadContent = 0; // well-framed messages whose body does not fit their type

  int HandleFrame(vtkROS2IGTLConnectorNode* self, const igtl::Frame& frame);
  void SendScene(vtkROS2IGTLConnectorNode* self);
  void Send(const igtl::Frame& frame, bool retain);
  std::string Device(const char* name);
  vtkROS2TransformNode* ReceivedTransformNode(
    vtkROS2IGTLConnectorNode* self, const std::string& device);
  void Publish(vtkROS2IGTLConnectorNode* self, const std::string& device, vtkObject* value,
    const std::string* text);
  static bool IsRobotDescription(vtkROS2Scene* scene, vtkROS2SubscriberNode* subscriber);
  bool ImagePose(vtkROS2IGTLConnectorNode* self, const std::string& frameID, vtkMatrix4x4* pose);

  void AddLog(const std::string& line)
  {
    this->Log.push_back(line);
    while (this->Log.size() > 200)
    {
      this->Log.pop_front();
    }
  }
};

vtkStandardNewMacro(vtkROS2IGTLConnectorNode);

namespace {
// The scene creates nodes by class name (vtkROS2Scene::CreateNodeByClass): one registry line.
const bool ConnectorRegistered = [] {
  std::string error;
  return ros2vtk::scene::NodeClassRegistry::instance().add(
    { "", "vtkROS2IGTLConnectorNode", "", ros2vtk::scene::NodeDirection::Other,
      []() -> vtkROS2SceneNode* {
        return vtkROS2IGTLConnectorNode::New();
      } },
    &error);
}();
} // namespace

//------------------------------------------------------------------------------
const char* const vtkROS2IGTLConnectorNode::MirroredNodeReferenceRole = "igtlMirrored";
const char* const vtkROS2IGTLConnectorNode::StartedROS2NodeReferenceRole = "igtlROS2Node";

vtkROS2IGTLConnectorNode::vtkROS2IGTLConnectorNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2IGTLConnectorNode::~vtkROS2IGTLConnectorNode()
{
  this->Stop();
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::OnRemovedFromScene()
{
  this->Stop();
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Type: " << (this->Client ? "client" : "server") << "\n";
  os << indent << "Host: " << this->Internals->Host << ":" << this->Port << "\n";
  os << indent << "State: " << this->GetState() << "\n";
  os << indent << "Clients: " << this->GetNumberOfClients() << "\n";
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::SetHostname(const char* host)
{
  this->Internals->Host = host ? host : "127.0.0.1";
  this->Modified();
}

const char* vtkROS2IGTLConnectorNode::GetHostname() const
{
  return this->Internals->Host.c_str();
}

//------------------------------------------------------------------------------
bool vtkROS2IGTLConnectorNode::Start(vtkROS2NodeNode* rosNode)
{
  vtkInternals& in = *this->Internals;
  this->Stop();
  if (!this->Client && in.Host != "127.0.0.1" && in.Host != "localhost")
  {
    vtkWarningMacro("OpenIGTLink server bound to " << in.Host << ": the scene is served to every "
                                                   << "host that reaches this address");
  }
  igtl::Endpoint::Options options;
  options.client = this->Client;
  options.host = in.Host;
  options.port = this->Port;
  std::string error;
  if (!in.Endpoint.start(options, error))
  {
    in.State = "error";
    in.LastError = error;
    in.AddLog(error);
    vtkErrorMacro("Start: " << error);
    return false;
  }
  in.State = this->Client ? "connecting" : "listening";
  in.LastError.clear();
  in.SentModels.clear();
  in.SentMessages.clear();
  in.ROSNode = rosNode;
  this->StartRequested = true;
  this->RemoveNodeReferenceIDs(StartedROS2NodeReferenceRole);
  if (rosNode)
  {
    rosNode->AddSpinCallback(this, [this]() { return this->Update(); });
    if (rosNode->GetID())
    {
      this->SetNodeReferenceID(StartedROS2NodeReferenceRole, rosNode->GetID());
    }
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::Stop()
{
  vtkInternals& in = *this->Internals;
  if (in.ROSNode)
  {
    in.ROSNode->RemoveSpinCallbacks(this);
  }
  in.ROSNode = nullptr;
  this->StartRequested = false;
  if (in.Endpoint.is_started())
  {
    in.Endpoint.stop();
    for (const igtl::Endpoint::Event& event : in.Endpoint.take_events())
    {
      in.AddLog(event.text);
    }
  }
  in.State = "off";
}

//------------------------------------------------------------------------------
const char* vtkROS2IGTLConnectorNode::GetState() const
{
  return this->Internals->State.c_str();
}

const char* vtkROS2IGTLConnectorNode::GetLastError() const
{
  return this->Internals->LastError.c_str();
}

int vtkROS2IGTLConnectorNode::GetNumberOfClients() const
{
  return static_cast<int>(this->Internals->Endpoint.peer_count());
}

vtkTypeInt64 vtkROS2IGTLConnectorNode::GetNumberOfMessagesSent() const
{
  return static_cast<vtkTypeInt64>(this->Internals->Endpoint.messages_sent());
}

vtkTypeInt64 vtkROS2IGTLConnectorNode::GetNumberOfBadMessages() const
{
  return static_cast<vtkTypeInt64>(this->Internals->Endpoint.bad_messages()) +
    this->Internals->BadContent;
}

vtkTypeInt64 vtkROS2IGTLConnectorNode::GetNumberOfDroppedMessages() const
{
  return static_cast<vtkTypeInt64>(this->Internals->Endpoint.messages_dropped());
}

std::string vtkROS2IGTLConnectorNode::GetEventLog() const
{
  std::string out;
  for (const std::string& line : this->Internals->Log)
  {
    out += line + "\n";
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::AddMirroredNodeID(const char* nodeID)
{
  if (nodeID && *nodeID)
  {
    this->RemoveNodeReferenceID(MirroredNodeReferenceRole, nodeID); // once
    this->AddNodeReferenceID(MirroredNodeReferenceRole, nodeID);
  }
}

void vtkROS2IGTLConnectorNode::RemoveMirroredNodeID(const char* nodeID)
{
  if (nodeID)
  {
    this->RemoveNodeReferenceID(MirroredNodeReferenceRole, nodeID);
  }
}

bool vtkROS2IGTLConnectorNode::IsMirrored(vtkROS2SceneNode* node) const
{
  if (!node || node == this || this->Internals->ReceivedNodeIDs.count(node->GetID()))
  {
    return false; // what Slicer sent is not echoed back
  }
  if (this->MirrorAllNodes)
  {
    return true;
  }
  const int count = this->GetNumberOfNodeReferences(MirroredNodeReferenceRole);
  for (int i = 0; i < count; ++i)
  {
    if (std::strcmp(this->GetNthNodeReferenceID(MirroredNodeReferenceRole, i), node->GetID()) == 0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::SetWorldToSlicer(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    this->Internals->WorldToSlicer->Identity();
  }
  else
  {
    this->Internals->WorldToSlicer->DeepCopy(matrix);
  }
  vtkMatrix4x4::Invert(this->Internals->WorldToSlicer, this->Internals->SlicerToWorld);
  this->Internals->SentModels.clear(); // everything is resent in the new frame
  this->Modified();
}

vtkMatrix4x4* vtkROS2IGTLConnectorNode::GetWorldToSlicer()
{
  return this->Internals->WorldToSlicer;
}

//------------------------------------------------------------------------------
bool vtkROS2IGTLConnectorNode::MapDeviceToTf(
  const char* device, const char* parentFrame, const char* childFrame)
{
  if (!device || !*device || !parentFrame || !*parentFrame || !childFrame || !*childFrame)
  {
    vtkErrorMacro("MapDeviceToTf: device, parent and child frames are required");
    return false;
  }
  vtkInternals::Route route;
  route.parent = parentFrame;
  route.child = childFrame;
  this->Internals->Routes[device] = route;
  return true;
}

bool vtkROS2IGTLConnectorNode::MapDeviceToTopic(
  const char* device, const char* topic, const char* type)
{
  if (!device || !*device || !topic || !*topic || !type || !*type)
  {
    vtkErrorMacro("MapDeviceToTopic: device, topic and type are required");
    return false;
  }
  vtkInternals::Route route;
  route.topic = topic;
  route.type = type;
  this->Internals->Routes[device] = route;
  return true;
}

std::string vtkROS2IGTLConnectorNode::GetDeviceMap(const char* device) const
{
  auto it = this->Internals->Routes.find(device ? device : "");
  if (it == this->Internals->Routes.end())
  {
    return std::string();
  }
  const vtkInternals::Route& route = it->second;
  return route.parent.empty() ? "topic:" + route.topic + ":" + route.type
                              : "tf:" + route.parent + ":" + route.child;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element); // the mirrored nodes and the ROS node are references
  vtkInternals& in = *this->Internals;
  element->SetAttribute("type", this->Client ? "client" : "server");
  element->SetAttribute("hostname", in.Host.c_str());
  element->SetIntAttribute("port", this->Port);
  element->SetIntAttribute("mirrorAllNodes", this->MirrorAllNodes ? 1 : 0);
  element->SetIntAttribute("modelsInWorld", this->ModelsInWorld ? 1 : 0);
  element->SetIntAttribute("started", in.Endpoint.is_started() ? 1 : 0);
  double matrix[16];
  vtkMatrix4x4::DeepCopy(matrix, in.WorldToSlicer);
  element->SetVectorAttribute("worldToSlicer", 16, matrix);
  for (const auto& [device, route] : in.Routes)
  {
    vtkNew<vtkXMLDataElement> map;
    map->SetName("DeviceMap");
    map->SetAttribute("device", device.c_str());
    if (!route.parent.empty())
    {
      map->SetAttribute("parentFrame", route.parent.c_str());
      map->SetAttribute("childFrame", route.child.c_str());
    }
    else
    {
      map->SetAttribute("topic", route.topic.c_str());
      map->SetAttribute("messageType", route.type.c_str());
    }
    element->AddNestedElement(map);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2IGTLConnectorNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  const char* type = element->GetAttribute("type");
  if (type && std::strcmp(type, "client") != 0 && std::strcmp(type, "server") != 0)
  {
    vtkErrorMacro("ReadXML: type is '" << type << "', expected 'client' or 'server'");
    return false;
  }
  int port = this->Port;
  if (element->GetScalarAttribute("port", port) && (port < 1 || port > 65535))
  {
    vtkErrorMacro("ReadXML: port " << port << " is not in 1..65535");
    return false;
  }
  double matrix[16];
  const bool hasMatrix = element->GetAttribute("worldToSlicer") != nullptr;
  if (hasMatrix && element->GetVectorAttribute("worldToSlicer", 16, matrix) != 16)
  {
    vtkErrorMacro("ReadXML: worldToSlicer needs 16 numbers");
    return false;
  }
  this->Client = type && std::strcmp(type, "client") == 0;
  this->Port = port;
  if (const char* host = element->GetAttribute("hostname"))
  {
    this->Internals->Host = host;
  }
  int value = 0;
  if (element->GetScalarAttribute("mirrorAllNodes", value))
    this->MirrorAllNodes = value != 0;
  if (element->GetScalarAttribute("modelsInWorld", value))
    this->ModelsInWorld = value != 0;
  this->StartRequested = element->GetScalarAttribute("started", value) && value != 0;
  if (hasMatrix)
  {
    vtkNew<vtkMatrix4x4> worldToSlicer;
    worldToSlicer->DeepCopy(matrix);
    this->SetWorldToSlicer(worldToSlicer);
  }
  this->Internals->Routes.clear();
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* map = element->GetNestedElement(i);
    if (!map->GetName() || std::strcmp(map->GetName(), "DeviceMap") != 0)
    {
      continue; // the base class's own elements
    }
    const char* device = map->GetAttribute("device");
    const bool ok = map->GetAttribute("parentFrame")
      ? this->MapDeviceToTf(
          device, map->GetAttribute("parentFrame"), map->GetAttribute("childFrame"))
      : this->MapDeviceToTopic(
          device, map->GetAttribute("topic"), map->GetAttribute("messageType"));
    if (!ok)
    {
      vtkErrorMacro("ReadXML: DeviceMap " << i << " is incomplete");
      return false;
    }
  }
  return true;
}

vtkROS2NodeNode* vtkROS2IGTLConnectorNode::GetStartedROS2Node() const
{
  return vtkROS2NodeNode::SafeDownCast(this->GetNodeReference(StartedROS2NodeReferenceRole));
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::OnSceneRestored()
{
  if (!this->StartRequested || this->Internals->Endpoint.is_started())
  {
    return;
  }
  this->Start(this->GetStartedROS2Node()); // a failure (port taken) is in GetState / GetLastError
}

//------------------------------------------------------------------------------
int vtkROS2IGTLConnectorNode::WriteSlicerScene(const char* path)
{
  vtkInternals& in = *this->Internals;
  std::ofstream out(path ? path : "");
  if (!path || !*path || !out)
  {
    in.LastError = std::string("WriteSlicerScene: cannot write '") + (path ? path : "") + "'";
    vtkErrorMacro(<< in.LastError);
    return -1;
  }
  // Element and attribute names as Slicer's own ReadXMLAttributes read them: vtkMRMLNode
  // ("references" = "role:id;"), vtkMRMLLinearTransformNode, vtkMRMLModelDisplayNode, and
  // SlicerOpenIGTLink's vtkMRMLIGTLConnectorNode (persistent 1 + state 1 = wait for connection:
  // OpenIGTLinkIF's logic starts it when the import ends, after the nodes below exist).
  out << "<MRML version=\"Slicer4.4.0\" userTags=\"\">\n";
  const std::string host =
    in.Host == "0.0.0.0" || in.Host == "127.0.0.1" || in.Host.empty() ? "localhost" : in.Host;
  out << " <IGTLConnector id=\"vtkMRMLIGTLConnectorNode1\" name=\"ros2vtk\" connectorType=\""
      << (this->Client ? "SERVER" : "CLIENT") << "\"";
  if (!this->Client)
  {
    out << " serverHostname=\"" << xml_escape(host) << "\"";
  }
  out
    << " serverPort=\"" << this->Port
    << "\" persistent=\"1\" checkCRC=\"1\" state=\"1\" restrictDeviceName=\"0\"></IGTLConnector>\n";
  std::map<std::string, std::string> transformIDs; // device → id in the file
  int models = 0;
  vtkROS2Scene* scene = this->GetScene();
  for (int i = 0; scene && i < scene->GetNumberOfNodes(); ++i)
  {
    auto* model = vtkROS2ModelNode::SafeDownCast(scene->GetNthNode(i));
    vtkROS2TransformNode* parent = model ? model->GetParentTransformNode() : nullptr;
    if (!model || !parent || !this->IsMirrored(model) || !this->IsMirrored(parent))
    {
      continue;
    }
    const std::string parentDevice = MakeDeviceName(parent->GetName() ? parent->GetName() : "");
    std::string& transformID = transformIDs[parentDevice];
    if (transformID.empty() && !this->ModelsInWorld) // meshes in world coordinates stay at the root
    {
      transformID = "vtkMRMLLinearTransformNode" + std::to_string(transformIDs.size());
      out << " <LinearTransform id=\"" << transformID << "\" name=\"" << xml_escape(parentDevice)
          << "\" matrixTransformToParent=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\"></LinearTransform>\n";
    }
    ++models;
    const std::string displayID = "vtkMRMLModelDisplayNode" + std::to_string(models);
    const double* color = model->GetColor();
    out << " <ModelDisplay id=\"" << displayID << "\" name=\"ModelDisplay\" color=\"" << color[0]
        << " " << color[1] << " " << color[2] << "\" visibility=\"true\"></ModelDisplay>\n";
    out << " <Model id=\"vtkMRMLModelNode" << models << "\" name=\""
        << xml_escape(MakeDeviceName(model->GetName() ? model->GetName() : ""))
        << "\" references=\"display:" << displayID << ";"
        << (this->ModelsInWorld ? std::string() : "transform:" + transformID + ";")
        << "\"></Model>\n";
  }
  out << "</MRML>\n";
  out.close();
  if (!out)
  {
    in.LastError = std::string("WriteSlicerScene: cannot write '") + path + "'";
    vtkErrorMacro(<< in.LastError);
    return -1;
  }
  return models;
}

//------------------------------------------------------------------------------
vtkImageData* vtkROS2IGTLConnectorNode::GetReceivedImage(const char* device)
{
  auto it = this->Internals->ReceivedImages.find(device ? device : "");
  return it == this->Internals->ReceivedImages.end() ? nullptr : it->second.GetPointer();
}

std::string vtkROS2IGTLConnectorNode::GetReceivedString(const char* device)
{
  auto it = this->Internals->ReceivedStrings.find(device ? device : "");
  return it == this->Internals->ReceivedStrings.end() ? std::string() : it->second;
}

vtkROS2SceneNode* vtkROS2IGTLConnectorNode::GetReceivedNode(const char* device)
{
  auto it = this->Internals->ReceivedNodes.find(device ? device : "");
  if (it == this->Internals->ReceivedNodes.end() || !this->GetScene())
  {
    return nullptr;
  }
  return this->GetScene()->GetNodeByID(it->second.c_str());
}

//------------------------------------------------------------------------------
int vtkROS2IGTLConnectorNode::Update()
{
  vtkInternals& in = *this->Internals;
  if (!in.Endpoint.is_started())
  {
    return 0;
  }
  std::vector<igtl::Endpoint::Received> received;
  in.Endpoint.poll(received);
  int handled = 0;
  for (const auto& item : received)
  {
    handled += in.HandleFrame(this, item.frame);
  }
  for (const igtl::Endpoint::Event& event : in.Endpoint.take_events())
  {
    in.AddLog(event.text);
    if (event.problem)
    {
      in.LastError = event.text;
      vtkWarningMacro("OpenIGTLink " << event.text);
    }
  }
  if (in.Endpoint.peer_count() > 0)
  {
    in.State = "connected";
    in.SendScene(this);
    in.Endpoint.flush();
  }
  else
  {
    // What was sent is retained by the endpoint, which queues it for every peer that connects
    // later: sending it again here would give that peer each mesh and image twice.
    in.State = this->Client ? "connecting" : "listening";
  }
  return handled;
}

//------------------------------------------------------------------------------
std::string vtkROS2IGTLConnectorNode::vtkInternals::Device(const char* name)
{
  const std::string full = name ? name : "";
  std::string device = vtkROS2IGTLConnectorNode::MakeDeviceName(full);
  if (device != full && this->Warned.insert(full).second)
  {
    this->AddLog(
      "node '" + full + "' is device '" + device + "' (OpenIGTLink names have 20 bytes)");
  }
  return device;
}

//------------------------------------------------------------------------------
std::string vtkROS2IGTLConnectorNode::MakeDeviceName(const std::string& nodeName)
{
  if (nodeName.size() <= 20)
  {
    return nodeName;
  }
  // Robot nodes are named "<robot>:<link>[:visualN]": the robot prefix goes first.
  const std::size_t colon = nodeName.find(':');
  if (colon != std::string::npos && nodeName.size() - colon - 1 <= 20 &&
    colon + 1 < nodeName.size())
  {
    return nodeName.substr(colon + 1);
  }
  // Still too long: 16 bytes, '~' and 3 hex digits of an FNV-1a hash of the whole name.
  std::uint32_t hash = 2166136261u;
  for (unsigned char c : nodeName)
  {
    hash = (hash ^ c) * 16777619u;
  }
  static const char* hex = "0123456789abcdef";
  std::string device =
    nodeName.substr(colon != std::string::npos && colon + 1 < nodeName.size() ? colon + 1 : 0, 16);
  device += '~';
  for (int shift = 8; shift >= 0; shift -= 4)
  {
    device += hex[(hash >> shift) & 0xf];
  }
  return device;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::vtkInternals::Send(const igtl::Frame& frame, bool retain)
{
  this->Endpoint.send(frame.type + ":" + frame.device, igtl::encode_frame(frame), retain);
}

//------------------------------------------------------------------------------
bool vtkROS2IGTLConnectorNode::vtkInternals::IsRobotDescription(
  vtkROS2Scene* scene, vtkROS2SubscriberNode* subscriber)
{
  for (int i = 0; i < scene->GetNumberOfNodes(); ++i)
  {
    auto* robot = vtkROS2RobotNode::SafeDownCast(scene->GetNthNode(i));
    if (robot && robot->GetDescriptionTopic() &&
      std::string(robot->GetDescriptionTopic()) == subscriber->GetTopic())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkROS2IGTLConnectorNode::vtkInternals::ImagePose(
  vtkROS2IGTLConnectorNode* self, const std::string& frameID, vtkMatrix4x4* pose)
{
  pose->Identity();
  vtkROS2Scene* scene = self->GetScene();
  for (int i = 0; scene && i < scene->GetNumberOfNodes(); ++i)
  {
    auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(scene->GetNthNode(i));
    if (lookup && frameID == lookup->GetChildID())
    {
      lookup->GetMatrixTransformToWorld(pose);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::vtkInternals::SendScene(vtkROS2IGTLConnectorNode* self)
{
  vtkROS2Scene* scene = self->GetScene();
  if (!scene)
  {
    return;
  }
  const std::uint64_t now = igtl::to_igtl_timestamp(wall_seconds());
  vtkNew<vtkMatrix4x4> world;
  vtkNew<vtkMatrix4x4> slicer;
  for (int i = 0; i < scene->GetNumberOfNodes(); ++i)
  {
    vtkROS2SceneNode* node = scene->GetNthNode(i);
    if (!self->IsMirrored(node))
    {
      continue;
    }
    if (auto* transform = vtkROS2TransformNode::SafeDownCast(node))
    {
      // Every spin: the newest pose replaces an unsent one in each peer's queue.
      transform->GetMatrixTransformToWorld(world);
      vtkMatrix4x4::Multiply4x4(this->WorldToSlicer, world, slicer);
      this->Send(
        igtl::encode_transform(this->Device(transform->GetName()), to_array(slicer), now), false);
    }
    else if (auto* model = vtkROS2ModelNode::SafeDownCast(node))
    {
      vtkPolyData* poly = model->GetPolyData();
      if (!poly || poly->GetNumberOfPoints() == 0)
      {
        continue;
      }
      const std::string device = this->Device(model->GetName());
      igtl::Frame frame;
      // Link-local only under a transform (Slicer's parent); a model at the root is in the world.
      const bool linkLocal = !self->ModelsInWorld && model->GetParentTransformNode();
      if (!linkLocal)
      {
        model->GetMatrixModelToWorld(world);
        vtkMatrix4x4::Multiply4x4(this->WorldToSlicer, world, slicer);
      }
      else
      {
        slicer->DeepCopy(model->GetMatrixModelToParent());
      }
      SentModel state{ poly->GetMTime(), to_array(slicer) };
      auto sent = this->SentModels.find(model->GetID());
      if (sent != this->SentModels.end() && sent->second.polyTime == state.polyTime &&
        sent->second.matrix == state.matrix)
      {
        continue; // large items only on change
      }
      this->SentModels[model->GetID()] = state;
      igtl::Mesh mesh;
      mesh.points.reserve(3 * static_cast<std::size_t>(poly->GetNumberOfPoints()));
      for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p)
      {
        double in[4] = { 0, 0, 0, 1 };
        poly->GetPoint(p, in);
        double out[4];
        slicer->MultiplyPoint(in, out);
        mesh.points.insert(mesh.points.end(),
          { static_cast<float>(out[0]), static_cast<float>(out[1]), static_cast<float>(out[2]) });
      }
      auto cells = [](vtkCellArray* array, std::vector<std::vector<std::uint32_t>>& list) {
        if (!array)
        {
          return;
        }
        vtkNew<vtkIdList> ids;
        for (array->InitTraversal(); array->GetNextCell(ids);)
        {
          std::vector<std::uint32_t> cell(static_cast<std::size_t>(ids->GetNumberOfIds()));
          for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
          {
            cell[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(ids->GetId(k));
          }
          list.push_back(std::move(cell));
        }
      };
      cells(poly->GetPolys(), mesh.polygons);
      cells(poly->GetLines(), mesh.lines);
      cells(poly->GetVerts(), mesh.vertices);
      frame = igtl::encode_polydata(device, mesh, now);
      if (linkLocal)
      {
        frame.metadata["ros.parent"] = this->Device(model->GetParentTransformNode()->GetName());
      }
      this->Send(frame, true);
    }
    else if (auto* subscriber = vtkROS2SubscriberNode::SafeDownCast(node))
    {
      if (this->IsRobotDescription(scene, subscriber))
      {
        continue; // a robot's description reaches Slicer as its models
      }
      const vtkTypeInt64 count = subscriber->GetNumberOfMessages();
      vtkTypeInt64& sentCount = this->SentMessages[subscriber->GetID()];
      if (count == 0 || count == sentCount)
      {
        continue;
      }
      sentCount = count;
      const std::string device =
        this->Device(subscriber->GetName() && *subscriber->GetName() ? subscriber->GetName()
                                                                     : subscriber->GetTopic());
      if (auto* strings = vtkROS2SubscriberStringNode::SafeDownCast(subscriber))
      {
        this->Send(igtl::encode_string(device, strings->GetLastMessage(), now), true);
      }
      else if (auto* images = vtkROS2SubscriberImageNode::SafeDownCast(subscriber))
      {
        vtkImageData* image = images->GetLastMessage();
        igtl::Image out;
        if (!image || !image->GetPointData()->GetScalars() ||
          !to_igtl_scalar(image->GetScalarType(), out.scalar))
        {
          if (this->Warned.insert(device + ":image").second)
          {
            this->AddLog("IMAGE '" + device + "': scalar type not sendable to Slicer");
          }
          continue;
        }
        int dims[3];
        image->GetDimensions(dims);
        double spacing[3];
        image->GetSpacing(spacing);
        double origin[3];
        image->GetOrigin(origin);
        vtkNew<vtkMatrix4x4> pose;
        if (!this->ImagePose(self, images->GetLastMessageFrameID(), pose) &&
          this->Warned.insert(device + ":pose").second)
        {
          this->AddLog("IMAGE '" + device + "': no tf lookup node has child frame '" +
            images->GetLastMessageFrameID() + "'; sent at the world origin");
        }
        vtkMatrix4x4::Multiply4x4(this->WorldToSlicer, pose, slicer);
        vtkNew<vtkMatrix4x4> ijk;
        ijk->DeepCopy(slicer);
        double corner[4] = { origin[0], origin[1], origin[2], 1.0 };
        double placed[4];
        slicer->MultiplyPoint(corner, placed);
        for (int r = 0; r < 3; ++r)
        {
          ijk->SetElement(r, 3, placed[r]);
        }
        out.ijk_to_world = to_array(ijk);
        out.size = { { dims[0], dims[1], dims[2] } };
        out.spacing = { { float(spacing[0]), float(spacing[1]), float(spacing[2]) } };
        out.components = image->GetNumberOfScalarComponents();
        const auto* bytes = static_cast<const std::uint8_t*>(image->GetScalarPointer());
        const std::size_t size = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2] *
          out.components * igtl::scalar_size(out.scalar);
        out.data.assign(bytes, bytes + size);
        this->Send(igtl::encode_image(device, out, now), true);
      }
      else if (auto* poses = vtkROS2SubscriberPoseArrayNode::SafeDownCast(subscriber))
      {
        // PoseArray → TDATA: Slicer makes one linear transform per element, named by it.
        vtkTransformCollection* collection = poses->GetLastMessage();
        if (!collection)
        {
          continue;
        }
        vtkNew<vtkMatrix4x4> pose;
        this->ImagePose(self, poses->GetLastMessageFrameID(), pose);
        vtkMatrix4x4::Multiply4x4(this->WorldToSlicer, pose, slicer);
        // The same poses as a POINT list: Slicer shows it as a markups point list (positions
        // only, one control point per pose, labelled as the TDATA element).
        std::vector<igtl::TrackingItem> items;
        std::vector<igtl::PointItem> points;
        collection->InitTraversal();
        while (vtkTransform* element = collection->GetNextItem())
        {
          igtl::TrackingItem item;
          item.name =
            vtkROS2IGTLConnectorNode::MakeDeviceName(device + "_" + std::to_string(items.size()));
          vtkMatrix4x4::Multiply4x4(slicer, element->GetMatrix(), world);
          item.matrix = to_array(world);
          igtl::PointItem point;
          point.name = item.name;
          point.group = "Selected";
          point.rgba = { { 255, 128, 128, 255 } }; // Slicer's default colour of a selected point
          point.position = { { static_cast<float>(world->GetElement(0, 3)),
            static_cast<float>(world->GetElement(1, 3)),
            static_cast<float>(world->GetElement(2, 3)) } };
          points.push_back(point);
          items.push_back(item);
        }
        this->Send(igtl::encode_tracking_data(device, items, now), true);
        this->Send(igtl::encode_points(device, points, now), true);
      }
      else
      {
        vtkPoints* points = nullptr;
        std::string frameID;
        if (auto* cloud = vtkROS2SubscriberPointCloudNode::SafeDownCast(subscriber))
        {
          points = cloud->GetLastMessage();
          frameID = cloud->GetLastMessageFrameID();
        }
        else if (auto* cloud2 = vtkROS2SubscriberPointCloud2Node::SafeDownCast(subscriber))
        {
          vtkPolyData* poly = cloud2->GetLastMessage();
          points = poly ? poly->GetPoints() : nullptr;
          frameID = cloud2->GetLastMessageFrameID();
        }
        if (!points)
        {
          continue; // other subscribers have no OpenIGTLink counterpart
        }
        vtkNew<vtkMatrix4x4> pose;
        this->ImagePose(self, frameID, pose);
        vtkMatrix4x4::Multiply4x4(this->WorldToSlicer, pose, slicer);
        igtl::Mesh mesh;
        for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
        {
          double pin[4] = { 0, 0, 0, 1 };
          points->GetPoint(p, pin);
          double pout[4];
          slicer->MultiplyPoint(pin, pout);
          mesh.points.insert(mesh.points.end(),
            { static_cast<float>(pout[0]), static_cast<float>(pout[1]),
              static_cast<float>(pout[2]) });
          mesh.vertices.push_back({ static_cast<std::uint32_t>(p) });
        }
        this->Send(igtl::encode_polydata(device, mesh, now), true);
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkROS2TransformNode* vtkROS2IGTLConnectorNode::vtkInternals::ReceivedTransformNode(
  vtkROS2IGTLConnectorNode* self, const std::string& device)
{
  vtkROS2Scene* scene = self->GetScene();
  if (!scene)
  {
    return nullptr;
  }
  auto it = this->ReceivedNodes.find(device);
  if (it != this->ReceivedNodes.end())
  {
    if (auto* node = vtkROS2TransformNode::SafeDownCast(scene->GetNodeByID(it->second.c_str())))
    {
      return node;
    }
  }
  vtkNew<vtkROS2TransformNode> node;
  node->SetName(device.c_str());
  scene->AddNode(node);
  this->ReceivedNodes[device] = node->GetID();
  this->ReceivedNodeIDs.insert(node->GetID());
  return node;
}

//------------------------------------------------------------------------------
void vtkROS2IGTLConnectorNode::vtkInternals::Publish(vtkROS2IGTLConnectorNode* self,
  const std::string& device, vtkObject* value, const std::string* text)
{
  auto routeIt = this->Routes.find(device);
  if (routeIt == this->Routes.end())
  {
    return;
  }
  Route& route = routeIt->second;
  vtkROS2NodeNode* rosNode = this->ROSNode;
  if (!rosNode)
  {
    if (this->Warned.insert(device + ":noros").second)
    {
      this->AddLog("'" + device + "' is mapped but the connector was started without a ROS node");
    }
    return;
  }
  if (!route.parent.empty())
  {
    auto* matrix = vtkMatrix4x4::SafeDownCast(value);
    if (!matrix)
    {
      if (this->Warned.insert(device + ":tf").second)
      {
        this->AddLog("'" + device +
          "' cannot go to tf: only a TRANSFORM, a POSITION or a TDATA "
          "element (mapped by its element name) is one transform");
      }
      return;
    }
    if (!route.broadcaster)
    {
      route.broadcaster =
        rosNode->GetTf2BroadcasterNodeByParentChild(route.parent.c_str(), route.child.c_str());
      if (!route.broadcaster)
      {
        route.broadcaster =
          rosNode->CreateAndAddTf2BroadcasterNode(route.parent.c_str(), route.child.c_str());
      }
    }
    if (route.broadcaster)
    {
      route.broadcaster->Broadcast(matrix);
    }
    return;
  }
  if (!route.publisher)
  {
    route.publisher = rosNode->GetPublisherNodeByTopic(route.topic.c_str());
    if (!route.publisher)
    {
      route.publisher = rosNode->CreateAndAddPublisherNode(route.type.c_str(), route.topic.c_str());
    }
    if (!route.publisher)
    {
      if (this->Warned.insert(device + ":pub").second)
      {
        this->AddLog("'" + device + "': cannot publish on " + route.topic + " as " + route.type);
      }
      return;
    }
  }
  // Any publisher class: the generic entry routes the value to its own Publish, or says why not.
  vtkROS2PublisherNode* publisher = route.publisher;
  const bool published =
    text ? publisher->PublishValue(vtkVariant(*text)) > 0 : publisher->PublishObject(value) > 0;
  if (!published && this->Warned.insert(device + ":type").second)
  {
    this->AddLog("'" + device + "' → " + route.topic + ": " + publisher->GetLastPublishError());
  }
  (void)self;
}

//------------------------------------------------------------------------------
int vtkROS2IGTLConnectorNode::vtkInternals::HandleFrame(
  vtkROS2IGTLConnectorNode* self, const igtl::Frame& frame)
{
  std::string error;
  const std::string& device = frame.device;
  if (frame.type == "TRANSFORM" || frame.type == "POSITION")
  {
    igtl::Matrix m;
    const bool ok = frame.type == "TRANSFORM" ? igtl::decode_transform(frame, m, error)
                                              : igtl::decode_position(frame, m, error);
    if (ok)
    {
      vtkNew<vtkMatrix4x4> slicer;
      from_array(m, slicer);
      vtkNew<vtkMatrix4x4> world;
      vtkMatrix4x4::Multiply4x4(this->SlicerToWorld, slicer, world);
      if (vtkROS2TransformNode* node = this->ReceivedTransformNode(self, device))
      {
        node->SetMatrixTransformToParent(world);
      }
      this->Publish(self, device, world, nullptr);
    }
  }
  else if (frame.type == "POINT")
  {
    std::vector<igtl::PointItem> items;
    if (igtl::decode_points(frame, items, error))
    {
      vtkNew<vtkPoints> points;
      for (const igtl::PointItem& item : items)
      {
        double in[4] = { item.position[0], item.position[1], item.position[2], 1.0 };
        double out[4];
        this->SlicerToWorld->MultiplyPoint(in, out);
        points->InsertNextPoint(out);
      }
      vtkROS2Scene* scene = self->GetScene();
      const std::string key = "POINT:" + device;
      vtkROS2ModelNode* model = nullptr;
      auto it = this->ReceivedNodes.find(key);
      if (scene && it != this->ReceivedNodes.end())
      {
        model = vtkROS2ModelNode::SafeDownCast(scene->GetNodeByID(it->second.c_str()));
      }
      if (scene && !model)
      {
        vtkNew<vtkROS2ModelNode> created;
        created->SetName(device.c_str());
        scene->AddNode(created);
        this->ReceivedNodes[key] = created->GetID();
        this->ReceivedNodeIDs.insert(created->GetID());
        model = created;
      }
      if (model)
      {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points);
        vtkNew<vtkCellArray> verts;
        for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
        {
          verts->InsertNextCell(1, &p);
        }
        poly->SetVerts(verts);
        model->SetPolyData(poly);
      }
      this->Publish(self, device, points, nullptr);
    }
  }
  else if (frame.type == "TDATA")
  {
    // As Slicer: one transform node per element (by element name); mapped as a whole
    // (PoseArray in world coordinates).
    std::vector<igtl::TrackingItem> items;
    if (igtl::decode_tracking_data(frame, items, error))
    {
      vtkNew<vtkTransformCollection> collection;
      for (const igtl::TrackingItem& item : items)
      {
        vtkNew<vtkMatrix4x4> slicer;
        from_array(item.matrix, slicer);
        vtkNew<vtkTransform> world;
        world->PostMultiply();
        world->SetMatrix(slicer);
        world->Concatenate(this->SlicerToWorld);
        vtkNew<vtkMatrix4x4> matrix;
        matrix->DeepCopy(world->GetMatrix());
        if (vtkROS2TransformNode* node = this->ReceivedTransformNode(self, item.name))
        {
          node->SetMatrixTransformToParent(matrix);
        }
        this->Publish(self, item.name, matrix, nullptr); // an element mapped by name (tf, topic)
        collection->AddItem(world);
      }
      this->Publish(self, device, collection, nullptr);
    }
  }
  else if (frame.type == "IMAGE")
  {
    igtl::Image image;
    if (igtl::decode_image(frame, image, error))
    {
      vtkNew<vtkMatrix4x4> slicer;
      from_array(image.ijk_to_world, slicer);
      vtkNew<vtkMatrix4x4> world;
      vtkMatrix4x4::Multiply4x4(this->SlicerToWorld, slicer, world);
      auto data = vtkSmartPointer<vtkImageData>::New();
      data->SetDimensions(image.size[0], image.size[1], image.size[2]);
      data->SetSpacing(image.spacing[0], image.spacing[1], image.spacing[2]);
      data->SetOrigin(world->GetElement(0, 3), world->GetElement(1, 3), world->GetElement(2, 3));
      double direction[9];
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          direction[3 * r + c] = world->GetElement(r, c);
        }
      }
      data->SetDirectionMatrix(direction);
      data->AllocateScalars(to_vtk_scalar(image.scalar), image.components);
      std::memcpy(data->GetScalarPointer(), image.data.data(), image.data.size());
      this->ReceivedImages[device] = data;
      this->Publish(self, device, data, nullptr);
    }
  }
  else if (frame.type == "STRING")
  {
    std::string text;
    if (igtl::decode_string(frame, text, error))
    {
      this->ReceivedStrings[device] = text;
      this->Publish(self, device, nullptr, &text);
    }
  }
  else
  {
    // STATUS (Slicer's connect handshake), COMMAND, … carry nothing for the scene.
    if (this->Warned.insert("type:" + frame.type).second && frame.type != "STATUS")
    {
      this->AddLog(frame.type + " '" + device + "' ignored: no scene counterpart");
    }
    return 0;
  }
  if (!error.empty())
  {
    this->LastError = error;
    this->AddLog(error);
    ++this->BadContent;
    vtkWarningWithObjectMacro(self, "OpenIGTLink: " << error);
    return 0;
  }
  ++self->MessagesReceived;
  self->InvokeEvent(ReceivedEvent, const_cast<char*>(device.c_str()));
  return 1;
}
