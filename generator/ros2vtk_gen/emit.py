"""Renders the templates for a set of specs and writes the files (only when they changed).

The templates get plain dictionaries (view models) built here, so C++ spelling rules (types,
literals, accessor names) live in Python, and the templates only lay the code out.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple, Union

import jinja2

from . import __version__, naming, nodes, typehash
from .errors import GeneratorError
from .model import (ARRAY, BOUNDED_SEQUENCE, PRIMITIVE_SIZES, SCALAR, SEQUENCE, Action, BaseType,
                    Field, Message, Service, Value)
from .msg_parser import messages_of, parse_spec_file, resolve, spec_identity

FAMILIES = ("messages", "nodes")  # nodes: ros2vtk_generate_nodes (see nodes.py)

CPP_PRIMITIVES = {
    "bool": "bool", "byte": "uint8_t", "char": "uint8_t",
    "int8": "int8_t", "uint8": "uint8_t", "int16": "int16_t", "uint16": "uint16_t",
    "int32": "int32_t", "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t",
    "float32": "float", "float64": "double",
    "string": "::std::string", "wstring": "::std::u16string",
}
FIELD_TYPE_ENUM = {
    "bool": "Bool", "byte": "Byte", "char": "Char", "int8": "Int8", "uint8": "UInt8",
    "int16": "Int16", "uint16": "UInt16", "int32": "Int32", "uint32": "UInt32",
    "int64": "Int64", "uint64": "UInt64", "float32": "Float32", "float64": "Float64",
    "string": "String", "wstring": "WString",
}
CONTAINER_ENUM = {SCALAR: "None", ARRAY: "Array", BOUNDED_SEQUENCE: "BoundedSequence",
                  SEQUENCE: "Sequence"}
EMPTY_MEMBER = Field("structure_needs_at_least_one_member", BaseType("uint8"))


@dataclass(frozen=True)
class Config:
    """What to generate: one target's specs, plus the specs of the targets it depends on."""

    family: str
    target: str
    output_dir: str
    specs: Tuple[str, ...]
    dependencies: Tuple[Tuple[str, Tuple[str, ...]], ...] = ()  # (target, spec files)
    templates_dir: Optional[str] = None
    # family "nodes" only: mapping rule files, the messages target whose types they map, and
    # the library name of the VTK module (names its export macro).
    mappings: Tuple[str, ...] = ()
    messages_target: str = ""
    library: str = ""


def default_templates_dir() -> str:
    return os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "templates"))


# ---------------------------------------------------------------- C++ literals

def cpp_string_literal(text: str, prefix: str = "") -> str:
    """A C++ string literal for `text`; non-printable and non-ASCII characters escaped."""
    out: List[str] = []
    for char in text:
        code = ord(char)
        if char in "\\\"":
            out.append("\\" + char)
        elif 0x20 <= code < 0x7f:
            out.append(char)
        elif prefix == "u":
            out.append(f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}")
        else:
            out.extend(f"\\{byte:03o}" for byte in char.encode("utf-8"))
    return f'{prefix}"{"".join(out)}"'


def cpp_scalar_literal(value: Union[bool, int, float, str], element: BaseType) -> str:
    name = element.name
    if name == "bool":
        return "true" if value else "false"
    if name == "string":
        return cpp_string_literal(str(value))
    if name == "wstring":
        return cpp_string_literal(str(value), "u")
    if name in ("float32", "float64"):
        text = repr(float(value))
        if "e" not in text and "." not in text:
            text += ".0"
        return text + ("f" if name == "float32" else "")
    number = int(value)
    if name == "int64":
        return "(-9223372036854775807LL - 1)" if number == -2**63 else f"{number}LL"
    if name == "uint64":
        return f"{number}ULL"
    if name == "int32" and number == -2**31:
        return "(-2147483647 - 1)"
    if name == "uint32":
        return f"{number}U"
    return str(number)


