"""Kind `marker`: visualization_msgs/Marker-like fields (a type, a pose, a scale, a colour and a
list of points) <-> a vtkPolyData drawn with VTK's shape sources. The template maps the
message's ARROW, CUBE, SPHERE, CYLINDER, LINE_STRIP and POINTS constants onto the helper's
shapes; other types are refused with a reason. Positions, sizes and points are lengths."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, prim, struct

COLOR = struct(r=prim("float32"), g=prim("float32"), b=prim("float32"), a=prim("float32"))
POINTS = struct(sequence=True, x=prim("float64"), y=prim("float64"), z=prim("float64"))

KIND = Kind(name="marker", vtk_types=("vtkPolyData",),
            roles=(("type", prim("int32")), ("position", XYZ_FLOAT64), ("orientation", QUATERNION),
                   ("scale", XYZ_FLOAT64), ("color", COLOR), ("points", POINTS)),
            scalable=("position", "scale", "points"))
