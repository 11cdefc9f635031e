"""Simulated time against rclpy: an rclpy simulator publishes /clock from an epoch of 1000 s (far
from any wall-clock time), our node /slicer gets use_sim_time (from rclpy's SetParameters call, or
from our Python API), and everything it stamps after that, as rclpy receives it, lies in the
simulated time published: tf broadcasts and PoseStamped headers. Our lookup of a transform the
simulator stamps in simulated time succeeds with that stamp."""
from __future__ import annotations

import json
import os

import pytest

from conftest import BUILD, HERE, VENV_PYTHON, tf2_msgs_env

EPOCH = 1000.0


def start_peer(ros, *args: str):
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
    return ros.start([str(VENV_PYTHON), str(HERE / 'sim_time_peer.py'), *args], env)


def start_ours(ros, *args: str):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', str(HERE / 'sim_time_runner.py'), *args], env)


@pytest.mark.parametrize('switch', ['rclpy_set_parameters', 'python_api'])
def test_our_stamps_follow_rclpy_clock_and_never_carry_wall_time(ros, switch):
    ours = start_ours(ros, '--seconds', '40', '--count', '80', *(['--use-sim-time'] if switch == 'python_api' else []))
    ros.wait_ready(ours)
    peer = start_peer(ros, '/slicer', '--epoch', str(EPOCH), '--seconds', '20', '--count', '20')
    code, out, err = ros.finish(peer, timeout=60)
    _, ours_out, ours_err = ros.finish(ours, timeout=60)
    assert code == 0, err
    seen = json.loads(out.splitlines()[-1])
    assert seen['set'] == [{'successful': True, 'reason': ''}], seen['set']
    assert seen['use_sim_time'] is True
    first, last = seen['clock_first'], seen['clock_last']
    assert EPOCH <= first < last < EPOCH + 120, (first, last)

    def simulated(seconds: float) -> bool:
        # 1 µs of slack: our seconds are nanoseconds * 1e-9, rclpy's sec + nanosec * 1e-9.
        return first - 1e-6 <= seconds <= last + 1e-6
    for name in ('tf_stamps', 'pose_stamps'):
        stamps = seen[name]
        assert len(stamps) >= 20, f'{name}: only {len(stamps)} received; ours said {ours_out} {ours_err[-2000:]}'
        # Every stamp is a simulated time: none is 0 (sent before the first /clock) and none is a
        # wall-clock time (about 1.7e9 s), which the range excludes.
        outside = [s for s in stamps if not simulated(s)]
        assert not outside, f'{name}: stamps outside the simulated time [{first}, {last}]: {outside[:5]}'
        assert stamps == sorted(stamps), f'{name} went backwards: {stamps}'
    if switch == 'rclpy_set_parameters':
        # The change event is stamped with our node's clock, already simulated when it is sent
        # (0 if no /clock had arrived yet, as rclpy's would be): never a wall-clock time.
        changes = [e for e in seen['events'] if 'use_sim_time' in e['changed']]
        assert len(changes) == 1, seen['events']
        assert changes[0]['stamp'] == 0.0 or simulated(changes[0]['stamp']), changes
    result = json.loads(ours_out.splitlines()[-1])
    assert result['use_sim_time'] is True and result['sim_time_received'] is True, result
    assert result['parameter'] == 'use_sim_time (bool): true', result
    assert simulated(result['first_sim_time']) and simulated(result['node_time']), (result, first, last)
    assert result['first_sim_time'] <= result['node_time'], result
    assert result['sent'] >= 20, result
    # The simulator's map -> base (0.5 m in x), stamped in simulated time, found by our lookup.
    assert result['lookup_status'] == 'ok', result
    assert simulated(result['lookup_stamp']), (result, first, last)
    # Its age, in our node's (simulated) clock: the simulator sends it at 100 Hz.
    assert 0.0 <= result['lookup_age'] < 2.0, result
    assert result['lookup_x_mm'] == pytest.approx(500.0), result
