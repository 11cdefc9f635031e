// ros2vtk — draws point-cloud subscribers (any subscriber node whose messages convert to
// vtkPoints, e.g. sensor_msgs/PointCloud, or to vtkPolyData, e.g. PointCloud2 with its fields
// as point data) as points at their pose ("transform" reference), coloured by their active
// scalars when they have some, else in the node's colour attribute "ros2vtk.display.color"
// ("r g b", 0..1; default light green). A vtkPolyData with lines, polygons or strips (e.g. a
// visualization_msgs/MarkerArray subscriber: every kept marker as a shape) is drawn as it is,
// surfaces filled, in its unsigned char RGBA "Color" scalars when it has them. Labels in its field
// data (a MarkerArray's TEXT_VIEW_FACING markers: ros2vtk::convert's kLabel* arrays) are drawn
// as text facing the camera (vtkFollower of vtkVectorText, capitals as high as the label's
// height, in its colour). The prop is a vtkPropAssembly: the actor first, then the labels.
#ifndef vtkROS2PointCloudDisplayableManager_h
#define vtkROS2PointCloudDisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro
#include "vtkROS2DisplayableManager.h"

class vtkMatrix4x4;

class ROS2VTKDISPLAY_EXPORT vtkROS2PointCloudDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static vtkROS2PointCloudDisplayableManager* New();
  vtkTypeMacro(vtkROS2PointCloudDisplayableManager, vtkROS2DisplayableManager);

  bool CanDisplay(vtkROS2SceneNode* node) override;

protected:
  vtkROS2PointCloudDisplayableManager() = default;
  ~vtkROS2PointCloudDisplayableManager() override = default;

  vtkProp* CreateProp(vtkROS2SceneNode* node) override;
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override;
  void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) override;

  /// One follower per label of the newest message (the Text markers' LabelText field arrays of
  /// ros2vtk::convert), after the actor in the node's assembly; PlaceLabels puts them where the
  /// node's pose (`toWorld`) takes their positions.
  void UpdateLabels(vtkROS2SceneNode* node, vtkProp* prop);
  void PlaceLabels(vtkROS2SceneNode* node, vtkProp* prop, vtkMatrix4x4* toWorld);

private:
  vtkROS2PointCloudDisplayableManager(const vtkROS2PointCloudDisplayableManager&) = delete;
  void operator=(const vtkROS2PointCloudDisplayableManager&) = delete;
};

#endif
