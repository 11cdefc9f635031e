// ros2vtk — a display marker (visualization_msgs/Marker: a shape, its pose, size and colour, or
// a list of points) <-> a vtkPolyData to draw, built with VTK's sources (vtkCubeSource,
// vtkSphereSource, vtkCylinderSource, vtkArrowSource) in the scene's units.
//
// The shape is an enum here: the template of kind `marker` maps the message's type constants
// to it, so nothing below knows a ROS constant.
#ifndef ros2vtk_convert_Marker_hpp
#define ros2vtk_convert_Marker_hpp

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkPolyData;

namespace ros2vtk {
namespace convert {

enum class MarkerShape
{
  Arrow,        ///< along +x: length scale.x, shaft diameter scale.y, head diameter scale.z;
                ///< with two `points`, from the first to the second: shaft diameter scale.x,
                ///< head diameter scale.y, head length scale.z (0: 23% of the length)
  Cube,         ///< side lengths scale.x, y, z
  Sphere,       ///< diameters scale.x, y, z
  Cylinder,     ///< along +z: diameters scale.x, y, height scale.z
  LineStrip,    ///< `points` (in the marker's frame) joined by one polyline
  Points,       ///< `points` as vertices
  LineList,     ///< `points` in pairs, each pair one line segment (an odd count is refused)
  CubeList,     ///< a cube of side lengths scale.x, y, z centred on each of `points`
  SphereList,   ///< a sphere of diameters scale.x, y, z centred on each of `points`
  TriangleList, ///< `points` in threes, each a triangle, the points scaled by scale.x, y, z
  Text,         ///< `text` centred on the position, facing the viewer, capitals scale.z high:
                ///< no geometry, a label (the Label* field arrays below) the display draws
  MeshResource, ///< the mesh file at `mesh_resource` (read by the MeshResourceLoader), scaled
                ///< by scale.x, y, z
  ArrowStrip,   ///< an arrow from each of `points` to the next (two or more), each sized as a
                ///< two-point Arrow, all in `color`
  Unsupported,
};

/// What a kept marker's message asks of the MarkerSet (MarkerSet::apply), as RViz applies a
/// marker's action: the template maps the message's ADD/MODIFY, DELETE and DELETEALL onto it.
enum class MarkerAction
{
  Add,       ///< ADD and MODIFY: keep it under (ns, id), replacing what was there
  Delete,    ///< drop (ns, id)
  DeleteAll, ///< drop every marker
  Unknown,   ///< anything else: refused with its value (Marker::action_value)
};

struct Marker
{
  /// The key a MarkerSet keeps it under (the message's ns and id) and what to do with it.
  std::string ns;
  int id = 0;
  MarkerAction action = MarkerAction::Add;
  int action_value = 0; ///< the action as sent (named in the reason of an Unknown one)
  MarkerShape shape = MarkerShape::Unsupported;
  double position[3] = { 0, 0, 0 };
  double orientation[4] = { 0, 0, 0, 1 }; ///< x, y, z, w
  double scale[3] = { 1, 1, 1 };
  double color[4] = { 1, 1, 1, 1 }; ///< r, g, b, a in 0..1
  std::vector<double> points;       ///< flat x0 y0 z0 x1 ..., in the marker's frame
  /// Flat r0 g0 b0 a0 r1 ... in 0..1: one colour per point (instead of `color`) when there are
  /// as many as points; a TriangleList also takes one per triangle (RViz's rules, Marker.cpp).
  std::vector<double> colors;
  /// Seconds a kept marker is shown after it was added (MarkerSet); 0 (or less) is forever.
  double lifetime = 0;
  std::string text;                         ///< Text: what is written
  std::string mesh_resource;                ///< MeshResource: a URI (package://, file://)
  bool mesh_use_embedded_materials = false; ///< MeshResource: the file's colours, if it has any
  /// The frame the pose is in (header.frame_id) and when (header.stamp, nanoseconds; 0: the
  /// latest transform). Used by a MarkerSet that places its markers in a fixed frame (locate).
  std::string frame_id;
  int64_t stamp_nanoseconds = 0;
  /// Placed again on every locate() at the latest transform (it moves with its frame), instead
  /// of once when it arrived at its stamp.
  bool frame_locked = false;
};

/// Where a frame is in the fixed frame: a rigid transform (translation in metres, rotation a
/// unit quaternion x, y, z, w) that maps points of the frame into the fixed frame.
struct FramePose
{
  double translation[3] = { 0, 0, 0 };
  double rotation[4] = { 0, 0, 0, 1 };
  /// Set by a lookup that fails because the stamp is older than the oldest transform its tf
  /// buffer still holds: waiting cannot help, so the marker is dropped (RViz's tf filter drops
  /// such a message) instead of being looked up again.
  bool older_than_history = false;
};

/// Looks `frame` up in the fixed frame at `stamp_nanoseconds` (0: the latest transform); false
/// with a reason when it cannot (the caller's tf buffer has no path, or not at that time).
using FrameLookup = std::function<bool(
  const std::string& frame, int64_t stamp_nanoseconds, FramePose* pose, std::string* error)>;

/// Reads the mesh a MeshResource marker names into `mesh` (triangles, in metres); when the file
/// has its own colours, they are RGBA unsigned char point scalars of `mesh`. False and a reason
/// (which URI, what was wrong) otherwise. Several threads may call it.
using MeshResourceLoader =
  std::function<bool(const std::string& uri, vtkPolyData* mesh, std::string* error)>;
/// The process's loader of MeshResource markers. The Scene module installs one that resolves
/// URIs as robot meshes are resolved (package:// through AMENT_PREFIX_PATH / ROS_PACKAGE_PATH,
/// file:// only inside those roots). Without one, MeshResource markers are refused.
void set_mesh_resource_loader(MeshResourceLoader loader);

/// The labels of Text markers travel as field data of the drawn poly data, one tuple per label
/// in these arrays: what is written (vtkStringArray), where (3 doubles, scene units, in the
/// poly data's frame), its height (scene units) and its RGBA colour (4 unsigned chars). A
/// display draws each facing the camera (runtime/Display's point-cloud and shape manager).
constexpr const char* kLabelTextArray = "LabelText";
constexpr const char* kLabelPositionArray = "LabelPosition";
constexpr const char* kLabelHeightArray = "LabelHeight";
constexpr const char* kLabelColorArray = "LabelColor";

/// ROS -> VTK: positions, sizes and points are lengths (times length_scale); the pose places
/// the shape. The poly data gets the surface (or line, or vertices) and an unsigned char RGBA
/// point array "Color" (set as its scalars). Unsupported shapes, a zero or non-finite size of a
/// solid shape, or a non-unit quaternion are refused; the output is then untouched.
bool marker_to_poly_data(
  const Marker& marker, double length_scale, vtkPolyData* poly_data, std::string* error);

/// VTK -> ROS: a poly data with one line cell becomes a LineStrip of the points along it,
/// anything else Points of all its points; identity pose, scale 1 VTK unit (1 mm when scaled)
/// and the colour of the first tuple of its "Color" array (opaque white without one).
bool poly_data_to_marker(
  vtkPolyData* poly_data, double length_scale, Marker* marker, std::string* error);

/// The markers a display keeps, as RViz does for a MarkerArray topic: each marker under its
/// (namespace, id), replaced by a later ADD of the same key, dropped by DELETE of that key, all
/// dropped by DELETEALL. The kind `marker_array` folds every received message into one (the
/// subscriber node owns it) and draws it with to_poly_data. Markers are kept as received (in
/// the message's units); scaling happens when drawn.
class MarkerSet
{
public:
  /// Adds `marker` under (ns, id), replacing what was there. A marker that cannot be drawn
  /// (unsupported type, zero size, non-unit quaternion...) is refused with a reason, and the
  /// key is then dropped (the sender replaced the old marker; RViz shows none either).
  bool add(const std::string& ns, int id, const Marker& marker, std::string* error);
  /// The time (nanoseconds, any clock the caller keeps using) stamped on the markers added from
  /// now on: a marker with a positive lifetime expires `lifetime` seconds after it.
  void set_time(int64_t now_nanoseconds) { this->now = now_nanoseconds; }
  /// Drops every marker whose lifetime has passed at `now_nanoseconds` (as RViz does on its
  /// clock); true when one was dropped. A clock that went backwards expires nothing early.
  bool expire(int64_t now_nanoseconds);
  /// Applies each marker's action in order (its ns, id and action): Add as add(), Delete as
  /// remove(), DeleteAll as clear(); an Unknown action is refused. False with the first reason
  /// when one could not be applied (the others are).
  bool apply(const std::vector<Marker>& markers, std::string* error);
  /// Drops (ns, id); false when no such marker was kept (not an error for a display).
  bool remove(const std::string& ns, int id);
  /// Drops every marker (DELETEALL).
  void clear()
  {
    this->markers.clear();
    this->dropped.clear();
  }

