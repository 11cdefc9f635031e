"""Kinds `multiarray_table` and `multiarray_array`: a MultiArrayLayout + int64/float64 data
<-> a vtkTable (one column per last-dimension index) or a flat VTK array whose class follows
the data's element type. One module: the two differ only in what they make."""
from __future__ import annotations

from ..errors import MAPPING_BAD_KIND
from .base import CPP_FIELD_TYPES, Kind, prim, struct

MULTI_ARRAY_LAYOUT = struct(
    dim=struct(sequence=True, label=prim("string"), size=prim("uint32"),
               stride=prim("uint32")),
    data_offset=prim("uint32"))
ROLES = (("layout", MULTI_ARRAY_LAYOUT), ("data", prim("int64", "float64", sequence=True)))
# multiarray_array: the array class follows the data's element type.
ARRAY_TYPES = {"int64": "vtkTypeInt64Array", "float64": "vtkDoubleArray"}


def _check_array(vtk_type, roles, table, fail) -> None:
    wanted = ARRAY_TYPES[roles["data"].primitive]
    if vtk_type != wanted:
        raise fail("vtk_type", f"{roles['data'].primitive} data goes into {wanted}, not "
                   f"'{vtk_type}'", MAPPING_BAD_KIND)


def _view(rule, table):
    return {"data_type": CPP_FIELD_TYPES[rule.roles["data"].field.type.name]}


KINDS = (
    Kind(name="multiarray_table", vtk_types=("vtkTable",), roles=ROLES, view=_view),
    Kind(name="multiarray_array", vtk_types=tuple(ARRAY_TYPES.values()), roles=ROLES,
         check=_check_array, view=_view, publish_input="vtkDataArray"),
)
