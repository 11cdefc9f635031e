// ros2vtk — a client of one ROS 2 service of any .srv type (SlicerROS2's service client node).
//
//   client = rosNode.CreateAndAddServiceClientNode("std_srvs/srv/SetBool", "/enable")
//   client.SetRequestField("data", "true")     # or SetRequestYAML("{data: true}")
//   client.SendAsyncRequest()                  # the answer arrives on a later Spin:
//   # ResponseReceivedEvent (GetLastResponseYAML / GetResponseField) or
//   # RequestFailedEvent (GetLastError: timeout, no server)
//   yaml = client.Call("{data: true}", 2.0)    # scripts: spins the ROS node until answered
//
// Requests and responses are YAML or single fields through the type's introspection table, so
// one class serves every generated service type. A request sent while no server is there waits
// (up to the timeout) until one appears: requests are volatile, one written before the server
// matched would be lost.
#ifndef vtkROS2ServiceClientNode_h
#define vtkROS2ServiceClientNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2EndpointNode.h"

#include "vtkCommand.h"       // for vtkCommand::UserEvent
#include "vtkWrappingHints.h" // for VTK_NEWINSTANCE

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2Message;
class vtkROS2NodeNode;

class ROS2VTKSCENE_EXPORT vtkROS2ServiceClientNode : public vtkROS2EndpointNode
{
public:
  static vtkROS2ServiceClientNode* New();
  vtkTypeMacro(vtkROS2ServiceClientNode, vtkROS2EndpointNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    /// A response arrived (fired on the Spin that took it, after ModifiedEvent).
    ResponseReceivedEvent = vtkCommand::UserEvent + 70,
    /// A request timed out or could not be sent; GetLastError says why.
    RequestFailedEvent = vtkCommand::UserEvent + 71
  };

  /// Where the latest request stands.
  enum CallStatus
  {
    Idle = 0,
    WaitingForServer,
    WaitingForResponse,
    Succeeded,
    TimedOut,
    Failed
  };

  /// "/enable" (resolved) and "std_srvs/srv/SetBool".
  const char* GetServiceName() const { return this->GetEndpointName(); }
  const char* GetServiceType() const { return this->GetEndpointType(); }
  /// True while a server's request reader and reply writer are matched.
  bool IsServiceReady() const;

  ///@{
  /// The request the next SendAsyncRequest sends; blank (defaults) until set. False with
  /// vtkErrorMacro naming the field on invalid YAML or a value that does not fit.
  bool SetRequestYAML(const char* yaml);
  std::string GetRequestYAML() const;
  bool SetRequestField(const char* path, const char* value);
  /// Back to the blank request.
  void ResetRequest();
  /// The request as a typed message object (docs/messages.md): copied in (its type must be
  /// this service's request type) or out.
  bool SetRequestObject(vtkROS2Message* request);
  bool GetRequestObject(vtkROS2Message* request) const;
  ///@}

  /// Seconds a request may wait for a server and its response (default 5).
  void SetTimeout(double seconds) { this->SetEndpointTimeout("SetTimeout", seconds); }
  double GetTimeout() const { return this->EndpointTimeout; }

  /// Sends the request set above; the response or the failure arrives on a later Spin of the
  /// ROS node. Returns the request's id (> 0), or -1 when not attached to a created ROS node.
  vtkTypeInt64 SendAsyncRequest();
  /// SetRequestYAML then SendAsyncRequest (-1 on invalid YAML).
  vtkTypeInt64 SendAsyncRequestYAML(const char* yaml);

  /// For scripts: sends `requestYAML` and spins every ROS node of the scene (everything on
  /// them keeps working, a server of this process answers too) until the response or
  /// `timeoutSeconds` (<= 0: GetTimeout()). Returns the response YAML, or
  /// "" with GetLastError saying why (timeout, no server, invalid YAML).
  std::string Call(const char* requestYAML, double timeoutSeconds = -1.0);

  int GetStatus() const;
  /// "idle", "waiting for server", "waiting for response", "succeeded", "timed out", "failed".
  const char* GetStatusAsString() const;
  /// Why the latest request failed ("" otherwise).
  const char* GetLastError() const;
  /// The newest response (blank before the first one), as YAML or one field.
  std::string GetLastResponseYAML() const;
  std::string GetResponseField(const char* path) const;
  /// The newest response as a typed message object; false before the first.
  bool GetLastResponseObject(vtkROS2Message* response) const;
  /// Id of the request the newest response answers.
  vtkTypeInt64 GetLastResponseRequestId() const;
  /// Requests sent and not yet answered or failed.
  int GetNumberOfPendingRequests() const;
  vtkTypeInt64 GetNumberOfResponses() const;
  vtkTypeInt64 GetNumberOfFailures() const;

  ///@{
  /// SlicerROS2's spelling of the above, with requests and responses as typed message objects
  /// (vtkROS2Message, or ros2vtk.Message(_vtk=...) in Python for Get<Field>/Set<Field>):
  /// a blank request of this service's type (the caller owns it), sent with
  /// SendAsyncRequest(request) (-1 when it is not of the request type), and the newest response
  /// as an object this node owns (nullptr with a warning before the first; overwritten by the
  /// next one). GetLastResponseStatus: whether the latest request got its response.
  VTK_NEWINSTANCE vtkROS2Message* CreateBlankRequest() const;
  vtkTypeInt64 SendAsyncRequest(vtkROS2Message* request);
  vtkROS2Message* GetLastResponse();
  bool GetLastResponseStatus() const { return this->GetStatus() == Succeeded; }
  const char* GetService() const { return this->GetServiceName(); }
  const char* GetROSType() const { return this->GetServiceType(); }
  /// SendAsyncRequest calls, and those that went out (attached to a created ROS node).
  vtkTypeInt64 GetNumberOfCalls() const;
  vtkTypeInt64 GetNumberOfRequestsSent() const;
  ///@}

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: chooses the type ("pkg/srv/T" or "pkg/T"), creates the wire
  /// client on `rosNode` and registers the per-spin work. False with vtkErrorMacro otherwise.
  bool Attach(
    vtkROS2NodeNode* rosNode, const std::string& type, const std::string& service) override;
  /// Releases the wire client (the ROS node is being destroyed); the node stays in the scene.
  void Detach() override;
  /// Per Spin: takes responses, sends requests whose server appeared, fails expired ones.
  int ProcessResponses();
#endif

  /// Spin hook (vtkROS2SceneNode::OnROS2NodeSpin): takes responses.
  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    return this->ProcessResponses();
  }

protected:
  vtkROS2ServiceClientNode();
  ~vtkROS2ServiceClientNode() override;
  bool IsEndpointAttached() const override;

private:
  vtkROS2ServiceClientNode(const vtkROS2ServiceClientNode&) = delete;
  void operator=(const vtkROS2ServiceClientNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
