// ros2vtk — a 2D slice view of a volume (axial, sagittal or coronal, as Slicer's red, yellow
// and green views) with the intersection of the scene's models with the slice plane drawn on
// it, as Slicer shows a needle in a CT: each visible model node (robot links included) is put
// in world coordinates and cut by the plane (vtkCutter), in its own colour.
//
//   view = ros2vtk.vtkROS2SliceView(); view.SetRenderer(renderer)
//   view.SetScene(logic.GetScene()); view.SetImageData(ct)        # or SetVolumeNode(subscriber)
//   view.SetOrientation('axial'); view.SetSliceCenter(x, y, z)    # mm, world
//   after each Spin: if view.Update(): renderWindow.Render()
//
// An image is taken in world coordinates (its origin and spacing), a volume node under its
// transform (a registration); the view's camera looks
// along the slice normal with a parallel projection. Runs on the spinning thread, like the
// display manager.
#ifndef vtkROS2SliceView_h
#define vtkROS2SliceView_h

#include "ros2vtkDisplayModule.h" // for export macro

#include "vtkObject.h"

#include <memory> // for std::unique_ptr (pimpl)

class vtkImageData;
class vtkImageSlice;
class vtkPolyData;
class vtkRenderer;
class vtkROS2Scene;
class vtkROS2SceneNode;

class ROS2VTKDISPLAY_EXPORT vtkROS2SliceView : public vtkObject
{
public:
  static vtkROS2SliceView* New();
  vtkTypeMacro(vtkROS2SliceView, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The renderer the slice and the intersections go into (not owned); its camera is set.
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer() const;
  /// The scene whose model nodes are intersected (not owned; may be null: no intersections).
  void SetScene(vtkROS2Scene* scene);
  vtkROS2Scene* GetScene() const;

  /// "axial" (normal +z), "sagittal" (+x) or "coronal" (+y), laid out on the screen as in
  /// Slicer (world = RAS: axial and coronal show patient right on the left). False
  /// (vtkErrorMacro) otherwise.
  bool SetOrientation(const char* orientation);
  const char* GetOrientation() const;
  /// The volume shown (referenced), in world coordinates.
  void SetImageData(vtkImageData* image);
  vtkImageData* GetImageData() const;
  /// Or a vtkROS2VolumeNode, or a subscriber node whose messages convert to vtkImageData (its
  /// newest image, refreshed on each Update that follows a spin with a new message). Null: back
  /// to SetImageData's. A volume node is resliced where its parent transform puts it (a
  /// registration); other images are taken in world coordinates.
  void SetVolumeNode(vtkROS2SceneNode* node);
  vtkROS2SceneNode* GetVolumeNode() const;

  /// The point the slice plane goes through, world mm; the camera centres on it.
  void SetSliceCenter(double x, double y, double z);
  void GetSliceCenter(double center[3]) const;
  /// Window and level of the slice; window <= 0 (default): the volume's scalar range.
  void SetWindowLevel(double window, double level);
  /// Half the height of the view, in mm; <= 0 (default): fits the volume.
  void SetFieldOfView(double halfHeight);

  /// Applies what changed (plane, volume, models that moved, were added or removed); returns
  /// whether the view changed (render then).
  bool Update();

  /// Models cut by the plane in the latest Update (a non-empty intersection).
  int GetNumberOfIntersectedModels() const;
  /// The intersection lines of a model node (world mm), or nullptr when it is not cut.
  vtkPolyData* GetIntersection(vtkROS2SceneNode* modelNode) const;
  /// The slice prop (for tests and custom styling).
  vtkImageSlice* GetImageSlice() const;

protected:
  vtkROS2SliceView();
  ~vtkROS2SliceView() override;

private:
  vtkROS2SliceView(const vtkROS2SliceView&) = delete;
  void operator=(const vtkROS2SliceView&) = delete;

  void UpdateCamera();
  bool UpdateIntersections();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
