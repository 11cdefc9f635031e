"""The demo, headless, as a newcomer runs it: a simulated robot (its own process) and the viewer
writing frames. Checks the pictures: robot pixels where the camera projection of its models says,
the phantom visible, the robot moving. Frames are kept in <build>/test-artifacts/demo/."""
from __future__ import annotations

import json
import os
import shutil
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


def test_demo_shows_a_moving_robot_beside_the_phantom():
    if ARTIFACTS.exists():
        shutil.rmtree(ARTIFACTS)
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', ROS_DOMAIN_ID='57',
               PYTHONPATH=str(BUILD / 'python'))
    phantom = BUILD / 'test-artifacts' / 'phantom.mha'
    phantom.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run([str(BUILD / 'runtime' / 'Viewer' / 'ros2vtk-make-phantom'), str(phantom)], check=True)
    sim = subprocess.Popen([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'), '--urdf',
                            str(REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf')],
                           env=env, stdout=subprocess.DEVNULL)
    try:
        demo = subprocess.run(['xvfb-run', '-a', '-s', '-screen 0 1280x720x24', '/usr/bin/python3',
                               str(REPO / 'examples' / 'demo' / 'demo.py'), '--phantom', str(phantom),
                               '--offscreen', str(ARTIFACTS), '--duration', '8'],
                              env=env, capture_output=True, text=True, timeout=120)
    finally:
        sim.kill()
        sim.wait()
    assert demo.returncode == 0, demo.stderr
    assert 'loaded, 8/8 links tracked' in demo.stdout, demo.stdout
    frames = sorted(ARTIFACTS.glob('frame_*.png'))
    assert len(frames) >= 6, demo.stdout
    # The last frames have the robot: each sizeable model's projected centre is not background.
    checked = 0
    for frame in frames[-3:]:
        image = read_png(frame)
        info = json.loads(frame.with_suffix('.json').read_text())
        assert info['models'], 'no robot model in the scene'
        for model in info['models'].values():
            if model['size_mm'] < 40:
                continue  # needle tip and small parts can be hidden behind others
            x, y = int(round(model['x'])), int(round(model['y']))  # display: origin bottom-left
            if not (0 <= x < info['window'][0] and 0 <= y < info['window'][1]):
                continue  # a link out of the view (the arm moves)
            assert differs_from_background(image, x, y), f'{frame.name}: nothing drawn at {x},{y}'
            checked += 1
    assert checked >= 9
    # The phantom: the slices show grey tissue right of the robot (it sits at +x in front).
    last = read_png(frames[-1])
    width, height = last.GetDimensions()[:2]
    greys = sum(1 for x in range(width // 2, width, 2) for y in range(0, height // 2, 2)
                if abs(pixel(last, x, y)[0] - pixel(last, x, y)[2]) < 6 and 40 < pixel(last, x, y)[0] < 180)
    assert greys > 50, 'phantom slices not visible'
    # The robot moves: consecutive frames differ.
    a, b = read_png(frames[-2]), read_png(frames[-1])
    changed = sum(1 for x in range(0, width, 4) for y in range(0, height, 4) if pixel(a, x, y) != pixel(b, x, y))
    assert changed > 20, 'consecutive frames are identical'
