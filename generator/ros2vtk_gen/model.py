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
    interface: str = "msg"  # "action" for the types synthesized from a .action (X_Goal, ...)

    @property
    def is_primitive(self) -> bool:
        return self.package is None

    @property
    def is_string(self) -> bool:
        return self.package is None and self.name in STRING_TYPES

    @property
    def is_message(self) -> bool:
        return self.package is not None

    def ros_name(self) -> str:
        """`std_msgs/msg/Header` for messages (`pkg/action/X_Goal` for the types an action
        synthesizes); the spelling of the spec for primitives."""
        if self.package is not None:
            return f"{self.package}/{self.interface}/{self.name}"
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
    """A message type. For services, `kind` is "srv" and `name` ends in _Request/_Response; the
    types synthesized from a .action have `kind` "action" (X_Goal, X_SendGoal_Request, ...)."""

    package: str
    kind: str
    name: str
    fields: Tuple[Field, ...]
    constants: Tuple[Constant, ...]
    spec: str  # spec path as shown in banners: `<pkg>/<kind>/<File>`
    source: str = field(default="", compare=False)  # path as given, for error messages
    # The .msg file's text (what a node serves as its TypeSource); "" for the halves of a .srv
    # and the types a .action synthesizes, which rosidl calls "implicit".
    text: str = field(default="", compare=False)

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
    kind: str = "srv"  # "action" for X_SendGoal / X_GetResult of an action
    text: str = field(default="", compare=False)  # the .srv file's text ("" for an action's)

    @property
    def ros_type(self) -> str:
        return f"{self.package}/{self.kind}/{self.name}"


@dataclass(frozen=True)
class Action:
    """A .action and what rosidl synthesizes from it (all in `pkg/action/`): X_Goal, X_Result,
    X_Feedback (the three blocks), the services X_SendGoal and X_GetResult and the message
    X_FeedbackMessage."""

    package: str
    name: str
    goal: Message
    result: Message
    feedback: Message
    send_goal: Service
    get_result: Service
    feedback_message: Message
    spec: str
    source: str = field(default="", compare=False)
    text: str = field(default="", compare=False)  # the .action file's text

    @property
    def ros_type(self) -> str:
        return f"{self.package}/action/{self.name}"

    @property
    def messages(self) -> Tuple[Message, ...]:
        """Every message type of the action, services flattened, in rosidl's order."""
        return (self.goal, self.result, self.feedback, self.send_goal.request,
                self.send_goal.response, self.get_result.request, self.get_result.response,
                self.feedback_message)
