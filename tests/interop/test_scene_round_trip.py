"""The paper's round-trip experiment as a test: an rclpy client sends Float64 timestamps, our
subscriber's observer (examples/round_trip/round_trip.py) publishes them back, none may be lost.
Latency figures belong to the benchmarks; here only delivery is checked."""
from __future__ import annotations

import json

from conftest import BUILD, REPO


def run_round_trip(ros, spin: str, rate: str):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    ours = ros.start(['/usr/bin/python3', str(REPO / 'examples' / 'round_trip' / 'round_trip.py'),
                      '--spin', spin, '--rate', '100', '--seconds', '25'], env=env)
    ros.wait_ready(ours)
    client = ros.peer('round_trip', '--count', '100', '--rate', rate)
    code, out, err = ros.finish(client, timeout=60)
    ours.kill()
    assert code == 0, err
    return json.loads(out.splitlines()[-1])


def test_round_trip_event_driven_50hz_none_lost(ros):
    result = run_round_trip(ros, 'event', '50')
    assert result['lost'] == 0, result
    assert result['received'] == 100


def test_round_trip_timer_100hz_none_lost(ros):
    result = run_round_trip(ros, 'timer', '100')
    assert result['lost'] == 0, result
