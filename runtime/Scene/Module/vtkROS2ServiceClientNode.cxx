// ros2vtk — vtkROS2ServiceClientNode: requests of any service type over the wire client
// (ros2vtk::wire::ServiceClient), answered or failed on the ROS node's spin.
#include "vtkROS2ServiceClientNode.h"

#include "vtkROS2Message.h"

#include "Internal/MessageFields.hpp"
#include "Internal/ServiceTypeName.hpp"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Service.hpp"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

#include <poll.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkROS2ServiceClientNode);

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk::wire::MessagePtr;
using ros2vtk::wire::MessageTypeSupport;

MessagePtr NewMessage(const MessageTypeSupport& type)
{
  return MessagePtr(&type, type.create());
}

MessagePtr CopyMessage(const MessageTypeSupport& type, const void* from)
{
  MessagePtr copy = NewMessage(type);
  type.copy(from, copy.get());
  return copy;
}

std::string FormatSeconds(double seconds)
{
  std::ostringstream text;
  text << seconds << " s";
  return text.str();
}
}

//------------------------------------------------------------------------------
class vtkROS2ServiceClientNode::vtkInternals
{
public:
  /// One request between SendAsyncRequest and its response or failure.
  struct Pending
  {
    vtkTypeInt64 Id = 0;
    int64_t Sequence = -1; // DDS sequence number once written; -1 while waiting for a server
    MessagePtr Request;
    Clock::time_point Deadline;
    double TimeoutSeconds = 0;
  };

  const ros2vtk::wire::ServiceTypeSupport* Type = nullptr;
  std::unique_ptr<ros2vtk::wire::ServiceClient> Client;
  MessagePtr Request;
  MessagePtr LastResponse;
  vtkTypeInt64 LastResponseRequestId = 0;
  std::vector<Pending> Pendings;
  vtkTypeInt64 NextId = 1;
  int Status = vtkROS2ServiceClientNode::Idle;
  std::string LastError;
  vtkTypeInt64 Responses = 0;
  vtkTypeInt64 Failures = 0;
  vtkTypeInt64 Calls = 0;
  vtkTypeInt64 RequestsSent = 0;
  vtkSmartPointer<vtkROS2Message> LastResponseObject; // GetLastResponse's, made on first use
  bool InCall = false;
};

//------------------------------------------------------------------------------
vtkROS2ServiceClientNode::vtkROS2ServiceClientNode()
  : vtkROS2EndpointNode("service", "timeout")
  , Internals(new vtkInternals)
{
}

