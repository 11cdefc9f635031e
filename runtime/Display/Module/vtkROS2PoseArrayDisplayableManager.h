// ros2vtk — draws pose-array subscribers (any subscriber node whose messages convert to a
// vtkTransformCollection, e.g. geometry_msgs/PoseArray) as one arrow per pose along its x axis,
// as RViz 2 does, at the node's pose ("transform" reference). Arrow length: the display
// manager's ArrowLength.
#ifndef vtkROS2PoseArrayDisplayableManager_h
#define vtkROS2PoseArrayDisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro
#include "vtkROS2DisplayableManager.h"

class ROS2VTKDISPLAY_EXPORT vtkROS2PoseArrayDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static vtkROS2PoseArrayDisplayableManager* New();
  vtkTypeMacro(vtkROS2PoseArrayDisplayableManager, vtkROS2DisplayableManager);

  bool CanDisplay(vtkROS2SceneNode* node) override;

protected:
  vtkROS2PoseArrayDisplayableManager() = default;
  ~vtkROS2PoseArrayDisplayableManager() override = default;

  vtkProp* CreateProp(vtkROS2SceneNode* node) override;
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override;
  void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) override;

private:
  vtkROS2PoseArrayDisplayableManager(const vtkROS2PoseArrayDisplayableManager&) = delete;
  void operator=(const vtkROS2PoseArrayDisplayableManager&) = delete;
};

#endif
