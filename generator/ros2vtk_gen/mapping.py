"""Mapping rules (msg_specs/mappings/*.toml): load, validate against the parsed specs.

A rule says how one ROS message type becomes one VTK / C++ type: its short name (and aliases),
the conversion pattern (`kind`), the message fields the kind reads (`fields`, as dotted paths),
the Header to stamp on publish (`header`) and the fields that are lengths (`lengths`, scaled
metres <-> millimetres). The format is documented in msg_specs/mappings/README.md.

Every problem is a MappingError `file:line: message [R2V2xx]` (line of the rule, or of the key
when it can be found), so a user never sees a traceback. tomllib keeps no line numbers, so the
lines are found by scanning the text for `[[mapping]]` headers and `key =` lines.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Sequence, Tuple, Union

from .errors import (MAPPING_BAD_FIELD, MAPPING_BAD_FILE, MAPPING_BAD_KEY, MAPPING_BAD_KIND,
                     MAPPING_BAD_LENGTHS, MAPPING_DUPLICATE, MAPPING_UNKNOWN_ROS_TYPE,
                     GeneratorError)
from .kinds import KINDS
from .kinds.base import Kind, Shape
from .model import ARRAY, BOUNDED_SEQUENCE, SCALAR, SEQUENCE, Field, Message

# Error codes (docs/errors.md), defined in errors.py beside the parse codes.
BAD_FILE = MAPPING_BAD_FILE
BAD_KEY = MAPPING_BAD_KEY
UNKNOWN_ROS_TYPE = MAPPING_UNKNOWN_ROS_TYPE
BAD_KIND = MAPPING_BAD_KIND
BAD_FIELD = MAPPING_BAD_FIELD
DUPLICATE = MAPPING_DUPLICATE
BAD_LENGTHS = MAPPING_BAD_LENGTHS

SHORT_NAME_RE = re.compile(r"^[A-Z][A-Za-z0-9]*$")
RULE_KEYS = ("short_name", "aliases", "ros_type", "vtk_type", "kind", "fields", "header",
             "child_frame", "lengths", "blank_message")
# What a publisher's GetBlankMessage hands out: its VTK value, or (as SlicerROS2 does for the
# types it generates a message class for) a message object of its ROS type whose fields of mapped
# types are VTK values (python/ros2vtk/blank_messages.py).
BLANK_MESSAGE_KINDS = ("vtk", "message")
HEADER_TYPE = "std_msgs/msg/Header"

class MappingError(GeneratorError):
    """A malformed or inconsistent mapping rule, located in its file."""

    def __init__(self, path: str, line: int, message: str, code: str) -> None:
        super().__init__(message, code)
        self.path = path
        self.line = line

    def __str__(self) -> str:
        where = f"{self.path}:{self.line}" if self.line else self.path
        return f"{where}: {self.message} [{self.code}]"


# ---------------------------------------------------------------- the validated rule

@dataclass(frozen=True)
class ResolvedField:
    """A field path checked against the specs: its C++ access path and its model field."""

    path: str         # as written in the rule ("pose.position")
    field: Field      # the last field of the path
    base: Message     # the message the path starts from

    @property
    def primitive(self) -> str:
        return self.field.type.name if self.field.type.is_primitive else ""


@dataclass(frozen=True)
class Rule:
    short_name: str
    aliases: Tuple[str, ...]
    ros_type: str
    vtk_type: str
    kind: str
    message: Message
    roles: Mapping[str, Union[ResolvedField, Tuple[ResolvedField, ...]]]
    element_roles: Mapping[str, ResolvedField]
    header: Optional[ResolvedField]
    scaled_roles: Tuple[str, ...]   # roles whose lengths are scaled
    source: str                     # mapping file as given
    line: int
    mapping_file: str = field(default="", compare=False)  # file name for banners
    child_frame: Optional[ResolvedField] = None  # a string the publisher fills (child_frame_id)
    blank_message: str = "vtk"  # one of BLANK_MESSAGE_KINDS


# ---------------------------------------------------------------- locating lines

class _Lines:
    """Line numbers of `[[mapping]]` tables and of `key =` lines inside them."""

    def __init__(self, text: str) -> None:
        self.lines = text.splitlines()
        self.starts = [i + 1 for i, line in enumerate(self.lines)
                       if re.match(r"^\s*\[\[\s*mapping\s*\]\]", line)]

    def rule(self, index: int) -> int:
        return self.starts[index] if index < len(self.starts) else 0

    def key(self, index: int, key: str) -> int:
        start = self.rule(index)
        if not start:
            return 0
        end = self.starts[index + 1] if index + 1 < len(self.starts) else len(self.lines) + 1
        pattern = re.compile(rf"^\s*{re.escape(key)}\s*=")
        for number in range(start + 1, end):
            if pattern.match(self.lines[number - 1]):
                return number
        return start


# ---------------------------------------------------------------- loading

def load_rule_tables(path: str) -> Tuple[List[dict], _Lines]:
    """The raw `[[mapping]]` tables of one file (TOML syntax checked, nothing else)."""
    try:
        with open(path, "rb") as handle:
            raw = handle.read()
    except OSError as error:
        raise MappingError(path, 0, f"cannot read mapping file: {error.strerror}",
                           BAD_FILE) from None
    try:
        text = raw.decode("utf-8")
        data = tomllib.loads(text)
    except UnicodeDecodeError:
        raise MappingError(path, 0, "mapping file is not UTF-8 text", BAD_FILE) from None
    except tomllib.TOMLDecodeError as error:
        match = re.search(r"\(at line (\d+), column \d+\)", str(error))
        line = int(match.group(1)) if match else 0
        message = re.sub(r"\s*\(at line \d+, column \d+\)", "", str(error))
        raise MappingError(path, line, f"not valid TOML: {message}", BAD_FILE) from None
    lines = _Lines(text)
    unknown = sorted(set(data) - {"mapping"})
    if unknown:
        raise MappingError(path, 1, f"unknown top-level key(s) {', '.join(unknown)} "
                           "(a mapping file holds [[mapping]] tables only)", BAD_KEY)
    tables = data.get("mapping", [])
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise MappingError(path, 1, "'mapping' must be an array of tables ([[mapping]])",
                           BAD_KEY)
    return tables, lines


def short_names_of(paths: Sequence[str]) -> List[str]:
    """Primary short names of every rule, in file order, reading only the TOML (what CMake
    needs at configure time to list the outputs; full validation happens at build time)."""
    names: List[str] = []
    for path in paths:
        tables, lines = load_rule_tables(path)
        for index, table in enumerate(tables):
            name = table.get("short_name")
            if not isinstance(name, str) or not SHORT_NAME_RE.match(name):
                raise MappingError(path, lines.key(index, "short_name"),
                                   f"rule {index + 1}: short_name must be a CamelCase "
                                   f"identifier, got {name!r}", BAD_KEY)
            names.append(name)
    return names


def load_rules(paths: Sequence[str], table: Mapping[str, Message]) -> List[Rule]:
    """Every rule of the files, validated against the messages in `table` (by ROS name)."""
    rules: List[Rule] = []
    for path in paths:
        tables, lines = load_rule_tables(path)
        for index, raw in enumerate(tables):
            rules.append(_rule(path, index, raw, lines, table))
    _check_unique(rules)
    return rules


def _rule(path: str, index: int, raw: dict, lines: _Lines,
          table: Mapping[str, Message]) -> Rule:
    line = lines.rule(index)

    def fail(key: Optional[str], message: str, code: str) -> MappingError:
        where = lines.key(index, key) if key else line
        label = raw.get("short_name") if isinstance(raw.get("short_name"), str) else index + 1
        return MappingError(path, where, f"rule {label}: {message}", code)

    unknown = sorted(set(raw) - set(RULE_KEYS))
    if unknown:
        raise fail(unknown[0], f"unknown key(s) {', '.join(unknown)} (known: "
                   f"{', '.join(RULE_KEYS)})", BAD_KEY)
    for key in ("short_name", "ros_type", "vtk_type", "kind"):
        if key not in raw:
            raise fail(None, f"'{key}' is required", BAD_KEY)
        if not isinstance(raw[key], str) or not raw[key]:
            raise fail(key, f"'{key}' must be a non-empty string", BAD_KEY)
    short_name = raw["short_name"]
    aliases = raw.get("aliases", [])
    if not isinstance(aliases, list) or not all(isinstance(a, str) for a in aliases):
        raise fail("aliases", "'aliases' must be a list of strings", BAD_KEY)
    for name in [short_name, *aliases]:
        if not SHORT_NAME_RE.match(name):
            raise fail("short_name" if name == short_name else "aliases",
                       f"'{name}' is not a valid short name (CamelCase letters and digits, as "
                       "it becomes part of a class name)", BAD_KEY)

    ros_type = _normalise_ros_type(raw["ros_type"])
    message = table.get(ros_type)
    if message is None:
        known = ", ".join(sorted(name for name in table if "/msg/" in name))
        raise fail("ros_type", f"unknown ROS type '{raw['ros_type']}' (known: {known})",
                   UNKNOWN_ROS_TYPE)

    kind_name = raw["kind"]
    kind = KINDS.get(kind_name)
    if kind is None:
        raise fail("kind", f"unknown kind '{kind_name}' (known: {', '.join(sorted(KINDS))})",
                   BAD_KIND)
    vtk_type = raw["vtk_type"]
    if vtk_type not in kind.vtk_types:
        raise fail("vtk_type", f"kind {kind_name} makes {' or '.join(kind.vtk_types)}, not "
                   f"'{vtk_type}'", BAD_KIND)

    fields = raw.get("fields", {})
    if not isinstance(fields, dict):
        raise fail("fields", "'fields' must be a table of role = \"path\"", BAD_KEY)
    known_roles = list(kind.role_names())
    extra = sorted(set(fields) - set(known_roles))
    if extra:
        raise fail("fields", f"kind {kind_name} has no role(s) {', '.join(extra)} (its roles: "
                   f"{', '.join(known_roles) or 'none'})", BAD_FIELD)
    missing = [name for name in known_roles
               if name not in fields and name not in kind.optional_roles]
    if missing:
        raise fail("fields", f"kind {kind_name} needs role(s) {', '.join(missing)}", BAD_FIELD)

    def resolve_role(name: str, shape: Shape, base: Message, prefix: str) -> ResolvedField:
        value = fields[name]
        if not isinstance(value, str) or not value:
            raise fail("fields", f"role {name} must be a field path string", BAD_FIELD)
        try:
            resolved = resolve_path(base, value, table)
        except ValueError as error:
            raise fail("fields", f"role {name}: {prefix}{error}", BAD_FIELD) from None
        try:
            check_shape(resolved.field, shape, table)
        except ValueError as error:
            hint = kind.shape_hint(resolved) if kind.shape_hint else ""
            raise fail("fields", f"role {name}: {prefix}{error}{hint}", BAD_FIELD) from None
        return resolved

    roles: Dict[str, Union[ResolvedField, Tuple[ResolvedField, ...]]] = {}
    for name, shape in kind.roles:
        if name not in fields:
            continue  # an optional role the rule leaves out
        if name in kind.list_roles:
            roles[name] = _resolve_components(fields[name], shape, message, table, fail)
        else:
            roles[name] = resolve_role(name, shape, message, "")
    element_roles: Dict[str, ResolvedField] = {}
    if kind.element_roles:
        sequence = roles["sequence"]
        assert isinstance(sequence, ResolvedField)
        if not sequence.field.type.is_message:
            raise fail("fields", f"role sequence: '{sequence.path}' must hold messages",
                       BAD_FIELD)
        element = table[sequence.field.type.ros_name()]
        for name, shape in kind.element_roles:
            if name not in fields:
                continue  # an optional role the rule leaves out
            element_roles[name] = resolve_role(name, shape, element,
                                               f"(inside each element of '{sequence.path}') ")
    if kind.check:
        kind.check(vtk_type, roles, table, fail)

    header = None
    if "header" in raw:
        if not isinstance(raw["header"], str) or not raw["header"]:
            raise fail("header", "'header' must be a field path string", BAD_KEY)
        try:
            header = resolve_path(message, raw["header"], table)
        except ValueError as error:
            raise fail("header", f"header: {error}", BAD_FIELD) from None
        if header.field.type.ros_name() != HEADER_TYPE or header.field.container != SCALAR:
            raise fail("header", f"header '{raw['header']}' is not a {HEADER_TYPE}", BAD_FIELD)

    child_frame = None
    if "child_frame" in raw:
        if not isinstance(raw["child_frame"], str) or not raw["child_frame"]:
            raise fail("child_frame", "'child_frame' must be a field path string", BAD_KEY)
        if header is None:
            raise fail("child_frame", "'child_frame' needs a 'header' (it names the child of the header's frame)",
                       BAD_KEY)
        try:
            child_frame = resolve_path(message, raw["child_frame"], table)
        except ValueError as error:
            raise fail("child_frame", f"child_frame: {error}", BAD_FIELD) from None
        if child_frame.field.type.ros_name() != "string" or child_frame.field.container != SCALAR:
            raise fail("child_frame", f"child_frame '{raw['child_frame']}' is not a string", BAD_FIELD)

    lengths = raw.get("lengths", [])
    if not isinstance(lengths, list) or not all(isinstance(p, str) for p in lengths):
        raise fail("lengths", "'lengths' must be a list of field paths", BAD_KEY)
    scaled = _scaled_roles(kind, lengths, roles, element_roles, message, table,
                           lambda text: fail("lengths", text, BAD_LENGTHS))

    blank_message = raw.get("blank_message", "vtk")
    if blank_message not in BLANK_MESSAGE_KINDS:
        raise fail("blank_message", f"'blank_message' must be one of "
                   f"{', '.join(BLANK_MESSAGE_KINDS)}, not {blank_message!r}", BAD_KEY)

    return Rule(short_name=short_name, aliases=tuple(aliases), ros_type=ros_type,
                vtk_type=vtk_type, kind=kind_name, message=message, roles=roles,
                element_roles=element_roles, header=header, scaled_roles=scaled, source=path,
                line=line, mapping_file=path.replace("\\", "/").rsplit("/", 1)[-1],
                child_frame=child_frame, blank_message=blank_message)


def _normalise_ros_type(text: str) -> str:
    """`pkg/Type` -> `pkg/msg/Type`; anything else unchanged (then reported as unknown)."""
    parts = text.split("/")
    return f"{parts[0]}/msg/{parts[1]}" if len(parts) == 2 else text


def _resolve_components(value, shape: Shape, message: Message, table, fail):
    if not isinstance(value, list) or not value or not all(isinstance(p, str) for p in value):
        raise fail("fields", "role components must be a non-empty list of field paths",
                   BAD_FIELD)
    resolved = []
    for path in value:
        try:
            item = resolve_path(message, path, table)
            check_shape(item.field, shape, table)
        except ValueError as error:
            raise fail("fields", f"role components: {error}", BAD_FIELD) from None
        resolved.append(item)
    return tuple(resolved)


def _scaled_roles(kind: Kind, lengths: List[str], roles, element_roles, message: Message,
                  table, fail) -> Tuple[str, ...]:
    """Maps each `lengths` path to the role it scales; a path the kind cannot scale is an
    error (the units policy must never be silently ignored)."""
    scalable = kind.paths_to_scale(roles, element_roles)
    scaled: List[str] = []
    for path in lengths:
        if path not in scalable:
            hint = (f"this kind can scale: {', '.join(sorted(scalable))}" if scalable
                    else f"kind {kind.name} has no length to scale")
            if not (kind.pseudo_length_suffix and path.endswith(kind.pseudo_length_suffix)):
                try:
                    resolve_path(message, path, table)
                except ValueError as error:
                    raise fail(f"lengths: {error}") from None
            raise fail(f"lengths: '{path}' is not a length of kind {kind.name} ({hint})")
        if scalable[path] in scaled:
            raise fail(f"lengths: '{path}' is listed twice")
        scaled.append(scalable[path])
    return tuple(scaled)


def _check_unique(rules: Sequence[Rule]) -> None:
    seen: Dict[str, Rule] = {}
    conversions: Dict[Tuple[str, str], Rule] = {}
    for rule in rules:
        for name in (rule.short_name, *rule.aliases):
            other = seen.get(name)
            if other is not None:
                raise MappingError(rule.source, rule.line, f"rule {rule.short_name}: short name "
                                   f"'{name}' is already used by rule {other.short_name} "
                                   f"({other.source}:{other.line})", DUPLICATE)
            seen[name] = rule
        key = (rule.ros_type, rule.vtk_type)
        other = conversions.get(key)
        if other is not None:
            raise MappingError(rule.source, rule.line, f"rule {rule.short_name}: {rule.ros_type} "
                               f"-> {rule.vtk_type} is already mapped by rule {other.short_name} "
                               f"({other.source}:{other.line}); the converters would clash",
                               DUPLICATE)
        conversions[key] = rule


# ---------------------------------------------------------------- field paths

def resolve_path(message: Message, path: str, table: Mapping[str, Message]) -> ResolvedField:
    """Walks `a.b.c` through nested message fields. Every segment but the last must be a
    single (non-sequence) message. Raises ValueError with a readable reason."""
    current = message
    segments = path.split(".")
    for position, name in enumerate(segments):
        item = next((f for f in current.fields if f.name == name), None)
        if item is None:
            have = ", ".join(f.name for f in current.fields) or "no fields"
            raise ValueError(f"'{path}': {current.ros_type} has no field '{name}' (it has: "
                             f"{have})")
        if position == len(segments) - 1:
            return ResolvedField(path, item, message)
        if not item.type.is_message or item.container != SCALAR:
            raise ValueError(f"'{path}': '{name}' is not a single message, so it has no "
                             f"field '{segments[position + 1]}'")
        current = table[item.type.ros_name()]
    raise ValueError(f"'{path}': empty path")  # unreachable: split gives at least one segment


def check_shape(item: Field, shape: Shape, table: Mapping[str, Message]) -> None:
    """Raises ValueError when the field does not have `shape`."""
    is_sequence = item.container in (SEQUENCE, BOUNDED_SEQUENCE)
    if shape.array_size:
        if item.container != ARRAY or item.size != shape.array_size or \
                not item.type.is_primitive or item.type.name not in shape.primitives:
            raise ValueError(f"field '{item.name}' must be a {shape.describe()}, it is "
                             f"{_describe_field(item)}")
        return
    if item.container == ARRAY or is_sequence != shape.sequence:
        raise ValueError(f"field '{item.name}' must be a {shape.describe()}, it is "
                         f"{_describe_field(item)}")
    if shape.primitives:
        if not item.type.is_primitive or item.type.name not in shape.primitives:
            raise ValueError(f"field '{item.name}' must be a {shape.describe()}, it is "
                             f"{_describe_field(item)}")
        return
    if not item.type.is_message:
        raise ValueError(f"field '{item.name}' must be a {shape.describe()}, it is "
                         f"{_describe_field(item)}")
    nested = table[item.type.ros_name()]
    for name, member_shape in shape.members:
        member = next((f for f in nested.fields if f.name == name), None)
        if member is None:
            raise ValueError(f"field '{item.name}' ({nested.ros_type}) lacks member '{name}' "
                             f"({member_shape.describe()})")
        check_shape(member, member_shape, table)


def _describe_field(item: Field) -> str:
    name = item.type.ros_name()
    if item.container == ARRAY:
        return f"{name}[{item.size}]"
    if item.container in (SEQUENCE, BOUNDED_SEQUENCE):
        return f"sequence of {name}"
    return name
