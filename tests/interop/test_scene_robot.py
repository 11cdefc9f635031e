"""Robots in our scene, driven by a real rclpy node playing robot_state_publisher (rsp_peer.py):
the robot node builds the robot from the description (parameter or topic), and every link's world
transform follows tf through several joint configurations, equal to yourdfpy's independent
forward kinematics to 1e-6 m."""
from __future__ import annotations

import json
import math
import os
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest

from conftest import BUILD, HERE, REPO, VENV_PYTHON, tf2_msgs_env

ARM = REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'
ARM_PACKAGE = REPO / 'examples' / 'robots' / 'surgical_arm'
ROBOT_DATA = VENV_PYTHON.parents[1] / 'lib' / 'python3.11' / 'site-packages' / 'cmeel.prefix'
UR5 = ROBOT_DATA / 'share' / 'example-robot-data' / 'robots' / 'ur_description' / 'urdf' / 'ur5_robot.urdf'
TOLERANCE_MM = 1e-3  # 1e-6 m


def start_rsp(ros, urdf: Path, *args: str):
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
    return ros.start([str(VENV_PYTHON), str(HERE / 'rsp_peer.py'), str(urdf), *args], env)


def start_scene_robot(ros, *args: str, prefix: Path | None = None):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    if prefix is not None:
        env['AMENT_PREFIX_PATH'] = str(prefix)
    return ros.start(['/usr/bin/python3', str(HERE / 'scene_runner.py'), *args], env)


def visual_count(urdf: Path) -> tuple[int, dict]:
    """Visuals per link, read from the URDF independently of our loader."""
    root = ElementTree.parse(urdf).getroot()
    per_link = {link.get('name'): len(link.findall('visual')) for link in root.findall('link')}
    return sum(per_link.values()), per_link


def matches(snapshot: dict, expected: dict, prefix_len: int = 0) -> float:
    """Largest difference (mm, or unitless for rotation) between a snapshot of our link world
    matrices (mm) and yourdfpy's (m), over every link."""
    worst = 0.0
    for link, rows in expected.items():
        ours = snapshot[link]
        for i in range(3):
            for j in range(3):
                worst = max(worst, abs(ours[i][j] - rows[i][j]))
            worst = max(worst, abs(ours[i][3] - 1000.0 * rows[i][3]))
    return worst


def run_robot(ros, urdf: Path, source: str, *, configs: int = 3, namespace: str = '', prefix: str = '',
              mesh_paths: list[Path] = (), ament_prefix: Path | None = None, rsp_host=None):
    """rsp_host: where robot_state_publisher runs (another host of tests/network), else beside us."""
    hold = 2.5
    rsp = start_rsp(rsp_host or ros, urdf, '--configs', str(configs), '--hold', str(hold), '--namespace', namespace,
                    '--frame-prefix', prefix)
    rsp_node = f'{namespace}/robot_state_publisher' if namespace else '/robot_state_publisher'
    # --follow counts from the load. A parameter or topic source loads when robot_state_publisher
    # is up; a file loads on our first spin, while that rclpy process may still be starting (on a
    # loaded machine the last configuration came after an 8.5 s window), so it follows longer.
    follow = configs * hold + 1.0 + (6.0 if source == 'file' else 0.0)
    args = ['--seconds', '30', 'robot', 'arm', '--source', source, '--rsp-node', rsp_node,
            '--topic', f'{namespace}/robot_description', '--tf-prefix', prefix,
            '--follow', str(follow), '--urdf', str(urdf)]  # after the load
    for folder in mesh_paths:
        args += ['--mesh-path', str(folder)]
    args += ['--mesh-base-folder', str(urdf.parent)]
    ours = start_scene_robot(ros, *args, prefix=ament_prefix)
    code, out, err = ros.finish(ours, timeout=configs * hold + 60)
    rsp_code, rsp_out, rsp_err = ros.finish(rsp, timeout=30)
    assert code == 0, err
    assert rsp_code == 0, rsp_err
    lines = [json.loads(line) for line in out.splitlines()]
    peer = [json.loads(line) for line in rsp_out.splitlines()]
    ready = peer[0]
    assert ready.get('ready'), rsp_out
    expected = [line for line in peer if 'config' in line]
    assert len(expected) == configs
    return ready, lines[1], lines[2:], expected


