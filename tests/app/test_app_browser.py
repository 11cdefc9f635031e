"""The web app in a real browser (Debian's headless Chromium driven by Selenium), against real
peers: the simulated robot (ros2vtk-sim-robot, its own process) and rclpy nodes (tests/interop/
ros_peer.py). The app server (`ros2vtk app`) binds 127.0.0.1 only. Each step keeps a screenshot
in <build>/test-artifacts/app/:
  1. add a robot from the parameter form -> link table filled, the robot's orange appears in the view;
  2. add a subscriber through the form while rclpy publishes -> its count rises, the YAML shows the text;
  3. add a YAML publisher and publish from the form -> the rclpy subscriber receives the text;
  4. save the scene, remove the nodes, reload the page, load the scene -> the same nodes are back.
  5-8. the tf frame tree, a remote node's parameter, YAML on a mapped publisher, the icon font;
  9. closing a tab leaves no traceback in the server's terminal;
  10. a volume file opened from the Volumes section -> the slice panes show it, with the robot's cut;
      the 3D view, smaller now, streams at its new size (the robot whole, nothing cropped);
  10e-f. Slicer's window/level presets; a camera the user moved is kept until "Reset view";
  11. array parameters (integer[], string[], double[]) set from the form -> the rclpy node holds them.
"""
from __future__ import annotations

import importlib.util
import io
import json
import os
import socket
import subprocess
import time
import urllib.request
from pathlib import Path

import pytest
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from view_pictures import pixels_on_the_border

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
ARTIFACTS = BUILD / 'test-artifacts' / 'app'
URDF = REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'
DOMAIN = int(os.environ.get('ROS2VTK_TEST_DOMAIN_BASE', '185')) + 1


def free_port() -> int:
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def wait_for(what: str, check, seconds: float = 60.0, step: float = 0.25):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = check()
        if value:
            return value
        time.sleep(step)
    raise AssertionError(f'timed out after {seconds:g} s waiting for {what}')


def orange_pixels(png: bytes) -> int:
    """Pixels of the surgical arm's 'signal' orange (0.95 0.45 0.1), shaded: nothing else in the
    view (Slicer's blue-grey background) is red-dominant."""
    image = Image.open(io.BytesIO(png)).convert('RGB')
    # 'signal' (0.95 0.45 0.1): green/red ~0.47, blue/red ~0.1 under any shading; the phantom's
    # pseudotumour (0.9 0.3 0.25) has green/red 0.33 and blue/red 0.28.
    return sum(1 for r, g, b in image.get_flattened_data() if r > 100 and 0.38 < g / r < 0.6 and b / r < 0.2)


@pytest.fixture(scope='module')
def world():
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, ROS_DOMAIN_ID=str(DOMAIN), ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST',
               PYTHONUNBUFFERED='1')
    env.pop('ROS_LOCALHOST_ONLY', None)
    processes = []

    def start(args, extra=None, **kwargs):
        process = subprocess.Popen([str(a) for a in args], env=dict(env, **(extra or {})), text=True, **kwargs)
        processes.append(process)
        return process

    start([BUILD / 'runtime' / 'Tools' / 'ros2vtk-sim-robot', '--urdf', URDF, '--rate', '20'],
          stdout=subprocess.DEVNULL)
    port = free_port()
    log = open(ARTIFACTS / 'server.log', 'w')
    server = start([VENV_PYTHON, '-m', 'ros2vtk', 'app', '--port', port], {'PYTHONPATH': str(BUILD / 'python')},
                   stdout=log, stderr=subprocess.STDOUT, cwd=ARTIFACTS)
    url = f'http://127.0.0.1:{port}/'
    options = webdriver.ChromeOptions()
    for flag in ('--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--window-size=1600,1000'):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=options)

    def listening():
        if server.poll() is not None:
            raise AssertionError(f'app server exited: {(ARTIFACTS / "server.log").read_text()[-2000:]}')
        try:
            with urllib.request.urlopen(url, timeout=5) as response:
                return response.status == 200
        except OSError:
            return False
    try:
        wait_for('the app server', listening, seconds=120, step=0.5)
        driver.get(url)
        wait_for('the app page', lambda: driver.find_elements(By.ID, 'robot_add'), seconds=60)
        yield {'driver': driver, 'start': start, 'env': env, 'url': url}
    finally:
        driver.quit()
        for process in reversed(processes):
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
        log.close()


def type_into(driver, element_id: str, text: str) -> None:
    """Types into a Vuetify field as a user does (select all, type), then closes any menu."""
    field = driver.find_element(By.ID, element_id)
    driver.execute_script('arguments[0].scrollIntoView({block: "center"})', field)
    field.click()
    field.send_keys(Keys.CONTROL, 'a')
    field.send_keys(Keys.DELETE)
    field.send_keys(text)
    field.send_keys(Keys.ESCAPE)  # a combobox's list would cover the next field
    assert field.get_attribute('value') == text, f'{element_id}: {field.get_attribute("value")!r}'
    # No wait for the field's model to reach the server: each form button sends its fields with
    # the click (layout.py). Only a menu still closing could take the next click.
    wait_for('menus closed', lambda: not driver.find_elements(By.CSS_SELECTOR, '.v-overlay--active .v-list-item'),
             seconds=10, step=0.05)


def click(driver, element_id: str) -> None:
    button = driver.find_element(By.ID, element_id)
    driver.execute_script('arguments[0].scrollIntoView({block: "center"})', button)
    button.click()