def constant_display(value: Value) -> str:
    """The value as ConstantInfo shows it: normalised spec spelling, strings unquoted."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value) if not isinstance(value, float) else repr(value)


# ---------------------------------------------------------------- view models

def element_cpp_type(element: BaseType) -> str:
    if element.is_message:
        return naming.cpp_type_of_message(element)
    return CPP_PRIMITIVES[element.name]


def member_cpp_type(item: Field) -> str:
    element = element_cpp_type(item.type)
    if item.container == ARRAY:
        return f"::std::array<{element}, {item.size}>"
    if item.container in (BOUNDED_SEQUENCE, SEQUENCE):
        return f"::std::vector<{element}>"
    return element


def member_initializer(item: Field) -> str:
    """What follows the member name: ` = 1.0`, ` = {{1, 2}}` or `{}` (value-initialised)."""
    if item.default is None:
        return "{}"
    if item.container == SCALAR:
        return " = " + cpp_scalar_literal(item.default, item.type)  # type: ignore[arg-type]
    values = ", ".join(cpp_scalar_literal(v, item.type) for v in item.default)  # type: ignore
    return f" = {{{{{values}}}}}" if item.container == ARRAY else f" = {{{values}}}"


def min_serialized_size(message: Message, table: Dict[str, Message]) -> int:
    """A lower bound of the serialized size (padding ignored): every sequence count read is
    checked against it so hostile counts never allocate."""
    if message.is_empty:
        return 1
    total = 0
    for item in message.fields:
        if item.container in (SEQUENCE, BOUNDED_SEQUENCE):
            total += 4
            continue
        count = item.size if item.container == ARRAY else 1
        total += count * element_min_size(item.type, table)
    return total


def element_min_size(element: BaseType, table: Dict[str, Message]) -> int:
    if element.is_message:
        return min_serialized_size(table[element.ros_name()], table)
    if element.is_string:
        return 4
    return PRIMITIVE_SIZES[element.name]


def field_view(item: Field, owner: str, table: Dict[str, Message]) -> dict:
    element = item.type
    if element.is_message:
        kind = "message"
    elif element.is_string:
        kind = element.name  # "string" / "wstring"
    elif element.name == "bool":
        kind = "bool"
    else:
        kind = "primitive"
    member_type = member_cpp_type(item)
    is_vector_bool = kind == "bool" and item.container in (SEQUENCE, BOUNDED_SEQUENCE)
    return {
        "name": item.name,
        "kind": kind,
        "container": item.container,
        "size": item.size,
        "bound": item.size if item.container == BOUNDED_SEQUENCE else 0,
        "string_bound": element.string_bound,
        "element_size": PRIMITIVE_SIZES.get(element.name, 0) if element.is_primitive else 0,
        "min_element_size": element_min_size(element, table),
        "cpp_type": member_type,
        "element_cpp_type": element_cpp_type(element),
        "initializer": member_initializer(item),
        "field_type": "Message" if element.is_message else FIELD_TYPE_ENUM[element.name],
        "container_enum": CONTAINER_ENUM[item.container],
        "nested_function": (f"nested_{element.package}_{naming.snake_case(element.name)}"
                            if element.is_message else ""),
        "nested_cpp_type": element_cpp_type(element) if element.is_message else "",
        "is_vector_bool": is_vector_bool,
        "resize_function": ("array_resize" if item.container == ARRAY else "vector_resize"),
        "owner": owner,
    }


def cpp_text_literal(text: str, indent: str) -> str:
    """`text` as adjacent C++ string literals, one per line of the text (a long .msg file stays
    readable in the generated code); "" for no text."""
    lines = text.splitlines(keepends=True)
    if not lines:
        return '""'
    def literal(line: str) -> str:
        if line.endswith("\n"):
            return cpp_string_literal(line[:-1])[:-1] + '\\n"'
        return cpp_string_literal(line)
    return ("\n" + indent).join(literal(line) for line in lines)


def description_view(description: dict, sources: List[dict],
                     table: Optional[Dict[str, Message]] = None) -> dict:
    """A TypeDescription (typehash.message_description / service_description) and the type
    sources served with it (typehash.description_sources) as the templates write them into a
    constant table: C++ literals, the type first, then the referenced types in order. A
    referenced .msg type of `table` (a generated type) is not written again: its entry names the
    type whose own table holds the text ("defined_by", a function returning its type support),
    so each interface file is in the generated code once."""
    table = table or {}

    def individual(item: dict, source: dict, own: bool) -> dict:
        name = item["type_name"]
        owner = table.get(name) if not own and source["encoding"] == "msg" else None
        defined_by = None if owner is None else {
            "function": "source_of_" + name.replace("/", "__"),
            "cpp_type": "::" + naming.cpp_qualified_name(owner),
            "header": naming.message_header(owner),
        }
        return {
            "type_name": cpp_string_literal(name),
            "encoding": cpp_string_literal(source["encoding"]),
            "raw_file_contents": ("nullptr" if defined_by else
                                  cpp_text_literal(source["raw_file_contents"], "    ")),
            "defined_by": defined_by,
            "fields": [{
                "name": cpp_string_literal(f["name"]),
                "type_id": f["type"]["type_id"],
                "capacity": f["type"]["capacity"],
                "string_capacity": f["type"]["string_capacity"],
                "nested_type_name": cpp_string_literal(f["type"]["nested_type_name"]),
                "default_value": cpp_string_literal(f["default_value"]),
            } for f in item["fields"]],
        }
    referenced = [individual(item, source, False) for item, source in
                  zip(description["referenced_type_descriptions"], sources[1:])]
    return {"type": individual(description["type_description"], sources[0], True),
            "referenced": referenced,
            "includes": sorted({r["defined_by"]["header"] for r in referenced if r["defined_by"]})}


def described(description: dict, item: Union[Message, Service, Action],
              table: Dict[str, Message]) -> dict:
    """description_view of `item`'s description with the sources served with it."""
    return description_view(description, typehash.description_sources(
        description, typehash.own_source(item), table), table)


