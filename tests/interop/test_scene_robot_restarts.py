"""A robot from the parameter source follows every restart of its robot_state_publisher (issue 11
item 7): the stand-in (rsp_peer.py, rclpy) is killed and started again at once, 10 times, with
alternating descriptions. A node killed this way stays matched until its lease ends (~20 s), so
only the new server's arrival (a new GUID) can tell the parameter client to fetch again; each
restart must reload the robot with the new description (counted by the robot's loads and its
link names)."""
from __future__ import annotations

import json
import queue
import signal
import threading
import time
from pathlib import Path

from test_scene_robot import start_rsp, start_scene_robot

RESTARTS = 10


def urdf(name: str, links: list[str]) -> str:
    joints = ''.join(
        f'<joint name="j_{child}" type="revolute"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        for parent, child in zip(links, links[1:]))
    return f'<robot name="{name}">' + ''.join(f'<link name="{link}"/>' for link in links) + joints + '</robot>'


def lines_of(process) -> queue.Queue:
    lines: queue.Queue = queue.Queue()

    def read():
        for line in process.stdout:
            lines.put(line)
    threading.Thread(target=read, daemon=True).start()
    return lines


def wait_for_loads(lines: queue.Queue, loads: int, timeout: float) -> dict | None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            line = json.loads(lines.get(timeout=max(0.01, deadline - time.monotonic())))
        except queue.Empty:
            return None
        if line.get('loads', 0) >= loads:
            return line
    return None


def test_every_quick_restart_of_robot_state_publisher_reloads_the_robot(ros, tmp_path: Path):
    descriptions = [tmp_path / 'a.urdf', tmp_path / 'b.urdf']
    links = [['base', 'upper_a'], ['base', 'upper_b', 'tip_b']]
    descriptions[0].write_text(urdf('robot_a', links[0]))
    descriptions[1].write_text(urdf('robot_b', links[1]))
    ours = start_scene_robot(ros, '--seconds', '240', 'robot', 'arm', '--source', 'parameter',
                             '--loads', str(RESTARTS + 1), '--follow', '1', '--every', '0.1')
    lines = lines_of(ours)
    reloads = 0
    gaps = []
    rsp = start_rsp(ros, descriptions[0], '--configs', '1', '--hold', '300', '--wait', '0')
    for start in range(RESTARTS + 1):
        which = start % 2
        snapshot = wait_for_loads(lines, start + 1, 60.0)
        assert snapshot is not None, (f'start {start} of robot_state_publisher never reloaded the robot '
                                      f'({reloads} of {start} restarts did)')
        assert sorted(snapshot['links']) == sorted(links[which]), snapshot['links']
        if start > 0:
            reloads += 1
        if start == RESTARTS:
            break
        # Killed (no goodbye: its endpoints stay matched until its lease ends) and started again at once.
        killed = time.monotonic()
        rsp.send_signal(signal.SIGKILL)
        rsp.wait()
        rsp = start_rsp(ros, descriptions[1 - which], '--configs', '1', '--hold', '300', '--wait', '0')
        gaps.append(time.monotonic() - killed)
    rsp.kill()
    ours.kill()
    assert reloads == RESTARTS
    assert max(gaps) < 1.0, gaps
