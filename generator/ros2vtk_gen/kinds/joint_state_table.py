"""Kind `joint_state_table`: JointState-like name/position/velocity/effort <-> a vtkTable with
one row per joint."""
from __future__ import annotations

from .base import Kind, prim

KIND = Kind(name="joint_state_table", vtk_types=("vtkTable",),
            roles=(("name", prim("string", sequence=True)),
                   ("position", prim("float64", sequence=True)),
                   ("velocity", prim("float64", sequence=True)),
                   ("effort", prim("float64", sequence=True))))
