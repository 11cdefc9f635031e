"""The demo, headless, as a newcomer runs it: a simulated robot (its own process) and the viewer
writing frames. Checks the pictures: robot pixels where the camera projection of its models says,
the phantom visible, the robot moving. Frames are kept in <build>/test-artifacts/demo/."""
from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import vtk

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
ARTIFACTS = BUILD / 'test-artifacts' / 'demo'


def read_png(path: Path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def pixel(image, x: int, y: int):
    scalars = image.GetPointData().GetScalars()
    width = image.GetDimensions()[0]
    index = y * width + x
    return [scalars.GetComponent(index, c) for c in range(3)]


def background(y: int, height: int):
    """The viewer's gradient background at row y (Slicer's: bottom -> top)."""
    t = y / max(height - 1, 1)
    return [255 * ((1 - t) * a + t * b) for a, b in zip((0.7568, 0.7647, 0.9098), (0.4549, 0.4706, 0.7451))]


def differs_from_background(image, x: int, y: int) -> bool:
    height = image.GetDimensions()[1]
    # The background is rendered exactly (no noise), so a small margin separates it from shaded parts.
    return max(abs(p - q) for p, q in zip(pixel(image, x, y), background(y, height))) > 10


def start_sim(env):
    return subprocess.Popen([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'), '--urdf',
                             str(REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf')],
                            env=env, stdout=subprocess.DEVNULL)


def make_phantom() -> Path:
    phantom = BUILD / 'test-artifacts' / 'phantom.mha'
    phantom.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run([str(BUILD / 'runtime' / 'Viewer' / 'ros2vtk-make-phantom'), str(phantom)], check=True,
                   stdout=subprocess.DEVNULL)
    return phantom


def demo_env(offset: int):
    return dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST',
                ROS_DOMAIN_ID=str(int(os.environ.get('ROS2VTK_TEST_DOMAIN_BASE', '55')) + offset),
                PYTHONPATH=str(BUILD / 'python'))


def test_demo_shows_a_moving_robot_beside_the_phantom():
    if ARTIFACTS.exists():
        shutil.rmtree(ARTIFACTS)
    env = demo_env(2)
    phantom = make_phantom()
    sim = start_sim(env)
    started = time.monotonic()
    try:
        # No --duration: with no display the window mode stops by itself (20 s) with a summary.
        demo = subprocess.run(['xvfb-run', '-a', '-s', '-screen 0 1280x720x24', '/usr/bin/python3',
                               str(REPO / 'examples' / 'demo' / 'demo.py'), '--phantom', str(phantom),
                               '--window', '--offscreen', str(ARTIFACTS)],
                              env=env, capture_output=True, text=True, timeout=120)
    finally:
        sim.kill()
        sim.wait()
    elapsed = time.monotonic() - started
    assert demo.returncode == 0, demo.stderr
    assert '[demo] summary: ' in demo.stdout and 'loaded 8/8 links' in demo.stdout, demo.stdout
    assert 'phantom placed at the tip' in demo.stdout, demo.stdout
    assert elapsed < 90, f'the bounded run took {elapsed:.0f} s'
    frames = sorted(ARTIFACTS.glob('frame_*.png'))
    assert 8 <= len(frames) <= 30, demo.stdout
    # The robot whole: in the last frames every sizeable model's projected centre is inside the
    # window and drawn (not background).
    checked = 0
    for frame in frames[-3:]:
        image = read_png(frame)
        info = json.loads(frame.with_suffix('.json').read_text())
        assert info['models'], 'no robot model in the scene'
        for model in info['models'].values():
            if model['size_mm'] < 40:
                continue  # needle tip and small parts can be hidden behind others
            x, y = int(round(model['x'])), int(round(model['y']))  # display: origin bottom-left
            assert 0 <= x < info['window'][0] and 0 <= y < info['window'][1], f'{frame.name}: a link out of view'
            assert differs_from_background(image, x, y), f'{frame.name}: nothing drawn at {x},{y}'
            checked += 1
    assert checked >= 9
    # The phantom at the tool tip: a frame where the tip is inside the phantom volume, its
    # projection inside the phantom's projected box, and grey tissue drawn in that box.
    at_tip = [f for f in frames if json.loads(f.with_suffix('.json').read_text()).get('tip_inside_phantom')]
    assert at_tip, 'no frame with the needle tip inside the phantom'
    info = json.loads(at_tip[0].with_suffix('.json').read_text())
    x0, y0, x1, y1 = info['phantom_display_box']
    tx, ty = info['tip_display']
    assert x0 <= tx <= x1 and y0 <= ty <= y1, info
    image = read_png(at_tip[0])
    width, height = image.GetDimensions()[:2]
    greys = sum(1 for x in range(max(int(x0), 0), min(int(x1), width), 2)
                for y in range(max(int(y0), 0), min(int(y1), height), 2)
                if abs(pixel(image, x, y)[0] - pixel(image, x, y)[2]) < 6 and 40 < pixel(image, x, y)[0] < 200)
    assert greys > 50, f'phantom slices not visible in {at_tip[0].name} ({greys} grey samples)'
    # The robot moves: consecutive frames differ.
    a, b = read_png(frames[-2]), read_png(frames[-1])
    changed = sum(1 for x in range(0, width, 4) for y in range(0, height, 4) if pixel(a, x, y) != pixel(b, x, y))
    assert changed > 20, 'consecutive frames are identical'


def start_xvfb():
    """An Xvfb of our own (xvfb-run would receive the test's SIGINT instead of the demo)."""
    read_fd, write_fd = os.pipe()
    server = subprocess.Popen(['Xvfb', '-displayfd', str(write_fd), '-screen', '0', '1280x720x24', '-nolisten', 'tcp'],
                              pass_fds=(write_fd,), stderr=subprocess.DEVNULL)
    os.close(write_fd)
    number = b''
    while not number.endswith(b'\n'):  # the number and its newline come once Xvfb accepts clients
        chunk = os.read(read_fd, 16)
        if not chunk:
            break
        number += chunk
    os.close(read_fd)
    number = number.decode().strip()
    assert number, 'Xvfb did not start'
    return server, ':' + number


def test_ctrl_c_stops_the_demo_with_one_line():
    env = demo_env(3)
    phantom = make_phantom()
    sim = start_sim(env)
    xvfb, display = start_xvfb()
    try:
        demo = subprocess.Popen(['/usr/bin/python3', str(REPO / 'examples' / 'demo' / 'demo.py'), '--phantom',
                                 str(phantom), '--window', '--offscreen', str(ARTIFACTS / 'interrupted'),
                                 '--duration', '60'],
                                env=dict(env, DISPLAY=display), stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 60
        line = ''
        while 'robot in /' not in line and time.monotonic() < deadline:
            line = demo.stdout.readline()
            if not line and demo.poll() is not None:
                break
        demo.send_signal(signal.SIGINT)
        out, err = demo.communicate(timeout=30)
    finally:
        for process in (sim, xvfb):
            process.kill()
            process.wait()
    assert demo.returncode == 0, err
    assert '[demo] interrupted (Ctrl-C): stopping' in out
    assert 'Traceback' not in err, err
