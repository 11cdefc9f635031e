// ros2vtk — draws transform nodes (tf lookups, robot links, registrations) as an axes glyph
// (x red, y green, z blue) at the frame's world pose, labelled with its frame name (the tf child
// frame of a lookup, else the node name). Shown only while the display manager's AxesVisible
// is on.
#ifndef vtkROS2TransformDisplayableManager_h
#define vtkROS2TransformDisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro
#include "vtkROS2DisplayableManager.h"

class ROS2VTKDISPLAY_EXPORT vtkROS2TransformDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static vtkROS2TransformDisplayableManager* New();
  vtkTypeMacro(vtkROS2TransformDisplayableManager, vtkROS2DisplayableManager);

  bool CanDisplay(vtkROS2SceneNode* node) override;

  /// The label of a transform node: the child frame of a tf lookup, else its name.
  static const char* GetFrameName(vtkROS2SceneNode* node);

protected:
  vtkROS2TransformDisplayableManager() = default;
  ~vtkROS2TransformDisplayableManager() override = default;

  vtkProp* CreateProp(vtkROS2SceneNode* node) override;
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override;
  void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) override;

private:
  vtkROS2TransformDisplayableManager(const vtkROS2TransformDisplayableManager&) = delete;
  void operator=(const vtkROS2TransformDisplayableManager&) = delete;
};

#endif
