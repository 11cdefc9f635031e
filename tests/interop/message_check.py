#!/usr/bin/env python3
"""Our side of the typed-message tests (Debian's python3 + <build>/python): reads the JSON lines
of message_peer.py on stdin; for each, builds a ros2vtk.Message of that type field by field from
the values, and prints {"type", "hex" (our CDR bytes), "read_back" (rclpy's bytes deserialized
into a Message and read field by field), "error"}.
"""
from __future__ import annotations

import json
import sys

import ros2vtk


def set_all(message: ros2vtk.Message, values: dict) -> None:
    for name, value in values.items():
        message.set(name, value)


def to_plain(value):
    if isinstance(value, ros2vtk.Message):
        return {name: to_plain(value.get(name)) for name in value.field_names()}
    if isinstance(value, list):
        return [to_plain(item) for item in value]
    return value


def main() -> int:
    for line in sys.stdin:
        case = json.loads(line)
        result = {'type': case['type'], 'error': ''}
        try:
            ours = ros2vtk.Message(case['type'])
            set_all(ours, case['values'])
            result['hex'] = ours.serialize().hex()
            theirs = ros2vtk.Message(case['type'])
            theirs.deserialize(bytes.fromhex(case['hex']))
            result['read_back'] = {name: to_plain(theirs.get(name)) for name in case['values']}
        except Exception as error:  # reported to the test, which fails with it
            result['error'] = f'{type(error).__name__}: {error}'
        print(json.dumps(result), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