def choose(driver, select_id: str, item: str) -> None:
    """Picks `item` in a Vuetify select (opens its menu, clicks the item)."""
    select = driver.find_element(By.ID, select_id)
    driver.execute_script('arguments[0].scrollIntoView({block: "center"})', select)
    select.find_element(By.XPATH, './ancestor::div[contains(@class, "v-field")][1]').click()  # the input is covered
    option = wait_for(f'{item} in the {select_id} menu', lambda: [o for o in driver.find_elements(
        By.CSS_SELECTOR, '.v-overlay--active .v-list-item') if o.text.strip() == item])
    option[0].click()
    wait_for(f'{select_id} = {item}', lambda: not driver.find_elements(By.CSS_SELECTOR, '.v-overlay--active .v-list-item'),
             step=0.05)  # the choice goes to the server with the form's button, as typed fields do


def row_text(driver, row_id: str) -> str:
    rows = driver.find_elements(By.ID, row_id)
    return rows[0].text if rows else ''


def view_png(driver) -> bytes:
    return driver.find_element(By.ID, 'view').screenshot_as_png


def step_shot(driver, name: str) -> None:
    driver.save_screenshot(str(ARTIFACTS / f'{name}.png'))


def test_1_add_robot_from_parameter_form(world):
    driver = world['driver']
    before = orange_pixels(view_png(driver))
    type_into(driver, 'robot_name', 'arm')
    click(driver, 'robot_source_parameter')
    type_into(driver, 'robot_param_node', '/robot_state_publisher')
    type_into(driver, 'robot_param_name', 'robot_description')
    type_into(driver, 'robot_mesh_base', str(URDF.parent))
    type_into(driver, 'robot_mesh_paths', str(REPO / 'examples' / 'robots'))
    click(driver, 'robot_add')
    row = wait_for('the robot loaded with 8/8 links tracked',
                   lambda: 'loaded' in row_text(driver, 'robot-arm') and '8/8' in row_text(driver, 'robot-arm')
                   and row_text(driver, 'robot-arm'))
    links = driver.find_element(By.TAG_NAME, 'body').text
    for link in ('base_link', 'instrument_link', 'needle_tip'):
        assert link in links, f'link {link} missing from the link table'
    # (The view frames the robot's whole workspace, a sphere of its reach: upright, the arm takes
    # about 40 % of the view's height, and its orange knob and needle guide some 70 pixels.)
    after = wait_for('the robot orange in the view', lambda: orange_pixels(view_png(driver)) > 40 and
                     orange_pixels(view_png(driver)), seconds=60)
    step_shot(driver, '1-robot-added')
    (ARTIFACTS / '1-view.png').write_bytes(view_png(driver))
    assert before < 10, f'orange before the robot was added: {before}'
    print(f'robot row: {row!r}; orange pixels {before} -> {after}')


