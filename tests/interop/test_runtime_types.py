"""Types nobody wrote a spec for (issue 13): our YAML subscriber, created with the name of a type
no library of ours registers, learns the type from the publishing rclpy node's
~/get_type_description (REP 2011) and shows the field values; a publisher that serves no type
descriptions gives a status that says so. Once learnt, our node serves the type's description
itself; `ros2vtk-topic echo` learns types the same way.

The type is service_msgs/msg/ServiceEventInfo: a Kilted wheel ships it, msg_specs/ does not
(checked below), and it has a nested type, a fixed array and 64-bit fields.
"""
from __future__ import annotations

import json
import subprocess
import textwrap
from pathlib import Path

from conftest import BUILD, HERE, REPO, VENV_PYTHON

ROS_TYPE = 'service_msgs/msg/ServiceEventInfo'
TOPIC = '/runtime_type'

PEER = textwrap.dedent('''
    import sys, time
    import rclpy
    from rclpy.parameter import Parameter
    from service_msgs.msg import ServiceEventInfo
    serve = sys.argv[1] == 'serve'
    rclpy.init()
    overrides = [] if serve else [Parameter('start_type_description_service', value=False)]
    node = rclpy.create_node(sys.argv[2], parameter_overrides=overrides)
    publisher = node.create_publisher(ServiceEventInfo, '/runtime_type', 10)
    msg = ServiceEventInfo(event_type=2, sequence_number=-9000000000123)
    msg.stamp.sec = 1234
    msg.stamp.nanosec = 56789
    msg.client_gid = list(range(200, 216))
    print('ready', flush=True)
    end = time.monotonic() + float(sys.argv[3])
    while time.monotonic() < end:
        publisher.publish(msg)
        rclpy.spin_once(node, timeout_sec=0.1)
    node.destroy_node()
    rclpy.shutdown()
''')

OURS = textwrap.dedent('''
    import json, sys, time
    import ros2vtk
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode(sys.argv[1], '/runtime_type')
    statuses = []
    end = time.monotonic() + float(sys.argv[2])
    while time.monotonic() < end and sub.GetNumberOfMessages() == 0:
        logic.SpinOnWakeUp(0.05)
        status = sub.GetTypeStatus()
        if not statuses or statuses[-1] != status:
            statuses.append(status)
    linger = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0
    if linger and sub.GetNumberOfMessages():
        print('learnt', flush=True)  # we now serve its description (~/get_type_description)
        end = time.monotonic() + linger
        while time.monotonic() < end:
            logic.SpinOnWakeUp(0.05)
    result = {'class': sub.GetClassName(), 'ros_type': sub.GetROSType(), 'statuses': statuses,
              'count': sub.GetNumberOfMessages(), 'yaml': sub.GetLastMessage()}
    if sub.GetNumberOfMessages():
        last = ros2vtk.Message.last_of(sub)
        result['fields'] = {'event_type': last.event_type, 'sec': last.stamp.sec,
                            'nanosec': last.stamp.nanosec, 'gid': list(last.client_gid),
                            'sequence_number': last.sequence_number,
                            'names': list(last.field_names())}
        # Constants of the learnt type: from the .msg source the publisher sent (type_sources).
        m = ros2vtk.vtkROS2Message()
        assert m.SetROSType(sys.argv[1]), m.GetLastError()
        result['constants'] = [[m.GetConstantName(i), m.GetConstant(m.GetConstantName(i))]
                               for i in range(m.GetNumberOfConstants())]
    print(json.dumps(result), flush=True)
''')


def start_peer(ros, mode: str, name: str, seconds: float):
    process = ros.start([str(VENV_PYTHON), '-c', PEER, mode, name, str(seconds)])
    line = process.stdout.readline()
    assert line.strip() == 'ready', line + process.stderr.read()
    return process


def start_ours(ros, seconds: float, linger: float = 0.0):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', '-c', OURS, ROS_TYPE, str(seconds), str(linger)], env)


def run_ours(ros, seconds: float) -> dict:
    process = start_ours(ros, seconds)
    code, out, err = ros.finish(process, timeout=seconds + 30)
    assert code == 0, err
    return json.loads(out.strip().splitlines()[-1])


def test_the_type_is_not_shipped():
    assert not (REPO / 'msg_specs' / 'service_msgs').exists()


