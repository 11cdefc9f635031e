// ros2vtk — a server of one ROS 2 service of any .srv type, answered by observers.
//
//   server = rosNode.CreateAndAddServiceServerNode("std_srvs/srv/SetBool", "/enable")
//   def on_request(caller, event):
//       enable = caller.GetRequestField("data") == "true"
//       caller.SetResponseYAML("{success: true, message: 'enabled'}")
//   server.AddObserver(vtkROS2ServiceServerNode.RequestReceivedEvent, on_request)
//
// Each request fires RequestReceivedEvent on the Spin that takes it; the observer fills the
// response (YAML or fields) and it is sent when the observer returns. A request the observer
// leaves unanswered stays pending (SendResponse answers the oldest later) until the response
// timeout: then it is answered with the default response (SetAnswerUnansweredWithDefault, on
// by default) or dropped, with a logged warning or error either way.
#ifndef vtkROS2ServiceServerNode_h
#define vtkROS2ServiceServerNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2EndpointNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2Message;
class vtkROS2NodeNode;

class ROS2VTKSCENE_EXPORT vtkROS2ServiceServerNode : public vtkROS2EndpointNode
{
public:
  static vtkROS2ServiceServerNode* New();
  vtkTypeMacro(vtkROS2ServiceServerNode, vtkROS2EndpointNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    /// A request arrived: read it and fill the response in the observer.
    RequestReceivedEvent = vtkCommand::UserEvent + 72
  };

  /// "/enable" (resolved) and "std_srvs/srv/SetBool".
  const char* GetServiceName() const { return this->GetEndpointName(); }
  const char* GetServiceType() const { return this->GetEndpointType(); }

  ///@{
  /// The request being handled: the one whose event is firing, else the oldest pending one.
  std::string GetRequestYAML() const;
  std::string GetRequestField(const char* path) const;
  /// The same request as a typed message object (docs/messages.md).
  bool GetRequestObject(vtkROS2Message* request) const;
  ///@}

  ///@{
  /// Fills the response to the request being handled (starts from the default response).
  /// Inside the event the response is sent when the observer returns. False with vtkErrorMacro
  /// on invalid YAML / a value that does not fit, or when no request is being handled.
  bool SetResponseYAML(const char* yaml);
  bool SetResponseField(const char* path, const char* value);
  /// The whole response from a typed message object of the service's response type.
  bool SetResponseObject(vtkROS2Message* response);
  ///@}

  /// Outside the event: sends the response filled so far for the oldest pending request.
  bool SendResponse();
  /// SetResponseYAML then SendResponse.
  bool SendResponseYAML(const char* yaml);

  /// Seconds a request may stay unanswered (default 5).
  void SetResponseTimeout(double seconds)
  {
    this->SetEndpointTimeout("SetResponseTimeout", seconds);
  }
  double GetResponseTimeout() const { return this->EndpointTimeout; }
  /// What happens to a request unanswered at the timeout: the default response (true, a
  /// warning is logged) or no response at all (false, an error is logged).
  void SetAnswerUnansweredWithDefault(bool answer);
  bool GetAnswerUnansweredWithDefault() const;

  int GetNumberOfPendingRequests() const;
  vtkTypeInt64 GetNumberOfRequests() const;
  vtkTypeInt64 GetNumberOfResponses() const;
  /// Requests that timed out unanswered.
  vtkTypeInt64 GetNumberOfUnansweredRequests() const;
  /// Malformed requests rejected by the deserializer, and why the newest was.
  vtkTypeInt64 GetNumberOfRejectedRequests() const;
  std::string GetLastRejection() const;

  /// Saves and reads answerUnansweredWithDefault (the rest: vtkROS2EndpointNode).
  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: see vtkROS2ServiceClientNode::Attach.
  bool Attach(
    vtkROS2NodeNode* rosNode, const std::string& type, const std::string& service) override;
  void Detach() override;
  /// Per Spin: takes requests, fires the events, sends responses, expires unanswered requests.
  int ProcessRequests();
#endif

  /// Spin hook (vtkROS2SceneNode::OnROS2NodeSpin): answers requests.
  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    return this->ProcessRequests();
  }

protected:
  vtkROS2ServiceServerNode();
  ~vtkROS2ServiceServerNode() override;
  bool IsEndpointAttached() const override;

private:
  vtkROS2ServiceServerNode(const vtkROS2ServiceServerNode&) = delete;
  void operator=(const vtkROS2ServiceServerNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
