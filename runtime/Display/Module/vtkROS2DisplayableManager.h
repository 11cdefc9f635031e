// ros2vtk — base class of the displayable managers: one subclass per kind of scene node it
// draws (Slicer's vtkMRMLAbstractDisplayableManager, in small).
//
// vtkROS2DisplayManager asks every registered displayable manager whether it CanDisplay() a
// node; the first that can owns the node's prop. The base class keeps the node -> prop map and
// puts the props into the renderer; a subclass says how to make a prop (CreateProp), how to fill
// it from the node's content (UpdateProp: new polydata, colour, a new message) and where to put
// it (UpdatePose: world matrix, link status). Everything runs on the thread that spins the
// scene; nothing here is called from DDS threads.
#ifndef vtkROS2DisplayableManager_h
#define vtkROS2DisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro

#include "vtkObject.h"

#include <memory> // for std::unique_ptr (pimpl)

class vtkMatrix4x4;
class vtkProp;
class vtkRenderer;
class vtkROS2DisplayManager;
class vtkROS2SceneNode;

class ROS2VTKDISPLAY_EXPORT vtkROS2DisplayableManager : public vtkObject
{
public:
  vtkTypeMacro(vtkROS2DisplayableManager, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Whether this manager draws `node` (the display manager asks when a node is added).
  virtual bool CanDisplay(vtkROS2SceneNode* node) = 0;

  /// The renderer the props go into (set by the display manager; props move along).
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer() const;
  /// The display manager this one works for (not owned); gives shared settings (axes, sizes).
  void SetDisplayManager(vtkROS2DisplayManager* manager) { this->DisplayManager = manager; }
  vtkROS2DisplayManager* GetDisplayManager() const { return this->DisplayManager; }

  /// Makes the node's prop, adds it to the renderer and fills it. False when it cannot.
  bool AddNode(vtkROS2SceneNode* node);
  /// Removes the node's prop from the renderer and forgets it.
  void RemoveNode(vtkROS2SceneNode* node);
  /// Refills the node's prop from the node (content and pose).
  void UpdateNode(vtkROS2SceneNode* node);
  /// Re-places every prop (a transform somewhere changed).
  void UpdatePoses();
  /// Re-applies shared settings (axes visibility, sizes) to every prop.
  void UpdateAll();
  /// Removes every prop.
  void RemoveAllNodes();

  bool HasNode(vtkROS2SceneNode* node) const;
  int GetNumberOfNodes() const;
  /// The prop drawing `node` (a vtkActor, vtkImageActor, vtkVolume or vtkPropAssembly), or nullptr.
  vtkProp* GetPropForNode(vtkROS2SceneNode* node) const;
  /// The node a prop (or a part of an assembly prop) draws, or nullptr: for picking.
  vtkROS2SceneNode* GetNodeForProp(vtkProp* prop) const;

  /// Node -> world of a node that hangs under a transform node through the "transform"
  /// reference (identity when it has none). Used by the subclasses.
  static void GetParentTransformToWorld(vtkROS2SceneNode* node, vtkMatrix4x4* matrix);

protected:
  vtkROS2DisplayableManager();
  ~vtkROS2DisplayableManager() override;

  virtual vtkProp* CreateProp(vtkROS2SceneNode* node) = 0; // new reference
  virtual void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) = 0;
  virtual void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) = 0;

  vtkROS2DisplayManager* DisplayManager = nullptr;

private:
  vtkROS2DisplayableManager(const vtkROS2DisplayableManager&) = delete;
  void operator=(const vtkROS2DisplayableManager&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
