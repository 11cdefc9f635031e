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
    ros.stop(peer)
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
    ros.stop(peer)
    assert '/cli_peer' in nodes_out.split()
    assert '/cli/chatter std_msgs/msg/String' in topics_out.splitlines()


# Every short name the README/user guide promise, each with a publisher and a subscriber class
# (written out by hand, not read from the registry under test).
SHORT_NAMES = ['Bool', 'DoubleArray', 'Double', 'DoubleTable', 'Empty', 'Image', 'IntArray', 'Int',
               'IntTable', 'JointState', 'PointCloud2', 'PointCloud', 'PoseArray', 'PoseStamped',
               'String', 'TransformStamped', 'UInt8Image', 'WrenchStamped',
               'Pose', 'Transform', 'Wrench', 'Vector3',
               # SlicerROS2's PolyData, and the rules of the common interfaces (docs/messages.md)
               'PolyData', 'Twist', 'TwistStamped', 'PointStamped', 'PolygonStamped',
               'PoseWithCovarianceStamped', 'Odometry', 'Path', 'Imu',
               # issue 13: what users see first
               'CameraInfo', 'CameraDistortion', 'JoyAxes', 'JoyButtons', 'PathPolyline', 'CompressedImage', 'Marker', 'MarkerArray',
               # issue 14: SlicerROS2's name for sensor_msgs/Joy (docs/porting-from-slicerros2.md)
               'Joy']


def test_types_lists_a_publisher_and_a_subscriber_class_per_short_name(ros):
    code, out, err = ros.finish(cli(ros, 'types'), timeout=20)
    assert code == 0, err
    lines = out.splitlines()
    assert len(lines) == 2 and lines[0].startswith('publishers:') and lines[1].startswith('subscribers:'), out
    publishers = lines[0].split()[1:]
    subscribers = lines[1].split()[1:]
    assert sorted(publishers) == sorted(f'vtkROS2Publisher{s}Node' for s in SHORT_NAMES)
    assert sorted(subscribers) == sorted(f'vtkROS2Subscriber{s}Node' for s in SHORT_NAMES)


def test_params_prints_every_type_of_an_rclpy_node(ros):
    peer = ros.peer('--node', 'cli_params', 'param_node', '--seconds', '25', '--change-after', '100')
    ros.wait_ready(peer)
    ours = cli(ros, 'params', '/cli_params', 'flag', 'count', 'gain', 'frame', 'bytes', 'flags',
               'counts', 'gains', 'frames')
    code, out, err = ros.finish(ours, timeout=20)
    assert code == 0, err
    # the values param_node declares, one line per requested name, in the order asked
    assert out.splitlines() == [
        'flag (bool): true',
        'count (integer): -7',
        'gain (double): 0.5',
        'frame (string): ct_scanner',
        'bytes (byte_array): [1, 255]',
        'flags (bool_array): [true, false, true]',
        'counts (integer_array): [1, -2, 3]',
        'gains (double_array): [0.25, 1.5]',
        "frames (string_array): ['base', 'tool']",
    ]


def test_params_of_an_absent_node_fails_with_a_message(ros):
    code, out, err = ros.finish(cli(ros, 'params', '/no_such_node', 'gain'), timeout=25)
    assert code == 3 and out == '', (code, out)
    assert '/no_such_node: not reachable' in err
