"""Kind `value`: one primitive field <-> a plain C++ value (std::string, bool, int, vtkTypeInt64,
double). Its converter functions are laid out in templates/convert/_kinds.j2 (no body template)."""
from __future__ import annotations

from typing import Dict, Tuple

from ..errors import MAPPING_BAD_KIND
from .base import CPP_FIELD_TYPES, FLOAT_TYPES, NUMERIC_TYPES, VALUE, Kind, prim

# The C++ value type -> the primitive field types it can hold without loss.
VALUE_TYPES: Dict[str, Tuple[str, ...]] = {
    "std::string": ("string",),
    "bool": ("bool",),
    "int": ("int8", "uint8", "int16", "uint16", "int32"),
    "vtkTypeInt64": ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64"),
    "double": FLOAT_TYPES,
}


def _check(vtk_type, roles, table, fail) -> None:
    primitive = roles["value"].primitive
    if primitive not in VALUE_TYPES[vtk_type]:
        raise fail("vtk_type", f"a {primitive} field cannot be held in '{vtk_type}' "
                   f"(that takes {' or '.join(VALUE_TYPES[vtk_type])})", MAPPING_BAD_KIND)


def _scalable_paths(roles, element_roles) -> Dict[str, str]:
    # Only floating-point values are lengths; an integer count never is.
    value = roles["value"]
    return {value.path: "value"} if value.primitive in FLOAT_TYPES else {}


def _view(rule, table):
    value = rule.roles["value"]
    return {
        "value_type": rule.vtk_type,
        "value_param": "const std::string&" if rule.vtk_type == "std::string" else rule.vtk_type,
        "value_field_cpp": CPP_FIELD_TYPES[value.field.type.name],
        "value_scaled": "value" in rule.scaled_roles and value.primitive in FLOAT_TYPES,
        "value_default": {"std::string": "std::string()", "bool": "false"}.get(rule.vtk_type,
                                                                               "0"),
    }


KIND = Kind(name="value", vtk_types=tuple(VALUE_TYPES),
            roles=(("value", prim("bool", "string", *NUMERIC_TYPES)),), scalable=("value",),
            signature=VALUE, check=_check, scalable_paths=_scalable_paths, view=_view)
