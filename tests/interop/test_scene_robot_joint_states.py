"""A robot loaded from a file with no robot_state_publisher (issue 15): with no tf it shows its
zero configuration; driven only by a real rclpy node publishing /joint_states, its links follow
yourdfpy's independent forward kinematics to 1e-6 m (mimic joint, continuous joint, limit clamps,
partial messages, an unknown name); with SetPublishTf(True) an rclpy tf listener sees the links
where yourdfpy puts them."""
from __future__ import annotations

import json
import os
from pathlib import Path

from conftest import HERE, VENV_PYTHON, tf2_msgs_env
from test_scene_robot import TOLERANCE_MM, matches, start_scene_robot

# Every joint kind robot_state_publisher handles: prismatic insertion whose range [0.02, 0.08]
# excludes 0 (the zero configuration clamps it), a continuous roll, a revolute jaw, its mirrored
# mimic and a fixed tip.
URDF = """<robot name="jaws">
  <link name="base"/><link name="shaft"/><link name="wrist"/><link name="jaw_a"/><link name="jaw_b"/><link name="tip"/>
  <joint name="insert" type="prismatic"><parent link="base"/><child link="shaft"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="0.02" upper="0.08" effort="1" velocity="1"/></joint>
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

CONFIGS = [
    {'insert': 0.05, 'roll': 2.5, 'jaw': 0.4, 'not_a_joint': 1.0},  # an unknown name is ignored
    {'insert': 0.5, 'roll': -4.0, 'jaw': 1.5},                     # insert and jaw clamped
    {'jaw': -0.1},                                                 # a partial message
]
LINKS = ['base', 'shaft', 'wrist', 'jaw_a', 'jaw_b', 'tip']
# A namespace and a frame prefix of their own: the sim robot's tests use the same joint names.
NAMESPACE = '/jsfk'
TOPIC = f'{NAMESPACE}/joint_states'
PREFIX = 'jsfk/'


def zero_configuration(urdf: Path) -> dict:
    """yourdfpy's link poses (m) at zero clamped into the limits: insert at its lower 0.02."""
    from yourdfpy import URDF as YourdfpyUrdf
    robot = YourdfpyUrdf.load(str(urdf), load_meshes=False, build_collision_scene_graph=False,
                              load_collision_meshes=False)
    robot.update_cfg({'insert': 0.02, 'roll': 0.0, 'jaw': 0.0})
    return {link: robot.get_transform(link).tolist() for link in robot.link_map}


def scene_robot(ros, urdf: Path, follow: float, *args: str):
    return start_scene_robot(ros, '--seconds', '30', 'robot', 'jaws', '--source', 'file', '--urdf', str(urdf),
                             '--follow', str(follow), '--every', '0.1', *args)


def tf_peer_env(ros) -> dict:
    """The environment of an rclpy peer that imports tf2_msgs (built for the tests)."""
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
    return env


def test_file_robot_without_tf_shows_its_zero_configuration(ros, tmp_path):
    urdf = tmp_path / 'jaws.urdf'
    urdf.write_text(URDF)
    ours = scene_robot(ros, urdf, 1.0)
    code, out, err = ros.finish(ours, timeout=60)
    assert code == 0, err
    lines = [json.loads(line) for line in out.splitlines()]
    state, snapshots = lines[1], lines[2:]
    assert state['state'] == 'loaded', state
    assert sorted(state['links']) == sorted(LINKS)
    assert snapshots
    expected = zero_configuration(urdf)
    last = snapshots[-1]
    assert last['tracked'] == 1  # the root link (the fixed frame) only: nothing came from tf
    assert last['pose_status'] == {'base': 'fixed frame', **{l: 'zero configuration (no tf)' for l in LINKS[1:]}}
    assert matches(last['links'], expected) < TOLERANCE_MM
    # Not piled at the origin: the tip is well above the base.
    assert last['links']['tip'][2][3] > 300.0


