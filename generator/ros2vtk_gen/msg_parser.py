"""Parser of the ROS 2 .msg / .srv grammar (as rosidl_adapter reads it) into model objects.

Hand-written because rosidl_adapter is not installable without a ROS distribution and the grammar
is small; the rules below follow its documented behaviour:

  line       := [field | constant] [# comment]
  field      := TYPE NAME [DEFAULT]
  constant   := PRIMITIVE NAME '=' VALUE
  TYPE       := [package '/'] Name | primitive ['<=' N] , then optionally [N] | [<=N] | []
  service    := request lines, a line '---', response lines
  action     := goal lines, '---', result lines, '---', feedback lines

A '#' inside a quoted string is not a comment. Every problem raises SpecError(file, line, ...).
"""
from __future__ import annotations

import math
import os
import re
from typing import Dict, Iterable, List, Optional, Sequence, Tuple, Union

from . import errors
from .errors import SpecError
from .model import (ARRAY, BOUNDED_SEQUENCE, PRIMITIVE_TYPES, SCALAR, SEQUENCE, Action, BaseType,
                    Constant, Field, Message, Service, Value)

PACKAGE_RE = re.compile(r"^[a-z]([a-z0-9_]?[a-z0-9]+)*$")
MESSAGE_RE = re.compile(r"^[A-Z][A-Za-z0-9]*$")
FIELD_RE = re.compile(r"^[a-z]([a-z0-9_]?[a-z0-9]+)*$")
CONSTANT_RE = re.compile(r"^[A-Z]([A-Z0-9_]?[A-Z0-9]+)*$")
TYPE_RE = re.compile(
    r"^(?P<base>[A-Za-z][A-Za-z0-9_]*(?:/[A-Za-z][A-Za-z0-9_]*)?)"
    r"(?:<=(?P<string_bound>[0-9]+))?"
    r"(?:\[(?P<bounded><=)?(?P<size>[0-9]*)\])?$")
CONSTANT_LINE_RE = re.compile(r"^(?P<name>[A-Za-z_][A-Za-z0-9_]*)\s*=(?P<value>.*)$")

INTEGER_RANGES = {
    "byte": (0, 255), "char": (0, 255),
    "int8": (-2**7, 2**7 - 1), "uint8": (0, 2**8 - 1),
    "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1),
    "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
    "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1),
}
FLOAT32_MAX = 3.4028234663852886e38

