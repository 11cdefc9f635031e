// ros2vtk — vtkROS2ServiceServerNode: requests of any service type from the wire server
// (ros2vtk::wire::ServiceServer), answered by observers on the ROS node's spin.
#include "vtkROS2ServiceServerNode.h"

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
#include "vtkXMLDataElement.h"

#include <chrono>
#include <cmath>
#include <list>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkROS2ServiceServerNode);

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk::wire::MessagePtr;
}

//------------------------------------------------------------------------------
class vtkROS2ServiceServerNode::vtkInternals
{
public:
  /// One request between its arrival and its response (or timeout).
  struct Pending
  {
    ros2vtk::wire::RequestId Id;
    MessagePtr Request;
    MessagePtr Response;
    Clock::time_point Received;
    bool Answered = false;
  };

  const ros2vtk::wire::ServiceTypeSupport* Type = nullptr;
  std::unique_ptr<ros2vtk::wire::ServiceServer> Server;
  std::list<Pending> Pendings; // stable addresses while observers run
  Pending* InEvent = nullptr;  // the request whose event is firing
  bool AnswerWithDefault = true;
  vtkTypeInt64 Requests = 0;
  vtkTypeInt64 Responses = 0;
  vtkTypeInt64 Unanswered = 0;
  uint64_t RejectedSeen = 0;

  Pending* Current()
  {
    return this->InEvent       ? this->InEvent
      : this->Pendings.empty() ? nullptr
                               : &this->Pendings.front();
  }
  const Pending* Current() const
  {
    return this->InEvent       ? this->InEvent
      : this->Pendings.empty() ? nullptr
                               : &this->Pendings.front();
  }
};

//------------------------------------------------------------------------------
vtkROS2ServiceServerNode::vtkROS2ServiceServerNode()
  : vtkROS2EndpointNode("service", "responseTimeout")
  , Internals(new vtkInternals)
{
}

