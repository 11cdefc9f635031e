"""The demo as a newcomer sees it (its default mode): examples/demo/demo.py serves the web app on
its own logic (`ros2vtk.app.serve(logic, on_app=...)`) with the simulated robot running its needle
insertions. In headless Chromium: the robot row is loaded with every link tracked, the view shows
the robot's orange (the phantom's pixels are checked by tests/demo, where its projected box is
known), the three slice panes show the phantom, and once the phantom is placed at the tip they
follow the needle (its cut drawn in all three at once); the demo stops by itself after --duration
with exit 0. Screenshots in <build>/test-artifacts/app/demo-app*.png."""
from __future__ import annotations

import io
import os
import socket
import subprocess
import time
import urllib.request
from pathlib import Path

from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
ARTIFACTS = BUILD / 'test-artifacts' / 'app'
URDF = REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'
MOTION = REPO / 'examples' / 'robots' / 'surgical_arm' / 'config' / 'needle_insertion.motion'


def wait_for(what, check, seconds=60.0, step=0.5):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = check()
        if value:
            return value
        time.sleep(step)
    raise AssertionError(f'timed out after {seconds:g} s waiting for {what}')


def orange_pixels(png: bytes) -> int:
    """Pixels of the robot's 'signal' orange material (nothing else in the view is red-dominant
    with so little blue)."""
    pixels = Image.open(io.BytesIO(png)).convert('RGB').get_flattened_data()
    # 'signal' (0.95 0.45 0.1): green/red ~0.47, blue/red ~0.1 under any shading; the phantom's
    # pseudotumour (0.9 0.3 0.25) has green/red 0.33 and blue/red 0.28.
    return sum(1 for r, g, b in pixels if r > 100 and 0.38 < g / r < 0.6 and b / r < 0.2)


def phantom_pixels(png: bytes) -> dict[str, int]:
    """Grey pixels of the phantom in a slice pane at W400/L40: gel (10 HU -> ~108), tissue
    (60 HU -> ~140), tumour (160 HU -> ~204); air is black. JPEG and the noise blur the levels, so
    each is counted within +-14 of its grey value; coloured pixels (model intersections, the
    label) are left out."""
    counts = {'gel': 0, 'tissue': 0, 'tumour': 0}
    levels = {'gel': 108, 'tissue': 140, 'tumour': 204}
    for r, g, b in Image.open(io.BytesIO(png)).convert('RGB').get_flattened_data():
        if max(r, g, b) - min(r, g, b) > 12:
            continue
        for name, level in levels.items():
            if abs(g - level) <= 14:
                counts[name] += 1
    return counts


def pixels_on_the_border(png: bytes, inset: int = 2) -> int:
    """Pixels of the view's border (a frame `inset` px in, off the JPEG's edge) that are not
    the background: Slicer's gradient is blue-dominant (blue exceeds red and green by 35+), the
    robot (grey, black, orange), the phantom's grey slices and its yellow outline are not. A
    model cut by the view's edge leaves such pixels on the border."""
    image = Image.open(io.BytesIO(png)).convert('RGB')
    w, h = image.size
    border = [(x, y) for x in range(inset, w - inset) for y in (inset, h - 1 - inset)] + \
             [(x, y) for y in range(inset, h - inset) for x in (inset, w - 1 - inset)]
    return sum(1 for x, y in border if (lambda r, g, b: b - max(r, g) < 20)(*image.getpixel((x, y))))