def test_yaml_subscriber_learns_an_unshipped_type_from_the_rclpy_publisher(ros):
    peer = start_peer(ros, 'serve', 'event_talker', 25)
    result = run_ours(ros, 20)
    ros.stop(peer)
    assert result['class'] == 'vtkROS2SubscriberGenericNode'
    assert result['ros_type'] == ROS_TYPE
    assert result['count'] >= 1, result
    assert 'waiting for the type description of service_msgs/msg/ServiceEventInfo from /event_talker' \
        in result['statuses'], result['statuses']
    assert result['statuses'][-1] == '', result['statuses']
    gid = list(range(200, 216))
    assert result['yaml'] == ('event_type: 2\nstamp:\n  sec: 1234\n  nanosec: 56789\nclient_gid:\n'
                              + ''.join(f'- {b}\n' for b in gid) + 'sequence_number: -9000000000123\n')
    assert result['fields'] == {'event_type': 2, 'sec': 1234, 'nanosec': 56789, 'gid': gid,
                                'sequence_number': -9000000000123,
                                'names': ['event_type', 'stamp', 'client_gid', 'sequence_number']}
    # Its constants (REQUEST_SENT, ...: uint8) as rclpy's class holds them, by name, order, value.
    theirs = subprocess.run([str(VENV_PYTHON), str(HERE / 'message_peer.py'), 'constants', ROS_TYPE],
                            capture_output=True, text=True, timeout=60, env=ros.env)
    assert theirs.returncode == 0, theirs.stderr
    expected = json.loads(theirs.stdout.splitlines()[-1])['constants']
    assert expected, 'rclpy has no constants for the type: the check would prove nothing'
    assert result['constants'] == [[name, str(value)] for name, value in expected], result['constants']


def test_a_publisher_without_type_descriptions_gets_a_clear_status(ros):
    peer = start_peer(ros, 'quiet', 'quiet_talker', 20)
    result = run_ours(ros, 10)
    ros.stop(peer)
    assert result['count'] == 0
    assert result['statuses'][-1].startswith(
        'the publisher /quiet_talker does not serve type descriptions (no /quiet_talker/get_type_description'), \
        result['statuses']


def test_we_serve_the_learnt_type_as_the_rclpy_publisher_does(ros):
    """Our node now uses the learnt type, so its ~/get_type_description serves it (as rcl's
    node type cache does): rclpy gets from /slicer what /event_talker serves."""
    peer = start_peer(ros, 'serve', 'event_talker', 40)
    ours = start_ours(ros, 20, linger=25)
    line = ours.stdout.readline()
    assert line.strip() == 'learnt', line + ours.stderr.read()
    describe = ros.start([str(VENV_PYTHON), str(Path(__file__).parent / 'introspection_peer.py'), 'describe',
                          '/slicer', '/event_talker', '--types', ROS_TYPE])
    code, out, err = ros.finish(describe, timeout=90)
    assert code == 0, err
    answers = json.loads(out.strip().splitlines()[-1])
    ros.stop(ours)
    ros.stop(peer)
    theirs = answers['/event_talker']['types'][ROS_TYPE]
    mine = answers['/slicer']['types'][ROS_TYPE]
    assert theirs['successful'], theirs
    assert mine['successful'], mine
    assert mine['type_description'] == theirs['type_description']
    assert mine['rclpy_hash'] == mine['asked_hash']


def test_ros2vtk_topic_echo_learns_the_type_too(ros):
    peer = start_peer(ros, 'serve', 'event_talker', 25)
    code, out, err = ros.finish(ros.tool('echo', TOPIC, ROS_TYPE, '--count', '1', '--timeout', '20'), timeout=40)
    ros.stop(peer)
    assert code == 0, err
    gid = ''.join(f'- {b}\n' for b in range(200, 216))
    assert out == ('event_type: 2\nstamp:\n  sec: 1234\n  nanosec: 56789\nclient_gid:\n' + gid
                   + 'sequence_number: -9000000000123\n---\n')
    assert 'waiting for the type description of service_msgs/msg/ServiceEventInfo from /event_talker' in err


def test_ros2vtk_topic_echo_says_when_the_publisher_serves_no_description(ros):
    peer = start_peer(ros, 'quiet', 'quiet_talker', 20)
    code, out, err = ros.finish(ros.tool('echo', TOPIC, ROS_TYPE, '--count', '1', '--timeout', '8'), timeout=30)
    ros.stop(peer)
    assert code == 3 and out == ''
    assert 'timeout: the publisher /quiet_talker does not serve type descriptions' in err, err


