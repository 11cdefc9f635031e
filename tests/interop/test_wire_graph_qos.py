"""The ROS graph, QoS and domains, against real rclpy nodes."""
from __future__ import annotations

import json
import time

from samples import SAMPLES


def test_our_node_and_topics_appear_in_rclpy_graph(ros):
    ours = ros.tool('pub', '/graph/chatter', 'std_msgs/msg/String', json.dumps({'data': 'x'}),
                    '--count', '60', '--rate', '10', '--node', 'ros2vtk_graph_probe',
                    '--wait-matched', '0')
    graph = ros.peer('graph', '--wait', '15', '--expect-node', 'ros2vtk_graph_probe')
    code, out, err = ros.finish(graph)
    ros.stop(ours)
    assert code == 0, err
    result = json.loads(out)
    assert ['ros2vtk_graph_probe', '/'] in result['nodes']
    assert result['topics'].get('/graph/chatter') == ['std_msgs/msg/String']
    assert ['ros2vtk_graph_probe', '/', 'std_msgs/msg/String'] in result['publishers']['/graph/chatter']


def test_rclpy_node_appears_in_our_graph(ros):
    # The peer publishes until killed and our tools look again until they see it: importing
    # rclpy can take seconds on a loaded machine, so a fixed head start would make this flaky.
    peer = ros.peer('--node', 'rclpy_graph_peer', 'pub', '/graph/from_py', 'std_msgs/msg/Bool',
                    json.dumps({'data': True}), '--count', '-1', '--rate', '10', '--wait-matched', '0')
    deadline = time.monotonic() + 60.0
    while True:
        nodes = ros.tool('nodes', '--wait', '3')
        topics = ros.tool('list', '--wait', '3')
        _, nodes_out, _ = ros.finish(nodes)
        _, topics_out, _ = ros.finish(topics)
        seen = ('/rclpy_graph_peer' in nodes_out.split()
                and '/graph/from_py [std_msgs/msg/Bool]' in topics_out.splitlines())
        if seen or peer.poll() is not None or time.monotonic() > deadline:
            break
    peer.kill()
    ros.finish(peer)
    assert '/rclpy_graph_peer' in nodes_out.split(), nodes_out
    assert '/graph/from_py [std_msgs/msg/Bool]' in topics_out.splitlines(), topics_out


def test_other_domain_sees_nothing(ros):
    other = dict(ros.env, ROS_DOMAIN_ID=str(ros.domain + 50))
    echo = ros.peer('echo', '/isolated', 'std_msgs/msg/String', '--count', '1', '--timeout', '4',
                    env=other)
    ros.wait_ready(echo)
    ours = ros.tool('pub', '/isolated', 'std_msgs/msg/String', json.dumps({'data': 'secret'}),
                    '--count', '30', '--rate', '10', '--wait-matched', '0', '--node', 'isolated_node')
    graph = ros.peer('graph', '--wait', '3', env=other)
    code, out, _ = ros.finish(echo)
    _, graph_out, _ = ros.finish(graph)
    ros.stop(ours)
    assert code == 3 and out.strip() == '', 'a node on another ROS_DOMAIN_ID received our message'
    assert 'isolated_node' not in graph_out


def test_transient_local_reaches_late_joiner(ros):
    ours = ros.tool('pub', '/latched', 'std_msgs/msg/String', json.dumps({'data': 'robot description'}),
                    '--count', '1', '--qos', 'transient_local', '--wait-matched', '0',
                    '--timeout', '15')
    time.sleep(2.0)  # the message is published before the subscriber exists
    echo = ros.peer('echo', '/latched', 'std_msgs/msg/String', '--count', '1', '--timeout', '10',
                    '--qos', 'transient_local')
    code, out, err = ros.finish(echo)
    ros.stop(ours)
    assert code == 0, err
    assert json.loads(out.splitlines()[-1]) == {'data': 'robot description'}


def test_best_effort_sensor_publisher_reaches_sensor_subscriber(ros):
    echo = ros.tool('echo', '/sensor', 'std_msgs/msg/Float64', '--count', '2', '--timeout', '20',
                    '--qos', 'sensor_data')
    peer = ros.peer('pub', '/sensor', 'std_msgs/msg/Float64', json.dumps({'data': 2.5}),
                    '--count', '60', '--rate', '20', '--qos', 'sensor_data')
    code, out, err = ros.finish(echo)
    ros.stop(peer)
    assert code == 0, err
    assert out.count('data: 2.5') == 2


def test_thousand_messages_at_1khz_none_lost(ros):
    # Reliable + keep-all on both sides: a keep-last(10) reader may legitimately drop samples
    # when the machine is busy; "none lost" is the reliable keep-all contract.
    echo = ros.tool('echo', '/fast', 'std_msgs/msg/Int64', '--count', '1000', '--timeout', '40',
                    '--qos', 'keep_all')
    time.sleep(0.5)
    peer = ros.peer('pub', '/fast', 'std_msgs/msg/Int64', json.dumps({'data': 0}),
                    '--count', '1000', '--rate', '1000', '--qos', 'keep_all',
                    '--sequence-field', 'data', '--linger', '3')
    code, out, err = ros.finish(echo, timeout=60)
    ros.stop(peer)
    assert code == 0, err
    values = [int(line.split(':')[1]) for line in out.splitlines() if line.startswith('data:')]
    assert values == list(range(1000))


def localhost_only_env(ros) -> dict:
    """ROS 2 Humble's switch: ROS_LOCALHOST_ONLY=1, with no ROS_AUTOMATIC_DISCOVERY_RANGE set."""
    env = dict(ros.env, ROS_LOCALHOST_ONLY='1')
    env.pop('ROS_AUTOMATIC_DISCOVERY_RANGE', None)
    return env


def test_ros_localhost_only_talks_to_a_localhost_rclpy_peer_both_ways(ros):
    env = localhost_only_env(ros)
    echo = ros.peer('echo', '/lo_only/out', 'std_msgs/msg/String', '--count', '1', '--timeout', '20')
    ros.wait_ready(echo)
    ours_pub = ros.tool('pub', '/lo_only/out', 'std_msgs/msg/String', json.dumps({'data': 'from ros2vtk'}),
                        '--count', '100', '--rate', '10', '--wait-matched', '0', env=env)
    ours_echo = ros.tool('echo', '/lo_only/in', 'std_msgs/msg/Float64', '--count', '1', '--timeout', '20',
                         env=env)
    peer = ros.peer('pub', '/lo_only/in', 'std_msgs/msg/Float64', json.dumps({'data': -1.5}),
                    '--count', '100', '--rate', '10', '--wait-matched', '0')
    code, out, err = ros.finish(echo)
    assert code == 0, f'rclpy never received from a ROS_LOCALHOST_ONLY=1 ros2vtk: {err}'
    assert json.loads(out.splitlines()[-1]) == {'data': 'from ros2vtk'}
    code, out, err = ros.finish(ours_echo)
    assert code == 0, f'a ROS_LOCALHOST_ONLY=1 ros2vtk never received from rclpy: {err}'
    assert 'data: -1.5' in out
    for process in (ours_pub, peer):
        process.kill()