vtkROS2ServiceServerNode::~vtkROS2ServiceServerNode() = default;

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::Attach(
  vtkROS2NodeNode* rosNode, const std::string& type, const std::string& service)
{
  vtkInternals& internals = *this->Internals;
  if (!rosNode || !rosNode->GetParticipant())
  {
    vtkErrorMacro("service server " << service << ": the ROS node is not created");
    return false;
  }
  std::string error;
  const ros2vtk::wire::ServiceTypeSupport* support =
    ros2vtk::scene::find_service_type_by_any_name(type, &error);
  if (!support)
  {
    vtkErrorMacro("service server " << service << ": " << error);
    return false;
  }
  auto server = rosNode->GetParticipant()->create_service_server(
    *support, service, ros2vtk::wire::QoS::services(), &error);
  if (!server)
  {
    vtkErrorMacro("service server " << service << ": " << error);
    return false;
  }
  internals.Type = support;
  internals.Server = std::move(server);
  internals.RejectedSeen = 0;
  this->EndpointAttached(rosNode, support->ros_type, service, internals.Server->service_name());
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceServerNode::Detach()
{
  this->Internals->InEvent = nullptr;
  this->Internals->Pendings.clear();
  this->Internals->Server.reset();
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::IsEndpointAttached() const
{
  return this->Internals->Server != nullptr;
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceServerNode::GetRequestYAML() const
{
  const vtkInternals::Pending* current = this->Internals->Current();
  if (!current)
  {
    vtkErrorMacro("GetRequestYAML: no request is being handled");
    return "";
  }
  return ros2vtk::wire::to_yaml(*this->Internals->Type->request(), current->Request.get());
}

//------------------------------------------------------------------------------
std::string vtkROS2ServiceServerNode::GetRequestField(const char* path) const
{
  const vtkInternals::Pending* current = this->Internals->Current();
  std::string value;
  std::string error = "no request is being handled";
  if (!current || !path ||
    !ros2vtk::scene::get_field_as_text(
      *this->Internals->Type->request(), current->Request.get(), path, value, &error))
  {
    vtkErrorMacro("GetRequestField: " << error);
    return "";
  }
  return value;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::GetRequestObject(vtkROS2Message* request) const
{
  const vtkInternals::Pending* current = this->Internals->Current();
  if (!current || !request)
  {
    vtkErrorMacro(
      "GetRequestObject: " << (current ? "null message object" : "no request is being handled"));
    return false;
  }
  request->CopyFromRaw(*this->Internals->Type->request(), current->Request.get());
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::SetResponseObject(vtkROS2Message* response)
{
  vtkInternals::Pending* current = this->Internals->Current();
  const ros2vtk::wire::MessageTypeSupport* type =
    this->Internals->Type ? this->Internals->Type->response() : nullptr;
  if (!current || !response || response->GetTypeSupport() != type)
  {
    vtkErrorMacro(
      "SetResponseObject: " << (!current ? std::string("no request is being handled")
                                         : std::string("needs a message object of type ") +
            (type ? type->ros_type : "?") + ", got " +
            (response && response->GetTypeSupport() ? response->GetROSType() : "(none)")));
    return false;
  }
  type->copy(response->GetRawMessage(), current->Response.get());
  current->Answered = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::SetResponseYAML(const char* yaml)
{
  vtkInternals::Pending* current = this->Internals->Current();
  if (!current)
  {
    vtkErrorMacro("SetResponseYAML: no request is being handled");
    return false;
  }
  std::string error;
  if (!ros2vtk::wire::from_yaml(
        *this->Internals->Type->response(), yaml ? yaml : "", current->Response.get(), &error))
  {
    vtkErrorMacro(
      "SetResponseYAML: invalid " << this->Internals->Type->response()->ros_type << ": " << error);
    return false;
  }
  current->Answered = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::SetResponseField(const char* path, const char* value)
{
  vtkInternals::Pending* current = this->Internals->Current();
  std::string error = "no request is being handled";
  if (!current || !path || !value ||
    !ros2vtk::scene::set_field_from_text(
      *this->Internals->Type->response(), current->Response.get(), path, value, &error))
  {
    vtkErrorMacro("SetResponseField: " << error);
    return false;
  }
  current->Answered = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::SendResponse()
{
  vtkInternals& internals = *this->Internals;
  if (internals.InEvent)
  {
    internals.InEvent->Answered = true; // sent when the observer returns
    return true;
  }
  if (internals.Pendings.empty() || !internals.Server)
  {
    vtkErrorMacro("SendResponse: no request is pending");
    return false;
  }
  vtkInternals::Pending pending = std::move(internals.Pendings.front());
  internals.Pendings.pop_front();
  if (!internals.Server->send_response(pending.Id, pending.Response.get()))
  {
    vtkWarningMacro(
      "SendResponse " << this->GetServiceName() << ": the client's reply reader is gone");
    return false;
  }
  ++internals.Responses;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::SendResponseYAML(const char* yaml)
{
  return this->SetResponseYAML(yaml) && this->SendResponse();
}

//------------------------------------------------------------------------------
int vtkROS2ServiceServerNode::ProcessRequests()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Server)
  {
    return 0;
  }
  int handled = 0;
  const uint64_t rejected = internals.Server->rejected_count();
  if (rejected > internals.RejectedSeen)
  {
    vtkErrorMacro("service " << this->GetServiceName() << ": "
                             << (rejected - internals.RejectedSeen)
                             << " malformed request(s) rejected ("
                             << internals.Server->last_rejection() << ")");
    internals.RejectedSeen = rejected;
    this->Modified();
    ++handled;
  }
  std::vector<ros2vtk::wire::ServiceRequest> requests;
  internals.Server->take(requests);
  const ros2vtk::wire::MessageTypeSupport& responseType = *internals.Type->response();
  for (auto& request : requests)
  {
    internals.Pendings.emplace_back();
    vtkInternals::Pending& pending = internals.Pendings.back();
    pending.Id = request.id;
    pending.Request = std::move(request.request);
    pending.Response = MessagePtr(&responseType, responseType.create());
    pending.Received = Clock::now();
    ++internals.Requests;
    ++handled;
    internals.InEvent = &pending;
    this->InvokeEvent(RequestReceivedEvent);
    internals.InEvent = nullptr;
    if (!internals.Server)
    {
      return handled; // an observer removed the node
    }
    if (pending.Answered)
    {
      if (internals.Server->send_response(pending.Id, pending.Response.get()))
      {
        ++internals.Responses;
      }
      else
      {
        vtkWarningMacro(
          "service " << this->GetServiceName() << ": the client's reply reader is gone");
      }
      internals.Pendings.pop_back();
    }
  }
  // Requests left unanswered past the timeout.
  const auto timeout = std::chrono::duration_cast<Clock::duration>(
    std::chrono::duration<double>(this->EndpointTimeout));
  const Clock::time_point now = Clock::now();
  while (!internals.Pendings.empty() && now - internals.Pendings.front().Received >= timeout)
  {
    vtkInternals::Pending pending = std::move(internals.Pendings.front());
    internals.Pendings.pop_front();
    ++internals.Unanswered;
    ++handled;
    if (internals.AnswerWithDefault)
    {
      vtkWarningMacro("service " << this->GetServiceName() << ": request unanswered after "
                                 << this->EndpointTimeout << " s, sending the default response");
      MessagePtr blank(&responseType, responseType.create());
      internals.Server->send_response(pending.Id, blank.get());
    }
    else
    {
      vtkErrorMacro("service " << this->GetServiceName() << ": request unanswered after "
                               << this->EndpointTimeout << " s, dropped without a response");
    }
  }
  if (handled)
  {
    this->Modified();
  }
  return handled;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceServerNode::SetAnswerUnansweredWithDefault(bool answer)
{
  this->Internals->AnswerWithDefault = answer;
  this->Modified();
}

bool vtkROS2ServiceServerNode::GetAnswerUnansweredWithDefault() const
{
  return this->Internals->AnswerWithDefault;
}

int vtkROS2ServiceServerNode::GetNumberOfPendingRequests() const
{
  return static_cast<int>(this->Internals->Pendings.size());
}

vtkTypeInt64 vtkROS2ServiceServerNode::GetNumberOfRequests() const
{
  return this->Internals->Requests;
}

vtkTypeInt64 vtkROS2ServiceServerNode::GetNumberOfResponses() const
{
  return this->Internals->Responses;
}

vtkTypeInt64 vtkROS2ServiceServerNode::GetNumberOfUnansweredRequests() const
{
  return this->Internals->Unanswered;
}

vtkTypeInt64 vtkROS2ServiceServerNode::GetNumberOfRejectedRequests() const
{
  return this->Internals->Server
    ? static_cast<vtkTypeInt64>(this->Internals->Server->rejected_count())
    : 0;
}

std::string vtkROS2ServiceServerNode::GetLastRejection() const
{
  return this->Internals->Server ? this->Internals->Server->last_rejection() : std::string();
}

//------------------------------------------------------------------------------
void vtkROS2ServiceServerNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  element->SetIntAttribute(
    "answerUnansweredWithDefault", this->Internals->AnswerWithDefault ? 1 : 0);
}

//------------------------------------------------------------------------------
bool vtkROS2ServiceServerNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  int answer = 1;
  if (element->GetScalarAttribute("answerUnansweredWithDefault", answer))
  {
    this->Internals->AnswerWithDefault = answer != 0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2ServiceServerNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Requests: " << this->Internals->Requests << "\n";
  os << indent << "Responses: " << this->Internals->Responses << "\n";
  os << indent << "PendingRequests: " << this->Internals->Pendings.size() << "\n";
}

//------------------------------------------------------------------------------
// vtkROS2NodeNode's SlicerROS2 methods for this kind (CreateAndAdd…, Get…, RemoveAndDelete…)
// live with the kind, so that the ROS node's own file includes no child kind
// (docs/architecture.md).
//------------------------------------------------------------------------------
vtkROS2ServiceServerNode* vtkROS2NodeNode::CreateAndAddServiceServerNode(
  const char* type, const char* service)
{
  vtkNew<vtkROS2ServiceServerNode> node;
  const bool attached = this->AdoptKeyedChild("CreateAndAddServiceServerNode", ServiceServerRole,
    node, type, service, "service", "this node serves ",
    "ros2:server:", [&] { return node->Attach(this, type, service); });
  return attached ? node.GetPointer() : nullptr; // the scene holds it
}

//------------------------------------------------------------------------------
vtkROS2ServiceServerNode* vtkROS2NodeNode::GetServiceServerNodeByService(const char* service)
{
  return vtkROS2ServiceServerNode::SafeDownCast(this->FindChildByName(ServiceServerRole, service));
}

//------------------------------------------------------------------------------
bool vtkROS2NodeNode::RemoveAndDeleteServiceServerNode(const char* service)
{
  return this->RemoveKeyedChild(
    "RemoveAndDeleteServiceServerNode", ServiceServerRole, service, "no server of ");
}