def test_2_subscriber_from_form_counts_rclpy_messages(world):
    driver = world['driver']
    world['start']([VENV_PYTHON, REPO / 'tests' / 'interop' / 'ros_peer.py', '--node', 'talker', 'pub', '/chatter',
                    'std_msgs/msg/String', json.dumps({'data': 'hello from rclpy'}), '--count', '-1', '--rate', '10',
                    '--wait-matched', '0'], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    click(driver, 'topic_direction_subscriber')
    type_into(driver, 'topic_type', 'String')
    type_into(driver, 'topic_name', '/chatter')
    click(driver, 'topic_add')
    row_id = 'topic-subscriber-/chatter'

    def count():
        cells = driver.find_elements(By.CSS_SELECTOR, f'[id="{row_id}"] td')
        return int(cells[5].text) if len(cells) > 5 and cells[5].text.isdigit() else 0
    first = wait_for('messages counted', count)
    second = wait_for('the count rising', lambda: count() > first + 5 and count())
    yaml = wait_for('the YAML of the last message', lambda: driver.find_elements(By.ID, 'topic_yaml') and
                    driver.find_element(By.ID, 'topic_yaml').text)
    step_shot(driver, '2-subscriber')
    assert 'hello from rclpy' in yaml, yaml
    assert 'std_msgs/msg/String' in row_text(driver, row_id)
    print(f'count {first} -> {second}; yaml {yaml!r}')


def test_3_publish_from_form_reaches_rclpy(world):
    driver = world['driver']
    listener = world['start']([VENV_PYTHON, REPO / 'tests' / 'interop' / 'ros_peer.py', '--node', 'listener', 'echo',
                               '/from_app', 'std_msgs/msg/String', '--count', '1', '--timeout', '60'],
                              stdout=subprocess.PIPE)
    assert json.loads(listener.stdout.readline()) == {'ready': True}
    click(driver, 'topic_direction_publisher')
    type_into(driver, 'topic_type', 'std_msgs/msg/String')
    type_into(driver, 'topic_name', '/from_app')
    click(driver, 'topic_add')
    row_id = 'topic-publisher-/from_app'

    def matched():
        cells = driver.find_elements(By.CSS_SELECTOR, f'[id="{row_id}"] td')
        return len(cells) > 4 and cells[4].text not in ('', '0')
    wait_for('the rclpy subscriber matched', matched)
    type_into(driver, 'publish_yaml', "{data: 'hello from the app'}")
    click(driver, 'publish')
    received = json.loads(listener.stdout.readline())
    step_shot(driver, '3-published')
    assert received == {'data': 'hello from the app'}
    wait_for('the outcome line', lambda: 'Published on /from_app' in driver.find_element(By.ID, 'message').text)


def test_4_save_reload_page_load_scene(world, tmp_path):
    driver = world['driver']
    scene_file = ARTIFACTS / 'scene.xml'
    scene_file.unlink(missing_ok=True)
    type_into(driver, 'scene_file', str(scene_file))
    click(driver, 'scene_save')
    wait_for('the scene file', scene_file.exists)
    saved = {rid: row_text(driver, rid) for rid in ('robot-arm', 'topic-subscriber-/chatter', 'topic-publisher-/from_app')}
    assert all(saved.values()), saved
    # Change the scene so that loading it visibly restores something: remove the robot and the subscriber.
    driver.find_element(By.ID, 'robot-arm').click()
    click(driver, 'robot_remove')
    wait_for('the robot removed', lambda: not driver.find_elements(By.ID, 'robot-arm'))
    driver.find_element(By.ID, 'topic-subscriber-/chatter').click()
    click(driver, 'topic_remove')
    wait_for('the subscriber removed', lambda: not driver.find_elements(By.ID, 'topic-subscriber-/chatter'))
    driver.refresh()
    wait_for('the page again', lambda: driver.find_elements(By.ID, 'scene_load'))
    type_into(driver, 'scene_file', str(scene_file))
    click(driver, 'scene_load')
    for rid in saved:
        wait_for(f'{rid} back after loading', lambda rid=rid: driver.find_elements(By.ID, rid))
    wait_for('the robot loaded again', lambda: 'loaded' in row_text(driver, 'robot-arm'))
    wait_for('the subscriber counting again', lambda: (lambda c: len(c) > 5 and c[5].text not in ('', '0'))(
        driver.find_elements(By.CSS_SELECTOR, '[id="topic-subscriber-/chatter"] td')))
    wait_for('the robot orange in the view again', lambda: orange_pixels(view_png(driver)) > 40, seconds=60)
    step_shot(driver, '4-scene-loaded')


def cells(driver, row_id: str) -> list[str]:
    return [cell.text for cell in driver.find_elements(By.CSS_SELECTOR, f'[id="{row_id}"] td')]


def tf2_msgs_env(env: dict) -> dict:
    """`env` plus what lets an rclpy peer import tf2_msgs (tests/interop/conftest.py builds it
    once), prepended to its paths as the interop tests do."""
    spec = importlib.util.spec_from_file_location('interop_conftest', REPO / 'tests' / 'interop' / 'conftest.py')
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return {key: os.pathsep.join(filter(None, [value, env.get(key)])) for key, value in module.tf2_msgs_env().items()}


def test_5_tf_frame_tree_shows_the_robots_frames_with_ages_and_publishers(world):
    """The tf section lists every frame of our node's buffer as a tree (parent before child,
    indented by depth), each with the age of its newest transform, 'static' for /tf_static, and
    the node that sent it: the simulated robot (node /robot_state_publisher, /tf and /tf_static)
    and an rclpy node (/camera_mount) that publishes one static frame on /tf_static too; each
    static frame is attributed to its own sender. Above: the nodes publishing /tf and /tf_static."""
    driver = world['driver']
    peer = world['start']([VENV_PYTHON, REPO / 'tests' / 'interop' / 'ros_peer.py', '--node', 'camera_mount',
                           'tf_pub', 'world', 'camera', '{"t": [0.5, 0, 1.2], "q": [0, 0, 0, 1]}', '--static',
                           '--seconds', '120'], tf2_msgs_env(world['env']), stdout=subprocess.DEVNULL)
    chain = ['base_link', 'column_link', 'upper_arm_link', 'forearm_link', 'wrist_link', 'instrument_link',
             'needle_guide_link', 'needle_tip']
    wait_for('every frame of the arm in the tf tree',
             lambda: all(driver.find_elements(By.ID, f'tf-frame-{frame}') for frame in chain))
    order = [row.get_attribute('id')[len('tf-frame-'):]
             for row in driver.find_elements(By.CSS_SELECTOR, '[id^="tf-frame-"]')]
    assert [frame for frame in order if frame in chain] == chain, order
    indents = [int(driver.find_element(By.CSS_SELECTOR, f'[id="tf-frame-{frame}"] td').value_of_css_property(
        'padding-left').rstrip('px').split('.')[0]) for frame in chain]
    assert indents == sorted(indents) and len(set(indents)) == len(chain), indents  # one level deeper each
    root = cells(driver, 'tf-frame-base_link')
    assert root[2] == '(root)', root
    column = cells(driver, 'tf-frame-column_link')
    assert column[1] == 'base_link', column
    age = float(column[2].removesuffix(' s'))  # a number of seconds: a moving joint on /tf
    assert age >= 0.0, column
    assert column[4] == '/robot_state_publisher', column
    # The static frames of both publishers of /tf_static, each with its own sender.
    camera = wait_for('the rclpy static frame with its publisher', lambda: (lambda c: len(c) == 5 and c[4] == '/camera_mount' and c)(
        cells(driver, 'tf-frame-camera')), seconds=30)
    assert camera[1] == 'world' and camera[2] == 'static', camera
    tip = cells(driver, 'tf-frame-needle_tip')
    assert tip[1] == 'needle_guide_link' and tip[2] == 'static', tip  # a fixed joint on /tf_static
    assert tip[4] == '/robot_state_publisher', tip
    statics = wait_for('both nodes listed for /tf_static', lambda: (lambda t: '/camera_mount' in t and t)(
        row_text(driver, 'tf-publishers-tf_static')))
    assert statics == '/tf_static published by /camera_mount, /robot_state_publisher', statics
    assert row_text(driver, 'tf-publishers-tf') == '/tf published by /robot_state_publisher'
    assert peer.poll() is None, 'the rclpy tf peer stopped early'
    driver.execute_script('arguments[0].scrollIntoView({block: "start"})',
                          driver.find_element(By.ID, 'tf-publishers-tf'))
    step_shot(driver, '5-tf-tree')
    print(f'tf tree order {order}; column_link {column}; needle_tip {tip}; camera {camera}')


def test_6_set_a_remote_rclpy_nodes_parameter_from_the_form(world):
    """Parameters: set `gain` of an rclpy node (its own process) through its set_parameters
    service; the node reports the new value; a refused value shows the node's reason."""
    driver = world['driver']
    peer = world['start']([VENV_PYTHON, REPO / 'tests' / 'app' / 'param_peer.py', '--node', 'tuner'],
                          stdout=subprocess.PIPE)
    assert json.loads(peer.stdout.readline()) == {'ready': True}
    world['tuner'] = peer  # test 11 sets its arrays
    type_into(driver, 'param_node', '/tuner')
    type_into(driver, 'param_names', 'gain')
    click(driver, 'param_watch')
    wait_for('the watched gain 0.5', lambda: '0.5' in driver.find_element(By.ID, 'parameters').text
             if driver.find_elements(By.ID, 'parameters') else False)
    type_into(driver, 'remote_param_node', '/tuner')
    type_into(driver, 'remote_param_name', 'gain')
    type_into(driver, 'remote_param_value', '1.75')  # the type select's default is double
    click(driver, 'remote_param_set')
    assert json.loads(peer.stdout.readline()) == {'gain': 1.75}  # the rclpy node's own report
    wait_for('the answer shown', lambda: 'gain = 1.75: set' in driver.find_element(By.ID, 'remote_param_result').text)
    wait_for('the watched value following', lambda: '1.75' in driver.find_element(By.ID, 'parameters').text)
    type_into(driver, 'remote_param_value', '-1')
    click(driver, 'remote_param_set')
    result = wait_for('the refusal shown', lambda: (lambda t: 'refused' in t and t)(
        driver.find_element(By.ID, 'remote_param_result').text))
    step_shot(driver, '6-remote-parameter')
    assert 'gain must be >= 0' in result, result
    assert 'gain must be >= 0' in driver.find_element(By.ID, 'message').text
    print(f'remote parameter: {result!r}')


def test_7_publish_yaml_on_a_mapped_posestamped_publisher(world):
    """A publisher added by short name (PoseStamped: a mapped node, no PublishYAML) publishes
    the form's YAML as a typed message: rclpy receives exactly the values, in metres."""
    driver = world['driver']
    listener = world['start']([VENV_PYTHON, REPO / 'tests' / 'interop' / 'ros_peer.py', '--node', 'pose_listener',
                               'echo', '/pose_from_app', 'geometry_msgs/msg/PoseStamped', '--count', '1',
                               '--timeout', '60'], stdout=subprocess.PIPE)
    assert json.loads(listener.stdout.readline()) == {'ready': True}
    click(driver, 'topic_direction_publisher')
    type_into(driver, 'topic_type', 'PoseStamped')
    type_into(driver, 'topic_name', '/pose_from_app')
    click(driver, 'topic_add')
    row_id = 'topic-publisher-/pose_from_app'
    wait_for('the rclpy subscriber matched', lambda: (lambda c: len(c) > 4 and c[4] not in ('', '0'))(
        cells(driver, row_id)))
    assert 'geometry_msgs/msg/PoseStamped' in row_text(driver, row_id)
    prefilled = wait_for('the blank message in the YAML box', lambda: (lambda v: 'position' in v and v)(
        driver.find_element(By.ID, 'publish_yaml').get_attribute('value')))
    type_into(driver, 'publish_yaml', '{header: {frame_id: base_link}, pose: {position: {x: 0.125, y: -0.25, '
                                      'z: 0.5}, orientation: {x: 0.0, y: 0.0, z: 0.0, w: 1.0}}}')
    click(driver, 'publish')
    received = json.loads(listener.stdout.readline())
    step_shot(driver, '7-posestamped-published')
    assert received['header']['frame_id'] == 'base_link', received
    assert received['pose']['position'] == {'x': 0.125, 'y': -0.25, 'z': 0.5}, received
    assert received['pose']['orientation'] == {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}, received
    wait_for('the outcome line', lambda: 'Published on /pose_from_app' in driver.find_element(By.ID, 'message').text)
    print(f'prefilled YAML {prefilled!r}; rclpy received {received}')


def test_8_icon_font_is_served_by_the_app(world):
    """The Material Design Icons font comes from the app server itself (trame-vuetify ships it),
    so icons are glyphs, not boxes, on a machine with no internet."""
    driver = world['driver']
    loaded = driver.execute_async_script(
        'const done = arguments[arguments.length - 1];'
        'document.fonts.load(\'24px "Material Design Icons"\').then('
        '  faces => done(faces.map(f => f.status)), error => done(String(error)));')
    assert loaded and all(status == 'loaded' for status in loaded), loaded
    sources = driver.execute_script(
        "return performance.getEntriesByType('resource').map(e => e.name).filter(n => n.includes('materialdesignicons'))")
    assert sources and all(s.startswith(world['url']) for s in sources), sources
    # A chevron of the expansion panels is drawn with that font (its ::before glyph).
    chevron = driver.find_element(By.CSS_SELECTOR, '.v-expansion-panel-title__icon .mdi')
    family = driver.execute_script("return getComputedStyle(arguments[0], '::before').fontFamily", chevron)
    assert 'Material Design Icons' in family, family
    print(f'icon font faces {loaded}, from {sources}')


def test_9_a_closed_tab_and_the_browser_leave_no_traceback_in_the_terminal(world):
    """A second tab streams the same view; closing it mid-stream is not an error: the server's
    terminal shows no traceback (aiohttp's reset connection) and no 'JS Error' lines (Chromium's
    benign ResizeObserver notice) over the whole session so far."""
    driver = world['driver']
    first = driver.current_window_handle
    driver.switch_to.new_window('tab')
    try:
        driver.get(world['url'])
        wait_for('the view streaming in the second tab', lambda: driver.find_elements(By.ID, 'view') and
                 orange_pixels(view_png(driver)) > 40, seconds=60)
    finally:
        driver.close()
        driver.switch_to.window(first)
    time.sleep(3)  # frames sent to the closed tab fail now, and their tasks are collected
    log = (ARTIFACTS / 'server.log').read_text()
    assert 'Traceback' not in log and 'never retrieved' not in log, log[-3000:]
    assert 'JS Error' not in log, log[-3000:]
    assert orange_pixels(view_png(driver)) > 40  # the first tab still streams


def write_sphere_volume(path: Path) -> None:
    """A 48^3 MetaImage of 5 mm voxels centred on the orange cylinder on the arm's base (120, 120,
    125 mm RAS; it does not move): a bright sphere (1000, radius 60 mm) in a dark block (0), written with
    numpy and VTK's writer. The panes' planes go through the centre, so each cuts the cylinder."""
    import numpy as np
    import vtk
    from vtk.util import numpy_support
    n, spacing = 48, 5.0
    z, y, x = (np.mgrid[:n, :n, :n] - (n - 1) / 2) * spacing
    voxels = np.where(x * x + y * y + z * z <= 60.0 ** 2, 1000, 0).astype(np.int16)
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(spacing, spacing, spacing)
    # A MetaImage's coordinates are LPS (the app reads them as ITK and Slicer do): the centre's
    # x and y are written negated. (The sphere is symmetric: the flip of its axes shows nowhere.)
    image.SetOrigin(*(c - (n - 1) / 2 * spacing for c in (-120.0, -120.0, 125.0)))
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(voxels.ravel(), deep=True, array_type=vtk.VTK_SHORT))
    writer = vtk.vtkMetaImageWriter()
    writer.SetFileName(str(path))
    writer.SetCompression(False)
    writer.SetInputData(image)
    writer.Write()


