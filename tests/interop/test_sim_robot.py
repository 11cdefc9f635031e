"""The simulated robot (runtime/Tools/ros2vtk-sim-robot) seen by real rclpy nodes: its
parameters through rclpy's parameter client, its latched robot_description, its joint states."""
from __future__ import annotations

import json
import os
import time
from pathlib import Path

from conftest import BUILD, HERE, REPO, VENV_PYTHON, tf2_msgs_env

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


# A small instrument with a mimic joint (the second jaw follows the first, mirrored), a fixed
# tip and a prismatic insertion: every joint kind robot_state_publisher handles.
MIMIC_URDF = """<robot name="jaws">
  <link name="base"/><link name="shaft"/><link name="wrist"/><link name="jaw_a"/><link name="jaw_b"/><link name="tip"/>
  <joint name="insert" type="prismatic"><parent link="base"/><child link="shaft"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="0" upper="0.08" effort="1" velocity="1"/></joint>
  <joint name="roll" type="continuous"><parent link="shaft"/><child link="wrist"/><origin xyz="0 0 0.2" rpy="0 0.3 0"/>
    <axis xyz="0 0 1"/></joint>
  <joint name="jaw" type="revolute"><parent link="wrist"/><child link="jaw_a"/><origin xyz="0.01 0 0.02"/>
    <axis xyz="0 1 0"/><limit lower="-0.2" upper="0.9" effort="1" velocity="1"/></joint>
  <joint name="jaw_mirror" type="revolute"><parent link="wrist"/><child link="jaw_b"/><origin xyz="-0.01 0 0.02"/>
    <axis xyz="0 1 0"/><limit lower="-0.9" upper="0.2" effort="1" velocity="1"/>
    <mimic joint="jaw" multiplier="-1.0" offset="0.05"/></joint>
  <joint name="tip_fixed" type="fixed"><parent link="jaw_a"/><child link="tip"/><origin xyz="0 0 0.015" rpy="0.1 0 0"/></joint>
</robot>
"""


def test_sim_robot_tf_equals_independent_forward_kinematics_with_mimic_joints(ros, tmp_path):
    urdf = tmp_path / 'jaws.urdf'
    urdf.write_text(MIMIC_URDF)
    robot = ros.start([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'), '--urdf', str(urdf), '--rate', '50',
                       '--namespace', '/tool', '--frame-prefix', 'tool/'])
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'tf_fk_peer.py'), str(urdf), '--namespace', '/tool',
                      '--frame-prefix', 'tool/', '--seconds', '4'], env)
    code, out, err = ros.finish(peer, timeout=60)
    robot.kill()
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['joint_names'] == ['insert', 'roll', 'jaw']  # the mimic joint is not a joint state
    assert result['static_children'] == ['tool/tip']
    assert result['dynamic_children'] == ['tool/jaw_a', 'tool/jaw_b', 'tool/shaft', 'tool/wrist']
    assert result['compared'] >= 50, result  # about 4 s at 50 Hz, allowing for discovery
    assert result['worst'] < 1e-6, result
