"""Kind `rigid_transform`: one translation + rotation (Pose, Transform and their stamped
forms) <-> vtkMatrix4x4, the translation a length."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind

KIND = Kind(name="rigid_transform", vtk_types=("vtkMatrix4x4",),
            roles=(("translation", XYZ_FLOAT64), ("rotation", QUATERNION)),
            scalable=("translation",))
