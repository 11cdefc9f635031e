// ros2vtk — a surface in the scene (Slicer's model node, in small): vtkPolyData plus display
// properties, placed under a transform node. Robot links' visuals are model nodes; the local
// matrix holds what sits between the link frame and the mesh (visual origin, mesh scale).
#ifndef vtkROS2ModelNode_h
#define vtkROS2ModelNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2SceneNode.h"

class vtkMatrix4x4;
class vtkPolyData;
class vtkROS2TransformNode;

class ROS2VTKSCENE_EXPORT vtkROS2ModelNode : public vtkROS2SceneNode
{
public:
  static vtkROS2ModelNode* New();
  vtkTypeMacro(vtkROS2ModelNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The surface (reference counted, not copied).
  void SetPolyData(vtkPolyData* polyData);
  vtkPolyData* GetPolyData() const { return this->PolyData; }
  /// MRML's name for SetPolyData (Slicer scripts call it on model nodes).
  void SetAndObservePolyData(vtkPolyData* polyData) { this->SetPolyData(polyData); }

  /// Model -> parent transform node (owned; use SetMatrixModelToParent to change it).
  vtkMatrix4x4* GetMatrixModelToParent() { return this->MatrixModelToParent; }
  void SetMatrixModelToParent(vtkMatrix4x4* matrix);

  /// The transform node this model hangs under (the "transform" reference); nullptr = world.
  void SetParentTransformNodeID(const char* id);
  const char* GetParentTransformNodeID() const;
  vtkROS2TransformNode* GetParentTransformNode() const;

  /// Parent's world matrix x model-to-parent.
  void GetMatrixModelToWorld(vtkMatrix4x4* matrix);

  /// Display properties (RGB 0..1, opacity 0..1).
  vtkSetVector3Macro(Color, double);
  vtkGetVector3Macro(Color, double);
  vtkSetClampMacro(Opacity, double, 0.0, 1.0);
  vtkGetMacro(Opacity, double);
  vtkSetMacro(Visibility, bool);
  vtkGetMacro(Visibility, bool);
  vtkBooleanMacro(Visibility, bool);
  /// Colour by the polydata's active point scalars (per-vertex colours of a mesh) instead of
  /// Color, as Slicer's model display node does. Off by default.
  vtkSetMacro(ScalarVisibility, bool);
  vtkGetMacro(ScalarVisibility, bool);
  vtkBooleanMacro(ScalarVisibility, bool);
  /// How the surface is drawn: Points, Wireframe or Surface (default), as vtkProperty's values
  /// (VTK_POINTS 0, VTK_WIREFRAME 1, VTK_SURFACE 2).
  enum RepresentationType
  {
    Points = 0,
    Wireframe = 1,
    Surface = 2
  };
  vtkSetClampMacro(Representation, int, Points, Surface);
  vtkGetMacro(Representation, int);
  /// Size of drawn points in pixels (point clouds, the Points representation), as vtkProperty.
  vtkSetClampMacro(PointSize, double, 1.0, 100.0);
  vtkGetMacro(PointSize, double);

  /// Slicer keeps display properties in a separate display node; here the model node holds
  /// them itself. These two let Slicer scripts (`CreateDefaultDisplayNodes()`,
  /// `GetDisplayNode().SetColor(...)`) run unchanged: the display node is the model node.
  void CreateDefaultDisplayNodes() {}
  vtkROS2ModelNode* GetDisplayNode() { return this; }

  /// A subscriber's vtkPolyData (a deep copy: the subscriber reuses its object every spin).
  bool CopyContentFrom(vtkObject* data, std::string* error) override;

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2ModelNode();
  ~vtkROS2ModelNode() override;

  vtkPolyData* PolyData = nullptr;
  vtkMatrix4x4* MatrixModelToParent;
  double Color[3] = { 0.8, 0.8, 0.8 };
  double Opacity = 1.0;
  bool Visibility = true;
  bool ScalarVisibility = false;
  int Representation = Surface;
  double PointSize = 1.0;

private:
  vtkROS2ModelNode(const vtkROS2ModelNode&) = delete;
  void operator=(const vtkROS2ModelNode&) = delete;
};

#endif
