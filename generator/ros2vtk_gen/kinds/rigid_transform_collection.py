"""Kind `rigid_transform_collection`: a sequence of poses (PoseArray) <-> vtkTransformCollection;
translation and rotation are read inside each element of `sequence`."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, Shape

KIND = Kind(name="rigid_transform_collection", vtk_types=("vtkTransformCollection",),
            roles=(("sequence", Shape(sequence=True)),),
            element_roles=(("translation", XYZ_FLOAT64), ("rotation", QUATERNION)),
            scalable=("translation",))