def message_view(message: Message, table: Dict[str, Message]) -> dict:
    qualified = "::" + naming.cpp_qualified_name(message)
    fields = list(message.fields) if message.fields else [EMPTY_MEMBER]
    field_views = [field_view(item, qualified, table) for item in fields]
    if message.is_empty:
        field_views[0]["initializer"] = " = 0"
    includes = sorted({naming.header_path(str(f.type.package), f.type.interface, f.type.name)
                       for f in message.fields if f.type.is_message})
    nested = sorted({(v["nested_function"], v["nested_cpp_type"]) for v in field_views
                     if v["kind"] == "message"})
    constants = [{
        "name": c.name,
        "cpp_type": ("const char*" if c.type.name == "string" else
                     "const char16_t*" if c.type.name == "wstring" else CPP_PRIMITIVES[c.type.name]),
        "literal": cpp_scalar_literal(c.value, c.type),  # type: ignore[arg-type]
        "field_type": FIELD_TYPE_ENUM[c.type.name],
        "display": cpp_string_literal(constant_display(c.value)),
    } for c in message.constants]
    header = naming.message_header(message)
    return {
        "name": message.name,
        "package": message.package,
        "kind": message.kind,
        "ros_type": message.ros_type,
        "dds_type_name": naming.dds_type_name(message),
        "type_hash": typehash.type_hash(message, table),
        "description": described(typehash.message_description(message, table), message, table),
        "namespace": naming.cpp_namespace(message.package, message.kind),
        "qualified": qualified,
        "header": header,
        "guard": naming.include_guard(header),
        "includes": includes,
        "fields": field_views,
        "nested": [{"function": f, "cpp_type": t} for f, t in nested],
        "constants": constants,
        "is_empty": message.is_empty,
        "spec": message.spec,
    }


# ---------------------------------------------------------------- outputs

@dataclass(frozen=True)
class Artefact:
    template: str  # relative to the templates folder
    path: str      # relative to the output folder
    spec: str      # spec named in the banner
    context: dict


def _message_paths(package: str, kind: str, name: str) -> List[Tuple[str, str]]:
    return [
        ("msg/struct.hpp.j2", "include/" + naming.header_path(package, kind, name)),
        ("msg/cdr.cpp.j2", "src/" + naming.source_path(package, kind, name, "cdr")),
        ("msg/type_support.cpp.j2", "src/" + naming.source_path(package, kind, name,
                                                               "type_support")),
    ]


def _service_paths(package: str, name: str, kind: str = "srv") -> List[Tuple[str, str]]:
    paths = _message_paths(package, kind, f"{name}_Request")
    paths += _message_paths(package, kind, f"{name}_Response")
    paths += [
        ("msg/service.hpp.j2", "include/" + naming.header_path(package, kind, name)),
        ("msg/service_type_support.cpp.j2",
         "src/" + naming.source_path(package, kind, name, "service_type_support")),
    ]
    return paths


def _action_paths(package: str, name: str) -> List[Tuple[str, str]]:
    paths: List[Tuple[str, str]] = []
    for suffix in ("Goal", "Result", "Feedback", "FeedbackMessage"):
        paths += _message_paths(package, "action", f"{name}_{suffix}")
    for suffix in ("SendGoal", "GetResult"):
        paths += _service_paths(package, f"{name}_{suffix}", "action")
    paths += [
        ("msg/action.hpp.j2", "include/" + naming.header_path(package, "action", name)),
        ("msg/action_type_support.cpp.j2",
         "src/" + naming.source_path(package, "action", name, "action_type_support")),
    ]
    return paths


REGISTER_PATH = "src/register_types.cpp"


