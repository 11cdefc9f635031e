"""The `ros2vtk` command line against real rclpy peers: `pub` (YAML, on our own runtime) reaches
an rclpy subscriber; `echo` prints what an rclpy publisher sends; bad input gets a clear error."""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
PEER = REPO / 'tests' / 'interop' / 'ros_peer.py'
ENV = dict(os.environ, ROS_DOMAIN_ID=str(int(os.environ.get('ROS2VTK_TEST_DOMAIN_BASE', '185')) + 2),
           ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONPATH=str(BUILD / 'python'), PYTHONUNBUFFERED='1')


def ros2vtk(*args, timeout=60):
    return subprocess.run([str(VENV_PYTHON), '-m', 'ros2vtk', *args], env=ENV, capture_output=True, text=True,
                          timeout=timeout)


def test_pub_reaches_an_rclpy_subscriber():
    listener = subprocess.Popen([str(VENV_PYTHON), str(PEER), 'echo', '/cli_pub', 'geometry_msgs/msg/Point',
                                 '--count', '2', '--timeout', '40'], env=ENV, stdout=subprocess.PIPE, text=True)
    try:
        assert json.loads(listener.stdout.readline()) == {'ready': True}
        result = ros2vtk('pub', '/cli_pub', 'geometry_msgs/msg/Point', '{x: 1.5, y: -2.0}', '-t', '2', '-r', '5',
                         '--wait-matching', '20')
        assert result.returncode == 0, result.stderr
        assert 'publishing #2' in result.stdout
        received = [json.loads(listener.stdout.readline()) for _ in range(2)]
    finally:
        listener.kill()
        listener.wait()
    assert received == [{'x': 1.5, 'y': -2.0, 'z': 0.0}] * 2


def test_echo_prints_rclpy_messages():
    talker = subprocess.Popen([str(VENV_PYTHON), str(PEER), 'pub', '/cli_echo', 'std_msgs/msg/String',
                               json.dumps({'data': 'from rclpy'}), '--count', '-1', '--rate', '10',
                               '--wait-matched', '0'], env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        result = ros2vtk('echo', '/cli_echo', 'String', '-n', '1', '--timeout', '30')
    finally:
        talker.kill()
        talker.wait()
    assert result.returncode == 0, result.stderr
    assert 'data: from rclpy' in result.stdout
    assert "# as 'from rclpy'" in result.stdout


def test_bad_input_gets_clear_errors():
    result = ros2vtk('pub', '/x', 'NoSuchType', '{}')
    assert result.returncode == 2 and 'not a registered ROS type' in result.stderr
    result = ros2vtk('pub', '/x', 'std_msgs/msg/String', '{data: [', '--wait-matching', '0')
    assert result.returncode == 2 and 'not valid' in result.stderr
    result = ros2vtk('app', '--host', '0.0.0.0')
    assert result.returncode == 2 and 'not the loopback' in result.stderr
    # A TCP discovery server (Fast DDS 3's syntax), which Fast DDS 2.9 cannot use: said, no traceback.
    result = subprocess.run([str(VENV_PYTHON), '-m', 'ros2vtk', '--wait', '0', 'nodes'], capture_output=True, text=True,
                            timeout=60, env=dict(ENV, ROS_DISCOVERY_SERVER='TCPv4:[127.0.0.1]:42100'))
    assert result.returncode == 2 and 'Traceback' not in result.stderr, result.stderr
    assert 'TCP discovery servers are not supported with Fast DDS 2.9' in result.stderr, result.stderr
    assert 'ros2vtk nodes: no ROS node could be created (see the error above)' in result.stderr, result.stderr


def test_a_graph_listing_that_finds_nobody_says_what_to_check():
    """No other process on this test's domain: `ros2vtk nodes` lists only itself and says, on
    stderr, which settings it used and what to check (the same advice as the node's warning)."""
    result = ros2vtk('--wait', '1', 'nodes')
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ['/slicer'], result.stdout
    domain = int(ENV['ROS_DOMAIN_ID'])
    assert (f'ros2vtk: found no other ROS 2 participant in 1 s: it uses ROS_DOMAIN_ID={domain} and '
            'ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, so it looks only on this computer; check that the other side '
            f'uses the same domain and range') in result.stderr, result.stderr
    assert f'UDP ports {7400 + 250 * domain}-{7649 + 250 * domain} (docs/networking.md)' in result.stderr


def test_app_volume_option_refuses_a_missing_or_unreadable_file(tmp_path):
    """`ros2vtk app --volume FILE`: a file it cannot show is refused with its reason, exit 2, before
    serving (the panel's form shows the same reasons: test_app_browser.py test 10)."""
    missing = ros2vtk('app', '--port', '0', '--volume', str(tmp_path / 'ct.nrrd'))
    assert missing.returncode == 2, missing.stdout + missing.stderr
    assert f'ros2vtk app: no such file: {tmp_path / "ct.nrrd"}' in missing.stderr
    garbage = tmp_path / 'ct.nii.gz'
    garbage.write_bytes(b'not a NIfTI file')
    unreadable = ros2vtk('app', '--port', '0', '--volume', str(garbage))
    assert unreadable.returncode == 2, unreadable.stdout + unreadable.stderr
    assert f'{garbage}: not a readable NIfTI file' in unreadable.stderr, unreadable.stderr
    assert 'Traceback' not in missing.stderr + unreadable.stderr
