"""REP 2011 type descriptions and RIHS01 type hashes, as rosidl_generator_type_description
makes them (WIRE_NOTES §2.6).

A type description is the type's IndividualTypeDescription plus every type it references,
sorted by name (type_description_interfaces/msg/TypeDescription). A node serves it on
~/get_type_description, default values included (as rosidl's Python str() of the value).
The hashed text is the JSON of the same description with the default values left out, dumped
with separators (', ', ': ') and ASCII escapes; the hash is SHA-256 of that text.

A service's description is synthesized as rosidl does: the service type with the fields
request_message, response_message and event_message, and its `<Srv>_Event` message (info,
request[<=1], response[<=1]) referencing service_msgs/msg/ServiceEventInfo. An action's is
the action type with the fields goal, result, feedback, send_goal_service, get_result_service
and feedback_message, referencing all of them and what they reference (docs/wire-notes.md §8.2).
"""
from __future__ import annotations

import hashlib
import json
import os
from typing import Dict, List, Optional, Union

from .model import ARRAY, BOUNDED_SEQUENCE, SEQUENCE, Action, Field, Message, Service, Value

# type_description_interfaces/msg/FieldType ids.
FIELD_TYPE_NESTED = 1
FIELD_TYPE_IDS = {
    "int8": 2, "uint8": 3, "int16": 4, "uint16": 5, "int32": 6, "uint32": 7,
    "int64": 8, "uint64": 9, "float32": 10, "float64": 11,
    "char": 3,  # .msg char is uint8 for rosidl
    "bool": 15, "byte": 16, "string": 17, "wstring": 18,
}
BOUNDED_STRING = 21
BOUNDED_WSTRING = 22
CONTAINER_OFFSET = {ARRAY: 48, BOUNDED_SEQUENCE: 96, SEQUENCE: 144}
EMPTY_MESSAGE_MEMBER = "structure_needs_at_least_one_member"

# service_msgs/msg/ServiceEventInfo and the builtin_interfaces/msg/Time it nests: every service
# description references them (REP 2011 / service introspection), whether or not the packages
# being generated ship service_msgs.
_TIME = "builtin_interfaces/msg/Time"
_SERVICE_EVENT_INFO = "service_msgs/msg/ServiceEventInfo"


def _plain_field(name: str, type_id: int, capacity: int = 0, nested: str = "") -> dict:
    return {"name": name,
            "type": {"type_id": type_id, "capacity": capacity, "string_capacity": 0,
                     "nested_type_name": nested},
            "default_value": ""}


_FIXED_DESCRIPTIONS = {
    _TIME: {"type_name": _TIME, "fields": [
        _plain_field("sec", FIELD_TYPE_IDS["int32"]),
        _plain_field("nanosec", FIELD_TYPE_IDS["uint32"])]},
    _SERVICE_EVENT_INFO: {"type_name": _SERVICE_EVENT_INFO, "fields": [
        _plain_field("event_type", FIELD_TYPE_IDS["uint8"]),
        _plain_field("stamp", FIELD_TYPE_NESTED, nested=_TIME),
        _plain_field("client_gid", FIELD_TYPE_IDS["char"] + CONTAINER_OFFSET[ARRAY], capacity=16),
        _plain_field("sequence_number", FIELD_TYPE_IDS["int64"])]},
}


def default_value_text(value: Optional[Value]) -> str:
    """A default as rosidl writes it into a type description: Python's str() of the value
    ('1.0', 'True', '-2'); arrays as rosidl_adapter's repr() of a tuple ('(0, 1, 255)',
    "('', 'max value')", '(1.5,)' for one element), which the IDL parser reads back as text;
    '' when there is none."""
    if value is None:
        return ""
    if isinstance(value, (tuple, list)):
        return repr(tuple(value))
    return str(value)


