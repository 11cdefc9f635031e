"""Kind `marker`: visualization_msgs/Marker-like fields (a type, a pose, a scale, a colour and a
list of points) <-> a vtkPolyData drawn with VTK's shape sources. The template maps the
message's ARROW, CUBE, SPHERE, CYLINDER, LINE_STRIP and POINTS constants onto the helper's
shapes (LINE_LIST, CUBE_LIST, SPHERE_LIST, TRIANGLE_LIST, ARROW_STRIP, TEXT_VIEW_FACING and MESH_RESOURCE too when the
message defines them: a lab's own Marker-like type may not; TEXT_VIEW_FACING needs the optional
`text` role and becomes a label in the poly data's field data, MESH_RESOURCE the optional
`mesh_resource` role, the file read by the loader the Scene module installs); other types are refused with a reason. Positions, sizes and points
are lengths. The optional role `colors` gives each point its own colour as RViz does (as many
colours as points; a triangle list also one per triangle); an ARROW with two points goes from
the first to the second.

Kept markers (optional roles `ns`, `id` and `action`, all three): the subscriber keeps the
topic's markers by (ns, id) as RViz does, in a ros2vtk::convert::MarkerSet (ADD/MODIFY replace,
DELETE drops one, DELETEALL all; `lifetime` expires them). Frames (optional roles `frame_id`,
`stamp`, `frame_locked`): each kept marker is placed at its frame's pose in the subscriber's fixed
frame (its tf buffer), again on every spin when frame_locked."""
from __future__ import annotations

from ..errors import MAPPING_BAD_FIELD
from .base import QUATERNION, XYZ_FLOAT64, Kind, prim, struct

COLOR = struct(r=prim("float32"), g=prim("float32"), b=prim("float32"), a=prim("float32"))
COLORS = struct(sequence=True, r=prim("float32"), g=prim("float32"), b=prim("float32"),
                a=prim("float32"))
POINTS = struct(sequence=True, x=prim("float64"), y=prim("float64"), z=prim("float64"))
DURATION = struct(sec=prim("int32"), nanosec=prim("uint32"))  # builtin_interfaces/Duration
TIME = struct(sec=prim("int32"), nanosec=prim("uint32"))  # builtin_interfaces/Time

# Roles that key a marker (RViz keeps a topic's markers by namespace and id) and say what to do
# with it (ADD, MODIFY, DELETE, DELETEALL), and how long it lives.
KEY_ROLES = (("ns", prim("string")), ("id", prim("int32")), ("action", prim("int32")),
             ("lifetime", DURATION))
# Roles that place a kept marker: its header's frame and stamp, and whether it moves with the frame.
FRAME_ROLES = (("frame_id", prim("string")), ("stamp", TIME), ("frame_locked", prim("bool")))

# The message's type constants the helper draws, and the helper's shape for each.
SHAPES = (("ARROW", "Arrow"), ("CUBE", "Cube"), ("SPHERE", "Sphere"), ("CYLINDER", "Cylinder"),
          ("LINE_STRIP", "LineStrip"), ("LINE_LIST", "LineList"), ("CUBE_LIST", "CubeList"),
          ("SPHERE_LIST", "SphereList"), ("POINTS", "Points"), ("TEXT_VIEW_FACING", "Text"),
          ("MESH_RESOURCE", "MeshResource"), ("TRIANGLE_LIST", "TriangleList"),
          ("ARROW_STRIP", "ArrowStrip"))

# Roles a Marker-like type may lack (a rule leaves them out): the text of TEXT_VIEW_FACING, the
# mesh of MESH_RESOURCE (a URI and whether the file's own colours are used) and, for kept
# markers, the lifetime.
MESH_ROLES = (("text", prim("string")), ("mesh_resource", prim("string")),
              ("mesh_use_embedded_materials", prim("bool")))
# Per-point colours (RViz uses them instead of `color` when there are as many as points).
COLOR_ROLES = (("colors", COLORS),)


def shapes_of(message) -> list:
    """[{"constant", "shape"}] for the SHAPES constants `message` defines."""
    names = {constant.name for constant in message.constants}
    return [{"constant": c, "shape": s} for c, s in SHAPES if c in names]


def state_view(roles) -> dict:
    """The state a subscriber of Marker-like messages keeps (`roles`: the rule's roles for one
    marker): a MarkerSet with lifetimes, placed in a fixed frame when the rule maps frame_id."""
    return {"state_class": "::ros2vtk::convert::MarkerSet",
            "state_header": "ros2vtk/convert/Marker.hpp",
            # The state has set_time(ns) / expire(ns): the subscriber stamps each spin's
            # messages with its node clock and drops expired markers on every spin.
            "state_expires": True,
            # ... and locate(lookup, fixed frame, all): the subscriber gets a FixedFrame.
            "state_frames": "frame_id" in roles,
            # ... which the runtime's subscriber base class does: keeping, lifetimes, frames.
            "state_node_class": "vtkROS2MarkerSubscriberNode"}


def _view(rule, table):
    view = {"shapes": shapes_of(table[rule.ros_type]), "to_markers": True,
            "state_header": "ros2vtk/convert/Marker.hpp"}
    if "ns" in rule.roles:
        view.update(state_view(rule.roles))
    return view


def _check(vtk_type, roles, table, fail):
    """ns, id and action come together (a key without an action, or the reverse, is a mistake);
    frames need kept markers."""
    present = [name for name in ("ns", "id", "action") if name in roles]
    if present and len(present) != 3:
        raise fail("fields", "roles ns, id and action go together (this rule maps only "
                   f"{', '.join(present)})", MAPPING_BAD_FIELD)
    if "frame_id" in roles and not present:
        raise fail("fields", "role frame_id needs ns, id and action (only kept markers are placed "
                   "in a fixed frame)", MAPPING_BAD_FIELD)


KIND = Kind(name="marker", vtk_types=("vtkPolyData",),
            roles=(("type", prim("int32")), ("position", XYZ_FLOAT64), ("orientation", QUATERNION),
                   ("scale", XYZ_FLOAT64), ("color", COLOR), ("points", POINTS)) + COLOR_ROLES
            + MESH_ROLES + KEY_ROLES + FRAME_ROLES,
            optional_roles=tuple(name for name, _ in COLOR_ROLES + MESH_ROLES + KEY_ROLES
                                 + FRAME_ROLES),
            scalable=("position", "scale", "points"),
            check=_check,
            view=_view)
