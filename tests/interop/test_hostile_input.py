"""Hostile but well-formed input from a real rclpy peer (issue 11): each message below once
crashed, hung or silently misled our side. Each test asserts that the process survives, that the
error names what arrived, and that valid messages sent afterwards still arrive."""
from __future__ import annotations

import json
from pathlib import Path


def bad_then_good(ros, short: str, topic: str, ros_type: str, bad: dict, good: dict, seconds: str = '20'):
    """Our subscriber gets `bad` (5 times), then `good`; returns our last JSON line."""
    # 6 = the 5 hostile ones (delivered and counted, refused on conversion) + 1 valid one.
    ours = ros.scene('--seconds', seconds, 'sub', short, topic, '--count', '6')
    ros.wait_ready(ours)
    hostile = ros.peer('pub', topic, ros_type, json.dumps(bad), '--count', '5', '--rate', '10')
    assert ros.finish(hostile)[0] == 0
    valid = ros.peer('pub', topic, ros_type, json.dumps(good), '--count', '40', '--rate', '10')
    code, out, err = ros.finish(ours, timeout=float(seconds) + 20)
    ros.stop(valid)
    assert code == 0, err
    return json.loads(out.splitlines()[-1]), err


def test_multi_array_of_rows_without_columns_is_refused_and_later_arrays_arrive(ros):
    # 11.1: 2^27 rows x 0 columns in a 60-byte message allocated 1 GiB; 2^32-1 rows aborted the
    # process (bad_alloc).
    bad = {'layout': {'dim': [{'label': 'rows', 'size': 4294967295, 'stride': 0},
                              {'label': 'cols', 'size': 0, 'stride': 0}], 'data_offset': 0}, 'data': []}
    good = {'layout': {'dim': [{'label': 'x', 'size': 3, 'stride': 3}], 'data_offset': 0},
            'data': [0.5, -1.25, 2.0]}
    result, _ = bad_then_good(ros, 'DoubleArray', '/hostile/array', 'std_msgs/msg/Float64MultiArray', bad, good)
    assert result['value'] == [0.5, -1.25, 2.0], result
    assert result['count'] >= 6, result  # the 5 refused ones were counted too


def test_multi_array_error_names_the_layout(ros):
    bad = {'layout': {'dim': [{'label': 'rows', 'size': 134217728, 'stride': 0},
                              {'label': 'cols', 'size': 0, 'stride': 0}], 'data_offset': 0}, 'data': []}
    ours = ros.scene('--seconds', '15', 'sub', 'IntTable', '/hostile/table')
    ros.wait_ready(ours)
    hostile = ros.peer('pub', '/hostile/table', 'std_msgs/msg/Int64MultiArray', json.dumps(bad), '--count', '30')
    code, out, err = ros.finish(ours)
    ros.stop(hostile)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['value'] is None or result['value'] == {}, result
    assert 'multi_array_to_table: layout has 134217728 rows of 0 columns' in result['conversion_error'], result


def test_invalid_utf8_arrives_as_str_with_replacement_characters(ros):
    # 11.9: bytes rclpy cannot send from a str, so raw CDR: length 4, 'a' 0xff 'b' NUL. Our
    # policy is rclpy's own (decode with "replace"): Python gets a str, never bytes.
    ours = ros.scene('--seconds', '15', 'sub', 'String', '/hostile/utf8')
    ros.wait_ready(ours)
    peer = ros.peer('pub_raw', '/hostile/utf8', 'std_msgs/msg/String', '000100000400000061ff6200', '--count', '30')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['value'] == 'a\ufffdb', result
    assert result['rejected'] == 0, result


