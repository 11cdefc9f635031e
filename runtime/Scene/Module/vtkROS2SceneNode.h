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
  const char* GetNodeReferenceID(const char* role) const { return this->GetNthNodeReferenceID(role, 0); }
  /// Resolves the reference through the scene; nullptr when not in a scene or not found.
  vtkROS2SceneNode* GetNthNodeReference(const char* role, int n) const;
  vtkROS2SceneNode* GetNodeReference(const char* role) const { return this->GetNthNodeReference(role, 0); }
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

  /// The tag used in scene files: the class name by default.
  virtual const char* GetXMLTagName() { return this->GetClassName(); }

#ifndef __VTK_WRAP__
  /// Used by vtkROS2Scene only (IDs and scene membership are the scene's to assign).
  void SetSceneAndID(vtkROS2Scene* scene, const char* id);
  /// Used by vtkROS2Scene when a referenced node is removed: drops every reference to it.
  void ForgetReferencesTo(const char* referencedNodeID);
#endif

protected:
  vtkROS2SceneNode();
  ~vtkROS2SceneNode() override;

  /// Called by SetSceneAndID when the node leaves its scene (scene == nullptr), before the
  /// scene pointer is cleared: subclasses release what they hold through the scene.
  virtual void OnRemovedFromScene() {}

  vtkROS2Scene* Scene = nullptr;
  bool SaveWithScene = true;

private:
  vtkROS2SceneNode(const vtkROS2SceneNode&) = delete;
  void operator=(const vtkROS2SceneNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