@pytest.mark.parametrize('source', ['parameter', 'topic', 'file'])
def test_arm_appears_and_follows_every_configuration(ros, source):
    ready, state, snapshots, expected = run_robot(ros, ARM, source, mesh_paths=[ARM_PACKAGE])
    assert state['state'] == 'loaded', state
    assert state['loaded_events'] == 1
    assert sorted(state['links']) == sorted(ready['links'])
    total, per_link = visual_count(ARM)
    assert state['models'] == total
    assert state['placeholders'] == 0, state['warnings']
    assert {link: state['model_links'].count(link) for link in per_link} == per_link
    assert snapshots, 'no snapshot after the robot loaded'
    for config in expected:
        best = min(matches(snapshot['links'], config['links']) for snapshot in snapshots)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched (best {best})"
    # It moves: the configurations differ, and so do our snapshots.
    first, last = snapshots[0]['links'], snapshots[-1]['links']
    assert any(abs(first[l][i][3] - last[l][i][3]) > 1.0 for l in first for i in range(3))


def test_namespaced_robot_with_tf_prefix(ros):
    ready, state, snapshots, expected = run_robot(ros, ARM, 'topic', configs=2, namespace='/PSM1',
                                                  prefix='PSM1/', mesh_paths=[ARM_PACKAGE])
    assert state['state'] == 'loaded', state
    for config in expected:
        best = min(matches(snapshot['links'], config['links']) for snapshot in snapshots)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched (best {best})"


def test_robot_without_a_fixed_frame_is_placed_in_the_scenes_fixed_frame(ros):
    """As RViz's global Fixed Frame places a RobotModel: our robot has no fixed frame of its own,
    the scene's is 'world', and an rclpy static broadcaster puts the root link in world (0.5,
    -0.25, 0.1) m turned a quarter about z. Every link's world matrix is then that transform times
    yourdfpy's pose of the link in the root link's frame (rsp_peer.py), through each
    configuration."""
    hold = 2.5
    world_to_root = {'t': [0.5, -0.25, 0.1], 'q': [0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)]}
    rsp = start_rsp(ros, ARM, '--configs', '2', '--hold', str(hold))
    ready = json.loads(rsp.stdout.readline())
    assert ready.get('ready'), ready
    static = ros.tf_peer('tf_pub', 'world', ready['root'], json.dumps(world_to_root), '--static',
                         '--seconds', '40')
    ours = start_scene_robot(ros, '--seconds', '30', 'robot', 'arm', '--source', 'topic', '--follow',
                             str(2 * hold + 1.0), '--mesh-path', str(ARM_PACKAGE), '--mesh-base-folder',
                             str(ARM.parent), '--scene-fixed-frame', 'world')
    code, out, err = ros.finish(ours, timeout=2 * hold + 60)
    rsp_code, rsp_out, rsp_err = ros.finish(rsp, timeout=30)
    ros.stop(static)
    assert code == 0, err
    assert rsp_code == 0, rsp_err
    lines = [json.loads(line) for line in out.splitlines()]
    state, snapshots = lines[1], lines[2:]
    assert state['state'] == 'loaded', state
    # A quarter turn about z: x -> y, y -> -x.
    rotation = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    offset = world_to_root['t']
    expected = []
    for line in rsp_out.splitlines():
        config = json.loads(line)
        if 'config' not in config:
            continue
        placed = {}
        for link, rows in config['links'].items():
            placed[link] = [[sum(rotation[i][k] * rows[k][j] for k in range(3)) for j in range(3)]
                            + [sum(rotation[i][k] * rows[k][3] for k in range(3)) + offset[i]] for i in range(3)]
        expected.append(placed)
    assert len(expected) == 2
    for index, config in enumerate(expected):
        best = min(matches(snapshot['links'], config) for snapshot in snapshots)
        assert best < TOLERANCE_MM, f'configuration {index} never matched in world (best {best})'


def test_example_robot_data_ur5_with_collada_meshes(ros):
    # example-robot-data is pinned in scripts/requirements-ros.txt: its absence is a failure, not a skip.
    assert UR5.exists(), f'example-robot-data missing from the venv ({UR5}): run scripts/setup.sh'
    ready, state, snapshots, expected = run_robot(ros, UR5, 'parameter', configs=2, ament_prefix=ROBOT_DATA)
    assert state['state'] == 'loaded', state
    assert state['placeholders'] == 0, state['warnings']
    total, _ = visual_count(UR5)
    assert state['models'] == total
    for config in expected:
        best = min(matches(snapshot['links'], config['links']) for snapshot in snapshots)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched (best {best})"


