"""What a mapping kind is: the roles it reads (with the field shapes they need), the VTK types it
makes, what it can scale, and the hooks for rules a Shape cannot say.

One module per kind in this folder defines `KIND` (or `KINDS`, a tuple); its code layout is the
template `templates/convert/kinds/<name>.j2`. __init__.py collects them, so adding a kind is one
module, one template and their tests (docs/extending.md).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Dict, Mapping, Optional, Tuple

INTEGER_TYPES = ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64")
FLOAT_TYPES = ("float32", "float64")
NUMERIC_TYPES = INTEGER_TYPES + ("uint64",) + FLOAT_TYPES

# C++ type of a primitive field (the struct member type the generated message uses).
CPP_FIELD_TYPES = {
    "bool": "bool", "byte": "uint8_t", "char": "uint8_t",
    "int8": "int8_t", "uint8": "uint8_t", "int16": "int16_t", "uint16": "uint16_t",
    "int32": "int32_t", "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t",
    "float32": "float", "float64": "double", "string": "std::string",
}

# How the converter functions of a kind look: a plain C++ value, no value at all (the message
# has no fields), or a VTK object filled in place.
VALUE, EMPTY, OBJECT = "value", "empty", "object"


@dataclass(frozen=True)
class Shape:
    """The type a role's field must have: a primitive of `primitives`, or a message that has
    at least `members` (each a Shape), held once (`sequence` False) or as a sequence."""

    primitives: Tuple[str, ...] = ()
    members: Tuple[Tuple[str, "Shape"], ...] = ()
    sequence: bool = False
    # N > 0: a fixed array T[N] of exactly that size (CameraInfo's float64[9] K).
    array_size: int = 0

    def describe(self) -> str:
        if self.array_size:
            return f"{' or '.join(self.primitives)}[{self.array_size}]"
        if self.primitives:
            text = " or ".join(self.primitives)
        elif self.members:
            text = "message with " + ", ".join(name for name, _ in self.members)
        else:
            text = "messages" if self.sequence else "message"
        return f"sequence of {text}" if self.sequence else text


def prim(*names: str, sequence: bool = False, array_size: int = 0) -> Shape:
    return Shape(primitives=names, sequence=sequence, array_size=array_size)


def struct(sequence: bool = False, **members: Shape) -> Shape:
    return Shape(members=tuple(members.items()), sequence=sequence)


XYZ_FLOAT64 = struct(x=prim("float64"), y=prim("float64"), z=prim("float64"))
QUATERNION = struct(x=prim("float64"), y=prim("float64"), z=prim("float64"), w=prim("float64"))

# Hook signatures (mapping.py calls them; `roles` maps role -> ResolvedField, or a tuple of them
# for list roles; `fail(key, text, code)` makes the located MappingError):
#   check(vtk_type, roles, table, fail)          rules a Shape cannot say
#   scalable_paths(roles, element_roles) -> {path: role}   what `lengths` may list
#   shape_hint(resolved) -> str                  appended to a role's shape error
#   view(rule, table) -> dict                    extra template values (nodes.rule_view); a
#                                                stateful kind returns state_class / state_header
#                                                (the C++ state its subscriber folds messages into,
#                                                see marker_array.py and docs/extending.md)
Check = Callable[..., None]


@dataclass(frozen=True)
class Kind:
    """One conversion pattern. `element_roles` are read relative to the element of the
    `sequence` role (PoseArray's `position` inside each of `poses`); `list_roles` take a list of
    paths (vector_array's components); `optional_roles` may be left out of a rule; `scalable`
    names the roles whose field may appear in `lengths`; `takes_encoding` adds the image encoding parameter to VTKToROS2 and an `Encoding`
    property to the publisher node."""

    name: str
    vtk_types: Tuple[str, ...]
    roles: Tuple[Tuple[str, Shape], ...] = ()
    element_roles: Tuple[Tuple[str, Shape], ...] = ()
    list_roles: Tuple[str, ...] = ()
    # Roles a rule may leave out (a lab's Marker-like type may have no `lifetime`); the
    # templates test `"role" in rule.roles` / `rule.element_roles` before reading one.
    optional_roles: Tuple[str, ...] = ()
    scalable: Tuple[str, ...] = ()
    signature: str = OBJECT
    takes_encoding: bool = False
    # The VTK class Publish and VTKToROS2 take when broader than what the subscriber gives
    # (a multi-array publisher takes any vtkDataArray, values converted with a range check).
    publish_input: str = ""
    check: Optional[Check] = None
    scalable_paths: Optional[Callable[..., Dict[str, str]]] = None
    # A `lengths` entry ending so names a place inside the bytes, not a field (pointcloud2).
    pseudo_length_suffix: str = ""
    shape_hint: Optional[Callable[..., str]] = None
    view: Optional[Callable[..., Mapping[str, object]]] = None

    def role_names(self) -> Tuple[str, ...]:
        return tuple(name for name, _ in self.roles + self.element_roles)

    def paths_to_scale(self, roles, element_roles) -> Dict[str, str]:
        """{path as written in `lengths`: role} for every scalable role of a rule."""
        if self.scalable_paths is not None:
            return self.scalable_paths(roles, element_roles)
        paths: Dict[str, str] = {}
        for role in self.scalable:
            if role in element_roles:
                paths[f"{roles['sequence'].path}.{element_roles[role].path}"] = role
            elif role in roles:
                paths[roles[role].path] = role
        return paths
