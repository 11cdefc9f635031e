"""Kind `point`: one position or vector (geometry_msgs/Point, Vector3, a field of a custom
message) <-> a vtkPoints holding exactly one point, scaled like any length when listed."""
from __future__ import annotations

from .base import XYZ_FLOAT64, Kind

KIND = Kind(name="point", vtk_types=("vtkPoints",), roles=(("point", XYZ_FLOAT64),),
            scalable=("point",))
