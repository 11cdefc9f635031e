"""rclpy's own answer for a table of topic/service names: expected results for test_names_vs_rclpy.

Run with the venv python (rclpy from the Kilted wheels). For every namespace and name it prints
one tab-separated line `namespace, name, "ok" or "invalid", expanded name or rclpy's error`, using
rclpy.expand_topic_name (rcl_expand_topic_name, which validates the name as written) followed by
rclpy.validate_full_topic_name (what rcl_node_resolve_name checks on the result). Only the inputs
are listed here; every expected output comes from rclpy at test time.
"""
import sys

from rclpy.expand_topic_name import expand_topic_name
from rclpy.validate_full_topic_name import validate_full_topic_name

NODE = 'talker'
NAMESPACES = ['/', '/a/b']
NAMES = [
    # absolute and relative
    'chatter', '/chatter', 'a/b/c', '/a/b/c', '_a', 'a__b', '__a/_1', 'x/y1',
    # private
    '~', '~/x', '~/status', '~/a/b', '~x', '~1', '~ab', '~{node}', '~/{node}', '~~',
    # substitutions
    '{node}', '{node}/status', '{ns}', '{ns}/x', '{namespace}/x', 'a/{node}', 'x{node}',
    '{node}x', 'a{ns}', '{ns}{node}', '/{node}', '/{ns}/x', 'a/{ns}', 'x/{node}1',
    '{bad}', '{}', '{}x', '{NODE}', '{a b}', '{{node}}', '{node', 'node}', '{node}{', '{1node}',
    '{no/de}',
    # invalid as written or after expansion
    '', '/', 'a/', '/a/', 'a//b', '//a', '1abc', 'a/1b', '/1a', '{node}/1x', 'a b', 'a-b',
    'a.b', '/~', 'a~', 'a/~/b', '{ns}/~', '{node}~',
    # length limit (rmw: 255 - 8 characters for the full name)
    '/' + 'b' * 246, '/' + 'b' * 247, 'b' * 240, 'b' * 246,
]


def rclpy_answer(name: str, namespace: str) -> tuple[str, str]:
    try:
        expanded = expand_topic_name(name, NODE, namespace)
        validate_full_topic_name(expanded)
    except Exception as error:  # rclpy raises ValueError / InvalidTopicNameException
        return 'invalid', str(error).splitlines()[0] if str(error) else type(error).__name__
    return 'ok', expanded


def main() -> int:
    for namespace in NAMESPACES:
        for name in NAMES:
            status, result = rclpy_answer(name, namespace)
            sys.stdout.write(f'{namespace}\t{name}\t{status}\t{result}\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
