"""Topics on the wire, both directions, against real rclpy nodes (one process each).

Our side is `ros2vtk-topic` (runtime/Tools), a thin command line over runtime/Wire and the
generated type supports, so these tests prove the wire layer for every shipped type without VTK.
"""
from __future__ import annotations

import json
import math

import pytest
import yaml

from samples import SAMPLES


def assert_matches(expected, actual, path: str = '') -> None:
    """Every field given in `expected` has this value in `actual` (floats exactly, as both
    sides must round-trip the same IEEE values)."""
    if isinstance(expected, dict):
        assert isinstance(actual, dict), f'{path}: expected a message, got {actual!r}'
        for key, value in expected.items():
            assert key in actual, f'{path}.{key} missing in {sorted(actual)}'
            assert_matches(value, actual[key], f'{path}.{key}')
    elif isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), f'{path}: {actual!r}'
        for i, (e, a) in enumerate(zip(expected, actual)):
            assert_matches(e, a, f'{path}[{i}]')
    elif isinstance(expected, float):
        assert isinstance(actual, (int, float)) and (actual == expected or
                                                    math.isclose(actual, expected, rel_tol=0, abs_tol=0)), \
            f'{path}: {actual!r} != {expected!r}'
    else:
        assert actual == expected, f'{path}: {actual!r} != {expected!r}'


def topic_for(ros_type: str) -> str:
    return '/interop/' + ros_type.split('/')[-1].lower()


@pytest.mark.parametrize('ros_type', sorted(SAMPLES))
def test_rclpy_publisher_reaches_our_subscriber(ros, ros_type):
    topic = topic_for(ros_type)
    echo = ros.tool('echo', topic, ros_type, '--count', '3', '--timeout', '30')
    publisher = ros.peer('pub', topic, ros_type, json.dumps(SAMPLES[ros_type]),
                         '--count', '40', '--rate', '20', '--wait-matched', '1')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(publisher)
    assert code == 0, f'our echo failed ({code}): {err}'
    documents = [d for d in out.split('---\n') if d.strip()]
    assert len(documents) == 3
    for document in documents:
        assert_matches(SAMPLES[ros_type], yaml.safe_load(document))


@pytest.mark.parametrize('ros_type', sorted(SAMPLES))
def test_our_publisher_reaches_rclpy_subscriber(ros, ros_type):
    topic = topic_for(ros_type)
    echo = ros.peer('echo', topic, ros_type, '--count', '3', '--timeout', '30')
    ros.wait_ready(echo)
    publisher = ros.tool('pub', topic, ros_type, json.dumps(SAMPLES[ros_type]),
                         '--count', '40', '--rate', '20', '--wait-matched', '1', '--wait', '15')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(publisher)
    assert code == 0, f'rclpy echo got too few messages ({code}): {err}'
    lines = [json.loads(line) for line in out.splitlines() if line.strip()]
    assert len(lines) == 3
    for value in lines:
        assert_matches(SAMPLES[ros_type], value)
