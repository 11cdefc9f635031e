"""The `nodes` artefact family: VTK publisher/subscriber node classes, ROS2ToVTK / VTKToROS2
converters and a registration source, from the mapping rules (mapping.py).

As in emit.py, the templates get plain dictionaries built here: every C++ expression that
depends on a rule (field access paths, scale factors, value types) is spelled in Python, the
templates only lay the code out.
"""
from __future__ import annotations

from typing import Dict, List, Sequence, Tuple

from . import naming
from .kinds import KINDS
from .kinds.base import CPP_FIELD_TYPES, EMPTY, OBJECT, VALUE
from .mapping import Rule, ResolvedField, load_rules, short_names_of
from .model import Message

# The scale argument of a role whose lengths are not scaled.
NO_LENGTH_SCALING = "::ros2vtk::convert::kNoLengthScaling"


def publisher_class(short_name: str) -> str:
    return f"vtkROS2Publisher{short_name}Node"


def subscriber_class(short_name: str) -> str:
    return f"vtkROS2Subscriber{short_name}Node"


def mrml_class(class_name: str) -> str:
    """The paper's Slicer spelling: vtkROS2PublisherStringNode -> vtkMRMLROS2PublisherStringNode."""
    return "vtkMRML" + class_name[len("vtk"):]


def convert_header(target: str) -> str:
    return f"{target}Convert.hpp"


def register_header(target: str) -> str:
    """The header declaring register_function(target), next to the converters' header."""
    return f"{target}Register.hpp"


def register_function(target: str) -> str:
    """The exported C function that registers every node class of a generated library."""
    return f"ros2vtk_register_{naming.c_identifier(target)}_nodes"


def export_macro(library: str) -> str:
    """What vtk_module_add_module calls the export macro of a module library."""
    return f"{library.upper()}_EXPORT"


def output_paths(target: str, short_names: Sequence[str]) -> List[Tuple[str, str, str]]:
    """(template, output path, rule short name or "") of every artefact."""
    paths = [
        ("convert/convert.hpp.j2", f"include/{convert_header(target)}", ""),
        ("convert/convert.cpp.j2", f"src/{target}Convert.cpp", ""),
        ("node/registration.cxx.j2", f"src/{target}Registration.cxx", ""),
        ("register.hpp.j2", f"include/{register_header(target)}", ""),
    ]
    for short in short_names:
        for template, class_name in (("node/publisher", publisher_class(short)),
                                     ("node/subscriber", subscriber_class(short))):
            paths.append((f"{template}.h.j2", f"vtk/{class_name}.h", short))
            paths.append((f"{template}.cxx.j2", f"vtk/{class_name}.cxx", short))
    return paths


def list_outputs(target: str, mappings: Sequence[str]) -> List[str]:
    return sorted(path for _, path, _ in output_paths(target, short_names_of(mappings)))


# ---------------------------------------------------------------- view models

def _expr(prefix: str, resolved: ResolvedField) -> str:
    return f"{prefix}.{resolved.path}"


def _cpp_type(resolved: ResolvedField) -> str:
    return CPP_FIELD_TYPES[resolved.field.type.name]


def rule_view(rule: Rule, table: Dict[str, Message]) -> dict:
    """Everything the convert/node templates need about one rule."""
    message_cpp = "::" + naming.cpp_qualified_name(rule.message)
    roles: Dict[str, object] = {}
    for name, resolved in rule.roles.items():
        if isinstance(resolved, tuple):
            roles[name] = [{"expr": _expr("message", r), "cpp_type": _cpp_type(r)}
                           for r in resolved]
        else:
            roles[name] = _expr("message", resolved)
    element_roles = {name: _expr("element", resolved)
                     for name, resolved in rule.element_roles.items()}
    scale = {name: ("lengthScale" if name in rule.scaled_roles else NO_LENGTH_SCALING)
             for name in list(rule.roles) + list(rule.element_roles)}
    kind = KINDS[rule.kind]
    view = {
        "short_name": rule.short_name,
        "aliases": list(rule.aliases),
        "ros_type": rule.ros_type,
        "vtk_type": rule.vtk_type,
        "kind": rule.kind,
        "message_cpp": message_cpp,
        "message_header": naming.message_header(rule.message),
        "publisher_class": publisher_class(rule.short_name),
        "subscriber_class": subscriber_class(rule.short_name),
        "alias_classes": [{"short_name": alias, "publisher_class": publisher_class(alias),
                           "subscriber_class": subscriber_class(alias)}
                          for alias in rule.aliases],
        "is_value": kind.signature == VALUE,
        "is_empty": kind.signature == EMPTY,
        "is_object": kind.signature == OBJECT,
        "takes_encoding": kind.takes_encoding,
        "publish_type": kind.publish_input or rule.vtk_type,
        "roles": roles,
        "element_roles": element_roles,
        "scale": scale,
        "uses_scale": bool(rule.scaled_roles),
        "scaled": list(rule.scaled_roles),
        "header": _expr("message", rule.header) if rule.header else "",
        "child_frame": _expr("message", rule.child_frame) if rule.child_frame else "",
        "blank_message_object": rule.blank_message == "message",
        "mapping_file": rule.mapping_file,
        "line": rule.line,
        "spec": f"mapping rule {rule.short_name} ({rule.mapping_file})",
        # A stateful kind (marker_array) names the C++ class its subscriber folds messages into.
        "state_class": "",
        "state_header": "",
        "state_expires": False,
        "state_frames": False,
        "state_node_class": "",
        # Marker-like kinds read a message's markers in one generated function (ROS2ToMarkers).
        "to_markers": False,
    }
    if kind.view:
        view.update(kind.view(rule, table))
    return view


def plan(target: str, library: str, messages_target: str, mappings: Sequence[str],
         table: Dict[str, Message]) -> List[Tuple[str, str, str, dict]]:
    """(template, path, spec for the banner, context) of every artefact, sorted by path."""
    rules = load_rules(mappings, table)
    views = [rule_view(rule, table) for rule in rules]
    by_short = {view["short_name"]: view for view in views}
    common = {
        "target": target,
        "library": library,
        "export_macro": export_macro(library),
        "module_header": f"{library}Module.h",
        "convert_header": convert_header(target),
        "register_function": register_function(target),
        "register_header": register_header(target),
        "messages_register_header": (naming.register_header(messages_target)
                                     if messages_target else ""),
        # register.hpp.j2
        "function": register_function(target),
        "guard": naming.include_guard(register_header(target)),
        "what": "node classes (and their message types)",
        "export_header": f"{library}Module.h",
        "messages_register_function": (naming.register_function(
            naming.c_identifier(messages_target)) if messages_target else ""),
        "rules": views,
        "message_headers": sorted({view["message_header"] for view in views}),
    }
    artefacts = []
    for template, path, short in output_paths(target, [view["short_name"] for view in views]):
        if short:
            context = dict(common, rule=by_short[short])
            spec = by_short[short]["spec"]
        else:
            context = common
            spec = "the mapping rules of target " + target
        artefacts.append((template, path, spec, context))
    artefacts.sort(key=lambda artefact: artefact[1])
    return artefacts
