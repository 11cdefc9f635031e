// ros2vtk — a transform in the scene: a matrix to its parent transform node, like Slicer's
// linear transform nodes. Transform nodes form a hierarchy through the "transform" reference;
// tf lookups, robot links and registrations are transform nodes. Matrices are in millimetres.
#ifndef vtkROS2TransformNode_h
#define vtkROS2TransformNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2SceneNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

class vtkMatrix4x4;

class ROS2VTKSCENE_EXPORT vtkROS2TransformNode : public vtkROS2SceneNode
{
public:
  static vtkROS2TransformNode* New();
  vtkTypeMacro(vtkROS2TransformNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Fired (besides ModifiedEvent) when the matrix or the parent changes; Slicer's id.
  enum
  {
    TransformModifiedEvent = 15000
  };

  /// The matrix to the parent (owned by the node; do not modify it directly, use Set...).
  vtkMatrix4x4* GetMatrixTransformToParent();
  /// The fill-in form (SlicerROS2 and MRML): copies the matrix into `matrix`.
  void GetMatrixTransformToParent(vtkMatrix4x4* matrix);
  /// Copies `matrix`; fires TransformModifiedEvent only when a value changed. Returns whether
  /// it changed.
  bool SetMatrixTransformToParent(vtkMatrix4x4* matrix);
#ifndef __VTK_WRAP__
  /// The same from 16 row-major elements, with no vtkMatrix4x4 in between (a tf lookup per
  /// robot link at every spin).
  bool SetMatrixTransformToParent(const double elements[16]);
#endif

  /// A subscriber's vtkMatrix4x4 (SetMatrixTransformToParent).
  bool CopyContentFrom(vtkObject* data, std::string* error) override;

  /// The parent transform node (the "transform" reference); nullptr = world.
  void SetParentTransformNodeID(const char* id);
  const char* GetParentTransformNodeID() const;
  vtkROS2TransformNode* GetParentTransformNode() const;

  /// This node's matrix composed with every ancestor's (a cycle is reported and cut).
  void GetMatrixTransformToWorld(vtkMatrix4x4* matrixToWorld);

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2TransformNode();
  ~vtkROS2TransformNode() override;

  vtkMatrix4x4* MatrixTransformToParent;

private:
  vtkROS2TransformNode(const vtkROS2TransformNode&) = delete;
  void operator=(const vtkROS2TransformNode&) = delete;
};

#endif
