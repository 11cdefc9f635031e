// ros2vtk — a transform node kept equal to a tf2 lookup (parent frame <- child frame) by the
// spin of its ROS node, like SlicerROS2's Tf2LookupNode. Matrices are in millimetres unless
// ScaleLengths is off. A lookup that fails is reported once and then kept as a state
// (GetLookupStatus), never logged on every spin.
#ifndef vtkROS2Tf2LookupNode_h
#define vtkROS2Tf2LookupNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2TransformNode.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkROS2NodeNode;
namespace ros2vtk {
namespace tf2 {
class BufferCore;
struct LookupResult;
}
}

class ROS2VTKSCENE_EXPORT vtkROS2Tf2LookupNode : public vtkROS2TransformNode
{
public:
  static vtkROS2Tf2LookupNode* New();
  vtkTypeMacro(vtkROS2Tf2LookupNode, vtkROS2TransformNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// tf frame ids: the lookup gives the pose of ChildID in ParentID.
  void SetParentID(const char* frame);
  const char* GetParentID() const { return this->ParentFrame.c_str(); }
  void SetChildID(const char* frame);
  const char* GetChildID() const { return this->ChildFrame.c_str(); }
  bool IsParentAndChildSet() const
  {
    return !this->ParentFrame.empty() && !this->ChildFrame.empty();
  }

  /// Metres on the wire -> millimetres in the matrix (default on).
  vtkSetMacro(ScaleLengths, bool);
  vtkGetMacro(ScaleLengths, bool);
  vtkBooleanMacro(ScaleLengths, bool);

  /// "waiting" (never succeeded yet), "ok", or "failed" (worked before, fails now); the
  /// reason is in GetLastLookupError.
  const char* GetLookupStatus() const;
  const char* GetLastLookupError() const { return this->LastError.c_str(); }
  /// Stamp of the transform last applied, in seconds (0 before the first success).
  double GetLastLookupTime() const { return this->LastStamp; }
  /// How old that transform is now, in seconds of the ROS node's clock (simulated time when
  /// its use_sim_time is on, so a simulator's transforms are not 1.7e9 s old): node time minus
  /// stamp. -1 before the first success or without a ROS node.
  double GetLastLookupAge() const;
  /// Off (default): events only when the looked-up matrix changes. On (SlicerROS2's
  /// SetModifiedOnLookup): a ModifiedEvent for every lookup that brings a new stamp, even when
  /// the matrix is the same (e.g. to drive a per-sample observer).
  vtkSetMacro(ModifiedOnLookup, bool);
  vtkGetMacro(ModifiedOnLookup, bool);
  vtkBooleanMacro(ModifiedOnLookup, bool);
  /// True when the transform stamp differs from (sec, nsec) — SlicerROS2's IsDifferentFromLast.
  bool IsDifferentFromLast(int sec, int nsec) const;

  /// The ROS node that spins this lookup.
  vtkROS2NodeNode* GetROS2Node() const;

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

#ifndef __VTK_WRAP__
  /// Called by the ROS node's Spin: looks up the latest transform and updates the matrix
  /// (TransformModifiedEvent only when it changed). Returns whether it changed.
  bool UpdateFromBuffer(const ros2vtk::tf2::BufferCore& buffer);
#endif

  /// Index key among the ROS node's lookups: "parent<newline>child".
  std::string GetROS2NodeChildKey() const override
  {
    return this->ParentFrame + '\n' + this->ChildFrame;
  }
  /// Spin hook: the latest transform from the ROS node's tf2 buffer.
  int OnROS2NodeSpin(vtkROS2NodeNode* rosNode) override;

protected:
  vtkROS2Tf2LookupNode();
  ~vtkROS2Tf2LookupNode() override;

  std::string ParentFrame;
  std::string ChildFrame;
  bool ScaleLengths = true;
  bool ModifiedOnLookup = false;
  int Status = 0; // 0 waiting, 1 ok, 2 failed
  std::string LastError;
  double LastStamp = 0.0;
  long long LastStampNanoseconds = 0;
  // What UpdateFromBuffer last applied: a lookup that brings the same transform again, at the
  // same scale, into a matrix nobody touched since, has nothing to convert or compare.
  double AppliedScale = 0.0;
  vtkMTimeType AppliedMatrixTime = 0;
#ifndef __VTK_WRAP__
  std::unique_ptr<ros2vtk::tf2::LookupResult> LastResult; // reused by UpdateFromBuffer
#endif

private:
  vtkROS2Tf2LookupNode(const vtkROS2Tf2LookupNode&) = delete;
  void operator=(const vtkROS2Tf2LookupNode&) = delete;
};

#endif