def test_demo_serves_the_app_with_robot_and_phantom():
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, ROS_DOMAIN_ID=str(int(os.environ.get('ROS2VTK_TEST_DOMAIN_BASE', '185')) + 3),
               ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONPATH=str(BUILD / 'python'), PYTHONUNBUFFERED='1')
    env.pop('DISPLAY', None)  # the app starts its own Xvfb
    phantom = BUILD / 'test-artifacts' / 'phantom.mha'
    phantom.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run([str(BUILD / 'runtime' / 'Viewer' / 'ros2vtk-make-phantom'), str(phantom)], check=True,
                   stdout=subprocess.DEVNULL)
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        port = s.getsockname()[1]
    sim = subprocess.Popen([str(BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot'), '--urdf', str(URDF),
                            '--motion', str(MOTION)], env=env, stdout=subprocess.DEVNULL)
    demo = subprocess.Popen([str(VENV_PYTHON), str(REPO / 'examples' / 'demo' / 'demo.py'), '--phantom', str(phantom),
                             '--port', str(port), '--duration', '60'], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    options = webdriver.ChromeOptions()
    for flag in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--window-size=1600,950'):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=options)
    url = f'http://127.0.0.1:{port}/'

    def listening():
        assert demo.poll() is None, demo.stdout.read()
        try:
            with urllib.request.urlopen(url, timeout=5) as response:
                return response.status == 200
        except OSError:
            return False
    try:
        wait_for('the demo app', listening, seconds=120)
        driver.get(url)
        wait_for('the robot loaded, 8/8 links', lambda: any(
            'loaded' in r.text and '8/8' in r.text for r in driver.find_elements(By.ID, 'robot-robot')))
        orange = wait_for('the robot orange in the view', lambda: (lambda n: n > 40 and n)(
            orange_pixels(driver.find_element(By.ID, 'view').screenshot_as_png)))
        # (The 3D view shares the page with the slice panes: the robot is smaller than in
        # test_app_browser's full-page view, so fewer orange pixels are asked for.)
        # The slice panes (vtkROS2SliceView) show the phantom: its gel's grey level (W400/L40)
        # over a large part of each of the three (tissue shows when a plane crosses the middle). Their planes follow the needle tip while it is inside the phantom; the
        # needle's cut (its orange) shows only in those moments, so it is reported, not required
        # (tests/display checks the intersections of vtkROS2SliceView by pixels).
        panes = ('axial', 'sagittal', 'coronal')

        last = {}

        def panes_with_phantom_and_needle():
            shots = {o: driver.find_element(By.ID, f'slice_{o}').screenshot_as_png for o in panes}
            phantom = {o: phantom_pixels(png) for o, png in shots.items()}
            needle = {o: orange_pixels(png) for o, png in shots.items()}
            last.update(shots=shots, phantom=phantom, needle=needle)
            if all(c['gel'] > 2000 for c in phantom.values()):
                return shots, phantom, needle
            return None
        try:
            shots, slices, needle = wait_for('the phantom in the three slice panes',
                                             panes_with_phantom_and_needle, seconds=40)
        finally:
            for orientation, png in last.get('shots', {}).items():
                (ARTIFACTS / f'demo-slice-{orientation}.png').write_bytes(png)
            print(f'slice panes, last look: phantom {last.get("phantom")}, needle {last.get("needle")}')
        driver.save_screenshot(str(ARTIFACTS / 'demo-app.png'))
        # Once the phantom is placed at the tip, the panes follow the needle tip while it is inside:
        # each plane then goes through the needle, whose cut (its orange) shows in all three panes
        # at once (the cut shows only when a plane crosses the needle).
        cuts = {}

        def needle_in_every_pane():
            cuts.update({o: orange_pixels(driver.find_element(By.ID, f'slice_{o}').screenshot_as_png) for o in panes})
            return all(n >= 4 for n in cuts.values())
        try:
            wait_for('the needle cut in the three panes', needle_in_every_pane, seconds=45)
        finally:
            driver.save_screenshot(str(ARTIFACTS / 'demo-app-later.png'))
            print(f'needle (orange) pixels in the panes, last look: {cuts}')
        # The whole robot and the phantom in the 3D view (framed again once the phantom is placed):
        # nothing but background on the view's border.
        view = driver.find_element(By.ID, 'view').screenshot_as_png
        (ARTIFACTS / 'demo-view.png').write_bytes(view)
        on_border = pixels_on_the_border(view)
        assert on_border < 5, f'{on_border} pixels of a model on the 3D view\'s border (demo-view.png)'
        output, _ = demo.communicate(timeout=120)  # --duration 60 ends it
    finally:
        driver.quit()
        for process in (demo, sim):
            if process.poll() is None:
                process.kill()
            process.wait()
    assert demo.returncode == 0, output
    assert 'phantom placed at the needle tip' in output, output
    assert '[demo] stopped' in output, output
    print(f'view: {orange} orange pixels, {on_border} model pixels on its border; slice panes (gel/tissue/tumour pixels): {slices}, '
          f'needle (orange) pixels {needle}')
