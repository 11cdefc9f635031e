// ros2vtk — base class of the subscribers of Marker-like messages (the generated subscribers of
// the mapping kinds `marker` with ns/id/action and `marker_array`): it keeps the topic's
// markers as RViz 2's marker display does, whatever the message type.
//
// A generated subclass only reads its messages' fields into ros2vtk::convert::Marker
// (ReadMarkers: one generated function per mapping rule); this class does the rest: keeps them
// by (ns, id) (ADD/MODIFY replace, DELETE one, DELETEALL all), expires lifetimes on the ROS
// node's clock, places each in the fixed frame through the node's tf buffer (at its stamp, or
// the latest transform when frame_locked), drops markers stamped older than the tf buffer's
// history (RViz's tf filter drops them), says why a marker is not drawn, and draws them all.
#ifndef vtkROS2MarkerSubscriberNode_h
#define vtkROS2MarkerSubscriberNode_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkROS2SubscriberNode.h"

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string
#include <vector> // for std::vector

class vtkPolyData;

namespace ros2vtk {
namespace convert {
struct Marker;
}
}

class ROS2VTKSCENE_EXPORT vtkROS2MarkerSubscriberNode : public vtkROS2SubscriberNode
{
public:
  vtkTypeMacro(vtkROS2MarkerSubscriberNode, vtkROS2SubscriberNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The frame the markers are drawn in, as RViz's fixed frame: each kept marker is placed at
  /// the pose of its header's frame in this frame, looked up in the ROS node's tf buffer at its
  /// stamp when it arrives (the latest transform for stamp 0), and again at the latest transform
  /// on every spin when it is frame_locked. A marker whose frame cannot be looked up is not
  /// drawn (GetLastConversionError and GetFrameStatus say "No transform from [a] to [b]") and
  /// is looked up again on later spins; one stamped older than the tf buffer's history is
  /// dropped, its status saying so. "" (the default): the scene's fixed frame
  /// (vtkROS2Scene::SetFixedFrame) is used; when that is "" too, frames are ignored and every
  /// marker is drawn at its own pose in this node's frame. Saved with the scene when set.
  /// Ignored (markers always at their own pose) when the node's mapping rule maps no frame_id.
  void SetFixedFrame(const char* frame);
  const char* GetFixedFrame() const;
  /// The frame markers are placed in now: this node's fixed frame, else the scene's ("" none).
  std::string GetEffectiveFixedFrame() const;
  /// Why kept markers are not drawn (or were dropped), one line per marker ("" when all are).
  std::string GetFrameStatus() const;
  /// Markers kept now (drawn or waiting for their frame).
  int GetNumberOfKeptMarkers() const;

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

protected:
  vtkROS2MarkerSubscriberNode();
  ~vtkROS2MarkerSubscriberNode() override;

  /// Appends the markers of raw message `raw` (of this node's type), in order: the generated
  /// subclass's one conversion of its mapping rule.
  virtual void ReadMarkers(const void* raw, std::vector<ros2vtk::convert::Marker>* markers) = 0;
  /// What is drawn changed (new messages, an expiry, a frame moved): the subclass drops its
  /// cached drawing.
  virtual void OnKeptMarkersChanged() {}
  /// False for a rule that maps no frame_id: markers are always drawn at their own pose.
  bool PlacesMarkersInFrames = true;

  /// Every kept marker drawn into `polyData` (scaled by ScaleLengths); `status` gets what the
  /// latest messages could not apply, then the markers not drawn for want of a frame. False
  /// (with the reason in `status`) when it cannot draw.
  bool DrawKeptMarkers(vtkPolyData* polyData, std::string* status) const;

  void OnNewMessages() override;
  bool ExpireKeptState(vtkTypeInt64 nowNanoseconds) override;

private:
  vtkROS2MarkerSubscriberNode(const vtkROS2MarkerSubscriberNode&) = delete;
  void operator=(const vtkROS2MarkerSubscriberNode&) = delete;

  /// Places the kept markers in the effective fixed frame (all: every one, else the new,
  /// unplaced and frame-locked ones); true when what is drawn changed.
  bool LocateKeptMarkers(bool all);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
