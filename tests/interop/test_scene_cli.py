"""`python -m ros2vtk` (the wrapped API's command line) against real rclpy nodes."""
from __future__ import annotations

import json

from conftest import BUILD
from samples import SAMPLES


def cli(ros, *args: str):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', '-m', 'ros2vtk', *args], env=env)


def test_echo_prints_yaml_and_the_vtk_value_in_mm(ros):
    ours = cli(ros, 'echo', '/cli/pose', 'PoseStamped', '--timeout', '25')
    peer = ros.peer('pub', '/cli/pose', 'geometry_msgs/msg/PoseStamped',
                    json.dumps(SAMPLES['geometry_msgs/msg/PoseStamped']), '--count', '50', '--rate', '10')
    code, out, err = ros.finish(ours)
    ros.finish(peer)
    assert code == 0, err
    assert 'frame_id: ct_scanner' in out
    assert '# as vtkMatrix4x4 translation (mm): 100, -250, 1500' in out


def test_nodes_and_topics_list_the_rclpy_node(ros):
    peer = ros.peer('--node', 'cli_peer', 'pub', '/cli/chatter', 'std_msgs/msg/String',
                    json.dumps({'data': 'x'}), '--count', '60', '--rate', '10', '--wait-matched', '0')
    nodes = cli(ros, '--wait', '3', 'nodes')
    topics = cli(ros, '--wait', '3', 'topics')
    _, nodes_out, _ = ros.finish(nodes)
    _, topics_out, _ = ros.finish(topics)
    ros.finish(peer)
    assert '/cli_peer' in nodes_out.split()
    assert '/cli/chatter std_msgs/msg/String' in topics_out.splitlines()