def _field_description(item: Field) -> dict:
    element = item.type
    if element.is_message:
        type_id = FIELD_TYPE_NESTED
        nested = element.ros_name()
    elif element.string_bound:
        type_id = BOUNDED_STRING if element.name == "string" else BOUNDED_WSTRING
        nested = ""
    else:
        type_id = FIELD_TYPE_IDS[element.name]
        nested = ""
    type_id += CONTAINER_OFFSET.get(item.container, 0)
    return {
        "name": item.name,
        "type": {
            "type_id": type_id,
            "capacity": item.size if item.container in (ARRAY, BOUNDED_SEQUENCE) else 0,
            "string_capacity": element.string_bound,
            "nested_type_name": nested,
        },
        "default_value": default_value_text(item.default),
    }


def _individual_description(message: Message) -> dict:
    if message.is_empty:
        fields = [{"name": EMPTY_MESSAGE_MEMBER,
                   "type": {"type_id": FIELD_TYPE_IDS["uint8"], "capacity": 0,
                            "string_capacity": 0, "nested_type_name": ""},
                   "default_value": ""}]
    else:
        fields = [_field_description(item) for item in message.fields]
    return {"type_name": message.ros_type, "fields": fields}


def _referenced(message: Message, table: Dict[str, Message], found: Dict[str, Message]) -> None:
    for item in message.fields:
        if item.type.is_message:
            name = item.type.ros_name()
            if name not in found:
                found[name] = table[name]
                _referenced(table[name], table, found)


def _references(messages: List[Message], table: Dict[str, Message]) -> Dict[str, dict]:
    found: Dict[str, Message] = {}
    for message in messages:
        _referenced(message, table, found)
    return {name: _individual_description(found[name]) for name in found}


def message_description(message: Message, table: Dict[str, Message]) -> dict:
    """The TypeDescription of `message` (default values included); `table` resolves nested
    types by ROS name."""
    references = _references([message], table)
    return {"type_description": _individual_description(message),
            "referenced_type_descriptions": [references[name] for name in sorted(references)]}


def service_description(service: Service, table: Dict[str, Message]) -> dict:
    """The TypeDescription of a service type, as rosidl synthesizes it (module docstring)."""
    request, response = service.request.ros_type, service.response.ros_type
    event = f"{service.ros_type}_Event"
    references = _references([service.request, service.response], table)
    references.update({
        request: _individual_description(service.request),
        response: _individual_description(service.response),
        event: {"type_name": event, "fields": [
            _plain_field("info", FIELD_TYPE_NESTED, nested=_SERVICE_EVENT_INFO),
            _plain_field("request", FIELD_TYPE_NESTED + CONTAINER_OFFSET[BOUNDED_SEQUENCE], 1,
                         request),
            _plain_field("response", FIELD_TYPE_NESTED + CONTAINER_OFFSET[BOUNDED_SEQUENCE], 1,
                         response)]},
    })
    for name, fixed in _FIXED_DESCRIPTIONS.items():
        references.setdefault(name, fixed)
    return {"type_description": {"type_name": service.ros_type, "fields": [
                _plain_field("request_message", FIELD_TYPE_NESTED, nested=request),
                _plain_field("response_message", FIELD_TYPE_NESTED, nested=response),
                _plain_field("event_message", FIELD_TYPE_NESTED, nested=event)]},
            "referenced_type_descriptions": [references[name] for name in sorted(references)]}


def action_description(action: Action, table: Dict[str, Message]) -> dict:
    """The TypeDescription of an action type, as rosidl synthesizes it (module docstring)."""
    references: Dict[str, dict] = {}
    for service in (action.send_goal, action.get_result):
        description = service_description(service, table)
        references[service.ros_type] = description["type_description"]
        for individual in description["referenced_type_descriptions"]:
            references.setdefault(individual["type_name"], individual)
    for message in (action.goal, action.result, action.feedback, action.feedback_message):
        references[message.ros_type] = _individual_description(message)
        references.update(_references([message], table))
    members = [("goal", action.goal.ros_type), ("result", action.result.ros_type),
               ("feedback", action.feedback.ros_type),
               ("send_goal_service", action.send_goal.ros_type),
               ("get_result_service", action.get_result.ros_type),
               ("feedback_message", action.feedback_message.ros_type)]
    return {"type_description": {"type_name": action.ros_type, "fields": [
                _plain_field(name, FIELD_TYPE_NESTED, nested=nested) for name, nested in members]},
            "referenced_type_descriptions": [references[name] for name in sorted(references)]}