def bright_disc(png: bytes) -> dict:
    """The sphere's cut in a slice pane: white pixels (the sphere at the top of the automatic
    window) around the pane's centre, in a dark block (most of the pane black; the robot's cut,
    thin lines in its colours, may run anywhere, the pane's corners included)."""
    image = Image.open(io.BytesIO(png)).convert('RGB')
    w, h = image.size
    pixels = list(image.get_flattened_data())
    white = sum(1 for r, g, b in pixels if min(r, g, b) > 200)
    dark = sum(1 for r, g, b in pixels if max(r, g, b) < 60)
    centre = image.getpixel((w // 2, h // 2))
    return {'white_fraction': white / (w * h), 'dark_fraction': dark / (w * h), 'centre': centre}


def wait_for_message(driver, text: str, seconds: float = 60.0) -> str:
    """The footer's outcome line once it contains `text` (the last line seen on a timeout)."""
    seen = []
    try:
        return wait_for(f'{text!r} in the outcome line', lambda: (lambda m: seen.append(m) or (text in m and m))(
            driver.find_element(By.ID, 'message').text), seconds=seconds)
    except AssertionError as error:
        raise AssertionError(f'{error}; last outcome line: {seen[-1] if seen else None!r}') from None


def test_10_open_a_volume_file_into_the_slice_panes(world):
    """Volumes: a MetaImage written here is opened from the panel; the three slice panes appear
    and each shows the sphere's cut as a bright disc in a dark block, with the robot's cut (the
    base's orange cylinder) drawn in its colour. A missing file and a file that is not a volume
    show their error in the panel."""
    driver = world['driver']
    assert not driver.find_elements(By.ID, 'slice_panes')  # no volume yet: no panes
    bad = ARTIFACTS / 'not-a-volume.mha'
    bad.write_text('this is not a MetaImage header\n')
    type_into(driver, 'volume_file', str(ARTIFACTS / 'missing.nrrd'))
    click(driver, 'volume_open')
    wait_for_message(driver, 'Open volume failed: no such file')
    type_into(driver, 'volume_file', str(bad))
    click(driver, 'volume_open')
    wait_for_message(driver, 'not a readable MetaImage file')
    step_shot(driver, '10-volume-errors')
    sphere = ARTIFACTS / 'sphere.mha'
    write_sphere_volume(sphere)
    type_into(driver, 'volume_file', str(sphere))
    click(driver, 'volume_open')
    wait_for_message(driver, 'Volume sphere opened: 48 x 48 x 48')
    wait_for('the slice panes shown', lambda: driver.find_elements(By.ID, 'slice_panes'))
    discs = {}

    def discs_in_every_pane():
        for orientation in ('axial', 'sagittal', 'coronal'):
            png = driver.find_element(By.ID, f'slice_{orientation}').screenshot_as_png
            (ARTIFACTS / f'10-slice-{orientation}.png').write_bytes(png)
            discs[orientation] = bright_disc(png)
        return all(d['white_fraction'] > 0.04 and min(d['centre']) > 200 and d['dark_fraction'] > 0.6
                   for d in discs.values())
    try:
        wait_for('a bright disc in each slice pane', discs_in_every_pane, seconds=30)
    finally:
        step_shot(driver, '10-volume-opened')
        print(f'slice panes: {discs}')
    # The robot's intersection with each plane, drawn in its colour as Slicer draws a needle in a CT:
    # the orange cylinder's cut.
    cuts = {o: orange_pixels(driver.find_element(By.ID, f'slice_{o}').screenshot_as_png)
            for o in ('axial', 'sagittal', 'coronal')}
    print(f'orange (the cylinder cut) in the panes: {cuts}')
    assert all(n >= 4 for n in cuts.values()), cuts
    assert 'sphere (volume, 48x48x48)' in driver.find_element(By.TAG_NAME, 'body').text


def view_fit(driver) -> dict:
    """The 3D view's element size, the size of the image streamed into it (its natural size, in
    device pixels) and the size the browser draws that image at (trame-rca: full width, centred,
    the overflow cut off)."""
    return driver.execute_script(
        "const view = document.getElementById('view'), image = view.querySelector('img');"
        "const box = view.getBoundingClientRect(), drawn = image.getBoundingClientRect();"
        "return {element: [box.width, box.height], streamed: [image.naturalWidth, image.naturalHeight],"
        "        drawn: [drawn.width, drawn.height], ratio: window.devicePixelRatio};")


def view_streamed_at_its_size(driver, fits: list | None = None) -> bool:
    """Whether the image streamed into the 3D view has its element's size (device pixels, within
    1 px) and is drawn within it; each look is appended to `fits`."""
    fit = view_fit(driver)
    if fits is not None:
        fits.append(fit)
    (w, h), (iw, ih), (_, dh) = fit['element'], fit['streamed'], fit['drawn']
    return abs(iw - int(w * fit['ratio'])) <= 1 and abs(ih - int(h * fit['ratio'])) <= 1 and dh <= h + 1


def test_10b_the_3d_view_follows_its_smaller_size_once_the_slice_panes_appear(world):
    """The slice panes took the lower third of the page (test 10): the 3D view's render window
    follows its element's new size (trame-rca reports it; the app's loop, kept free by rendering
    the volume within the frame's time, handles it at once), so the streamed image is the
    element's size and the browser cuts nothing off; the scene is drawn in it. (Before: the view
    kept streaming at its earlier, taller size for 10 s and more, cropped at top and bottom.)"""
    driver = world['driver']
    assert driver.find_elements(By.ID, 'slice_panes'), 'test 10 opened no volume'
    fits = []
    try:
        wait_for('the streamed image at the 3D view\'s size', lambda: view_streamed_at_its_size(driver, fits),
                 seconds=30)
    finally:
        print(f'3D view element, streamed and drawn sizes: first {fits[:1]}, last {fits[-1:]}')
    view = view_png(driver)
    (ARTIFACTS / '10b-view.png').write_bytes(view)
    image = Image.open(io.BytesIO(view)).convert('RGB')
    assert abs(image.height - fits[-1]['element'][1]) <= 1, image.size
    # The robot and the volume: pixels that are not Slicer's blue-dominant background.
    drawn = sum(1 for r, g, b in image.get_flattened_data() if b - max(r, g) < 20)
    assert drawn > 2000, f'{drawn} pixels of the scene in the 3D view (10b-view.png)'


def test_10c_the_swinging_robot_stays_whole_in_the_3d_view(world):
    """The simulated arm swings (its default motion: every joint over 70 % of its range, periods of
    6-10 s) beside the volume of test 10: the view is framed on the robot's workspace (every pose
    within its joint limits) and the volume, so no part of the robot reaches the view's border in
    any of six views taken over 7.5 s, and the camera does not follow the moves (the server frames
    the view no more times during the swing: one terminal line per framing)."""
    driver = world['driver']
    log = ARTIFACTS / 'server.log'
    framed_before = log.read_text().count('[app] 3D view framed')
    on_border = []
    for k in range(6):
        view = view_png(driver)
        (ARTIFACTS / f'10c-swing-{k}.png').write_bytes(view)
        on_border.append(pixels_on_the_border(view))
        time.sleep(1.25)
    framings = [line for line in log.read_text().splitlines() if '[app] 3D view framed' in line]
    print(f'model pixels on the border: {on_border}; framings so far: {framings}')
    assert max(on_border) < 5, f'the robot reaches the 3D view\'s border: {on_border} (10c-swing-k.png)'
    assert framed_before >= 1 and 'robot workspace' in framings[-1], framings
    assert len(framings) == framed_before, f'the camera moved by itself during the swing: {framings[framed_before:]}'


def test_10d_window_and_level_of_the_volume_from_the_panel(world):
    """The Volumes section sets the chosen volume's window/level (vtkROS2VolumeNode.SetWindow/
    SetLevel): with a level far above the sphere's 1000 the panes' centres (the sphere's) go
    dark; text that is no number is refused with its reason; an empty window goes back to the
    scalar range and the white disc returns."""
    driver = world['driver']
    panes = ('axial', 'sagittal', 'coronal')

    def discs():
        return {o: bright_disc(driver.find_element(By.ID, f'slice_{o}').screenshot_as_png) for o in panes}
    type_into(driver, 'volume_window', '100')
    type_into(driver, 'volume_level', '5000')
    click(driver, 'volume_window_level')
    wait_for_message(driver, 'sphere: window 100, level 5000')
    # (The robot's cut stays drawn in its colours around the centre: only the image goes dark.)
    try:
        dark = wait_for('the sphere dark at the centre of each pane (level above it)',
                        lambda: (lambda d: all(max(v['centre']) < 60 for v in d.values()) and d)(discs()), seconds=30)
    finally:
        step_shot(driver, '10d-window-level')
        print(f'panes, last look: {discs()}')
    type_into(driver, 'volume_window', 'wide')
    click(driver, 'volume_window_level')
    wait_for_message(driver, 'Window/level not set: window and level are numbers')
    type_into(driver, 'volume_window', '')
    click(driver, 'volume_window_level')
    wait_for_message(driver, 'window/level from its scalar range')
    back = wait_for('the white disc back in every pane', lambda: (lambda d: all(
        v['white_fraction'] > 0.04 and min(v['centre']) > 200 for v in d.values()) and d)(discs()), seconds=30)
    print(f'panes at level 5000: {dark}; at the scalar range: {back}')


def grey_levels(png: bytes) -> dict:
    """How many pixels of a slice pane are grey (r, g and b within 8 of each other) at each
    level from 10 to 245 (the pane's black background and the sphere's white left out)."""
    image = Image.open(io.BytesIO(png)).convert('RGB')
    levels = {}
    for r, g, b in image.get_flattened_data():
        if max(r, g, b) - min(r, g, b) <= 8 and 10 <= g <= 245:
            levels[g] = levels.get(g, 0) + 1
    return levels


def block_grey(png: bytes) -> tuple[int, float]:
    """The commonest grey level of a slice pane (the sphere volume's block, 0 in the file) and the
    fraction of the pane at that level +-6; (0, 0.0) when no grey is seen (a black block)."""
    levels = grey_levels(png)
    if not levels:
        return 0, 0.0
    image = Image.open(io.BytesIO(png))
    mode = max(levels, key=levels.get)
    near = sum(n for level, n in levels.items() if abs(level - mode) <= 6)
    return mode, near / (image.width * image.height)


def test_10e_window_level_presets_of_slicer(world):
    """The Volumes section's presets (Slicer's VolumeDisplayPresets.json) set the chosen volume's
    window and level: the sphere volume's block (value 0) is drawn at the grey the numbers
    predict, 255 x (0 - (level - window / 2)) / window; 'auto' (the scalar range 0..1000) draws it
    black again. The fields show the preset's numbers."""
    driver = world['driver']
    panes = ('axial', 'sagittal', 'coronal')
    expected = {'CT-Abdomen': (350, 40), 'CT-Bone': (1000, 400), 'CT-Lung': (1400, -500)}
    seen = {}
    for name, (window, level) in expected.items():
        click(driver, f'volume_preset_{name.lower().replace("-", "_")}')
        wait_for_message(driver, f'sphere: window {window}, level {level} ({name})')
        grey = round(255 * (0 - (level - window / 2)) / window)

        def block_at_the_predicted_grey(grey=grey):
            shots = {o: driver.find_element(By.ID, f'slice_{o}').screenshot_as_png for o in panes}
            seen[name] = {o: block_grey(png) for o, png in shots.items()}
            return all(abs(mode - grey) <= 6 and fraction > 0.15 for mode, fraction in seen[name].values())
        try:
            wait_for(f'the block at grey {grey} in every pane ({name})', block_at_the_predicted_grey, seconds=30)
        finally:
            print(f'{name} W{window}/L{level}: block predicted {grey}, seen (grey, fraction) {seen.get(name)}')
        assert driver.find_element(By.ID, 'volume_window').get_attribute('value') == str(window)
        assert driver.find_element(By.ID, 'volume_level').get_attribute('value') == str(level)
        step_shot(driver, f'10e-preset-{name}')
    click(driver, 'volume_preset_auto')
    wait_for_message(driver, 'sphere: window/level from its scalar range')
    wait_for('the block black again (auto: 0 at the bottom of 0..1000)', lambda: all(
        block_grey(driver.find_element(By.ID, f'slice_{o}').screenshot_as_png)[1] < 0.05 for o in panes), seconds=30)
    assert driver.find_element(By.ID, 'volume_window').get_attribute('value') == ''


def framing_lines(log: Path) -> list[str]:
    return [line for line in log.read_text(errors='replace').splitlines() if '[app] 3D view framed' in line]


def test_10f_a_camera_the_user_moved_is_kept_until_reset_view(world):
    """A drag in the 3D view (Selenium's pointer actions, through trame-rca to the render window's
    interactor) rotates the camera; from then on nothing frames the view by itself: neither the
    view's new shape (the browser window narrowed) nor a volume opened (both framed it before).
    "Reset view" frames it at once, and framing is automatic again (the window's width restored:
    framed once more)."""
    from selenium.webdriver.common.action_chains import ActionChains
    driver = world['driver']
    log = ARTIFACTS / 'server.log'
    view = driver.find_element(By.ID, 'view')
    driver.execute_script('arguments[0].scrollIntoView({block: "center"})', view)
    before = view_png(driver)
    ActionChains(driver).move_to_element(view).click_and_hold().move_by_offset(60, 20).pause(0.3) \
        .move_by_offset(60, 20).pause(0.3).release().perform()
    wait_for('the server seeing the user\'s camera', lambda: 'camera moved by the user' in log.read_text(), seconds=20)
    framed = len(framing_lines(log))
    (ARTIFACTS / '10f-dragged.png').write_bytes(view_png(driver))
    size = driver.get_window_size()
    driver.set_window_size(size['width'] - 300, size['height'])
    wait_for('the streamed image at the view\'s new size', lambda: view_streamed_at_its_size(driver), seconds=30)
    second = ARTIFACTS / 'sphere2.mha'
    write_sphere_volume(second)
    type_into(driver, 'volume_file', str(second))
    click(driver, 'volume_open')
    wait_for_message(driver, 'Volume sphere2 opened')
    time.sleep(2)  # several spins and frames: time for a framing, had there been one
    (ARTIFACTS / '10f-kept.png').write_bytes(view_png(driver))
    after_changes = framing_lines(log)
    assert len(after_changes) == framed, f'framed while the user held the camera: {after_changes[framed:]}'
    click(driver, 'volume_remove')
    wait_for_message(driver, 'Volume sphere2 removed')
    click(driver, 'reset_view')
    wait_for('"Reset view" framing the view', lambda: len(framing_lines(log)) == framed + 1, seconds=20)
    driver.set_window_size(size['width'], size['height'])
    wait_for('automatic framing again (the view\'s shape changed back)', lambda: len(framing_lines(log)) >= framed + 2,
             seconds=30)
    step_shot(driver, '10f-reset-view')
    print(f'framings: {framed} before the drag, {len(after_changes)} after the resize and the volume, '
          f'then Reset view and the resize back: {len(framing_lines(log))}; view changed by the drag: '
          f'{before != view_png(driver)}')


def read_json_line(process, seconds: float = 60.0):
    """The next JSON line a peer prints, or an AssertionError after `seconds` (never a hang)."""
    import select
    ready, _, _ = select.select([process.stdout], [], [], seconds)
    assert ready, f'no line from the peer within {seconds:g} s'
    return json.loads(process.stdout.readline())


def test_11_set_array_parameters_from_the_form(world):
    """Parameters: arrays typed as a YAML list. An rclpy node (its own process, started by test 6)
    gets `ids` (integer[]) and `names` (string[]) through its set_parameters service and prints
    the values it now holds; a wrong element type is refused in the panel before anything is
    sent; our own node's double[] parameter is read back by an rclpy parameter client."""
    driver = world['driver']
    peer = world['tuner']
    type_into(driver, 'remote_param_node', '/tuner')

    def set_remote(name: str, kind: str, text: str) -> None:
        type_into(driver, 'remote_param_name', name)
        choose(driver, 'remote_param_type', kind)
        type_into(driver, 'remote_param_value', text)
        click(driver, 'remote_param_set')
    set_remote('ids', 'integer[]', '[4, 5, 6]')
    assert read_json_line(peer) == {'ids': [4, 5, 6]}  # the rclpy node's own value
    wait_for('the answer shown', lambda: 'ids = [4, 5, 6]: set' in driver.find_element(By.ID, 'remote_param_result').text)
    set_remote('names', 'string[]', "[left, 'right arm']")
    assert read_json_line(peer) == {'names': ['left', 'right arm']}
    wait_for('the answer shown', lambda: ": set" in driver.find_element(By.ID, 'remote_param_result').text
             and 'names' in driver.find_element(By.ID, 'remote_param_result').text)
    set_remote('ids', 'integer[]', '[7, eight]')
    refused = wait_for_message(driver, "integer[]: element 1 ('eight') is not a whole number")
    # Our own node: a double[] parameter, read back by rclpy.
    type_into(driver, 'own_param_name', 'weights')
    choose(driver, 'own_param_type', 'double[]')
    type_into(driver, 'own_param_value', '[0.25, 1.5, 3]')
    click(driver, 'own_param_set')
    wait_for_message(driver, 'weights = [0.25, 1.5, 3]')
    step_shot(driver, '11-array-parameters')
    reader = subprocess.run([str(VENV_PYTHON), str(REPO / 'tests' / 'interop' / 'ros_peer.py'), '--node', 'param_reader',
                             'params', '/slicer', '--get', 'weights'], env=world['env'], capture_output=True, text=True,
                            timeout=60)
    got = json.loads(reader.stdout.strip().splitlines()[-1])
    assert got['get'] == {'weights': [0.25, 1.5, 3.0]}, got
    assert peer.poll() is None
    print(f'refused: {refused!r}; our weights read by rclpy: {got["get"]}')


def test_12_sets_on_one_node_wait_in_order_for_its_answer(world):
    """Parameters: a set asked for while an earlier one on the same node waits for its answer is
    queued, not refused. An rclpy node that answers its first set 6 s late: `gain` = 4, then 5
    while 4 waits (queued, one terminal line); the node receives them in that order (it prints
    4.0, then 5.0) and both answers are shown."""
    driver = world['driver']
    peer = world['start']([VENV_PYTHON, REPO / 'tests' / 'app' / 'param_peer.py', '--node', 'slow_tuner',
                           '--slow-first', '6'], stdout=subprocess.PIPE)
    assert read_json_line(peer) == {'ready': True}
    choose(driver, 'remote_param_type', 'double')
    type_into(driver, 'remote_param_node', '/slow_tuner')
    type_into(driver, 'remote_param_name', 'gain')
    for value, state in (('4', 'sent, waiting for the answer'), ('5', 'queued behind the set in flight')):
        type_into(driver, 'remote_param_value', value)
        click(driver, 'remote_param_set')
        wait_for(f'gain = {value}: {state}', lambda value=value, state=state: f'gain = {value}: {state}' in
                 driver.find_element(By.ID, 'remote_param_result').text, seconds=20)
    received = [read_json_line(peer), read_json_line(peer)]
    assert received == [{'gain': 4.0}, {'gain': 5.0}], received
    result = wait_for('the answer to the queued set', lambda: (lambda t: 'gain = 5: set' in t and t)(
        driver.find_element(By.ID, 'remote_param_result').text))
    step_shot(driver, '12-queued-parameter-set')
    log = (ARTIFACTS / 'server.log').read_text(errors='replace')
    assert log.count('[app] parameter set queued behind the one in flight: /slow_tuner: gain = 5') == 1, log[-2000:]
    print(f'rclpy received in order: {received}; last answer {result!r}')
