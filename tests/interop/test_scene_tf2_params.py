"""tf2 and parameters through our VTK-wrapped Python API, against real rclpy nodes."""
from __future__ import annotations

import json
import math


def test_rclpy_dynamic_transform_drives_our_lookup_node_in_millimetres(ros):
    peer = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.1, -0.02, 0.3], 'q': [0, 0, 0.7071067811865476, 0.7071067811865476]}),
                       '--seconds', '20')
    ours = ros.scene('--seconds', '15', 'lookup', 'world', 'needle', '--linger', '1.5')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['status'] == 'ok', result
    m = result['matrix']
    assert [round(m[i][3], 9) for i in range(3)] == [100.0, -20.0, 300.0]  # metres -> mm
    assert math.isclose(m[0][1], -1.0, abs_tol=1e-12) and math.isclose(m[1][0], 1.0, abs_tol=1e-12)
    # ~30 identical transforms arrived in the 1.5 s after the first: the matrix did not change,
    # so no further event fired.
    assert result['events'] == 1
    assert result['stamp'] > 1.6e9  # the rclpy broadcaster stamps with the current time


def test_rclpy_static_transform_reaches_late_lookup(ros):
    peer = ros.tf_peer('tf_pub', 'ct', 'robot_base', json.dumps({'t': [1.0, 2.0, 3.0], 'q': [0, 0, 0, 1]}),
                       '--static', '--seconds', '20')
    ours = ros.scene('--seconds', '12', 'lookup', 'ct', 'robot_base', '--changes', '1')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['status'] == 'ok', result
    assert [result['matrix'][i][3] for i in range(3)] == [1000.0, 2000.0, 3000.0]