def list_outputs(config: Config) -> List[str]:
    """Output paths (relative) from the spec file names alone, so CMake can ask at configure
    time without the specs having to be valid yet."""
    if config.family == "nodes":
        return nodes.list_outputs(config.target, config.mappings)
    paths: List[str] = []
    for spec in config.specs:
        package, kind, name = spec_identity(spec)
        if kind == "action":
            pairs = _action_paths(package, name)
        elif kind == "srv":
            pairs = _service_paths(package, name)
        else:
            pairs = _message_paths(package, kind, name)
        paths.extend(path for _, path in pairs)
    paths.append(REGISTER_PATH)
    paths.append("include/" + naming.register_header(config.target))
    return sorted(set(paths))


def plan(config: Config) -> List[Artefact]:
    """Parses, resolves and returns every artefact to render."""
    if config.family not in FAMILIES:
        raise GeneratorError(f"unknown artefact family '{config.family}' "
                             f"(known: {', '.join(FAMILIES)})", "R2V301")
    specs = [parse_spec_file(path) for path in config.specs]
    known = [parse_spec_file(path) for _, paths in config.dependencies for path in paths]
    table = resolve(specs, known)
    if config.family == "nodes":
        return [Artefact(template, path, spec, context) for template, path, spec, context in
                nodes.plan(config.target, config.library or config.target,
                           config.messages_target, config.mappings, table)]
    artefacts: List[Artefact] = []
    registered_messages: List[str] = []
    registered_services: List[str] = []
    registered_actions: List[str] = []
    for spec in specs:
        for message in messages_of([spec]):
            view = message_view(message, table)
            registered_messages.append(view["qualified"])
            for template, path in _message_paths(message.package, message.kind, message.name):
                artefacts.append(Artefact(template, path, message.spec, {"message": view}))
        services = ([spec.send_goal, spec.get_result] if isinstance(spec, Action) else
                    [spec] if isinstance(spec, Service) else [])
        for service in services:
            artefacts.extend(_service_artefacts(service, table))
            registered_services.append("::" + naming.cpp_namespace(service.package, service.kind)
                                       + "::" + service.name)
        if isinstance(spec, Action):
            artefacts.extend(_action_artefacts(spec, table))
            registered_actions.append("::" + naming.cpp_namespace(spec.package, "action") + "::"
                                      + spec.name)
    headers = sorted({a.path[len("include/"):] for a in artefacts if a.path.startswith("include/")})
    register_header = naming.register_header(config.target)
    artefacts.append(Artefact("register.hpp.j2", "include/" + register_header,
                              f"the specs of target {config.target}", {
                                  "function": naming.register_function(
                                      naming.c_identifier(config.target)),
                                  "guard": naming.include_guard(register_header),
                                  "what": "message and service types",
                                  "target": config.target,
                                  "export_header": "", "export_macro": "",
                              }))
    artefacts.append(Artefact("msg/register_types.cpp.j2", REGISTER_PATH,
                              f"the specs of target {config.target}", {
                                  "function": naming.register_function(
                                      naming.c_identifier(config.target)),
                                  "register_header": register_header,
                                  "dependency_functions": [
                                      naming.register_function(naming.c_identifier(target))
                                      for target, _ in config.dependencies if target],
                                  "headers": headers,
                                  "messages": sorted(registered_messages),
                                  "services": sorted(registered_services),
                                  "actions": sorted(registered_actions),
                              }))
    artefacts.sort(key=lambda a: a.path)
    duplicates = {a.path for a in artefacts if sum(b.path == a.path for b in artefacts) > 1}
    if duplicates:
        raise GeneratorError(f"two specs map to the same output: {', '.join(sorted(duplicates))}",
                             "R2V302")
    return artefacts


def _service_artefacts(service: Service, table: Dict[str, Message]) -> List[Artefact]:
    header = naming.service_header(service)
    view = {
        "name": service.name,
        "ros_type": service.ros_type,
        "type_hash": typehash.type_hash(service, table),
        "description": described(typehash.service_description(service, table), service, table),
        "namespace": naming.cpp_namespace(service.package, service.kind),
        "header": header,
        "guard": naming.include_guard(header),
        "request": naming.message_header(service.request),
        "response": naming.message_header(service.response),
    }
    return [
        Artefact("msg/service.hpp.j2", "include/" + header, service.spec, {"service": view}),
        Artefact("msg/service_type_support.cpp.j2",
                 "src/" + naming.source_path(service.package, service.kind, service.name,
                                             "service_type_support"),
                 service.spec, {"service": view}),
    ]