def test_two_robots_at_once_each_in_its_namespace_follow_their_own_motion(ros):
    hold = 2.5
    # The first configuration is held longer: each peer's clock starts when our node listens to
    # /tf, which the first robot to load already makes true for the other.
    first = start_rsp(ros, ARM, '--configs', '2', '--hold', str(hold), '--first-hold', '6', '--namespace', '/PSM1',
                      '--frame-prefix', 'PSM1/', '--seed', '7')
    second = start_rsp(ros, ARM, '--configs', '2', '--hold', str(hold), '--first-hold', '6', '--namespace', '/PSM2',
                       '--frame-prefix', 'PSM2/', '--seed', '11')
    ours = start_scene_robot(ros, '--seconds', '30', 'robot', 'psm1', '--source', 'topic',
                             '--topic', '/PSM1/robot_description', '--tf-prefix', 'PSM1/',
                             '--also', 'psm2=/PSM2/robot_description=PSM2/', '--mesh-path', str(ARM_PACKAGE),
                             '--mesh-base-folder', str(ARM.parent), '--follow', str(6 + hold + 1.0))
    code, out, err = ros.finish(ours, timeout=6 + hold + 60)
    results = [ros.finish(peer, timeout=30) for peer in (first, second)]
    assert code == 0, err
    lines = [json.loads(line) for line in out.splitlines()]
    state, snapshots = lines[1], lines[2:]
    assert state['state'] == 'loaded' and state['others'] == {'psm2': 'loaded'}, state
    for (peer_code, peer_out, peer_err), pick in zip(results, (lambda s: s['links'],
                                                                 lambda s: s['others']['psm2'])):
        assert peer_code == 0, peer_err
        expected = [json.loads(line) for line in peer_out.splitlines() if '"config"' in line]
        assert len(expected) == 2
        for config in expected:
            trace = [round(matches(pick(snapshot), config['links']), 3) for snapshot in snapshots]
            assert min(trace) < TOLERANCE_MM, f"configuration {config['config']} never matched: {trace}"


def shifted(config_links: dict, y_mm: float) -> dict:
    """yourdfpy's link poses (m) with the robot's base moved by y_mm along y."""
    return {link: [row[:3] + [row[3] + (y_mm / 1000.0 if i == 1 else 0.0)] for i, row in enumerate(rows)]
            for link, rows in config_links.items()}


@pytest.mark.parametrize('source', ['parameter', 'topic'])
def test_robot_state_publisher_restarted_with_another_urdf_reloads_the_robot(ros, source):
    assert UR5.exists(), f'example-robot-data missing from the venv ({UR5}): run scripts/setup.sh'
    base_y = 300.0  # the user's placement of the robot survives the reload
    ours = start_scene_robot(ros, '--seconds', '40', 'robot', 'arm', '--source', source, '--loads', '2',
                             '--follow', '9', '--base-y', str(base_y), '--mesh-path', str(ARM_PACKAGE),
                             '--mesh-base-folder', str(ARM.parent), prefix=ROBOT_DATA)
    first = start_rsp(ros, ARM, '--configs', '1', '--hold', '3')
    first_code, first_out, first_err = ros.finish(first, timeout=40)
    assert first_code == 0, first_err
    # robot_state_publisher comes back, same node name and topic, with another robot.
    second = start_rsp(ros, UR5, '--configs', '2', '--hold', '2.5', '--first-hold', '5')
    code, out, err = ros.finish(ours, timeout=90)
    second_code, second_out, second_err = ros.finish(second, timeout=30)
    assert code == 0, err
    assert second_code == 0, second_err
    lines = [json.loads(line) for line in out.splitlines()]
    snapshots = [line for line in lines if 'loads' in line]
    arm = [json.loads(line) for line in first_out.splitlines() if '"config"' in line]
    ur5 = [json.loads(line) for line in second_out.splitlines() if '"config"' in line]
    ur5_links = json.loads(second_out.splitlines()[0])['links']
    before = [s for s in snapshots if s['loads'] == 1]
    after = [s for s in snapshots if s['loads'] == 2]
    assert before and after, [s['loads'] for s in snapshots]
    assert sorted(after[-1]['links']) == sorted(ur5_links)
    total, _ = visual_count(UR5)
    assert after[-1]['models'] == total and after[-1]['placeholders'] == 0
    best = min(matches(s['links'], shifted(arm[0]['links'], base_y)) for s in before)
    assert best < TOLERANCE_MM, f'the first robot never matched (best {best})'
    for config in ur5:
        best = min(matches(s['links'], shifted(config['links'], base_y)) for s in after)
        assert best < TOLERANCE_MM, f"UR5 configuration {config['config']} never matched (best {best})"


