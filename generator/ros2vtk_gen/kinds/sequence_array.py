"""Kind `sequence_array`: a sequence of numbers (CameraInfo's distortion D, Joy's axes and
buttons) <-> a one-component VTK array whose class follows the element type. Never scaled.
Publish takes exactly that class: two rules of one message (Joy's axes and buttons) would
otherwise give VTKToROS2 overloads that clash."""
from __future__ import annotations

from ..errors import MAPPING_BAD_KIND
from .base import CPP_FIELD_TYPES, Kind, prim

# The element types and the VTK array that holds each exactly.
ARRAY_TYPES = {
    "float64": "vtkDoubleArray", "float32": "vtkFloatArray",
    "int32": "vtkIntArray", "int16": "vtkIntArray", "int8": "vtkIntArray",
    "uint16": "vtkIntArray", "uint8": "vtkIntArray",
}


def _check(vtk_type, roles, table, fail) -> None:
    wanted = ARRAY_TYPES[roles["data"].primitive]
    if vtk_type != wanted:
        raise fail("vtk_type", f"{roles['data'].primitive} values go into {wanted}, not "
                   f"'{vtk_type}'", MAPPING_BAD_KIND)


def _view(rule, table):
    element = rule.roles["data"].field.type.name
    return {"element_type": CPP_FIELD_TYPES[element], "integral": element.startswith(("int", "uint"))}


KIND = Kind(name="sequence_array", vtk_types=tuple(sorted(set(ARRAY_TYPES.values()))),
            roles=(("data", prim(*ARRAY_TYPES, sequence=True)),), check=_check, view=_view)
