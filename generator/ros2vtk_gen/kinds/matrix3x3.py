"""Kind `matrix3x3`: a fixed float64[9] field, row-major (CameraInfo's intrinsics K) <->
vtkMatrix3x3. Never scaled: K is in pixels."""
from __future__ import annotations

from .base import Kind, prim

KIND = Kind(name="matrix3x3", vtk_types=("vtkMatrix3x3",),
            roles=(("elements", prim("float64", array_size=9)),))