# Names the generated C++ cannot use as members: keywords, and our own member function.
RESERVED_FIELD_NAMES = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char16_t char32_t
class compl const constexpr const_cast continue decltype default delete do double dynamic_cast
else enum explicit export extern false float for friend goto if inline int long mutable namespace
new noexcept not not_eq nullptr operator or or_eq private protected public register
reinterpret_cast return short signed sizeof static static_assert static_cast struct switch
template this thread_local throw true try typedef typeid typename union unsigned using virtual
void volatile wchar_t while xor xor_eq type_support
""".split())

ScalarValue = Union[bool, int, float, str]


class _Located:
    """Raises SpecErrors at one line of one file."""

    def __init__(self, path: str, line: int) -> None:
        self.path = path
        self.line = line

    def error(self, message: str, code: str = errors.BAD_LINE) -> SpecError:
        return SpecError(self.path, self.line, message, code)


def strip_comment(line: str) -> str:
    """The line without its comment; '#' inside single or double quotes is kept."""
    quote: Optional[str] = None
    escaped = False
    for index, char in enumerate(line):
        if escaped:
            escaped = False
        elif quote is not None and char == "\\":
            escaped = True
        elif quote is not None and char == quote:
            quote = None
        elif quote is None and char in "\"'":
            quote = char
        elif quote is None and char == "#":
            return line[:index]
    return line


def parse_type(text: str, package: str, at: _Located) -> Tuple[BaseType, str, int]:
    """`TYPE` -> (element type, container kind, N)."""
    match = TYPE_RE.match(text)
    if not match:
        raise at.error(f"malformed type '{text}'", errors.BAD_TYPE)
    base = match.group("base")
    string_bound = 0
    if match.group("string_bound") is not None:
        if base not in ("string", "wstring"):
            raise at.error(f"only string and wstring take a bound '<=N', not '{base}'",
                           errors.BAD_TYPE)
        string_bound = int(match.group("string_bound"))
        if string_bound <= 0:
            raise at.error(f"string bound must be positive in '{text}'", errors.BAD_TYPE)
    if "/" in base:
        type_package, type_name = base.split("/")
        if not PACKAGE_RE.match(type_package):
            raise at.error(f"invalid package name '{type_package}' in type '{text}'",
                           errors.BAD_TYPE)
        if not MESSAGE_RE.match(type_name):
            raise at.error(f"invalid message type name '{type_name}' in type '{text}'",
                           errors.BAD_TYPE)
        element = BaseType(type_name, type_package)
    elif base in PRIMITIVE_TYPES:
        element = BaseType(base, None, string_bound)
    elif MESSAGE_RE.match(base):
        element = BaseType(base, package)  # short names live in the same package
    else:
        raise at.error(f"unknown primitive type '{base}'", errors.BAD_TYPE)

    if text.endswith("]"):
        size_text = match.group("size")
        if match.group("bounded"):
            if not size_text:
                raise at.error(f"bounded sequence '{text}' needs a size: T[<=N]", errors.BAD_TYPE)
            container = BOUNDED_SEQUENCE
        elif size_text:
            container = ARRAY
        else:
            container = SEQUENCE
        size = int(size_text) if size_text else 0
        if container != SEQUENCE and size <= 0:
            raise at.error(f"array size must be positive in '{text}'", errors.BAD_TYPE)
        return element, container, size
    return element, SCALAR, 0


def _unquote(text: str, at: _Located) -> str:
    """'abc' or "abc" with backslash escapes -> abc."""
    quote = text[0]
    if len(text) < 2 or text[-1] != quote:
        raise at.error(f"unterminated string {text}", errors.BAD_VALUE)
    body = text[1:-1]
    result: List[str] = []
    escapes = {"n": "\n", "t": "\t", "\\": "\\", "'": "'", '"': '"'}
    index = 0
    while index < len(body):
        char = body[index]
        if char == "\\" and index + 1 < len(body):
            result.append(escapes.get(body[index + 1], "\\" + body[index + 1]))
            index += 2
            continue
        if char == quote:
            raise at.error(f"unescaped quote inside string {text}", errors.BAD_VALUE)
        result.append(char)
        index += 1
    return "".join(result)


def parse_scalar(text: str, element: BaseType, at: _Located) -> ScalarValue:
    """One value of a primitive type, range-checked."""
    text = text.strip()
    name = element.name
    if element.is_string:
        value = _unquote(text, at) if text[:1] in ("'", '"') else text
        if element.string_bound and len(value) > element.string_bound:
            raise at.error(f"string value '{value}' is longer than its bound {element.string_bound}",
                           errors.BAD_VALUE)
        return value
    if not text:
        raise at.error(f"missing value for {name}", errors.BAD_VALUE)
    if name == "bool":
        lowered = text.lower()
        if lowered in ("true", "1"):
            return True
        if lowered in ("false", "0"):
            return False
        raise at.error(f"'{text}' is not a bool (true, false, 1 or 0)", errors.BAD_VALUE)
    if name in INTEGER_RANGES:
        try:
            number = int(text, 0)
        except ValueError:
            raise at.error(f"'{text}' is not an integer for {name}", errors.BAD_VALUE) from None
        low, high = INTEGER_RANGES[name]
        if not low <= number <= high:
            raise at.error(f"{number} is out of range for {name} [{low}, {high}]", errors.BAD_VALUE)
        return number
    try:
        real = float(text)
    except ValueError:
        raise at.error(f"'{text}' is not a number for {name}", errors.BAD_VALUE) from None
    if not math.isfinite(real):
        raise at.error(f"'{text}' is not a finite number", errors.BAD_VALUE)
    if name == "float32" and abs(real) > FLOAT32_MAX:
        raise at.error(f"{text} is out of range for float32", errors.BAD_VALUE)
    return real


def _split_list(text: str, at: _Located) -> List[str]:
    """'[a, "b,c"]' -> ['a', '"b,c"'] (commas inside quotes do not split)."""
    text = text.strip()
    if not (text.startswith("[") and text.endswith("]")):
        raise at.error(f"array default must be written [v1, v2, ...], got '{text}'",
                       errors.BAD_VALUE)
    body = text[1:-1].strip()
    if not body:
        return []
    items: List[str] = []
    current: List[str] = []
    quote: Optional[str] = None
    escaped = False
    for char in body:
        if escaped:
            escaped = False
        elif quote is not None and char == "\\":
            escaped = True
        elif quote is not None and char == quote:
            quote = None
        elif quote is None and char in "\"'":
            quote = char
        elif quote is None and char == ",":
            items.append("".join(current).strip())
            current = []
            continue
        current.append(char)
    items.append("".join(current).strip())
    if any(not item for item in items):
        raise at.error(f"empty element in array default '{text}'", errors.BAD_VALUE)
    return items


def parse_default(text: str, element: BaseType, container: str, size: int,
                  at: _Located) -> Value:
    if element.is_message:
        raise at.error("fields of message type cannot have a default value", errors.BAD_VALUE)
    if container == SCALAR:
        return parse_scalar(text, element, at)
    values = tuple(parse_scalar(item, element, at) for item in _split_list(text, at))
    if container == ARRAY and len(values) != size:
        raise at.error(f"array default has {len(values)} elements, the type needs {size}",
                       errors.BAD_VALUE)
    if container == BOUNDED_SEQUENCE and len(values) > size:
        raise at.error(f"sequence default has {len(values)} elements, the bound is {size}",
                       errors.BAD_VALUE)
    return values


def parse_message_text(text: str, package: str, name: str, *, kind: str = "msg",
                       path: str = "<string>", spec: Optional[str] = None,
                       lines: Optional[Sequence[Tuple[int, str]]] = None) -> Message:
    """Parses the body of a .msg (or one half of a .srv given as numbered `lines`)."""
    if not PACKAGE_RE.match(package):
        raise SpecError(path, 1, f"invalid package name '{package}'", errors.BAD_PATH)
    numbered = list(lines) if lines is not None else list(enumerate(text.splitlines(), start=1))
    fields: List[Field] = []
    constants: List[Constant] = []
    seen: Dict[str, int] = {}
    for number, raw in numbered:
        at = _Located(path, number)
        line = strip_comment(raw).strip()
        if not line:
            continue
        parts = line.split(None, 1)
        if len(parts) < 2:
            raise at.error(f"expected 'TYPE NAME' or 'TYPE NAME=VALUE', got '{line}'")
        type_text, rest = parts
        constant = CONSTANT_LINE_RE.match(rest)
        if constant:
            item_name = constant.group("name")
            element, container, _ = parse_type(type_text, package, at)
            if not element.is_primitive or container != SCALAR:
                raise at.error(f"constant '{item_name}' must have a primitive, non-array type",
                               errors.BAD_TYPE)
            if not CONSTANT_RE.match(item_name):
                raise at.error(f"invalid constant name '{item_name}' (use UPPER_CASE)",
                               errors.BAD_NAME)
            value_text = constant.group("value").strip()
            if not value_text and not element.is_string:
                raise at.error(f"constant '{item_name}' has no value", errors.BAD_VALUE)
            value = parse_scalar(value_text, element, at)
            _remember(seen, item_name, at)
            constants.append(Constant(item_name, element, value, number))
            continue
        name_and_default = rest.split(None, 1)
        item_name = name_and_default[0]
        element, container, size = parse_type(type_text, package, at)
        if not FIELD_RE.match(item_name) or "__" in item_name:
            raise at.error(f"invalid field name '{item_name}' (use lower_snake_case)",
                           errors.BAD_NAME)
        if item_name in RESERVED_FIELD_NAMES:
            raise at.error(f"field name '{item_name}' is reserved in the generated C++",
                           errors.BAD_NAME)
        default = None
        if len(name_and_default) == 2:
            default = parse_default(name_and_default[1], element, container, size, at)
        _remember(seen, item_name, at)
        fields.append(Field(item_name, element, container, size, default, number))
    display = spec if spec is not None else f"{package}/{kind}/{name}.{kind}"
    return Message(package, kind, name, tuple(fields), tuple(constants), display, path,
                   text=text if lines is None else "")


def _remember(seen: Dict[str, int], name: str, at: _Located) -> None:
    if name in seen:
        raise at.error(f"'{name}' is already defined on line {seen[name]}", errors.DUPLICATE)
    seen[name] = at.line


def parse_service_text(text: str, package: str, name: str, *, path: str = "<string>",
                       spec: Optional[str] = None) -> Service:
    """Parses a .srv: request lines, `---`, response lines."""
    numbered = list(enumerate(text.splitlines(), start=1))
    separators = [n for n, raw in numbered if strip_comment(raw).strip() == "---"]
    if not separators:
        raise SpecError(path, max(len(numbered), 1),
                        "a service needs a '---' line between request and response",
                        errors.BAD_SERVICE)
    if len(separators) > 1:
        raise SpecError(path, separators[1], "a service has exactly one '---' line",
                        errors.BAD_SERVICE)
    cut = separators[0]
    display = spec if spec is not None else f"{package}/srv/{name}.srv"
    request = parse_message_text("", package, f"{name}_Request", kind="srv", path=path,
                                 spec=display, lines=numbered[:cut - 1])
    response = parse_message_text("", package, f"{name}_Response", kind="srv", path=path,
                                  spec=display, lines=numbered[cut:])
    return Service(package, name, request, response, display, path, text=text)


# The fixed types every action's synthesized types nest (rosidl_adapter action.idl.em).
UUID_TYPE = BaseType("UUID", "unique_identifier_msgs")
TIME_TYPE = BaseType("Time", "builtin_interfaces")


def parse_action_text(text: str, package: str, name: str, *, path: str = "<string>",
                      spec: Optional[str] = None) -> Action:
    """Parses a .action (goal `---` result `---` feedback) and synthesizes, as rosidl does,
    X_SendGoal (goal_id, goal / accepted, stamp), X_GetResult (goal_id / status, result) and
    X_FeedbackMessage (goal_id, feedback), all of kind "action"."""
    numbered = list(enumerate(text.splitlines(), start=1))
    separators = [n for n, raw in numbered if strip_comment(raw).strip() == "---"]
    if len(separators) != 2:
        line = separators[2] if len(separators) > 2 else max(len(numbered), 1)
        raise SpecError(path, line, "an action needs exactly two '---' lines (goal --- result "
                        f"--- feedback), found {len(separators)}", errors.BAD_SERVICE)
    first, second = separators
    display = spec if spec is not None else f"{package}/action/{name}.action"

    def block(suffix: str, lines: Sequence[Tuple[int, str]]) -> Message:
        return parse_message_text("", package, f"{name}_{suffix}", kind="action", path=path,
                                  spec=display, lines=lines)

    def synthesized(suffix: str, fields: Sequence[Field]) -> Message:
        return Message(package, "action", f"{name}_{suffix}", tuple(fields), (), display, path)

    def own(suffix: str) -> BaseType:
        return BaseType(f"{name}_{suffix}", package, interface="action")

    goal = block("Goal", numbered[:first - 1])
    result = block("Result", numbered[first:second - 1])
    feedback = block("Feedback", numbered[second:])
    goal_id = Field("goal_id", UUID_TYPE, line=1)  # errors about it point at the file's top
    send_goal = Service(package, f"{name}_SendGoal",
                        synthesized("SendGoal_Request", [goal_id, Field("goal", own("Goal"))]),
                        synthesized("SendGoal_Response", [Field("accepted", BaseType("bool")),
                                                          Field("stamp", TIME_TYPE)]),
                        display, path, kind="action")
    get_result = Service(package, f"{name}_GetResult",
                         synthesized("GetResult_Request", [goal_id]),
                         synthesized("GetResult_Response", [Field("status", BaseType("int8")),
                                                            Field("result", own("Result"))]),
                         display, path, kind="action")
    feedback_message = synthesized("FeedbackMessage", [goal_id, Field("feedback", own("Feedback"))])
    return Action(package, name, goal, result, feedback, send_goal, get_result, feedback_message,
                  display, path, text=text)


SPEC_KINDS = ("msg", "srv", "action")


def spec_identity(path: str) -> Tuple[str, str, str]:
    """`.../<package>/<msg|srv|action>/<Name>.<msg|srv|action>` -> (package, kind, Name)."""
    directory, file_name = os.path.split(os.path.normpath(path))
    stem, extension = os.path.splitext(file_name)
    kind = extension[1:]
    parent = os.path.basename(directory)
    package = os.path.basename(os.path.dirname(directory))
    if kind not in SPEC_KINDS or parent != kind:
        raise SpecError(path, 1, f"spec files must be laid out as <package>/{kind or 'msg'}/"
                        f"<Name>.{kind or 'msg'} (.msg, .srv or .action)", errors.BAD_PATH)
    if not PACKAGE_RE.match(package):
        raise SpecError(path, 1, f"invalid package name '{package}' (from the spec's folder)",
                        errors.BAD_PATH)
    if not MESSAGE_RE.match(stem):
        raise SpecError(path, 1, f"invalid type name '{stem}' (use CamelCase)", errors.BAD_PATH)
    return package, kind, stem


def parse_spec_file(path: str) -> Union[Message, Service, Action]:
    """Reads one spec file; its package, kind and name come from its path."""
    package, kind, name = spec_identity(path)
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
    except OSError as error:
        raise SpecError(path, 1, f"cannot read spec: {error.strerror}", errors.BAD_PATH) from None
    except UnicodeDecodeError:
        raise SpecError(path, 1, "spec is not UTF-8 text", errors.BAD_PATH) from None
    display = f"{package}/{kind}/{name}.{kind}"
    if kind == "srv":
        return parse_service_text(text, package, name, path=path, spec=display)
    if kind == "action":
        return parse_action_text(text, package, name, path=path, spec=display)
    return parse_message_text(text, package, name, kind="msg", path=path, spec=display)


def messages_of(specs: Iterable[Union[Message, Service, Action]]) -> List[Message]:
    """Every message, services flattened into their request and response, actions into the
    eight messages they synthesize."""
    result: List[Message] = []
    for spec in specs:
        if isinstance(spec, Action):
            result.extend(spec.messages)
        elif isinstance(spec, Service):
            result.extend((spec.request, spec.response))
        else:
            result.append(spec)
    return result


def resolve(specs: Sequence[Union[Message, Service, Action]],
            known: Sequence[Union[Message, Service, Action]] = ()) -> Dict[str, Message]:
    """Checks that every referenced type exists (in `specs` or `known`) and that no message
    contains itself. Returns all messages by ROS name (`pkg/msg/Type`)."""
    table: Dict[str, Message] = {}
    for message in messages_of(list(known) + list(specs)):
        if message.ros_type in table and table[message.ros_type].source != message.source:
            raise SpecError(message.source, 1, f"type {message.ros_type} is defined twice "
                            f"(also in {table[message.ros_type].source})", errors.DUPLICATE)
        table[message.ros_type] = message
    for message in messages_of(specs):
        for item in message.fields:
            if item.type.is_message and item.type.ros_name() not in table:
                same_package = sorted(m.name for m in table.values()
                                      if m.package == item.type.package and m.kind == "msg")
                hint = (f"; {item.type.package} has: {', '.join(same_package)}" if same_package
                        else f"; no spec of package {item.type.package} was given")
                raise SpecError(message.source, item.line,
                                f"unknown type '{item.type.package}/{item.type.name}' of field "
                                f"'{item.name}'{hint}", errors.UNKNOWN_TYPE)
    for message in messages_of(specs):
        _check_no_cycle(message, table, [])
    return table


def _check_no_cycle(message: Message, table: Dict[str, Message], stack: List[str]) -> None:
    if message.ros_type in stack:
        chain = " -> ".join(stack + [message.ros_type])
        raise SpecError(message.source, 1, f"message contains itself: {chain}",
                        errors.UNKNOWN_TYPE)
    for item in message.fields:
        if item.type.is_message:
            _check_no_cycle(table[item.type.ros_name()], table, stack + [message.ros_type])
