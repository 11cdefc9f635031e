"""Private and substituted topic names on the wire: an rclpy subscriber on the name rclpy itself
expands `~/status` / `{node}/status` to receives what our publisher created with that name sends.

Our side is `ros2vtk-topic pub` with a node name and namespace, so the name goes through
Participant::resolve_name exactly as every publisher of the runtime does. The expected topic is
rclpy's own expansion (rclpy.expand_topic_name), not ours. The last test runs the whole table of
tests/names (rclpy's answers) through our Python API's publisher nodes.
"""
from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from conftest import BUILD, VENV_PYTHON
from rclpy.expand_topic_name import expand_topic_name

NODE = 'names_talker'
NAMESPACE = '/names_ns/robot'


@pytest.mark.parametrize('written', ['~/status', '{node}/status', '{ns}/{node}_state'])
def test_rclpy_subscriber_receives_our_private_and_substituted_topics(ros, written):
    topic = expand_topic_name(written, NODE, NAMESPACE)
    assert topic.startswith(NAMESPACE + '/')  # rclpy put it under our namespace, not at the root
    message = {'data': f'sent on {written}'}
    echo = ros.peer('echo', topic, 'std_msgs/msg/String', '--count', '3', '--timeout', '30')
    ros.wait_ready(echo)
    publisher = ros.tool('pub', written, 'std_msgs/msg/String', json.dumps(message),
                         '--node', NODE, '--namespace', NAMESPACE, '--count', '40', '--rate', '20',
                         '--wait-matched', '1', '--wait', '15')
    code, out, err = ros.finish(echo, timeout=40)
    pub_code, _, pub_err = ros.finish(publisher)
    assert code == 0, f'rclpy echo on {topic} got too few messages ({code}): {err}; ours: {pub_err}'
    lines = [json.loads(line) for line in out.splitlines() if line.strip()]
    assert lines == [message] * 3


@pytest.mark.parametrize('written', ['{bad}/status', '~ab', 'a//b'])
def test_our_publisher_refuses_what_rclpy_refuses(ros, written):
    with pytest.raises(Exception):  # rclpy refuses it too (expansion or full-name validation)
        from rclpy.validate_full_topic_name import validate_full_topic_name
        validate_full_topic_name(expand_topic_name(written, NODE, NAMESPACE))
    publisher = ros.tool('pub', written, 'std_msgs/msg/String', json.dumps({'data': 'x'}),
                         '--node', NODE, '--namespace', NAMESPACE, '--count', '1', '--wait', '0')
    code, _, err = ros.finish(publisher)
    assert code != 0 and written in err, f'exit {code}, stderr: {err}'


def test_python_api_publisher_nodes_resolve_the_table_as_rclpy(ros):
    """Every row of tests/names (rclpy's answer, computed now by the venv python) against the
    topic our Python API's publisher node resolved, or its refusal."""
    names_dir = Path(__file__).resolve().parents[1] / 'names'
    table = subprocess.run([str(VENV_PYTHON), str(names_dir / 'rclpy_names_table.py')],
                           capture_output=True, text=True, check=True).stdout
    rows = [line.split('\t') for line in table.splitlines()]
    assert len(rows) >= 50
    ours = subprocess.run(['/usr/bin/python3', str(names_dir / 'python_api_names.py')],
                          input=''.join(f'{ns}\t{name}\n' for ns, name, _, _ in rows),
                          env=dict(ros.env, PYTHONPATH=str(BUILD / 'python')),
                          capture_output=True, text=True, timeout=120)
    out, err = ours.stdout, ours.stderr
    assert ours.returncode == 0, err
    results = [json.loads(line) for line in out.splitlines() if line.startswith('{')]
    assert len(results) == len(rows), err
    mismatches = []
    for (ns, name, status, expected), result in zip(rows, results):
        assert (result['namespace'], result['name']) == (ns, name)
        wanted = expected if status == 'ok' else None
        if result['topic'] != wanted:
            mismatches.append(f'{name!r} in {ns!r}: rclpy {status} {expected!r}, ours {result["topic"]!r}')
    assert not mismatches, '\n'.join(mismatches)
