#!/usr/bin/env python3
"""Takes docs/app.png: the demo's web app (headless Chromium) at a moment the needle tip is in the
pseudotumour (the needle's cut in the three slice panes, the tumour's grey in the sagittal and
coronal ones). Needs a build (ros2vtk-sim-robot, the Python package) and the venv:
    .venv/bin/python scripts/app_screenshot.py [OUT.png]   (default docs/app.png; ROS_DOMAIN_ID, default 93)"""
import os, socket, subprocess, sys, time, urllib.request
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'tests' / 'app'))
import test_demo_app as t
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
env = dict(os.environ, ROS_DOMAIN_ID=os.environ.get('ROS_DOMAIN_ID', '93'), ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONPATH=str(t.BUILD / 'python'))
env.pop('DISPLAY', None)
with socket.socket() as s:
    s.bind(('127.0.0.1', 0)); port = s.getsockname()[1]
OUT = sys.argv[1] if len(sys.argv) > 1 else str(t.REPO / 'docs' / 'app.png')
phantom = t.BUILD / 'test-artifacts' / 'phantom.mha'
phantom.parent.mkdir(parents=True, exist_ok=True)
subprocess.run([str(t.BUILD / 'runtime/Viewer/ros2vtk-make-phantom'), str(phantom)], check=True, stdout=subprocess.DEVNULL)
sim = subprocess.Popen([str(t.BUILD / 'runtime/Tools/ros2vtk-sim-robot'), '--urdf', str(t.URDF), '--motion', str(t.MOTION)], env=env, stdout=subprocess.DEVNULL)
demo = subprocess.Popen([str(t.VENV_PYTHON), str(t.REPO / 'examples/demo/demo.py'), '--phantom', str(phantom), '--port', str(port), '--duration', '150'], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
o = webdriver.ChromeOptions()
for f in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--window-size=1600,950'): o.add_argument(f)
d = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=o)
try:
    url = f'http://127.0.0.1:{port}/'
    for _ in range(240):
        try:
            urllib.request.urlopen(url, timeout=5); break
        except OSError: time.sleep(0.5)
    d.get(url)
    end = time.monotonic() + 100
    while time.monotonic() < end:
        if len(d.find_elements(By.CSS_SELECTOR, '[id^="slice_"]')) < 3:
            time.sleep(1); continue
        shots = {o: d.find_element(By.ID, f'slice_{o}').screenshot_as_png for o in ('axial', 'sagittal', 'coronal')}
        cuts = {o: t.orange_pixels(p) for o, p in shots.items()}
        tumour = t.phantom_pixels(shots['sagittal'])['tumour']
        # The tip in the tumour: tumour grey in all three panes (the sagittal alone also passed with the
        # tip in the air above the phantom, the tumour at the pane's bottom edge).
        if all(c >= 10 for c in cuts.values()) and tumour > 800 and all(
                t.phantom_pixels(shots[o])['tumour'] > 300 for o in ('axial', 'coronal')):
            d.save_screenshot(OUT); print(f'{OUT}: needle pixels {cuts}, tumour pixels (sagittal) {tumour}'); break
        time.sleep(0.3)
    else:
        sys.exit('no moment with the needle tip in the tumour')
finally:
    d.quit(); demo.kill(); sim.kill()
