// ros2vtk — base class of every node of a vtkROS2Scene (the MRML node contract, in small).
//
// A scene node has an ID unique in its scene (given by the scene when the node is added, like
// MRML: `<ClassName><n>`), a free-form Name, string attributes, and references to other nodes of
// the same scene by role (stored as IDs, resolved through the scene, so saving and restoring a
// scene keeps them). Property changes fire ModifiedEvent. Subclasses add their properties to
// WriteXML/ReadXML so the scene can be saved and restored.
#ifndef vtkROS2SceneNode_h
#define vtkROS2SceneNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkObject.h"

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string (child keys)
#include <vector> // for std::vector (role lists)

class vtkROS2NodeNode;
class vtkROS2Scene;
class vtkXMLDataElement;

class ROS2VTKSCENE_EXPORT vtkROS2SceneNode : public vtkObject
{
public:
  vtkTypeMacro(vtkROS2SceneNode, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Unique in the scene; empty until the node is added to a scene.
  const char* GetID() const;
  /// A user-visible label (not unique). Fires ModifiedEvent when it changes.
  void SetName(const char* name);
  const char* GetName() const;

  /// The scene this node belongs to (not owned; nullptr when not in a scene).
  vtkROS2Scene* GetScene() const { return this->Scene; }

  /// Free-form string attributes, saved with the scene. GetAttribute returns nullptr when unset.
  void SetAttribute(const char* name, const char* value);
  const char* GetAttribute(const char* name) const;
  void RemoveAttribute(const char* name);
  /// Space-separated attribute names, sorted.
  const char* GetAttributeNames();

  /// References to other nodes of the scene by role (MRML: SetNodeReferenceID). Setting an
  /// empty/null ID removes the references of the role. Several references per role are kept
  /// in order (AddNodeReferenceID).
  void SetNodeReferenceID(const char* role, const char* referencedNodeID);
  void AddNodeReferenceID(const char* role, const char* referencedNodeID);
  void RemoveNodeReferenceID(const char* role, const char* referencedNodeID);
  void RemoveNodeReferenceIDs(const char* role);
  int GetNumberOfNodeReferences(const char* role) const;
  /// nullptr when there is no n-th reference of the role.
  const char* GetNthNodeReferenceID(const char* role, int n) const;
  const char* GetNodeReferenceID(const char* role) const
  {
    return this->GetNthNodeReferenceID(role, 0);
  }
  /// Resolves the reference through the scene; nullptr when not in a scene or not found.
  vtkROS2SceneNode* GetNthNodeReference(const char* role, int n) const;
  vtkROS2SceneNode* GetNodeReference(const char* role) const
  {
    return this->GetNthNodeReference(role, 0);
  }
  /// Space-separated roles that hold at least one reference, sorted.
  const char* GetNodeReferenceRoles();

  /// Whether the node goes into scene files (MRML's SaveWithScene). Off for nodes that are
  /// rebuilt from another node's state (a robot's links and models): references to such nodes
  /// are left out of the file too. On by default.
  void SetSaveWithScene(bool save) { this->SaveWithScene = save; }
  bool GetSaveWithScene() const { return this->SaveWithScene; }

  /// Serializes the node's properties (ID, name, attributes, references, then the subclass's
  /// own) into `element`. Subclasses call Superclass::WriteXML first.
  virtual void WriteXML(vtkXMLDataElement* element);
  /// Reads what WriteXML wrote. Returns false (with vtkErrorMacro) on invalid content.
  /// The ID in the element is applied by the scene, not here.
  virtual bool ReadXML(vtkXMLDataElement* element);

  /// Called by vtkROS2Scene after every node of a restored file has been read and added, so
  /// that nodes can act on references (e.g. a publisher re-attaches to its ROS node).
  virtual void OnSceneRestored() {}

  ///@{
  /// Children of a ROS node (publishers, lookups, robots, ...) reference it under this one role
  /// (MRML style, like vtkMRMLTransformableNode::TransformNodeReferenceRole). Scene files of
  /// earlier versions also spelled it LegacyROS2NodeReferenceRole ("ROS2Node"); ReadXML reads
  /// both into the one role.
  static const char* const ROS2NodeReferenceRole;
  static const char* const LegacyROS2NodeReferenceRole;
  ///@}
  /// The ROS node this node belongs to (its ROS2NodeReferenceRole reference), or nullptr.
  /// Defined in vtkROS2NodeNode.cxx so that this base class needs no header of a subclass.
  vtkROS2NodeNode* GetROS2Node() const;
  /// Whether it belongs to a ROS node (SlicerROS2's name, on every kind).
  bool IsAddedToROS2Node() const { return this->GetROS2Node() != nullptr; }

  /// The per-spin hook: vtkROS2NodeNode::Spin calls it on each of its children, role by role in
  /// the documented order (tf lookups, subscribers, parameters, services, robots, then any
  /// other kind; docs/architecture.md). Returns how many items it handled. Does nothing by
  /// default.
  virtual int OnROS2NodeSpin(vtkROS2NodeNode* rosNode);
  /// Called by vtkROS2NodeNode::Destroy on each child before its participant goes: a child
  /// whose endpoints live in the participant (topics, services) releases them here; the node
  /// stays in the scene. Does nothing by default.
  virtual void OnROS2NodeDestroyed(vtkROS2NodeNode* rosNode);

  /// The key that makes this node unique among its ROS node's children of the same role
  /// (topic, "parent<newline>child" frame pair, monitored node, robot name, service name);
  /// empty for nodes that are not looked up by key. The ROS node indexes its children by it.
  virtual std::string GetROS2NodeChildKey() const { return std::string(); }

  /// Takes the content of a received message (a subscriber's target node, SlicerROS2's
  /// SetTargetNodeID): a model node copies a vtkPolyData, a transform node a vtkMatrix4x4.
  /// False with `error` saying what this kind accepts, by default.
  virtual bool CopyContentFrom(vtkObject* data, std::string* error);

  /// The tag used in scene files: the class name by default.
  virtual const char* GetXMLTagName() { return this->GetClassName(); }

#ifndef __VTK_WRAP__
  /// Used by vtkROS2Scene only (IDs and scene membership are the scene's to assign). When the
  /// node leaves, `leftBecause` says why if it was not a plain removal (kept for error messages).
  void SetSceneAndID(
    vtkROS2Scene* scene, const char* id, const std::string& leftBecause = std::string());
  /// Why this node left its scene when that was not a plain removal ("" otherwise), e.g. the
  /// logic that owned the scene was deleted: errors about a missing scene quote it.
  const std::string& GetLeftSceneBecause() const
  {
    return this->LeftSceneBecause;
  }
  /// Used by vtkROS2Scene when a referenced node is removed: drops every reference to it.
  void ForgetReferencesTo(const char* referencedNodeID);
  /// Grows by one on every change of this node's references (or of a referenced child's key,
  /// see ROS2NodeChildKeyChanged): indexes built over the references compare it to know they
  /// are current.
  unsigned long GetReferencesVersion() const
  {
    return this->ReferencesVersion;
  }
  /// The roles that hold at least one reference, sorted (GetNodeReferenceRoles as a list).
  void GetNodeReferenceRoleList(std::vector<std::string>& roles) const;
#endif

protected:
  vtkROS2SceneNode();
  ~vtkROS2SceneNode() override;

  /// Called by SetSceneAndID when the node leaves its scene (scene == nullptr), before the
  /// scene pointer is cleared: subclasses release what they hold through the scene.
  virtual void OnRemovedFromScene() {}

  /// Subclasses whose GetROS2NodeChildKey can change while they belong to a ROS node call this
  /// so that the ROS node's index of its children is rebuilt.
  void ROS2NodeChildKeyChanged();

  vtkROS2Scene* Scene = nullptr;
  bool SaveWithScene = true;
  std::string LeftSceneBecause;
  unsigned long ReferencesVersion = 0;

private:
  vtkROS2SceneNode(const vtkROS2SceneNode&) = delete;
  void operator=(const vtkROS2SceneNode&) = delete;
#ifndef __VTK_WRAP__
  /// Tells the scene (if any) that this node refers to `referencedNodeID`
  /// (vtkROS2Scene::NoteReferrer).
  void NoteReferenceInScene(const std::string& referencedNodeID);
#endif

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
