"""LOCALHOST discovery keeps our node on this host (issue 11 item 11): with
ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST or ROS_LOCALHOST_ONLY=1 every socket of our process is
bound to 127.0.0.1 (`ss`, from iproute2), its SPDP announcements carry only 127.0.0.1 locators
(read by an independent RTPS parser from the datagrams it sends), and an rclpy peer in the same
mode (which announces this host's external address) still talks to it both ways.
Nothing here sends to a non-loopback address."""
from __future__ import annotations

import json
import shutil
import socket
import subprocess

import pytest

from spdp_capture import announcements

PORT_BASE, DOMAIN_GAIN, METATRAFFIC_UNICAST_OFFSET, PARTICIPANT_GAIN = 7400, 250, 10, 2


def loopback_env(ros, mode: str) -> dict:
    env = dict(ros.env)
    if mode == 'ROS_LOCALHOST_ONLY':
        env.pop('ROS_AUTOMATIC_DISCOVERY_RANGE', None)
        env['ROS_LOCALHOST_ONLY'] = '1'
    return env


def sockets_of(pid: int) -> list[str]:
    """Local addresses of the UDP and TCP sockets `ss` lists for one process."""
    addresses = []
    for flags in ('-lunpH', '-ltnpH', '-unpH', '-tnpH'):
        out = subprocess.run(['ss', flags], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            if f'pid={pid},' in line:
                addresses.append(line.split()[3])
    return addresses


def assert_loopback_sockets(*processes: subprocess.Popen) -> None:
    for process in processes:
        assert process.poll() is None, process.communicate()
        addresses = sockets_of(process.pid)
        assert addresses, f'ss lists no socket of pid {process.pid}'
        assert all(address.startswith('127.0.0.1:') for address in addresses), addresses


def capture_announcements(sock: socket.socket, seconds: float) -> dict[bytes, list]:
    def from_loopback(sender: tuple) -> None:
        assert sender[0] == '127.0.0.1', sender

    return announcements(sock, seconds, from_loopback)


@pytest.mark.parametrize('mode', ['ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_LOCALHOST_ONLY'])
def test_localhost_mode_binds_and_announces_only_loopback_and_talks_to_rclpy(ros, mode):
    assert shutil.which('ss'), 'ss (iproute2) missing: scripts/setup.sh installs it'
    env = loopback_env(ros, mode)
    # Participant id 0's metatraffic port on 127.0.0.1: our participants take the next ids and
    # send their announcements here (LOCALHOST initial peers), as they do to any local peer.
    listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    listener.bind(('127.0.0.1', PORT_BASE + DOMAIN_GAIN * ros.domain + METATRAFFIC_UNICAST_OFFSET))
    ours_pub = ros.tool('pub', '/lo/out', 'std_msgs/msg/String', json.dumps({'data': 'from ros2vtk'}),
                        '--count', '400', '--rate', '10', '--wait-matched', '0', env=env)
    ours_echo = ros.tool('echo', '/lo/in', 'std_msgs/msg/Float64', '--count', '1', '--timeout', '40',
                         env=env)
    announced = capture_announcements(listener, 3.0)
    listener.close()
    assert_loopback_sockets(ours_pub, ours_echo)
    # Before any rclpy peer exists, only our two processes announce on this domain.
    assert len(announced) == 2, announced
    for prefix, listed in announced.items():
        assert {kind for kind, *_ in listed} >= {'metatraffic_unicast', 'default_unicast'}, listed
        assert all(locator_kind == 1 and address == '127.0.0.1'
                   for _, locator_kind, address, _ in listed), f'non-loopback locator announced: {listed}'

    echo = ros.peer('echo', '/lo/out', 'std_msgs/msg/String', '--count', '1', '--timeout', '40',
                    env=env)
    peer = ros.peer('pub', '/lo/in', 'std_msgs/msg/Float64', json.dumps({'data': -1.5}),
                    '--count', '400', '--rate', '10', '--wait-matched', '0', env=env)
    code, out, err = ros.finish(echo, timeout=60)
    assert code == 0, f'rclpy never received from a loopback-only ros2vtk: {err}'
    assert json.loads(out.splitlines()[-1]) == {'data': 'from ros2vtk'}
    # Our publisher has now matched and sent to rclpy: its sockets again, after the exchange.
    assert_loopback_sockets(ours_pub)
    code, out, err = ros.finish(ours_echo, timeout=60)
    assert code == 0, f'a loopback-only ros2vtk never received from rclpy: {err}'
    assert 'data: -1.5' in out
    for process in (ours_pub, peer):
        process.kill()