IMPLICIT = "implicit"


def type_source(encoding: str, text: str) -> dict:
    """One TypeSource as rosidl_generator_c embeds it (full__description.c.em): the file's
    lines joined by '\\n', so without the file's last newline; "implicit" types (the halves of
    a .srv, what a .action synthesizes) have no text."""
    return {"encoding": encoding, "raw_file_contents": "\n".join(text.splitlines())}


def own_source(item: Union[Message, Service, Action]) -> dict:
    """The TypeSource of a spec's own type: its file for a .msg, .srv or .action, "implicit"
    for the messages and services rosidl synthesizes from a .srv or .action."""
    if isinstance(item, Action):
        return type_source("action", item.text)
    if isinstance(item, Service):
        return type_source("srv", item.text) if item.kind == "srv" else type_source(IMPLICIT, "")
    return type_source("msg", item.text) if item.kind == "msg" else type_source(IMPLICIT, "")


# The .msg files of the fixed types above that no spec set has to give (fixed_specs/ holds
# service_msgs/msg/ServiceEventInfo.msg as the ROS 2 wheels install it).
_FIXED_SPECS_DIR = os.path.join(os.path.dirname(__file__), "fixed_specs")


def _fixed_text(ros_type: str) -> str:
    package, kind, name = ros_type.split("/")
    path = os.path.join(_FIXED_SPECS_DIR, package, kind, name + "." + kind)
    if not os.path.exists(path):
        return ""
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def description_sources(description: dict, own: dict, table: Dict[str, Message]) -> List[dict]:
    """The type_sources rcl serves for `description` when asked (include_type_sources): the
    type's own source (`own`), then one per referenced type in the description's order; a
    referenced pkg/msg/ type's is its .msg file (from `table`, else from fixed_specs/ for the
    fixed types every service references), a pkg/srv/ or pkg/action/ type's is implicit (a
    service or action only references the types it synthesizes there)."""
    sources = [own]
    for individual in description["referenced_type_descriptions"]:
        name = individual["type_name"]
        if name.split("/")[1] == "msg":
            sources.append(type_source("msg", table[name].text if name in table else _fixed_text(name)))
        else:
            sources.append(type_source(IMPLICIT, ""))
    return sources


def _without_defaults(individual: dict) -> dict:
    return {"type_name": individual["type_name"],
            "fields": [{"name": f["name"], "type": f["type"]} for f in individual["fields"]]}


def hashable(description: dict) -> dict:
    """`description` as it is hashed: default values left out."""
    return {"type_description": _without_defaults(description["type_description"]),
            "referenced_type_descriptions": [_without_defaults(individual) for individual in
                                             description["referenced_type_descriptions"]]}


def hashable_description(message: Message, table: Dict[str, Message]) -> dict:
    return hashable(message_description(message, table))


def description_hash(description: dict) -> str:
    """`RIHS01_<64 hex>` of a TypeDescription (message_description, service_description)."""
    text = json.dumps(hashable(description), separators=(", ", ": "),
                      ensure_ascii=True, sort_keys=False)
    return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()


def type_hash(message_or_service: Union[Message, Service, Action],
              table: Dict[str, Message]) -> str:
    """`RIHS01_<64 hex>` of a message, service or action; `table` resolves nested types by ROS
    name."""
    if isinstance(message_or_service, Action):
        return description_hash(action_description(message_or_service, table))
    if isinstance(message_or_service, Service):
        return description_hash(service_description(message_or_service, table))
    return description_hash(message_description(message_or_service, table))
