"""The demo, headless, as a newcomer runs it: a simulated robot (its own process, with the surgical
arm's needle-insertion motion) and the viewer writing frames. Checks each frame's numbers, which the
demo reads back from its scene and renderer (the tip from its tf lookup and from its drawn marker,
the phantom's box from its outline actor, the slice planes from their actors, the robot's box from
its actors), and the pictures: the robot whole in view, the needle tip inside the phantom with the
three slices through it, the phantom drawn there, the robot moving. Frames are kept in
<build>/test-artifacts/demo/."""
from __future__ import annotations

import json
import math
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


ARM = REPO / 'examples' / 'robots' / 'surgical_arm'
SIM = BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'


def start_sim(env):
    return subprocess.Popen([str(SIM), '--urdf', str(ARM / 'urdf' / 'surgical_arm.urdf'),
                             '--motion', str(ARM / 'config' / 'needle_insertion.motion')],
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


def test_demo_shows_the_needle_reaching_into_the_phantom():
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
    infos = {frame: json.loads(frame.with_suffix('.json').read_text()) for frame in frames}
    # The robot whole, in every frame once its links are tracked: the projected box of its
    # actors' bounds (8 corners) inside the 3D view (the left of the window; the slice panes
    # share the rest).
    tracked = [f for f in frames if 'robot_display_box' in infos[f] and 'tip_mm' in infos[f]]
    assert len(tracked) >= len(frames) - 4, f'the arm tracked in {len(tracked)} of {len(frames)} frames'
    for frame in tracked:
        x0, y0, x1, y1 = infos[frame]['robot_display_box']
        vx0, vy0, vx1, vy1 = infos[frame]['view_viewport_px']
        assert vx0 <= x0 < x1 <= vx1 and vy0 <= y0 < y1 <= vy1, f'{frame.name}: robot out of view {x0, y0, x1, y1}'
    # Its sizeable models drawn where their projected centres are (not background), last frames.
    checked = 0
    for frame in frames[-3:]:
        image = read_png(frame)
        info = infos[frame]
        for model in info['models'].values():
            if model['size_mm'] < 40:
                continue  # needle tip and small parts can be hidden behind others
            x, y = int(round(model['x'])), int(round(model['y']))  # display: origin bottom-left
            assert differs_from_background(image, x, y), f'{frame.name}: nothing drawn at {x},{y}'
            checked += 1
    assert checked >= 9
    # The needle tip from its tf lookup is where its marker (a model under the tip link) is drawn.
    for frame in tracked:
        tip, marker = infos[frame]['tip_mm'], infos[frame]['tip_marker_mm']
        assert max(abs(a - b) for a, b in zip(tip, marker)) < 3.0, f'{frame.name}: tip {tip}, marker {marker}'

    def inside(point, bounds):
        return all(bounds[2 * i] <= point[i] <= bounds[2 * i + 1] for i in range(3))
    # The phantom at the tool tip: frames where the tip is inside the drawn phantom's box.
    at_tip = [f for f in tracked if infos[f]['phantom_visible'] and inside(infos[f]['tip_mm'], infos[f]['phantom_bounds_mm'])]
    assert at_tip, 'no frame with the needle tip inside the phantom: ' + str(
        [(infos[f].get('tip_mm'), infos[f]['phantom_bounds_mm']) for f in frames])
    # At the robot's scale and in its workspace: a torso-sized box (20..50 cm a side), whose
    # nearest point is within the arm's reach from the base (under 1 m).
    bounds = infos[at_tip[0]]['phantom_bounds_mm']
    sides = [bounds[2 * i + 1] - bounds[2 * i] for i in range(3)]
    assert all(150 <= side <= 500 for side in sides), sides
    nearest = [min(max(0.0, bounds[2 * i]), bounds[2 * i + 1]) for i in range(3)]
    assert math.dist(nearest, (0, 0, 0)) < 1000, bounds
    # Framed on the robot's workspace and the phantom once it is placed, the camera stays where it
    # is while the arm moves (no camera that follows each frame's bounds).
    placed = [f for f in tracked if infos[f]['phantom_visible']]
    cameras = {tuple(round(c, 3) for c in infos[f]['camera_mm']) for f in placed}
    assert len(placed) >= 3 and len(cameras) == 1, [(f.name, infos[f]['camera_mm'], infos[f]['framings']) for f in placed]
    # The three slices through the tip (within a voxel) whenever it is inside; the 2D panes
    # centred on it, their planes cutting the needle (vtkCutter of the scene's models).
    for frame in at_tip:
        info = infos[frame]
        for axis, name in enumerate(('sagittal', 'coronal', 'axial')):
            assert abs(info['slice_planes_mm'][name] - info['tip_mm'][axis]) <= info['voxel_mm'][axis], (frame.name, info)
            assert math.dist(info['slice_view_centres_mm'][name], info['tip_mm']) <= info['voxel_mm'][axis], (frame.name, info)
            assert info['slice_view_cuts'][name] >= 1, (frame.name, name, info['slice_view_cuts'])
    # The needle approaching, outside the phantom's box: each pane shows the whole phantom cut at
    # the tip's coordinate (kept within the box), as Slicer's slice views driven by a tool: its
    # centre is the box's, moved along the pane's normal to the tip (not where the tip last was).
    approaching = [f for f in placed if not inside(infos[f]['tip_mm'], infos[f]['phantom_bounds_mm'])]
    for frame in approaching:
        info, box = infos[frame], infos[frame]['phantom_bounds_mm']
        for axis, name in enumerate(('sagittal', 'coronal', 'axial')):
            expected = [(box[2 * i] + box[2 * i + 1]) / 2 for i in range(3)]
            expected[axis] = min(max(info['tip_mm'][axis], box[2 * axis]), box[2 * axis + 1])
            assert math.dist(info['slice_view_centres_mm'][name], expected) <= info['voxel_mm'][axis], (frame.name, info)
    print(f'{len(at_tip)} frames with the tip inside the phantom, {len(approaching)} with it outside')
    # On the picture: the tip's projection inside the phantom's projected box, grey tissue there.
    info = infos[at_tip[0]]
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


def test_sim_robot_refuses_a_bad_motion_file(tmp_path):
    """--motion: a clear error (file:line: what) and exit 1 before anything is published."""
    cases = {
        'no_such_joint 0 0.1 5\n': "'no_such_joint' is not an actuated joint of surgical_arm",
        'elbow_pitch 0 0.1\n': "expected '<joint> <mid> <amplitude> <period s> [<phase rad>]'",
        'elbow_pitch 0 0.1 0\n': 'the period must be > 0 s',
        '# a comment\n\nelbow_pitch 2.0 0.5 5\n': "'elbow_pitch' would move over [1.5, 2.5], outside its limits [-2.2, 2.2]",
        'elbow_pitch 0 0.1 5\nelbow_pitch 0 0.2 5\n': "'elbow_pitch' was already given on line 1",
        'elbow_pitch 0 0.1 5 0 extra\n': "unexpected 'extra'",
    }
    for number, (text, message) in enumerate(cases.items()):
        motion = tmp_path / f'bad{number}.motion'
        motion.write_text(text)
        run = subprocess.run([str(SIM), '--urdf', str(ARM / 'urdf' / 'surgical_arm.urdf'), '--motion', str(motion)],
                             capture_output=True, text=True, timeout=30, env=demo_env(4))
        assert run.returncode == 1 and message in run.stderr and str(motion) in run.stderr, (text, run.stderr)
    run = subprocess.run([str(SIM), '--urdf', str(ARM / 'urdf' / 'surgical_arm.urdf'), '--motion',
                          str(tmp_path / 'missing.motion')], capture_output=True, text=True, timeout=30, env=demo_env(4))
    assert run.returncode == 1 and 'cannot read the motion file' in run.stderr, run.stderr
