"""RIHS01 type hashes, computed as rosidl_generator_type_description does (WIRE_NOTES §2.6).

The hashed text is the JSON of the type description (the type and every type it references,
sorted by name, default values left out), dumped with separators (', ', ': ') and ASCII escapes;
the hash is SHA-256 of that text.
"""
from __future__ import annotations

import hashlib
import json
from typing import Dict, List

from .model import ARRAY, BOUNDED_SEQUENCE, SEQUENCE, Field, Message

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
    }


def _individual_description(message: Message) -> dict:
    if message.is_empty:
        fields = [{"name": EMPTY_MESSAGE_MEMBER,
                   "type": {"type_id": FIELD_TYPE_IDS["uint8"], "capacity": 0,
                            "string_capacity": 0, "nested_type_name": ""}}]
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


def hashable_description(message: Message, table: Dict[str, Message]) -> dict:
    found: Dict[str, Message] = {}
    _referenced(message, table, found)
    references: List[dict] = [_individual_description(found[name]) for name in sorted(found)]
    return {"type_description": _individual_description(message),
            "referenced_type_descriptions": references}


def type_hash(message: Message, table: Dict[str, Message]) -> str:
    """`RIHS01_<64 hex>` of `message`; `table` resolves nested types by ROS name."""
    text = json.dumps(hashable_description(message, table), separators=(", ", ": "),
                      ensure_ascii=True, sort_keys=False)
    return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()
