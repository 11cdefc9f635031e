"""Kind `marker`: visualization_msgs/Marker-like fields (a type, a pose, a scale, a colour and a
list of points) <-> a vtkPolyData drawn with VTK's shape sources. The template maps the
message's ARROW, CUBE, SPHERE, CYLINDER, LINE_STRIP and POINTS constants onto the helper's
shapes (LINE_LIST, CUBE_LIST and SPHERE_LIST too when the message defines them: a lab's own
Marker-like type may not); other types are refused with a reason. Positions, sizes and points
are lengths."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, prim, struct

COLOR = struct(r=prim("float32"), g=prim("float32"), b=prim("float32"), a=prim("float32"))
POINTS = struct(sequence=True, x=prim("float64"), y=prim("float64"), z=prim("float64"))

# The message's type constants the helper draws, and the helper's shape for each.
SHAPES = (("ARROW", "Arrow"), ("CUBE", "Cube"), ("SPHERE", "Sphere"), ("CYLINDER", "Cylinder"),
          ("LINE_STRIP", "LineStrip"), ("LINE_LIST", "LineList"), ("CUBE_LIST", "CubeList"),
          ("SPHERE_LIST", "SphereList"), ("POINTS", "Points"))


def shapes_of(message) -> list:
    """[{"constant", "shape"}] for the SHAPES constants `message` defines."""
    names = {constant.name for constant in message.constants}
    return [{"constant": c, "shape": s} for c, s in SHAPES if c in names]


def _view(rule, table):
    return {"shapes": shapes_of(table[rule.ros_type])}


KIND = Kind(name="marker", vtk_types=("vtkPolyData",),
            roles=(("type", prim("int32")), ("position", XYZ_FLOAT64), ("orientation", QUATERNION),
                   ("scale", XYZ_FLOAT64), ("color", COLOR), ("points", POINTS)),
            scalable=("position", "scale", "points"),
            view=_view)