def test_joint_states_only_drive_the_robot_like_independent_forward_kinematics(ros, tmp_path):
    urdf = tmp_path / 'jaws.urdf'
    urdf.write_text(URDF)
    hold = 2.0
    # The peer waits for our subscriber; we follow until its joint states stop (3 s without one;
    # it publishes at 20 Hz), --follow (from the load) being only an upper bound.
    ours = scene_robot(ros, urdf, 60.0, '--joint-states', TOPIC, '--joint-states-quiet', '3')
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'joint_states_peer.py'), str(urdf), json.dumps(CONFIGS),
                      '--hold', str(hold), '--topic', TOPIC], dict(ros.env))
    code, out, err = ros.finish(ours, timeout=120)
    peer_code, peer_out, peer_err = ros.finish(peer, timeout=60)
    assert code == 0, err
    assert peer_code == 0, peer_err + peer_out
    lines = [json.loads(line) for line in out.splitlines()]
    state, snapshots = lines[1], lines[2:]
    assert state['state'] == 'loaded', state
    peer_lines = [json.loads(line) for line in peer_out.splitlines()]
    assert peer_lines[0].get('ready'), peer_out
    expected = [line for line in peer_lines if 'config' in line]
    assert len(expected) == len(CONFIGS)
    assert expected[1]['state']['insert'] == 0.08 and expected[1]['state']['jaw'] == 0.9  # the clamps
    driven = [s for s in snapshots if s['joint_states'] > 0]
    assert driven, 'no joint state was applied'
    for snapshot in driven:
        assert snapshot['tracked'] == 1, snapshot['pose_status']
        assert snapshot['pose_status']['jaw_b'] == 'joint positions (no tf)'
    for config in expected:
        best = min(matches(snapshot['links'], config['links']) for snapshot in driven)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched (best {best} mm)"
    # Before the first joint state: the zero configuration.
    before = [s for s in snapshots if s['joint_states'] == 0]
    if before:  # the peer may start publishing before our first snapshot
        assert matches(before[0]['links'], zero_configuration(urdf)) < TOLERANCE_MM


def test_publish_tf_lets_an_rclpy_listener_see_the_links(ros, tmp_path):
    urdf = tmp_path / 'jaws.urdf'
    urdf.write_text(URDF)
    hold = 1.5
    within_limits = [{'insert': 0.05, 'roll': 2.5, 'jaw': 0.4}, {'insert': 0.03, 'roll': -1.0, 'jaw': -0.1}]
    # Few snapshots (--every 5): the peers are read first, and our output must fit the pipe's
    # buffer meanwhile or our process blocks on print and stops spinning.
    ours = scene_robot(ros, urdf, 60.0, '--joint-states', TOPIC, '--publish-tf', '--every', '5',
                       '--joint-states-quiet', '3', '--tf-prefix', PREFIX)
    checker = ros.start([str(VENV_PYTHON), str(HERE / 'tf_fk_peer.py'), str(urdf), '--namespace', NAMESPACE,
                         '--frame-prefix', PREFIX, '--seconds', str(len(within_limits) * hold + 14.0)],
                        tf_peer_env(ros))
    # The peer waits for both joint-state subscribers (ours, the checker's), then a little more,
    # so the checker's /tf subscription matches our broadcaster too.
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'joint_states_peer.py'), str(urdf), json.dumps(within_limits),
                      '--hold', str(hold), '--subscribers', '2', '--settle', '3', '--topic', TOPIC], dict(ros.env))
    peer_code, peer_out, peer_err = ros.finish(peer, timeout=60)
    check_code, check_out, check_err = ros.finish(checker, timeout=60)
    code, out, err = ros.finish(ours, timeout=90)
    assert code == 0, err
    assert peer_code == 0, peer_err + peer_out
    assert check_code == 0, check_err
    result = json.loads(check_out.splitlines()[-1])
    assert [c for c in result['static_children'] if c.startswith(PREFIX)] == [PREFIX + 'tip']
    assert [c for c in result['dynamic_children'] if c.startswith(PREFIX)] == [
        PREFIX + link for link in ('jaw_a', 'jaw_b', 'shaft', 'wrist')]
    assert result['compared'] >= 5, result
    assert result['worst'] < 1e-6, result
