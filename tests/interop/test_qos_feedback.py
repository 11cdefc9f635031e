"""A subscriber whose QoS cannot match a publisher says so (rclpy logs "requesting incompatible
QoS"): our reliable subscriber beside an rclpy best-effort publisher receives nothing, counts the
publisher once, names the policy, and warns once, not on every spin."""
from __future__ import annotations

import json


def test_reliable_subscriber_reports_a_best_effort_rclpy_publisher_once(ros):
    ours = ros.scene('--seconds', '8', 'sub', 'String', '/camera_status', '--count', '1')
    ros.wait_ready(ours)
    peer = ros.peer('pub', '/camera_status', 'std_msgs/msg/String', json.dumps({'data': 'x'}), '--count', '-1',
                    '--rate', '50', '--qos', 'sensor_data', '--wait', '0')
    code, out, err = ros.finish(ours, timeout=30)
    ros.close()
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] == 0, result
    assert result['incompatible_qos'] == 1, result
    assert result['incompatible_policy'] == 'RELIABILITY', result
    # VTK shows a warning twice (its logger's line and the output window's text): count the latter.
    warnings = [line for line in err.splitlines() if 'incompatible QoS' in line and line.startswith('vtkROS2')]
    assert len(warnings) == 1, err
    assert '/camera_status' in warnings[0] and 'reliable' in warnings[0], warnings


def test_matching_qos_reports_nothing(ros):
    ours = ros.scene('--seconds', '10', 'sub', 'String', '/camera_status', '--count', '3', '--qos', 'sensor_data')
    ros.wait_ready(ours)
    peer = ros.peer('pub', '/camera_status', 'std_msgs/msg/String', json.dumps({'data': 'x'}), '--count', '-1',
                    '--rate', '50', '--qos', 'sensor_data', '--wait', '0')
    code, out, err = ros.finish(ours, timeout=30)
    ros.close()
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] >= 3 and result['incompatible_qos'] == 0, result
    assert 'incompatible QoS' not in err
