"""Our node's warnings on /rosout, as an rclpy node's: an rclpy subscriber to /rosout receives the
warning our subscriber node gives for malformed samples, with severity, logger name, file, line."""
from __future__ import annotations

import json
import time


def test_rclpy_rosout_subscriber_receives_our_warning_for_rejected_samples(ros):
    # Transient local, as rqt_console subscribes: /rosout is transient local (rcl's rosout QoS),
    # so a warning written before our writer has discovered this reader still reaches it (a
    # volatile echo lost it once under CI load against Jazzy). Ten bad samples, 20 ms apart: the
    # first may go before our reader has discovered the publisher.
    echo = ros.peer('echo', '/rosout', 'rcl_interfaces/msg/Log', '--count', '1', '--timeout', '30',
                    '--qos', 'transient_local')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '15', 'sub', 'String', '/bad/string')
    ros.wait_ready(ours)
    bad = ros.peer('pub_raw', '/bad/string', 'std_msgs/msg/String', '00010000ffffffff41', '--count', '10')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(bad)
    ros.stop(ours)
    assert code == 0, err
    log = json.loads(out.splitlines()[-1])
    assert log['level'] == 30, log  # WARN
    assert log['name'] == 'slicer', log  # rcl's logger name of node /slicer
    assert 'rejected' in log['msg'] and '/bad/string' in log['msg'], log
    assert log['file'].endswith('vtkROS2SubscriberNode.cxx') and log['line'] > 0, log
    assert log['function'] == 'vtkROS2SubscriberStringNode', log  # the reporting object's class
    assert abs(log['stamp']['sec'] - time.time()) < 120, log


def test_log_level_error_keeps_warnings_off_rosout(ros):
    echo = ros.peer('echo', '/rosout', 'rcl_interfaces/msg/Log', '--count', '1', '--timeout', '12')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '10', '--log-level', '40', 'sub', 'String', '/bad/string')
    ros.wait_ready(ours)
    bad = ros.peer('pub_raw', '/bad/string', 'std_msgs/msg/String', '00010000ffffffff41', '--count', '3')
    code, out, err = ros.finish(echo, timeout=30)
    ros.stop(bad)
    code_ours, out_ours, err_ours = ros.finish(ours)
    assert code == 3, f'a warning reached /rosout although the level is error: {out}'
    result = json.loads(out_ours.splitlines()[-1])
    assert result['rejected'] >= 3, result  # the samples were rejected (and warned on the console)
    assert 'rejected' in err_ours