def test_pose_that_overflows_in_millimetres_is_refused_and_later_poses_arrive(ros):
    # 11.9: 1e306 m is finite; in mm it was an infinite matrix.
    header = {'stamp': {'sec': 1, 'nanosec': 0}, 'frame_id': 'world'}
    bad = {'header': header, 'pose': {'position': {'x': 1e306, 'y': 0.0, 'z': 0.0},
                                      'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}}
    good = {'header': header, 'pose': {'position': {'x': 0.25, 'y': 0.0, 'z': 0.0},
                                       'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}}
    ours = ros.scene('--seconds', '15', 'sub', 'PoseStamped', '/hostile/pose', '--count', '5')
    ros.wait_ready(ours)
    hostile = ros.peer('pub', '/hostile/pose', 'geometry_msgs/msg/PoseStamped', json.dumps(bad), '--count', '30')
    code, out, err = ros.finish(ours)
    ros.stop(hostile)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['value'] is None, result
    assert 'translation (1e+306, 0, 0) is not finite once scaled by 1000' in result['conversion_error'], result
    result, _ = bad_then_good(ros, 'PoseStamped', '/hostile/pose2', 'geometry_msgs/msg/PoseStamped', bad, good)
    assert result['value'][0][3] == 250.0, result


def test_description_from_the_network_cannot_make_us_read_meshes_outside_the_roots(ros, tmp_path):
    # 11.10: a robot_description from an rclpy peer names real STL files outside every root
    # (through `..` in a package URI, and by file://); they stay unread placeholders with a
    # warning, while the mesh inside the package loads.
    stl = (Path(__file__).resolve().parents[2] / 'examples' / 'robots' / 'surgical_arm' / 'meshes' / 'base.stl').read_bytes()
    (tmp_path / 'ws' / 'pkg' / 'meshes').mkdir(parents=True)
    (tmp_path / 'ws' / 'pkg' / 'package.xml').write_text('<package format="3"><name>pkg</name></package>')
    (tmp_path / 'ws' / 'pkg' / 'meshes' / 'ok.stl').write_bytes(stl)
    (tmp_path / 'outside').mkdir()
    (tmp_path / 'outside' / 'x.stl').write_bytes(stl)
    urdf = f"""<robot name="sneaky">
  <link name="base"><visual><geometry><mesh filename="package://pkg/meshes/ok.stl"/></geometry></visual></link>
  <link name="dotdot"><visual><geometry><mesh filename="package://pkg/../../outside/x.stl"/></geometry></visual></link>
  <link name="file"><visual><geometry><mesh filename="file://{tmp_path}/outside/x.stl"/></geometry></visual></link>
  <joint name="a" type="fixed"><parent link="base"/><child link="dotdot"/></joint>
  <joint name="b" type="fixed"><parent link="base"/><child link="file"/></joint>
</robot>"""
    peer = ros.peer('pub', '/robot_description', 'std_msgs/msg/String', json.dumps({'data': urdf}),
                    '--qos', 'latched', '--count', '1', '--linger', '20')
    ours = ros.scene('--seconds', '15', 'robot', 'sneaky', '--source', 'topic',
                     '--mesh-path', str(tmp_path / 'ws'), '--follow', '0.5')
    code, out, err = ros.finish(ours, timeout=40)
    ros.stop(peer)
    assert code == 0, err
    loaded = json.loads(out.splitlines()[1])
    assert loaded['state'] == 'loaded', loaded
    assert loaded['models'] == 3 and loaded['placeholders'] == 2, loaded
    warnings = loaded['warnings']
    assert "link 'dotdot'" in warnings and 'outside its package folder' in warnings, warnings
    assert "link 'file'" in warnings and 'outside the allowed roots' in warnings, warnings


def test_empty_robot_description_says_what_arrived_and_a_later_one_loads(ros):
    # 11.8: an empty robot_description gave no error; the robot waited forever.
    empty = ros.peer('pub', '/robot_description', 'std_msgs/msg/String', json.dumps({'data': ''}),
                     '--qos', 'latched', '--count', '1', '--linger', '4')
    ours = ros.scene('--seconds', '8', 'robot', 'r', '--source', 'topic', '--follow', '1', '--every', '0.5')
    assert json.loads(ours.stdout.readline())['ready']
    first = json.loads(ours.stdout.readline())
    ros.finish(empty)
    assert first['state'] == "failed: the robot description from the topic '/robot_description' is empty (0 bytes)", first
    urdf = '<robot name="r"><link name="base"/><link name="tip"/>' \
           '<joint name="j" type="fixed"><parent link="base"/><child link="tip"/></joint></robot>'
    valid = ros.peer('pub', '/robot_description', 'std_msgs/msg/String', json.dumps({'data': urdf}),
                     '--qos', 'latched', '--count', '1', '--linger', '10')
    code, out, err = ros.finish(ours, timeout=40)
    ros.stop(valid)
    assert code == 0, err
    last = json.loads(out.splitlines()[-1])
    assert last['state'] == 'loaded' and last['loads'] == 1, last
