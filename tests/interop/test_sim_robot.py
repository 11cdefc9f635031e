"""The simulated robot (runtime/Tools/ros2vtk-sim-robot) seen by real rclpy nodes: its
parameters through rclpy's parameter client, its latched robot_description, its joint states."""
from __future__ import annotations

import json
import time
from pathlib import Path

from conftest import BUILD, REPO

URDF = REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'


def sim(ros, *args: str):
    return ros.start([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'), '--urdf', str(URDF),
                      '--rate', '50', *args])


def test_rclpy_parameter_client_lists_gets_and_sets_our_parameters(ros):
    robot = sim(ros)
    peer = ros.peer('params', '/robot_state_publisher', '--get', 'robot_description', 'publish_frequency',
                    '--set', 'publish_frequency=25.0', 'robot_description="<robot"')
    code, out, err = ros.finish(peer, timeout=60)
    robot.kill()
    assert code == 0, err
    result = json.loads(out)
    assert {'robot_description', 'publish_frequency', 'frame_prefix', 'ignore_timestamp',
            'use_sim_time'} <= set(result['list'])
    assert result['get']['robot_description'] == URDF.read_text()
    assert result['get']['publish_frequency'] == 50.0
    assert result['types'] == [4, 3]  # STRING, DOUBLE
    assert result['set'][0] == {'successful': True, 'reason': ''}
    assert result['set'][1]['successful'] is False and 'URDF' in result['set'][1]['reason']
    assert result['get_after']['publish_frequency'] == 25.0
    assert result['get_after']['robot_description'] == URDF.read_text()
    assert {'node': '/robot_state_publisher', 'changed': ['publish_frequency']} in result['events']


def test_parameters_in_a_namespace(ros):
    robot = sim(ros, '--namespace', '/PSM1')
    peer = ros.peer('params', '/PSM1/robot_state_publisher', '--get', 'frame_prefix')
    code, out, err = ros.finish(peer, timeout=60)
    robot.kill()
    assert code == 0, err
    assert json.loads(out)['get'] == {'frame_prefix': ''}


def test_latched_robot_description_and_joint_states_reach_rclpy(ros):
    robot = sim(ros, '--namespace', '/PSM2')
    time.sleep(1.5)  # subscribers join late: the description is transient local
    description = ros.peer('echo', '/PSM2/robot_description', 'std_msgs/msg/String', '--count', '1',
                           '--qos', 'transient_local', '--timeout', '15')
    states = ros.peer('echo', '/PSM2/joint_states', 'sensor_msgs/msg/JointState', '--count', '5',
                      '--timeout', '15')
    code, out, err = ros.finish(description)
    code_states, out_states, err_states = ros.finish(states)
    robot.kill()
    assert code == 0, err
    assert json.loads(out.splitlines()[-1])['data'] == URDF.read_text()
    assert code_states == 0, err_states
    messages = [json.loads(line) for line in out_states.splitlines()[1:]]
    assert len(messages) == 5
    assert messages[0]['name'] == ['base_to_column', 'shoulder_pitch', 'elbow_pitch', 'forearm_roll',
                                   'wrist_pitch', 'instrument_insertion']
    limits = [(-2.8, 2.8), (-1.6, 1.6), (-2.2, 2.2), (-3.0, 3.0), (-1.5, 1.5), (0.0, 0.08)]
    for message in messages:
        for position, (lower, upper) in zip(message['position'], limits):
            assert lower <= position <= upper
    assert messages[0]['position'] != messages[-1]['position'], 'the robot does not move'