# A publisher of ours with a type nobody registers learns it from the node it publishes to: the
# rclpy subscription's node serves the type's description too (rcl's node type cache holds the
# types of every endpoint), so the first message can go out before anyone of ours learnt it.
LISTENER = textwrap.dedent('''
    import json, sys, time
    import rclpy
    from rclpy.parameter import Parameter
    from service_msgs.msg import ServiceEventInfo
    serve = sys.argv[1] == 'serve'
    rclpy.init()
    overrides = [] if serve else [Parameter('start_type_description_service', value=False)]
    node = rclpy.create_node(sys.argv[2], parameter_overrides=overrides)
    received = []
    node.create_subscription(ServiceEventInfo, '/runtime_type_out', received.append, 10)
    print('ready', flush=True)
    end = time.monotonic() + float(sys.argv[3])
    while time.monotonic() < end and not received:
        rclpy.spin_once(node, timeout_sec=0.1)
    fields = [{'event_type': m.event_type, 'sec': m.stamp.sec, 'nanosec': m.stamp.nanosec,
               'gid': [int(b) for b in m.client_gid], 'sequence_number': m.sequence_number}
              for m in received]
    print(json.dumps(fields), flush=True)
    node.destroy_node()
    rclpy.shutdown()
''')

OUR_PUBLISHER = textwrap.dedent('''
    import json, sys, time
    import ros2vtk
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode(sys.argv[1], '/runtime_type_out')
    early = pub.PublishYAML('{event_type: 1}')  # the type is not learnt yet: refused, said why
    early_error = pub.GetLastPublishError()
    statuses = [pub.GetTypeStatus()]
    sent = 0
    end = time.monotonic() + float(sys.argv[2])
    while time.monotonic() < end and sent < 5:
        logic.SpinOnWakeUp(0.05)
        if statuses[-1] != pub.GetTypeStatus():
            statuses.append(pub.GetTypeStatus())
        if not pub.IsWaitingForType() and pub.GetNumberOfMatchedSubscriptions() > 0:
            yaml = '{event_type: 3, stamp: {sec: 77, nanosec: 88}, client_gid: [%s], sequence_number: -5}' % (
                ', '.join(str(b) for b in range(16)))
            sent += bool(pub.PublishYAML(yaml))
            time.sleep(0.2)
    print(json.dumps({'class': pub.GetClassName(), 'ros_type': pub.GetROSType(), 'early': bool(early),
                      'early_error': early_error, 'statuses': statuses, 'sent': sent}), flush=True)
''')


def run_our_publisher(ros, seconds: float) -> dict:
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    process = ros.start(['/usr/bin/python3', '-c', OUR_PUBLISHER, ROS_TYPE, str(seconds)], env)
    code, out, err = ros.finish(process, timeout=seconds + 30)
    assert code == 0, err
    return json.loads(out.strip().splitlines()[-1])


def test_yaml_publisher_learns_an_unshipped_type_from_the_rclpy_subscriber(ros):
    listener = ros.start([str(VENV_PYTHON), '-c', LISTENER, 'serve', 'event_listener', '30'])
    assert listener.stdout.readline().strip() == 'ready'
    result = run_our_publisher(ros, 20)
    code, out, err = ros.finish(listener, timeout=40)
    assert code == 0, err
    received = json.loads(out.strip().splitlines()[-1])
    assert result['class'] == 'vtkROS2PublisherGenericNode'
    assert result['ros_type'] == ROS_TYPE
    assert not result['early']
    assert result['early_error'].startswith('the message type is not known yet: waiting for a subscriber or '
                                            'publisher of service_msgs/msg/ServiceEventInfo'), result
    assert 'waiting for the type description of service_msgs/msg/ServiceEventInfo from /event_listener' \
        in result['statuses'], result['statuses']
    assert result['statuses'][-1] == '', result['statuses']
    assert result['sent'] >= 1, result
    assert received and received[0] == {'event_type': 3, 'sec': 77, 'nanosec': 88, 'gid': list(range(16)),
                                        'sequence_number': -5}, received


def test_a_subscriber_without_type_descriptions_gets_a_clear_status_on_our_publisher(ros):
    listener = ros.start([str(VENV_PYTHON), '-c', LISTENER, 'quiet', 'quiet_listener', '20'])
    assert listener.stdout.readline().strip() == 'ready'
    result = run_our_publisher(ros, 10)
    ros.stop(listener)
    assert result['sent'] == 0
    assert result['statuses'][-1].startswith(
        'the subscriber /quiet_listener does not serve type descriptions (no /quiet_listener/get_type_description'), \
        result['statuses']