  /// Places the markers in a fixed frame, as RViz does: a marker is drawn at the pose of its
  /// frame_id in the fixed frame, looked up by `lookup` at its stamp when it arrives, and again
  /// at the latest transform on every call when it is frame_locked. A marker whose frame cannot
  /// be looked up is kept but not drawn, its reason in status(), and looked up again on the next
  /// call (as RViz's tf message filter holds a message until its transform arrives); one whose
  /// lookup says its stamp is older than the tf history (FramePose::older_than_history) is
  /// dropped, and status() says so until its key is added again or the set cleared. `all`
  /// places every marker again (the fixed frame changed). Without a call markers are drawn at
  /// their own pose, frames ignored. True when a marker moved, appeared or disappeared.
  bool locate(const FrameLookup& lookup, const std::string& fixed_frame, bool all);
  /// Drops the placement of every marker: drawn at their own pose again (no fixed frame).
  void unlocate();
  /// Why kept markers are not drawn, one line each ("marker (ns 'a', id 1): No transform from
  /// [b] to [world]: ..."), in (ns, id) order, then the markers dropped as too old; "" when
  /// every kept marker is drawn and none was dropped.
  std::string status() const;
  size_t size() const { return this->markers.size(); }
  bool contains(const std::string& ns, int id) const
  {
    return this->markers.count(std::make_pair(ns, id)) != 0;
  }

