// ros2vtk — an image held in the scene (Slicer's scalar volume node, in small): a vtkImageData
// that is not a ROS message (a CT or MRI phantom, a volume read from a file), placed under a
// transform node through the "transform" reference, with window/level. The display manager
// draws it like an image subscriber: a slice when 2D, a volume when 3D; slice views take it
// through SetVolumeNode. Not saved with the scene (its voxels are not a ROS configuration).
#ifndef vtkROS2VolumeNode_h
#define vtkROS2VolumeNode_h

#include "ros2vtkDisplayModule.h" // for export macro

#include "vtkROS2SceneNode.h"

class vtkImageData;
class vtkROS2TransformNode;

class ROS2VTKDISPLAY_EXPORT vtkROS2VolumeNode : public vtkROS2SceneNode
{
public:
  static vtkROS2VolumeNode* New();
  vtkTypeMacro(vtkROS2VolumeNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The image (referenced, not copied), in the parent transform's coordinates (mm).
  void SetImageData(vtkImageData* image);
  vtkImageData* GetImageData() const { return this->ImageData; }

  /// The transform node the image hangs under (the "transform" reference); nullptr = world.
  void SetParentTransformNodeID(const char* id);
  const char* GetParentTransformNodeID() const;
  vtkROS2TransformNode* GetParentTransformNode() const;

  /// Window and level of its display; Window <= 0 (default): the image's scalar range.
  vtkSetMacro(Window, double);
  vtkGetMacro(Window, double);
  vtkSetMacro(Level, double);
  vtkGetMacro(Level, double);
  vtkSetMacro(Visibility, bool);
  vtkGetMacro(Visibility, bool);
  vtkBooleanMacro(Visibility, bool);

protected:
  vtkROS2VolumeNode();
  ~vtkROS2VolumeNode() override;

  vtkImageData* ImageData = nullptr;
  double Window = 0.0;
  double Level = 0.0;
  bool Visibility = true;

private:
  vtkROS2VolumeNode(const vtkROS2VolumeNode&) = delete;
  void operator=(const vtkROS2VolumeNode&) = delete;
};

#endif
