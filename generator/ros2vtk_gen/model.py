"""The parsed interface model: frozen dataclasses, no behaviour beyond small queries."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Tuple, Union

# Primitive .msg types and their size on the wire (strings: None, variable).
PRIMITIVE_SIZES = {
    "bool": 1, "byte": 1, "char": 1,
    "int8": 1, "uint8": 1, "int16": 2, "uint16": 2,
    "int32": 4, "uint32": 4, "int64": 8, "uint64": 8,
    "float32": 4, "float64": 8,
}
STRING_TYPES = ("string", "wstring")
PRIMITIVE_TYPES = tuple(PRIMITIVE_SIZES) + STRING_TYPES

# A default or constant value once parsed: bool, int, float, str, or a tuple of those.
Value = Union[bool, int, float, str, Tuple[Union[bool, int, float, str], ...]]


@dataclass(frozen=True)
class BaseType:
    """Element type of a field: a primitive (package None) or a message `package/name`."""

    name: str
    package: Optional[str] = None
    string_bound: int = 0  # N of string<=N; 0 = unbounded

    @property
    def is_primitive(self) -> bool:
        return self.package is None

    @property
    def is_string(self) -> bool:
        return self.package is None and self.name in STRING_TYPES

    @property
    def is_message(self) -> bool:
        return self.package is not None

    def ros_name(self, kind: str = "msg") -> str:
        """`std_msgs/msg/Header` for messages; the spelling of the spec for primitives."""
        if self.package is not None:
            return f"{self.package}/{kind}/{self.name}"
        return f"{self.name}<={self.string_bound}" if self.string_bound else self.name


# Container kinds of a field.
SCALAR = "none"
ARRAY = "array"              # T[N]
BOUNDED_SEQUENCE = "bounded"  # T[<=N]
SEQUENCE = "sequence"        # T[]


@dataclass(frozen=True)
class Field:
    name: str
    type: BaseType
    container: str = SCALAR
    size: int = 0  # N of T[N] / T[<=N]
    default: Optional[Value] = None
    line: int = 0

    @property
    def is_container(self) -> bool:
        return self.container != SCALAR


@dataclass(frozen=True)
class Constant:
    name: str
    type: BaseType
    value: Value
    line: int = 0


@dataclass(frozen=True)
class Message:
    """A message type. For services, `kind` is "srv" and `name` ends in _Request/_Response."""

    package: str
    kind: str
    name: str
    fields: Tuple[Field, ...]
    constants: Tuple[Constant, ...]
    spec: str  # spec path as shown in banners: `<pkg>/<kind>/<File>`
    source: str = field(default="", compare=False)  # path as given, for error messages

    @property
    def ros_type(self) -> str:
        return f"{self.package}/{self.kind}/{self.name}"

    @property
    def is_empty(self) -> bool:
        return not self.fields


@dataclass(frozen=True)
class Service:
    package: str
    name: str
    request: Message
    response: Message
    spec: str
    source: str = field(default="", compare=False)

    @property
    def ros_type(self) -> str:
        return f"{self.package}/srv/{self.name}"