  /// Every kept marker drawn (marker_to_poly_data) and appended into `poly_data`, in (ns, id)
  /// order: the points of each, its cells (vertices, lines, polygons), its colour in the RGBA
  /// point array "Color" (the scalars), and an int cell array "MarkerIndex" numbering the
  /// markers drawn in that order. After locate(), each marker is placed at its frame's pose in
  /// the fixed frame and those whose frame was not found are left out. No marker: an empty poly
  /// data. False (output untouched) only on a bad length scale or a null output.
  bool to_poly_data(double length_scale, vtkPolyData* poly_data, std::string* error) const;

private:
  struct Kept
  {
    Marker marker;
    int64_t expires_at = 0; ///< nanoseconds; 0 forever
    /// Placed in the fixed frame (locate): where its frame is, or why it is not drawn.
    bool located = false;
    FramePose frame;
    std::string status;
  };
  bool place(Kept& kept, const FrameLookup& lookup, const std::string& fixed_frame, bool* too_old);
  std::map<std::pair<std::string, int>, Kept> markers;
  /// Markers dropped by locate() as older than the tf history, and why (until re-added).
  std::map<std::pair<std::string, int>, std::string> dropped;
  int64_t now = 0;
  bool placing = false; ///< locate() was called (and not undone by unlocate()): frames count
};

} // namespace convert
} // namespace ros2vtk

#endif
