"""Fixtures for the examples' tests: the example (our Python API under Debian's python3) and a
real rclpy peer (the venv's wheels, tests/examples/peers.py) in separate processes on a ROS domain
of their own, discovery on the loopback only. Domains are 220-232: Fast DDS refuses IDs above 232
(RTPS port numbers would pass 65535), and the interop tests (100+) and benchmarks (200+) use lower ones.

pytest itself runs under the venv's python (numpy for the independent expected values).
"""
from __future__ import annotations

import json
import os
import queue
import re
import subprocess
import threading
import time
from pathlib import Path
from typing import Iterator

import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
EXAMPLES = REPO / 'examples'


class Process:
    """A child process whose stdout lines are read by a thread (so waits can time out)."""

    def __init__(self, args: list[str], env: dict) -> None:
        self.args = args
        self.name = next((Path(a).name for a in args if a.endswith('.py')), args[0])
        self.popen = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        self.lines: queue.Queue = queue.Queue()
        self.stdout: list[str] = []
        self.stderr = ''
        threading.Thread(target=self._read, daemon=True).start()
        self._err_thread = threading.Thread(target=self._read_err, daemon=True)
        self._err_thread.start()

    def _read(self) -> None:
        for line in self.popen.stdout:
            self.stdout.append(line)
            self.lines.put(line)
        self.lines.put(None)

    def _read_err(self) -> None:
        self.stderr = self.popen.stderr.read()

    def next_json(self, timeout: float, where=lambda obj: True) -> dict:
        """The next JSON line satisfying `where` (other lines are skipped)."""
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise AssertionError(f'{self.name}: no matching line within {timeout} s; '
                                     f'stdout so far: {"".join(self.stdout)[-2000:]}')
            try:
                line = self.lines.get(timeout=remaining)
            except queue.Empty:
                continue
            if line is None:
                self.popen.wait()
                self._err_thread.join(2)
                raise AssertionError(f'{self.name} ended (rc {self.popen.returncode}) before a '
                                     f'matching line; stderr: {self.stderr[-2000:]}; stdout: {"".join(self.stdout)[-2000:]}')
            line = line.strip()
            if not line.startswith('{'):
                continue
            obj = json.loads(line)
            if where(obj):
                return obj

    def finish(self, timeout: float) -> int:
        try:
            self.popen.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.popen.kill()
            self.popen.wait()
        self._err_thread.join(2)
        return self.popen.returncode

    def json_lines(self) -> list[dict]:
        return [json.loads(line) for line in self.stdout if line.strip().startswith('{')]


class Ros:
    def __init__(self, domain: int) -> None:
        assert 220 <= domain <= 232, 'Fast DDS ports overflow above 232; the examples use 220-232'
        self.env = dict(os.environ, ROS_DOMAIN_ID=str(domain), ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST',
                        PYTHONUNBUFFERED='1')
        self.env.pop('ROS_LOCALHOST_ONLY', None)
        self.processes: list[Process] = []

    def example(self, name: str, *args: str, display: bool = False) -> Process:
        """examples/<name>/<name>.py with our Python API; `display`: it renders (offscreen), which
        VTK's X11 build still needs an X server for: Xvfb when there is no DISPLAY."""
        env = dict(self.env, PYTHONPATH=str(BUILD / 'python'))
        command = ['/usr/bin/python3', str(EXAMPLES / name / f'{name}.py'), *args]
        if display and not os.environ.get('DISPLAY'):
            command = ['xvfb-run', '-a', '-s', '-screen 0 1024x768x24'] + command
        process = Process(command, env)
        self.processes.append(process)
        return process

    def peer(self, *args: str) -> Process:
        """An rclpy node (tests/examples/peers.py)."""
        process = Process([str(VENV_PYTHON), str(HERE / 'peers.py'), *args], self.env)
        self.processes.append(process)
        return process

    def close(self) -> None:
        for process in self.processes:
            if process.popen.poll() is None:
                process.popen.kill()
                process.popen.wait()


@pytest.fixture
def ros_domain(request) -> Iterator[callable]:
    sessions: list[Ros] = []

    def make(domain: int) -> Ros:
        if not VENV_PYTHON.exists():
            pytest.fail(f'no ROS 2 venv at {VENV_PYTHON}: run scripts/setup.sh')
        session = Ros(domain)
        sessions.append(session)
        return session

    yield make
    for session in sessions:
        session.close()


class Phantom:
    """The phantom made by ros2vtk-make-phantom, and what it printed about its layout."""

    def __init__(self, path: Path, tumour_centre: list[float], tumour_radius: float) -> None:
        self.path = path
        self.tumour_centre = tumour_centre
        self.tumour_radius = tumour_radius


@pytest.fixture(scope='session')
def phantom(tmp_path_factory) -> Phantom:
    tool = BUILD / 'runtime' / 'Viewer' / 'ros2vtk-make-phantom'
    assert tool.exists(), f'{tool} missing: build the project first'
    path = tmp_path_factory.mktemp('phantom') / 'phantom.mha'
    out = subprocess.run([str(tool), str(path)], check=True, capture_output=True, text=True).stdout
    match = re.search(r'tumour at \(([-\d.e]+), ([-\d.e]+), ([-\d.e]+)\) mm, radius ([-\d.e]+) mm', out)
    assert match, out
    return Phantom(path, [float(match.group(i)) for i in (1, 2, 3)], float(match.group(4)))
