// ros2vtk — the scene: a container of vtkROS2SceneNode objects (MRML's vtkMRMLScene, in small).
//
// The scene owns its nodes (holds a reference), gives each a unique ID `<ClassName><n>` when it
// is added, finds nodes by ID, name or class, and fires NodeAddedEvent / NodeRemovedEvent with the
// node as call data. It saves the ROS configuration (ROS nodes, publishers and subscribers with
// topic, type and QoS, attributes, references) to an XML file and restores it.
#ifndef vtkROS2Scene_h
#define vtkROS2Scene_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkObject.h"
#include "vtkWrappingHints.h" // for VTK_NEWINSTANCE

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkCollection;
class vtkROS2SceneNode;
class vtkXMLDataElement;

class ROS2VTKSCENE_EXPORT vtkROS2Scene : public vtkObject
{
public:
  static vtkROS2Scene* New();
  vtkTypeMacro(vtkROS2Scene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Events fired by the scene; call data is the vtkROS2SceneNode* concerned. Same values as
  /// vtkMRMLScene's, so observers ported from Slicer keep their numbers.
  enum Events
  {
    NodeAddedEvent = 66000,
    NodeRemovedEvent = 66001,
  };

  /// Adds `node` (the scene keeps a reference), gives it a unique ID and fires NodeAddedEvent.
  /// Returns the node, or nullptr (vtkErrorMacro) when it is null or already in a scene.
  vtkROS2SceneNode* AddNode(vtkROS2SceneNode* node);
  /// Removes `node`, drops every reference other nodes hold to it, fires NodeRemovedEvent and
  /// releases the scene's reference. False when the node is not in this scene.
  bool RemoveNode(vtkROS2SceneNode* node);
  /// Removes every node (last added first).
  void Clear();
#ifndef __VTK_WRAP__
  /// Clear, telling each node why it left (vtkROS2SceneNode::GetLeftSceneBecause): the owner of
  /// the scene is going away, so the nodes' later errors can name the cause.
  void ClearBecause(const std::string& reason);
  /// Used by vtkROS2SceneNode when it gains a reference to `referencedNodeID`: the scene keeps
  /// who refers to each ID, so removing a node visits only its referrers (a robot of 10 000 links
  /// is some 30 000 nodes: visiting every node on each removal made closing it minutes long).
  void NoteReferrer(const std::string& referencedNodeID, vtkROS2SceneNode* referrer);
#endif

  int GetNumberOfNodes() const;
  vtkROS2SceneNode* GetNthNode(int n) const;
  vtkROS2SceneNode* GetNodeByID(const char* id) const;
  /// Changes whenever a node is added or removed: lets nodes cache what their references resolve
  /// to.
  unsigned long GetNodesVersion() const;
  /// First node (in the order they were added) with this Name; nullptr when none.
  vtkROS2SceneNode* GetFirstNodeByName(const char* name) const;
  /// Nodes of a class or of a subclass of it (vtkObject::IsA), in order, appended to `nodes`.
  void GetNodesByClass(const char* className, vtkCollection* nodes) const;
  int GetNumberOfNodesByClass(const char* className) const;
  vtkROS2SceneNode* GetNthNodeByClass(int n, const char* className) const;

  /// Creates a node of a registered class by class name (not added to the scene).
  /// nullptr (vtkErrorMacro listing the known classes) for an unknown name.
  VTK_NEWINSTANCE vtkROS2SceneNode* CreateNodeByClass(const char* className);
  /// MRML's AddNewNodeByClass: creates the node (class names as registered, SlicerROS2's
  /// vtkMRMLROS2… spelling, or Slicer's vtkMRMLModelNode / vtkMRMLLinearTransformNode /
  /// vtkMRMLTransformNode for our model and transform nodes), names it `name` when given, adds
  /// it; the scene holds it. nullptr
  /// (error listing the known classes) for an unknown class.
  vtkROS2SceneNode* AddNewNodeByClass(const char* className, const char* name = "");

  /// The scene's fixed frame, as RViz's global "Fixed Frame": the frame displays draw in when
  /// they have none of their own (marker subscribers without SetFixedFrame place their markers
  /// in it through their ROS node's tf buffer). "" (the default): none, each display draws in
  /// its own frame. Saved with the scene (attribute `fixedFrame` of the root, only when set);
  /// reading a scene file sets it from the file. Fires ModifiedEvent when it changes.
  void SetFixedFrame(const char* frame);
  const char* GetFixedFrame() const;

  /// Saves every node to an XML scene file / string. False (vtkErrorMacro) on I/O failure.
  bool WriteToXMLFile(const char* fileName);
  std::string WriteToXMLString();
  /// Replaces the scene's content by the content of a file / string written by WriteTo…:
  /// the text is parsed within bounds (64 MiB, depth 16, 100 000 elements, 256 attributes per
  /// element: SceneXmlReader), every node is created by class and read; only when all are valid
  /// is the scene cleared and the nodes added with their saved IDs, then each gets
  /// OnSceneRestored() in file order (ROS nodes are created, publishers and subscribers
  /// re-attached). False (vtkErrorMacro naming the node or the limit) on invalid content; the
  /// scene is then exactly as it was (reading is atomic).
  bool ReadFromXMLFile(const char* fileName);
  bool ReadFromXMLString(const char* xml);

protected:
  vtkROS2Scene();
  ~vtkROS2Scene() override;

private:
  vtkROS2Scene(const vtkROS2Scene&) = delete;
  void operator=(const vtkROS2Scene&) = delete;

  bool AddNodeWithID(vtkROS2SceneNode* node, const std::string& id);
  bool ReadFromXMLElement(vtkXMLDataElement* root);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
