"""Fixtures for interop tests: real rclpy peers in their own processes, our tools in others.

Every test gets a ROS_DOMAIN_ID no test before it used recently, so lingering peers never cross,
and discovery stays on the loopback (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST).
"""
from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Iterator

import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
# One domain per test, reused in turn after ROS2VTK_TEST_DOMAIN_COUNT (80) tests (the tests of
# one shard run one after another and each kills its processes): ROS domain IDs stop at 232 (UDP
# ports), and test_other_domain_sees_nothing goes 50 above its own: counting up without end fails
# ('port number is too high') as soon as ~80 tests sort before that one or a shard passes 132
# tests. Shards that run at the same time (tests/interop/CMakeLists.txt) get disjoint ranges.
_DOMAIN_BASE = int(os.environ.get('ROS2VTK_TEST_DOMAIN_BASE', '100'))
_DOMAIN_COUNT = int(os.environ.get('ROS2VTK_TEST_DOMAIN_COUNT', '80'))
_domains = (_DOMAIN_BASE + n % _DOMAIN_COUNT for n in itertools.count())
TF2_MSGS_INSTALL = Path(os.environ.get('ROS2VTK_FIXTURES_BUILD_DIR', REPO / 'build-fixtures')) / 'tf2_msgs' / 'install'


def tf2_msgs_env() -> dict:
    """Environment additions that let rclpy peers import tf2_msgs (no wheel on PyPI: its Python
    support is built from tests/fixtures/tf2_msgs_pkg with the ROS 2 generators of the wheels by
    tests/fixtures/make_cdr_fixtures.py, which runs it once when missing)."""
    site = TF2_MSGS_INSTALL / 'lib' / 'python3.11' / 'site-packages'
    if not (site / 'tf2_msgs').exists():
        import fcntl
        TF2_MSGS_INSTALL.parent.mkdir(parents=True, exist_ok=True)
        with open(TF2_MSGS_INSTALL.parent / '.lock', 'w') as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            if not (site / 'tf2_msgs').exists():
                subprocess.run([str(VENV_PYTHON), str(REPO / 'tests' / 'fixtures' / 'make_cdr_fixtures.py'),
                                '--check'], check=False, stdout=subprocess.DEVNULL)
    assert (site / 'tf2_msgs').exists(), f'tf2_msgs Python support missing under {TF2_MSGS_INSTALL}'
    return {'PYTHONPATH': str(site), 'LD_LIBRARY_PATH': str(TF2_MSGS_INSTALL / 'lib'),
            'AMENT_PREFIX_PATH': str(TF2_MSGS_INSTALL)}


class Ros:
    """Starts processes on one ROS domain and cleans them up."""

    def __init__(self, domain: int) -> None:
        self.domain = domain
        self.env = dict(os.environ, ROS_DOMAIN_ID=str(domain),
                        ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONUNBUFFERED='1')
        self.env.pop('ROS_LOCALHOST_ONLY', None)
        self.processes: list[subprocess.Popen] = []

    def start(self, args: list[str], env: dict | None = None) -> subprocess.Popen:
        process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                   env=env or self.env)
        self.processes.append(process)
        return process

    def peer(self, *args: str, env: dict | None = None) -> subprocess.Popen:
        """An rclpy node running tests/interop/ros_peer.py."""
        return self.start([str(VENV_PYTHON), str(HERE / 'ros_peer.py'), *args], env)

    def tf_peer(self, *args: str) -> subprocess.Popen:
        """An rclpy node that can use tf2_msgs (built from its .msg, see tf2_msgs_env)."""
        env = dict(self.env)
        for key, value in tf2_msgs_env().items():
            env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
        return self.peer(*args, env=env)

    def scene(self, *args: str) -> subprocess.Popen:
        """Our VTK-wrapped Python API (Debian's python3 + <build>/python) running scene_runner.py."""
        env = dict(self.env, PYTHONPATH=str(BUILD / 'python'))
        return self.start(['/usr/bin/python3', str(HERE / 'scene_runner.py'), *args], env)

    def tool(self, *args: str, env: dict | None = None) -> subprocess.Popen:
        """Our `ros2vtk-topic` command line."""
        return self.start([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-topic'), *args], env)

    @staticmethod
    def finish(process: subprocess.Popen, timeout: float = 30.0) -> tuple[int, str, str]:
        try:
            out, err = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            out, err = process.communicate()
            return -9, out, err
        return process.returncode, out, err

    @staticmethod
    def stop(process: subprocess.Popen) -> None:
        """Ends a process whose output the test does not need (a publisher that would go on for
        its --seconds after the peer has what it wanted)."""
        if process.poll() is None:
            process.terminate()
        try:
            process.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.communicate()

    @staticmethod
    def wait_ready(process: subprocess.Popen, timeout: float = 20.0) -> None:
        """Waits for the {"ready": true} line an echo peer prints once subscribed."""
        line = process.stdout.readline()
        assert line and json.loads(line).get('ready') is True, line or process.stderr.read()

    def close(self) -> None:
        for process in self.processes:
            if process.poll() is None:
                process.kill()
                process.communicate()


@pytest.fixture
def ros() -> Iterator[Ros]:
    if not VENV_PYTHON.exists():
        pytest.fail(f'no ROS 2 venv at {VENV_PYTHON}: run scripts/setup.sh')
    session = Ros(next(_domains))
    yield session
    session.close()
