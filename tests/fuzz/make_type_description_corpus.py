"""Writes the seed corpus of the `type_description` fuzz target (tests/fuzz/fuzz_inputs.cpp) from
rclpy's own answers: each tests/fixtures/type_descriptions/*.json holds the GetTypeDescription
response an rclpy node served (CDR), read here with rclpy's generated Python type, and one payload
of the type as rclpy serialized it (tests/fixtures/cdr, or the fixture's samples).

Run with the venv of scripts/setup.sh:  .venv/bin/python tests/fuzz/make_type_description_corpus.py

The format, one line each (fields separated by single spaces, '-' for an empty word):
    T <type name>                                           the main type, then referenced types
    F <name> <type id> <capacity> <string capacity> <nested type name> <default value to the end>
    P <payload as hex>                                      CDR with its encapsulation header
"""
from __future__ import annotations

import json
from pathlib import Path

from rclpy.serialization import deserialize_message
from type_description_interfaces.srv import GetTypeDescription

FIXTURES = Path(__file__).resolve().parents[1] / 'fixtures'
CORPUS = Path(__file__).resolve().parent / 'corpus' / 'type_description'


def word(text: str) -> str:
    return text if text else '-'


def lines_of(individual) -> list[str]:
    out = [f'T {individual.type_name}']
    for field in individual.fields:
        t = field.type
        out.append(f'F {field.name} {t.type_id} {t.capacity} {t.string_capacity} '
                   f'{word(t.nested_type_name)} {field.default_value}'.rstrip())
    return out


def payload_of(ros_type: str, document: dict) -> str:
    for sample in document.get('samples', []):
        return sample['hex']
    cdr = FIXTURES / 'cdr' / f'{ros_type.replace("/msg/", "__")}__1.json'
    return json.loads(cdr.read_text())['hex'] if cdr.exists() else ''


def main() -> int:
    CORPUS.mkdir(parents=True, exist_ok=True)
    for path in sorted((FIXTURES / 'type_descriptions').glob('*.json')):
        document = json.loads(path.read_text())
        response = deserialize_message(bytes.fromhex(document['response_hex']), GetTypeDescription.Response)
        description = response.type_description
        lines = lines_of(description.type_description)
        for referenced in description.referenced_type_descriptions:
            lines += lines_of(referenced)
        payload = payload_of(document['ros_type'], document)
        if payload:
            lines.append(f'P {payload}')
        (CORPUS / f'{path.stem}.txt').write_text('\n'.join(lines) + '\n')
        print(f'{path.stem}: {len(lines)} lines{", with a payload" if payload else ""}')
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
