// ros2vtk — keeps a vtkRenderer in step with a vtkROS2Scene, with no actor code in user scripts
// (Slicer's displayable manager group, in small).
//
//   dm = ros2vtk.vtkROS2DisplayManager()
//   dm.SetScene(logic.GetScene()); dm.SetRenderer(renderer)
//   while running: logic.Spin(); if dm.Update(): renderWindow.Render()
//
// It observes the scene (nodes added and removed) and each node (ModifiedEvent,
// TransformModifiedEvent); the observers only note what changed, Update() applies it. Every node
// kind is drawn by a displayable manager (one small class per kind: models, transforms, images,
// point clouds, pose arrays); the first registered manager that CanDisplay() a node draws it, and
// a new kind is one class plus RegisterDisplayableManagerClass(). Scene events fire on the thread
// that spins the scene, so the renderer is only touched there: never from DDS threads.
#ifndef vtkROS2DisplayManager_h
#define vtkROS2DisplayManager_h

#include "ros2vtkDisplayModule.h" // for export macro

#include "vtkObject.h"

#include <memory> // for std::unique_ptr (pimpl)

class vtkActor;
class vtkProp;
class vtkRenderer;
class vtkROS2DisplayableManager;
class vtkROS2Scene;
class vtkROS2SceneNode;

class ROS2VTKDISPLAY_EXPORT vtkROS2DisplayManager : public vtkObject
{
public:
  static vtkROS2DisplayManager* New();
  vtkTypeMacro(vtkROS2DisplayManager, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The scene drawn (observed, not owned). Setting it queues every node already in it.
  void SetScene(vtkROS2Scene* scene);
  vtkROS2Scene* GetScene() const;
  /// The renderer the props go into (not owned). Props move when it changes.
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer() const;

  /// Applies the changes noted since the last call (nodes added or modified, transforms moved);
  /// returns whether anything drawn changed (render then). Cheap when nothing changed: call it
  /// after every Spin.
  bool Update();
  /// Whether changes wait for Update().
  bool IsUpdatePending() const;

  /// Transform nodes show an axes glyph (x red, y green, z blue) with their frame name. Off by
  /// default.
  void SetAxesVisible(bool visible);
  bool GetAxesVisible() const { return this->AxesVisible; }
  vtkBooleanMacro(AxesVisible, bool);
  /// Length of each axis of the glyph, in scene units (mm). Default 50.
  void SetAxesLength(double length);
  vtkGetMacro(AxesLength, double);
  /// Length of a PoseArray arrow, in scene units (mm). Default 50.
  void SetArrowLength(double length);
  vtkGetMacro(ArrowLength, double);
  /// Point size of point clouds, in pixels. Default 3.
  void SetPointSize(double size);
  vtkGetMacro(PointSize, double);

  /// Colour of a model whose transform is an untracked tf lookup (it failed, or never worked),
  /// unless its robot places the link from joint positions (a robot at its zero configuration is
  /// still untracked). Default red (1, 0.1, 0.1).
  void SetUntrackedColor(double r, double g, double b);
  vtkGetVector3Macro(UntrackedColor, double);
  /// Colour of a placeholder (a robot visual whose mesh did not load); drawn as a wireframe.
  /// Default magenta (1, 0, 1).
  void SetPlaceholderColor(double r, double g, double b);
  vtkGetVector3Macro(PlaceholderColor, double);

  /// Nodes that have a prop in the renderer (hidden axes glyphs included).
  int GetNumberOfDisplayedNodes() const;
  /// The prop drawing `node` (vtkActor, vtkImageActor, vtkVolume or vtkPropAssembly), or nullptr.
  vtkProp* GetPropForNode(vtkROS2SceneNode* node) const;
  /// The prop as a vtkActor (models, point clouds, pose arrays; of an assembly, its first part: a
  /// shape subscriber's actor before its labels), or nullptr.
  vtkActor* GetActorForNode(vtkROS2SceneNode* node) const;
  /// The node a picked prop draws (the prop or a part of it), or nullptr: click-to-select.
  vtkROS2SceneNode* GetNodeForProp(vtkProp* prop) const;
  /// The displayable manager that draws `node`, or nullptr.
  vtkROS2DisplayableManager* GetDisplayableManagerForNode(vtkROS2SceneNode* node) const;

  /// The displayable managers, in the order they are asked (registered classes first).
  int GetNumberOfDisplayableManagers() const;
  vtkROS2DisplayableManager* GetNthDisplayableManager(int n) const;
  /// Adds a displayable manager to this display manager only (asked after those already there).
  void AddDisplayableManager(vtkROS2DisplayableManager* manager);

#ifndef __VTK_WRAP__
  /// Every display manager made afterwards gets one of these, in registration order. The
  /// built-in kinds are registered first.
  using DisplayableManagerFactory = vtkROS2DisplayableManager* (*)();
  static void RegisterDisplayableManagerClass(DisplayableManagerFactory factory);
#endif

protected:
  vtkROS2DisplayManager();
  ~vtkROS2DisplayManager() override;

  bool AxesVisible = false;
  double AxesLength = 50.0;
  double ArrowLength = 50.0;
  double PointSize = 3.0;
  double UntrackedColor[3] = { 1.0, 0.1, 0.1 };
  double PlaceholderColor[3] = { 1.0, 0.0, 1.0 };

private:
  vtkROS2DisplayManager(const vtkROS2DisplayManager&) = delete;
  void operator=(const vtkROS2DisplayManager&) = delete;

  void OnSceneEvent(vtkObject* caller, unsigned long event, void* callData);
  void OnNodeEvent(vtkObject* caller, unsigned long event, void* callData);
  void ObserveNode(vtkROS2SceneNode* node);
  void ForgetNode(vtkROS2SceneNode* node);
  /// Shared settings changed: every prop is refilled on the next Update.
  void SettingsChanged();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
