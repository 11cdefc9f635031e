"""Kind `points`: a sequence of messages with x, y, z (all float32 or all float64) <-> vtkPoints,
scaled as lengths when listed."""
from __future__ import annotations

from ..errors import MAPPING_BAD_FIELD
from .base import CPP_FIELD_TYPES, Kind, Shape
from ..model import SCALAR

POINT_ELEMENT_TYPES = ("float32", "float64")


def _check(vtk_type, roles, table, fail) -> None:
    sequence = roles["sequence"]
    if not sequence.field.type.is_message:
        raise fail("fields", f"role sequence: '{sequence.path}' must hold messages with "
                   "x, y, z", MAPPING_BAD_FIELD)
    element = table[sequence.field.type.ros_name()]
    types = set()
    for axis in "xyz":
        item = next((f for f in element.fields if f.name == axis), None)
        if item is None or item.container != SCALAR or \
                item.type.name not in POINT_ELEMENT_TYPES or not item.type.is_primitive:
            raise fail("fields", f"role sequence: elements of '{sequence.path}' "
                       f"({element.ros_type}) need a float32 or float64 field '{axis}'",
                       MAPPING_BAD_FIELD)
        types.add(item.type.name)
    if len(types) != 1:
        raise fail("fields", f"role sequence: x, y, z of {element.ros_type} must have "
                   "one type", MAPPING_BAD_FIELD)


def _shape_hint(resolved) -> str:
    if resolved.field.container == SCALAR and resolved.field.type.is_message:
        return " (for a single point or vector use kind \"point\" with role point)"
    return ""


def _view(rule, table):
    element = table[rule.roles["sequence"].field.type.ros_name()]
    x = next(f for f in element.fields if f.name == "x")
    return {"point_type": CPP_FIELD_TYPES[x.type.name]}


KIND = Kind(name="points", vtk_types=("vtkPoints",), roles=(("sequence", Shape(sequence=True)),),
            scalable=("sequence",), check=_check, shape_hint=_shape_hint, view=_view)