def test_a_saved_scene_reopened_brings_the_robot_back_from_its_robot_state_publisher(ros):
    base_y = -200.0
    rsp = start_rsp(ros, ARM, '--configs', '3', '--hold', '3', '--first-hold', '5')
    ours = start_scene_robot(ros, '--seconds', '30', 'robot', 'arm', '--source', 'parameter', '--follow', '11',
                             '--restore-after', '1.0', '--base-y', str(base_y), '--mesh-path', str(ARM_PACKAGE),
                             '--mesh-base-folder', str(ARM.parent))
    code, out, err = ros.finish(ours, timeout=60)
    rsp_code, rsp_out, rsp_err = ros.finish(rsp, timeout=30)
    assert code == 0, err
    assert rsp_code == 0, rsp_err
    lines = [json.loads(line) for line in out.splitlines()]
    restored = [line for line in lines if 'restored' in line and 'links' not in line]
    assert len(restored) == 1 and restored[0]['models_in_file'] == 0, restored
    after = [line for line in lines if line.get('restored') is True and 'links' in line]
    loaded = [s for s in after if s['state'] == 'loaded']
    assert loaded, [s['state'] for s in after]
    total, _ = visual_count(ARM)
    assert loaded[-1]['models'] == total and loaded[-1]['loads'] == 1
    expected = [json.loads(line) for line in rsp_out.splitlines() if '"config"' in line]
    for config in expected[1:]:  # the configurations held after the scene was reopened
        best = min(matches(s['links'], shifted(config['links'], base_y)) for s in loaded)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched after restore (best {best})"


def test_relative_meshes_of_a_topic_description_load_through_the_mesh_search_path(ros, tmp_path):
    # Issue 15: a robot_description from an rclpy peer with relative meshes (meshes/x.stl,
    # ../meshes/x.STL) has no folder of its own. With the meshes' folder added as a mesh search
    # path every mesh loads; without it the warning says what to call.
    stl = (ARM_PACKAGE / 'meshes' / 'base.stl').read_bytes()
    (tmp_path / 'robot_files' / 'meshes').mkdir(parents=True)
    (tmp_path / 'robot_files' / 'meshes' / 'a.stl').write_bytes(stl)
    (tmp_path / 'robot_files' / 'meshes' / 'b.STL').write_bytes(stl)
    urdf = """<robot name="relative">
  <link name="base"><visual><geometry><mesh filename="meshes/a.stl"/></geometry></visual></link>
  <link name="tip"><visual><geometry><mesh filename="../meshes/b.STL"/></geometry></visual></link>
  <joint name="j" type="fixed"><parent link="base"/><child link="tip"/></joint>
</robot>"""
    results = {}
    for label, extra in (('with', ['--mesh-path', str(tmp_path / 'robot_files')]), ('without', [])):
        peer = ros.peer('pub', '/robot_description', 'std_msgs/msg/String', json.dumps({'data': urdf}),
                        '--qos', 'latched', '--count', '1', '--linger', '15')
        ours = ros.scene('--seconds', '12', 'robot', 'relative', '--source', 'topic', *extra, '--follow', '0.5')
        code, out, err = ros.finish(ours, timeout=40)
        ros.stop(peer)
        assert code == 0, err
        results[label] = json.loads(out.splitlines()[1])
    loaded = results['with']
    assert loaded['state'] == 'loaded' and loaded['models'] == 2 and loaded['placeholders'] == 0, loaded
    missing = results['without']
    assert missing['state'] == 'loaded' and missing['placeholders'] == 2, missing
    assert "could not load mesh 'meshes/a.stl': no such file" in missing['warnings'], missing['warnings']
    assert 'SetMeshBaseFolder' in missing['warnings'] and 'AddMeshSearchPath' in missing['warnings'], missing['warnings']
