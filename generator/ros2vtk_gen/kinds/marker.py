"""Kind `marker`: visualization_msgs/Marker-like fields (a type, a pose, a scale, a colour and a
list of points) <-> a vtkPolyData drawn with VTK's shape sources. The template maps the
message's ARROW, CUBE, SPHERE, CYLINDER, LINE_STRIP and POINTS constants onto the helper's
shapes (LINE_LIST, CUBE_LIST, SPHERE_LIST, TEXT_VIEW_FACING and MESH_RESOURCE too when the
message defines them: a lab's own Marker-like type may not; TEXT_VIEW_FACING needs the optional
`text` role and becomes a label in the poly data's field data, MESH_RESOURCE the optional
`mesh_resource` role, the file read by the loader the Scene module installs); other types are refused with a reason. Positions, sizes and points
are lengths."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, prim, struct

COLOR = struct(r=prim("float32"), g=prim("float32"), b=prim("float32"), a=prim("float32"))
POINTS = struct(sequence=True, x=prim("float64"), y=prim("float64"), z=prim("float64"))
DURATION = struct(sec=prim("int32"), nanosec=prim("uint32"))  # builtin_interfaces/Duration

# The message's type constants the helper draws, and the helper's shape for each.
SHAPES = (("ARROW", "Arrow"), ("CUBE", "Cube"), ("SPHERE", "Sphere"), ("CYLINDER", "Cylinder"),
          ("LINE_STRIP", "LineStrip"), ("LINE_LIST", "LineList"), ("CUBE_LIST", "CubeList"),
          ("SPHERE_LIST", "SphereList"), ("POINTS", "Points"), ("TEXT_VIEW_FACING", "Text"),
          ("MESH_RESOURCE", "MeshResource"))

# Roles a Marker-like type may lack (a rule leaves them out): the text of TEXT_VIEW_FACING, the
# mesh of MESH_RESOURCE (a URI and whether the file's own colours are used) and, for kept
# markers, the lifetime.
MESH_ROLES = (("text", prim("string")), ("mesh_resource", prim("string")),
              ("mesh_use_embedded_materials", prim("bool")))


def shapes_of(message) -> list:
    """[{"constant", "shape"}] for the SHAPES constants `message` defines."""
    names = {constant.name for constant in message.constants}
    return [{"constant": c, "shape": s} for c, s in SHAPES if c in names]


def _view(rule, table):
    return {"shapes": shapes_of(table[rule.ros_type])}


KIND = Kind(name="marker", vtk_types=("vtkPolyData",),
            roles=(("type", prim("int32")), ("position", XYZ_FLOAT64), ("orientation", QUATERNION),
                   ("scale", XYZ_FLOAT64), ("color", COLOR), ("points", POINTS)) + MESH_ROLES,
            optional_roles=tuple(name for name, _ in MESH_ROLES),
            scalable=("position", "scale", "points"),
            view=_view)
