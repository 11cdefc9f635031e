// ros2vtk — draws model nodes (vtkROS2ModelNode: robot link visuals, phantoms, any surface) as
// actors under their transform hierarchy, with the node's display properties (visibility,
// colour, opacity, representation, scalar visibility). Link status shows: a model whose
// transform is a tf lookup that is not tracking is drawn in the display manager's untracked
// colour, and a placeholder (attribute ros2vtk.placeholder, a mesh that did not load) as a
// wireframe in the placeholder colour.
#ifndef vtkROS2ModelDisplayableManager_h
#define vtkROS2ModelDisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro
#include "vtkROS2DisplayableManager.h"

class ROS2VTKDISPLAY_EXPORT vtkROS2ModelDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static vtkROS2ModelDisplayableManager* New();
  vtkTypeMacro(vtkROS2ModelDisplayableManager, vtkROS2DisplayableManager);

  bool CanDisplay(vtkROS2SceneNode* node) override;

  /// Whether the model's transform is an untracked tf lookup (its status is not "ok"), looking
  /// up the transform hierarchy.
  static bool IsUntracked(vtkROS2SceneNode* node);
  /// Whether the model stands in for a mesh that did not load.
  static bool IsPlaceholder(vtkROS2SceneNode* node);

protected:
  vtkROS2ModelDisplayableManager() = default;
  ~vtkROS2ModelDisplayableManager() override = default;

  vtkProp* CreateProp(vtkROS2SceneNode* node) override;
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override;
  void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) override;

private:
  vtkROS2ModelDisplayableManager(const vtkROS2ModelDisplayableManager&) = delete;
  void operator=(const vtkROS2ModelDisplayableManager&) = delete;
};

#endif
