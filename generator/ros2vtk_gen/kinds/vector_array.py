"""Kind `vector_array`: a list of numeric fields (a wrench's force and torque) <-> the components
of a vtkDoubleArray. Never scaled: forces and torques are not lengths."""
from __future__ import annotations

from .base import NUMERIC_TYPES, Kind, prim

KIND = Kind(name="vector_array", vtk_types=("vtkDoubleArray",),
            roles=(("components", prim(*NUMERIC_TYPES)),), list_roles=("components",))