vtkROS2ServiceClientNode::~vtkROS2ServiceClientNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::Attach(
  vtkROS2NodeNode* rosNode, const std::string& type, const std::string& service)
{
  vtkInternals& internals = *this->Internals;
  if (!rosNode || !rosNode->GetParticipant())
  {
    vtkErrorMacro("service client " << service << ": the ROS node is not created");
    return false;
  }
  std::string error;
  const ros2vtk::wire::ServiceTypeSupport* support =
    ros2vtk::scene::find_service_type_by_any_name(type, &error);
  if (!support)
  {
    vtkErrorMacro("service client " << service << ": " << error);
    return false;
  }
  auto client = rosNode->GetParticipant()->create_service_client(
    *support, service, ros2vtk::wire::QoS::services(), &error);
  if (!client)
  {
    vtkErrorMacro("service client " << service << ": " << error);
    return false;
  }
  if (internals.Type != support || !internals.Request)
  {
    internals.Request = NewMessage(*support->request());
    internals.LastResponse = NewMessage(*support->response());
  }
  internals.Type = support;
  internals.Client = std::move(client);
  this->EndpointAttached(rosNode, support->ros_type, service, internals.Client->service_name());
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceClientNode::Detach()
{
  this->Internals->Pendings.clear();
  this->Internals->Client.reset();
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::IsEndpointAttached() const
{
  return this->Internals->Client != nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::IsServiceReady() const
{
  return this->Internals->Client && this->Internals->Client->is_server_available();
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::SetRequestYAML(const char* yaml)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type)
  {
    vtkErrorMacro("SetRequestYAML: the client has no service type yet");
    return false;
  }
  std::string error;
  if (!ros2vtk::wire::from_yaml(
        *internals.Type->request(), yaml ? yaml : "", internals.Request.get(), &error))
  {
    vtkErrorMacro(
      "SetRequestYAML: invalid " << internals.Type->request()->ros_type << ": " << error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceClientNode::GetRequestYAML() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Type
    ? ros2vtk::wire::to_yaml(*internals.Type->request(), internals.Request.get())
    : "";
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::SetRequestField(const char* path, const char* value)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type || !path || !value)
  {
    vtkErrorMacro("SetRequestField: needs a service type, a field path and a value");
    return false;
  }
  std::string error;
  if (!ros2vtk::scene::set_field_from_text(
        *internals.Type->request(), internals.Request.get(), path, value, &error))
  {
    vtkErrorMacro("SetRequestField: " << error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::SetRequestObject(vtkROS2Message* request)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Type || !request || request->GetTypeSupport() != internals.Type->request())
  {
    vtkErrorMacro("SetRequestObject: needs a message object of type "
      << (internals.Type ? internals.Type->request()->ros_type : "(no service type yet)")
      << ", got " << (request && request->GetTypeSupport() ? request->GetROSType() : "(none)"));
    return false;
  }
  internals.Type->request()->copy(request->GetRawMessage(), internals.Request.get());
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::GetRequestObject(vtkROS2Message* request) const
{
  const vtkInternals& internals = *this->Internals;
  if (!internals.Type || !request)
  {
    return false;
  }
  request->CopyFromRaw(*internals.Type->request(), internals.Request.get());
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceClientNode::ResetRequest()
{
  if (this->Internals->Type)
  {
    this->Internals->Request = NewMessage(*this->Internals->Type->request());
  }
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::SendAsyncRequest()
{
  vtkInternals& internals = *this->Internals;
  ++internals.Calls;
  if (!internals.Client)
  {
    vtkErrorMacro("SendAsyncRequest: the client is not attached to a created ROS node");
    return -1;
  }
  vtkInternals::Pending pending;
  pending.Id = internals.NextId++;
  pending.Request = CopyMessage(*internals.Type->request(), internals.Request.get());
  pending.TimeoutSeconds = this->EndpointTimeout;
  pending.Deadline = Clock::now() +
    std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(this->EndpointTimeout));
  // Written at once when a server is there; otherwise on the spin that sees one.
  if (internals.Client->is_server_available())
  {
    pending.Sequence = internals.Client->send_request(pending.Request.get());
  }
  internals.Status = pending.Sequence >= 0 ? WaitingForResponse : WaitingForServer;
  internals.LastError.clear();
  internals.Pendings.push_back(std::move(pending));
  ++internals.RequestsSent;
  this->Modified();
  return internals.Pendings.back().Id;
}

//------------------------------------------------------------------------------
vtkROS2Message* vtkROS2ServiceClientNode::CreateBlankRequest() const
{
  vtkROS2Message* request = vtkROS2Message::New();
  if (this->Internals->Type)
  {
    request->SetROSType(this->Internals->Type->request()->ros_type);
  }
  return request;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::SendAsyncRequest(vtkROS2Message* request)
{
  if (!this->SetRequestObject(request))
  {
    ++this->Internals->Calls;
    return -1;
  }
  return this->SendAsyncRequest();
}

//------------------------------------------------------------------------------
vtkROS2Message* vtkROS2ServiceClientNode::GetLastResponse()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.LastResponseObject)
  {
    internals.LastResponseObject = vtkSmartPointer<vtkROS2Message>::New();
  }
  if (!this->GetLastResponseObject(internals.LastResponseObject))
  {
    vtkWarningMacro("GetLastResponse: no response yet on " << this->GetServiceName());
    return nullptr;
  }
  return internals.LastResponseObject;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::GetNumberOfCalls() const
{
  return this->Internals->Calls;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::GetNumberOfRequestsSent() const
{
  return this->Internals->RequestsSent;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::SendAsyncRequestYAML(const char* yaml)
{
  return this->SetRequestYAML(yaml) ? this->SendAsyncRequest() : -1;
}

//------------------------------------------------------------------------------
int vtkROS2ServiceClientNode::ProcessResponses()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Client || internals.Pendings.empty())
  {
    // Nothing asked: drop strays (answers to timed-out requests) without touching the graph.
    std::vector<ros2vtk::wire::ServiceResponse> strays;
    if (internals.Client)
    {
      internals.Client->take(strays);
    }
    return 0;
  }
  std::vector<ros2vtk::wire::ServiceResponse> responses;
  internals.Client->take(responses);
  std::vector<vtkTypeInt64> answered;
  for (auto& response : responses)
  {
    auto found = std::find_if(
      internals.Pendings.begin(), internals.Pendings.end(), [&](const vtkInternals::Pending& p) {
        return p.Sequence >= 0 && p.Sequence == response.sequence_number;
      });
    if (found == internals.Pendings.end())
    {
      continue; // answer to a request that already timed out, or a second server's duplicate
    }
    answered.push_back(found->Id);
    internals.Pendings.erase(found);
    internals.LastResponse = std::move(response.response);
  }
  // Requests waiting for a server go out once it is there (the first spin that sees it).
  std::vector<std::pair<vtkTypeInt64, std::string>> failed;
  const bool waiting = std::any_of(internals.Pendings.begin(), internals.Pendings.end(),
    [](const vtkInternals::Pending& p) { return p.Sequence < 0; });
  const bool ready = waiting && internals.Client->is_server_available();
  const Clock::time_point now = Clock::now();
  for (auto it = internals.Pendings.begin(); it != internals.Pendings.end();)
  {
    if (it->Sequence < 0 && ready)
    {
      it->Sequence = internals.Client->send_request(it->Request.get());
      if (it->Sequence < 0)
      {
        failed.emplace_back(
          it->Id, "Fast DDS refused to write the request to " + internals.Client->service_name());
        it = internals.Pendings.erase(it);
        continue;
      }
    }
    if (now >= it->Deadline)
    {
      failed.emplace_back(it->Id,
        it->Sequence < 0 ? "timed out: no server for " + internals.Client->service_name() + " (" +
            std::string(this->GetServiceType()) + ") appeared within " +
            FormatSeconds(it->TimeoutSeconds)
                         : "timed out: " + internals.Client->service_name() +
            " sent no response within " + FormatSeconds(it->TimeoutSeconds));
      it = internals.Pendings.erase(it);
      continue;
    }
    ++it;
  }
  if (answered.empty() && failed.empty())
  {
    return 0;
  }
  // The newest outcome decides the status; each outcome fires its own event.
  this->Modified();
  for (const vtkTypeInt64 id : answered)
  {
    internals.LastResponseRequestId = id;
    internals.Status = Succeeded;
    internals.LastError.clear();
    ++internals.Responses;
    this->InvokeEvent(ResponseReceivedEvent, &internals.LastResponseRequestId);
  }
  for (auto& failure : failed)
  {
    internals.Status = failure.second.compare(0, 9, "timed out") == 0 ? TimedOut : Failed;
    internals.LastError = failure.second;
    ++internals.Failures;
    vtkTypeInt64 id = failure.first;
    this->InvokeEvent(RequestFailedEvent, &id);
  }
  return static_cast<int>(answered.size() + failed.size());
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceClientNode::Call(const char* requestYAML, double timeoutSeconds)
{
  vtkInternals& internals = *this->Internals;
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  if (!internals.Client || !rosNode)
  {
    vtkErrorMacro("Call: the client is not attached to a created ROS node");
    return "";
  }
  if (internals.InCall)
  {
    vtkErrorMacro("Call: already inside a Call of this client (call from an observer?)");
    return "";
  }
  const double savedTimeout = this->EndpointTimeout;
  if (timeoutSeconds > 0 && std::isfinite(timeoutSeconds))
  {
    this->EndpointTimeout = timeoutSeconds;
  }
  const vtkTypeInt64 id = this->SendAsyncRequestYAML(requestYAML);
  this->EndpointTimeout = savedTimeout;
  if (id < 0)
  {
    internals.Status = Failed;
    internals.LastError = "invalid request YAML";
    return "";
  }
  internals.InCall = true;
  const int fd = rosNode->GetWakeUpFileDescriptor();
  auto stillPending = [&] {
    return std::any_of(internals.Pendings.begin(), internals.Pendings.end(),
      [id](const vtkInternals::Pending& p) { return p.Id == id; });
  };
  while (stillPending())
  {
    // Short waits while no server is there (matching raises no wake-up), else until data.
    pollfd wait{ fd, POLLIN, 0 };
    ::poll(&wait, 1, 10);
    // Every ROS node of the scene: a server on another node of this process must answer too.
    vtkROS2Scene* scene = this->GetScene();
    const int count = scene ? scene->GetNumberOfNodesByClass("vtkROS2NodeNode") : 0;
    for (int i = 0; i < count; ++i)
    {
      if (auto* node =
            vtkROS2NodeNode::SafeDownCast(scene->GetNthNodeByClass(i, "vtkROS2NodeNode")))
      {
        node->Spin();
      }
    }
    if (!scene)
    {
      rosNode->Spin();
    }
  }
  internals.InCall = false;
  if (internals.LastResponseRequestId == id)
  {
    return this->GetLastResponseYAML();
  }
  vtkErrorMacro("Call " << this->GetServiceName() << ": " << internals.LastError);
  return "";
}

//------------------------------------------------------------------------------
int vtkROS2ServiceClientNode::GetStatus() const
{
  return this->Internals->Status;
}

//------------------------------------------------------------------------------
const char* vtkROS2ServiceClientNode::GetStatusAsString() const
{
  switch (this->Internals->Status)
  {
    case WaitingForServer:
      return "waiting for server";
    case WaitingForResponse:
      return "waiting for response";
    case Succeeded:
      return "succeeded";
    case TimedOut:
      return "timed out";
    case Failed:
      return "failed";
    default:
      return "idle";
  }
}

//------------------------------------------------------------------------------
const char* vtkROS2ServiceClientNode::GetLastError() const
{
  return this->Internals->LastError.c_str();
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceClientNode::GetLastResponseYAML() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Type
    ? ros2vtk::wire::to_yaml(*internals.Type->response(), internals.LastResponse.get())
    : "";
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceClientNode::GetResponseField(const char* path) const
{
  const vtkInternals& internals = *this->Internals;
  std::string value;
  std::string error;
  if (!internals.Type || !path ||
    !ros2vtk::scene::get_field_as_text(
      *internals.Type->response(), internals.LastResponse.get(), path, value, &error))
  {
    vtkErrorMacro(
      "GetResponseField: " << (internals.Type ? error : "the client has no service type yet"));
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceClientNode::GetLastResponseObject(vtkROS2Message* response) const
{
  const vtkInternals& internals = *this->Internals;
  if (!internals.Type || !response || this->GetNumberOfResponses() == 0)
  {
    return false;
  }
  response->CopyFromRaw(*internals.Type->response(), internals.LastResponse.get());
  return true;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::GetLastResponseRequestId() const
{
  return this->Internals->LastResponseRequestId;
}

//------------------------------------------------------------------------------
int vtkROS2ServiceClientNode::GetNumberOfPendingRequests() const
{
  return static_cast<int>(this->Internals->Pendings.size());
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::GetNumberOfResponses() const
{
  return this->Internals->Responses;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2ServiceClientNode::GetNumberOfFailures() const
{
  return this->Internals->Failures;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceClientNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Ready: " << this->IsServiceReady() << "\n";
  os << indent << "Status: " << this->GetStatusAsString() << "\n";
  os << indent << "PendingRequests: " << this->Internals->Pendings.size() << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2ServiceClientNode* vtkROS2NodeNode::CreateAndAddServiceClientNode(
  const char* type, const char* service)
{
  vtkNew<vtkROS2ServiceClientNode> node;
  const bool attached = this->AdoptKeyedChild("CreateAndAddServiceClientNode", ServiceClientRole,
    node, type, service, "service", "this node has a client of ",
    "ros2:client:", [&] { return node->Attach(this, type, service); });
  return attached ? node.GetPointer() : nullptr; // the scene holds it
}

//------------------------------------------------------------------------------
vtkROS2ServiceClientNode* vtkROS2NodeNode::GetServiceClientNodeByService(const char* service)
{
  return vtkROS2ServiceClientNode::SafeDownCast(this->FindChildByName(ServiceClientRole, service));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteServiceClientNode(const char* service)
{
  return this->RemoveKeyedChild(
    "RemoveAndDeleteServiceClientNode", ServiceClientRole, service, "no client of ");
}