def _action_artefacts(action: Action, table: Dict[str, Message]) -> List[Artefact]:
    header = naming.action_header(action)
    view = {
        "name": action.name,
        "ros_type": action.ros_type,
        "type_hash": typehash.type_hash(action, table),
        "description": described(typehash.action_description(action, table), action, table),
        "namespace": naming.cpp_namespace(action.package, "action"),
        "header": header,
        "guard": naming.include_guard(header),
        "includes": [naming.message_header(action.goal), naming.message_header(action.result),
                     naming.message_header(action.feedback),
                     naming.message_header(action.feedback_message),
                     naming.service_header(action.send_goal),
                     naming.service_header(action.get_result)],
        "goal": action.goal.name,
        "result": action.result.name,
        "feedback": action.feedback.name,
        "feedback_message": action.feedback_message.name,
        "send_goal": action.send_goal.name,
        "get_result": action.get_result.name,
    }
    return [
        Artefact("msg/action.hpp.j2", "include/" + header, action.spec, {"action": view}),
        Artefact("msg/action_type_support.cpp.j2",
                 "src/" + naming.source_path(action.package, "action", action.name,
                                             "action_type_support"),
                 action.spec, {"action": view}),
    ]


def make_environment(templates_dir: str) -> jinja2.Environment:
    environment = jinja2.Environment(
        loader=jinja2.FileSystemLoader(templates_dir),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    environment.filters["rstrip"] = lambda text: str(text).rstrip()
    return environment


def render(config: Config) -> List[Tuple[str, str]]:
    """(relative path, text) of every output, sorted by path."""
    templates_dir = config.templates_dir or default_templates_dir()
    environment = make_environment(templates_dir)
    rendered: List[Tuple[str, str]] = []
    for artefact in plan(config):
        try:
            template = environment.get_template(artefact.template)
            text = template.render(generator_version=__version__, template_name=artefact.template,
                                   spec=artefact.spec, **artefact.context)
        except jinja2.TemplateError as error:
            where = getattr(error, "filename", None) or artefact.template
            line = getattr(error, "lineno", None) or 0
            raise GeneratorError(f"{where}:{line}: template error: {error}", "R2V303") from None
        rendered.append((artefact.path, text))
    return rendered


def write_if_changed(path: str, text: str) -> bool:
    """Writes `text` unless the file already holds it (keeps timestamps, so builds stay
    incremental). Returns whether the file was written."""
    try:
        with open(path, encoding="utf-8", newline="") as handle:
            if handle.read() == text:
                return False
    except OSError:
        pass
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as handle:
        handle.write(text)
    return True


# The folders of the output folder the generator owns: files there that it no longer lists
# (a removed spec or rule) are deleted, so the build tree, its install and generated/ hold only
# what the specs make. Other folders (CMake writes module/ next to them) are left alone.
OWNED_FOLDERS = ("include", "src", "vtk")


def prune_stale(output_dir: str, keep: Sequence[str]) -> List[str]:
    """Deletes files under the owned folders of `output_dir` that are not in `keep` (relative
    paths), then the folders left empty. Returns the deleted paths (relative)."""
    kept = {path.replace(os.sep, "/") for path in keep}
    removed: List[str] = []
    for folder in OWNED_FOLDERS:
        top = os.path.join(output_dir, folder)
        for root, dirs, files in os.walk(top, topdown=False):
            for name in files:
                full = os.path.join(root, name)
                relative = os.path.relpath(full, output_dir).replace(os.sep, "/")
                if relative not in kept:
                    os.remove(full)
                    removed.append(relative)
            if root != top and not os.listdir(root):
                os.rmdir(root)
    return sorted(removed)


def generate(config: Config) -> List[str]:
    """Renders everything, then writes: nothing is written when any spec is bad. Files an
    earlier run wrote for specs that are gone are deleted (prune_stale)."""
    rendered = render(config)
    written = []
    for path, text in rendered:
        if write_if_changed(os.path.join(config.output_dir, path), text):
            written.append(path)
    prune_stale(config.output_dir, [path for path, _ in rendered])
    return written


def expand_spec_paths(paths: Sequence[str]) -> List[str]:
    """Files stay; folders become the .msg/.srv/.action files below them (sorted)."""
    result: List[str] = []
    for path in paths:
        if os.path.isdir(path):
            found = []
            for root, _, files in os.walk(path):
                found.extend(os.path.join(root, f) for f in files
                             if f.endswith((".msg", ".srv", ".action")))
            result.extend(sorted(found))
        else:
            result.append(path)
    return result