def test_our_broadcaster_reaches_rclpy_in_metres_with_a_stamp(ros):
    echo = ros.tf_peer('tf_echo', '--count', '2', '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '8', 'broadcast', 'image', 'probe')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    message = json.loads(out.splitlines()[-1])
    t = message['transforms'][0]
    assert t['header']['frame_id'] == 'image' and t['child_frame_id'] == 'probe'
    assert t['header']['stamp']['sec'] > 1600000000, 'broadcasts carry the current time, not zero'
    assert [round(v, 12) for v in t['transform']['translation'].values()] == [0.1, -0.02, 0.3]
    q = t['transform']['rotation']
    assert math.isclose(q['z'], math.sqrt(0.5), abs_tol=1e-9) and math.isclose(q['w'], math.sqrt(0.5), abs_tol=1e-9)


def test_our_static_broadcast_reaches_late_rclpy_subscriber(ros):
    ours = ros.scene('--seconds', '15', 'broadcast', 'ct', 'registration', '--static')
    import time
    time.sleep(4.0)
    echo = ros.tf_peer('tf_echo', '--static', '--count', '1', '--timeout', '10')
    code, out, err = ros.finish(echo)
    ros.stop(ours)
    assert code == 0, err
    t = json.loads(out.splitlines()[-1])['transforms'][0]
    assert (t['header']['frame_id'], t['child_frame_id']) == ('ct', 'registration')


def test_parameter_node_follows_every_type_and_a_remote_change(ros):
    peer = ros.peer('--node', 'planner', 'param_node', '--seconds', '30', '--change-after', '12')
    ros.wait_ready(peer)
    ours = ros.scene('--seconds', '18', 'params', '/planner', 'flag', 'count', 'gain', 'frame', 'bytes',
                     'flags', 'counts', 'gains', 'frames', 'missing')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['ready'] is True
    # The snapshot once everything was fetched and before the remote change.
    first = next(h for h in result['history'] if all(h[n]['type'] not in ('not set', '') for n in h if n != 'missing'))
    assert first['flag'] == {'type': 'bool', 'value': True}
    assert first['count'] == {'type': 'integer', 'value': -7}
    assert first['gain'] == {'type': 'double', 'value': 0.5}
    assert first['frame'] == {'type': 'string', 'value': 'ct_scanner'}
    assert first['bytes'] == {'type': 'byte_array', 'value': [1, 255]}
    assert first['flags'] == {'type': 'bool_array', 'value': [True, False, True]}
    assert first['counts'] == {'type': 'integer_array', 'value': [1, -2, 3]}
    assert first['gains'] == {'type': 'double_array', 'value': [0.25, 1.5]}
    assert first['frames'] == {'type': 'string_array', 'value': ['base', 'tool']}
    assert first['missing'] == {'type': '', 'value': None}  # never seen: '' as SlicerROS2 answers
    assert result['history'][-1]['gain'] == {'type': 'double', 'value': 2.5}, 'remote change not followed'
    assert result['events'] >= 2


def test_parameter_node_reports_an_absent_node_and_reconnects_when_it_returns(ros):
    import time
    ours = ros.scene('--seconds', '24', 'params', '/surgeon_console', 'gain', '--with-ready')
    time.sleep(3.0)  # nobody serves /surgeon_console yet
    first = ros.peer('--node', 'surgeon_console', 'param_node', '--seconds', '6', '--change-after', '100')
    assert ros.finish(first, timeout=30)[0] == 0
    time.sleep(4.0)  # gone
    second = ros.peer('--node', 'surgeon_console', 'param_node', '--seconds', '8', '--change-after', '100',
                      '--gain', '3.5')
    assert ros.finish(second, timeout=30)[0] == 0
    code, out, err = ros.finish(ours, timeout=40)
    assert code == 0, err
    states = [(h['_ready'], h['gain']['value']) for h in json.loads(out.splitlines()[-1])['history']]
    # Collapse repeats, then look for: absent -> served (0.5) -> absent -> served again (3.5).
    sequence = [s for i, s in enumerate(states) if i == 0 or s[0] != states[i - 1][0] or s[1] != states[i - 1][1]]
    ready = [s for s in sequence if s[0]]
    assert sequence[0][0] is False, sequence
    assert (True, 0.5) in ready and (True, 3.5) in ready, sequence
    assert ready.index((True, 0.5)) < ready.index((True, 3.5))
    between = sequence[sequence.index((True, 0.5)):sequence.index((True, 3.5))]
    assert any(not s[0] for s in between), f'the node going away was never reported: {sequence}'


def test_rclpy_parameter_client_reads_and_sets_our_nodes_parameters(ros):
    """Our node's own parameters (SetParameterAs...), scalars and the five array types, read by
    rclpy's parameter client; the array setters' refusals (an element that does not fit, two
    components, no array, another type) leave the values as they were."""
    ours = ros.scene('--seconds', '20', 'serve')
    ready = json.loads(ours.stdout.readline())
    assert ready['ready'] is True
    assert ready['set_arrays'] == [True] * 5 and ready['refused_arrays'] == [False] * 5, ready
    arrays = ['flags', 'ids', 'weights', 'key', 'frames']
    peer = ros.peer('params', '/slicer', '--get', 'use_registration', 'frame_count', 'needle_depth_mm',
                    'image_frame', *arrays, '--set', 'needle_depth_mm=40.0', 'frame_count="wrong type"')
    code, out, err = ros.finish(peer, timeout=60)
    ros.stop(ours)
    assert code == 0, err
    result = json.loads(out)
    assert {'use_registration', 'frame_count', 'needle_depth_mm', 'image_frame', *arrays} <= set(result['list'])
    assert result['get'] == {'use_registration': True, 'frame_count': 42, 'needle_depth_mm': 37.5,
                             'image_frame': 'ct', 'flags': [True, False, True], 'ids': [-2 ** 63, 7, 2 ** 63 - 1],
                             'weights': [0.25, -1.5], 'key': [0, 17, 255], 'frames': ['ct', 'needle tip']}
    assert result['types'][4:] == [6, 7, 8, 5, 9]  # rcl_interfaces ParameterType: bool[] integer[] double[] byte[] string[]
    assert result['set'][0]['successful'] is True
    assert result['set'][1]['successful'] is False
    assert result['get_after']['needle_depth_mm'] == 40.0
    assert {'node': '/slicer', 'changed': ['needle_depth_mm']} in result['events']
