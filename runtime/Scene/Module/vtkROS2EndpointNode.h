// ros2vtk — abstract base of the ROS node's children that are one named service or action
// endpoint: vtkROS2ServiceClientNode, vtkROS2ServiceServerNode, vtkROS2ActionClientNode,
// vtkROS2ActionServerNode (topics have vtkROS2TopicNode).
//
// What the four share lives here once: the type and name as given (saved in scene files as
// `<kind>Type` / `<kind>Name`, e.g. serviceType / actionName), the resolved name once attached,
// the key they are indexed by in their ROS node (that name), and the life cycle: released when the
// ROS node is destroyed or the node leaves the scene, attached again when a scene file is
// restored. Each subclass keeps its public SlicerROS2 names (GetServiceName, GetActionType…).
#ifndef vtkROS2EndpointNode_h
#define vtkROS2EndpointNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2SceneNode.h"

#include <string> // for std::string

class vtkROS2NodeNode;

class ROS2VTKSCENE_EXPORT vtkROS2EndpointNode : public vtkROS2SceneNode
{
public:
  vtkTypeMacro(vtkROS2EndpointNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Saves and reads the type and name attributes (and the timeout, for kinds that have one).
  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  /// Attaches again to the ROS node of a restored file (when it is created).
  void OnSceneRestored() override;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: chooses the type, creates the wire endpoints on `rosNode`. False
  /// with vtkErrorMacro otherwise.
  virtual bool Attach(
    vtkROS2NodeNode* rosNode, const std::string& type, const std::string& name) = 0;
  /// Releases the wire endpoints (the ROS node is being destroyed or the node leaves the
  /// scene); the node keeps its type and name.
  virtual void Detach() = 0;
#endif

  /// Destroy hook: the wire endpoints live in the participant
  /// (vtkROS2SceneNode::OnROS2NodeDestroyed).
  void OnROS2NodeDestroyed(vtkROS2NodeNode*) override
  {
    this->Detach();
  }
  /// Index key among the ROS node's children of the same kind: the (resolved) name.
  std::string GetROS2NodeChildKey() const override
  {
    return this->GetEndpointName();
  }

protected:
  /// `kind` names the XML attributes (`<kind>Type`, `<kind>Name`) and PrintSelf's labels;
  /// `timeoutAttribute` is the attribute of the endpoint's timeout, nullptr for a kind without one.
  vtkROS2EndpointNode(const char* kind, const char* timeoutAttribute);
  ~vtkROS2EndpointNode() override;
  void OnRemovedFromScene() override;

  /// Whether the wire endpoints exist (between a successful Attach and Detach).
  virtual bool IsEndpointAttached() const = 0;
  /// For Attach, once the wire endpoints exist: records the type's ROS name, the name as given
  /// and as resolved, and references `rosNode`.
  void EndpointAttached(vtkROS2NodeNode* rosNode, const char* type, const std::string& name,
    const std::string& resolved);

  /// The resolved name while attached, else the name as given; the type's ROS name.
  const char* GetEndpointName() const;
  const char* GetEndpointType() const
  {
    return this->EndpointType.c_str();
  }

  ///@{
  /// The endpoint's timeout in seconds (default 5; clients: waiting for a server and its
  /// answer, servers: for the observer's answer). The setter refuses what is not a positive
  /// finite number (vtkErrorMacro naming `method`) and fires ModifiedEvent on a change.
  void SetEndpointTimeout(const char* method, double seconds);
  double EndpointTimeout = 5.0;
  ///@}

private:
  vtkROS2EndpointNode(const vtkROS2EndpointNode&) = delete;
  void operator=(const vtkROS2EndpointNode&) = delete;

  std::string Kind;             // "service" or "action"
  const char* TimeoutAttribute; // nullptr: not saved
  std::string EndpointType;     // as given, then the type's ROS name (saved with the scene)
  std::string Name;             // as given (saved with the scene)
  std::string ResolvedName;     // once attached
};

#endif
