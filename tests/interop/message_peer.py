#!/usr/bin/env python3
"""rclpy side of the typed-message tests: fills every field of a message type with distinct
non-default values (walking rclpy's own SLOT_TYPES, so rclpy decides what each field is) and
prints, per type, one JSON line {"type", "values", "hex"} where hex is rclpy's
serialize_message() of that message. Our side must rebuild the same bytes field by field.

    message_peer.py fill TYPE [TYPE ...]
    message_peer.py equal      (stdin: JSON lines {"type", "ours", "theirs"} of hex payloads;
                                prints {"type", "equal", "error"}: rclpy deserializes both)
    message_peer.py constants TYPE [TYPE ...]   (per type: {"type", "constants": [[name, value]]})
"""
from __future__ import annotations

import importlib
import itertools
import json
import sys
from typing import Any

from rclpy.serialization import deserialize_message, serialize_message
from rosidl_parser import definition

_counter = itertools.count(1)

INT_RANGES = {
    'int8': (-128, 127), 'uint8': (0, 255), 'int16': (-32768, 32767), 'uint16': (0, 65535),
    'int32': (-2**31, 2**31 - 1), 'uint32': (0, 2**32 - 1), 'int64': (-2**63, 2**63 - 1),
    'uint64': (0, 2**64 - 1),
}


def message_class(type_name: str) -> type:
    """rclpy's class of a message type; also the halves of a service (pkg/srv/X_Request) and
    the messages of an action (pkg/action/X_Goal: rclpy keeps them on the action's class, and
    X_FeedbackMessage on its Impl)."""
    parts = type_name.split('/')
    if len(parts) == 2:
        parts = [parts[0], 'msg', parts[1]]
    package, kind, name = parts
    module = importlib.import_module(f'{package}.{kind}')
    if hasattr(module, name):
        return getattr(module, name)
    base, _, suffix = name.partition('_')
    owner = getattr(module, base)
    return getattr(owner, suffix) if hasattr(owner, suffix) else getattr(owner.Impl, suffix)


def basic_value(type_name: str) -> tuple[Any, Any]:
    """(value for rclpy, value for JSON) of one primitive, different at every call."""
    k = next(_counter)
    if type_name == 'boolean':
        return k % 2 == 1, k % 2 == 1
    if type_name == 'octet':
        value = (k * 37) % 256
        return bytes([value]), value
    if type_name == 'char':
        value = 32 + (k * 7) % 90  # printable
        return chr(value), value
    if type_name in ('float', 'double'):
        # float: a value float32 holds exactly; double: many significant digits.
        value = k * 0.5 + 0.25 if type_name == 'float' else k * 1.2345678901234567e-3 - 7.0
        return value, value
    low, high = INT_RANGES[type_name]
    # Near the ends of the range: catches truncation and sign mistakes.
    offset = k % min(high - low, 100)
    value = high - offset if k % 2 else low + offset
    return value, value


def string_value(bound: int = 0) -> str:
    text = f's{next(_counter)}-é✓'
    return text[:bound] if bound else text


def element(type_def) -> tuple[Any, Any]:
    if isinstance(type_def, definition.BasicType):
        return basic_value(type_def.typename)
    if isinstance(type_def, (definition.UnboundedString, definition.BoundedString)):
        text = string_value(getattr(type_def, 'maximum_size', 0))
        return text, text
    if isinstance(type_def, definition.NamespacedType):
        cls = message_class('/'.join(type_def.namespaces + [type_def.name]))
        return fill(cls())
    raise TypeError(f'unsupported element type {type_def!r}')


def fill(message: Any) -> tuple[Any, dict]:
    plain: dict = {}
    for name, type_def in zip(message.get_fields_and_field_types(), message.SLOT_TYPES):
        if isinstance(type_def, (definition.UnboundedWString, definition.BoundedWString)):
            continue  # wstring fields stay default: our typed objects set them through YAML
        if isinstance(type_def, definition.AbstractNestedType):
            if isinstance(type_def, definition.Array):
                count = type_def.size
            elif isinstance(type_def, definition.BoundedSequence):
                count = min(2, type_def.maximum_size)
            else:
                count = 2
            if isinstance(type_def.value_type, (definition.UnboundedWString,
                                                definition.BoundedWString)):
                continue
            pairs = [element(type_def.value_type) for _ in range(count)]
            values = [p[0] for p in pairs]
            if isinstance(type_def.value_type, definition.BasicType) and \
                    type_def.value_type.typename == 'octet':
                values = [bytes(v) for v in values]
            setattr(message, name, values)
            plain[name] = [p[1] for p in pairs]
        else:
            value, shown = element(type_def)
            setattr(message, name, value)
            plain[name] = shown
    return message, plain


def equal() -> int:
    for line in sys.stdin:
        case = json.loads(line)
        result = {'type': case['type'], 'equal': False, 'error': ''}
        try:
            cls = message_class(case['type'])
            ours = deserialize_message(bytes.fromhex(case['ours']), cls)
            theirs = deserialize_message(bytes.fromhex(case['theirs']), cls)
            result['equal'] = ours == theirs
        except Exception as error:  # reported to the test
            result['error'] = f'{type(error).__name__}: {error}'
        print(json.dumps(result), flush=True)
    return 0


def constants(type_names) -> int:
    """One JSON line per type: its constants as rosidl's Python class holds them, in the .msg
    file's order ([name, value]; bytes as their integer)."""
    for type_name in type_names:
        meta = type(message_class(type_name))
        pairs = getattr(meta, f'_{meta.__name__}__constants').items()
        print(json.dumps({'type': type_name, 'constants': [
            [name, value[0] if isinstance(value, bytes) else value] for name, value in pairs]}), flush=True)
    return 0


def main() -> int:
    if len(sys.argv) == 2 and sys.argv[1] == 'equal':
        return equal()
    if len(sys.argv) >= 3 and sys.argv[1] == 'constants':
        return constants(sys.argv[2:])
    if len(sys.argv) < 3 or sys.argv[1] != 'fill':
        print(__doc__, file=sys.stderr)
        return 2
    for type_name in sys.argv[2:]:
        message, plain = fill(message_class(type_name)())
        print(json.dumps({'type': type_name, 'values': plain,
                          'hex': serialize_message(message).hex()}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
