"""Kind `polyline`: a sequence of messages each holding a position (nav_msgs/Path's poses)
<-> a vtkPolyData with those points and one polyline cell, scaled as lengths when listed."""
from __future__ import annotations

from .base import XYZ_FLOAT64, Kind, Shape

KIND = Kind(name="polyline", vtk_types=("vtkPolyData",), roles=(("sequence", Shape(sequence=True)),),
            element_roles=(("point", XYZ_FLOAT64),), scalable=("point",))
