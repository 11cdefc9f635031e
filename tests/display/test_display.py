"""The display layer (vtkROS2DisplayManager, vtkROS2SliceView) through the wrapped API, rendered
offscreen (under Xvfb) and checked by actors AND pixels, with real rclpy peers (their own
processes, tests/interop/ros_peer.py) publishing tf, an image and a point cloud.

Every rendered case is saved as a PNG under <build>/display_test_images/ to look at.
"""
from __future__ import annotations

import importlib.util
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
IMAGES = BUILD / 'display_test_images'
VENV_PYTHON = Path(os.environ.get('ROS2VTK_VENV_PYTHON', REPO / '.venv' / 'bin' / 'python'))
PEER = REPO / 'tests' / 'interop' / 'ros_peer.py'

# A base box (grey, 100 mm) and a tool sphere (blue, r 20 mm, 80 mm above the tool frame, so
# it is seen from above); the tool link follows tf base <- tool.
ROBOT = """<robot name="dm">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <link name="base"><visual><geometry><box size="0.1 0.1 0.1"/></geometry><material name="grey"/></visual></link>
  <link name="tool"><visual><origin xyz="0 0 0.08"/><geometry><sphere radius="0.02"/></geometry>
    <material name="blue"/></visual></link>
  <joint name="j" type="floating"><parent link="base"/><child link="tool"/></joint>
</robot>"""


def _interop_conftest():
    spec = importlib.util.spec_from_file_location('interop_conftest', REPO / 'tests' / 'interop' / 'conftest.py')
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope='module')
def vtk():
    import vtk as module
    return module


class View:
    """An offscreen render window with a top-down parallel camera; pixels as numpy."""

    def __init__(self, vtk, size=(300, 300)):
        self.vtk = vtk
        self.renderer = vtk.vtkRenderer()
        self.window = vtk.vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(*size)
        self.window.AddRenderer(self.renderer)

    def top_down(self, center=(0.0, 0.0, 0.0), half_height=200.0):
        camera = self.renderer.GetActiveCamera()
        camera.ParallelProjectionOn()
        camera.SetFocalPoint(*center)
        camera.SetPosition(center[0], center[1], center[2] + 1000.0)
        camera.SetViewUp(0, 1, 0)
        camera.SetParallelScale(half_height)
        self.renderer.ResetCameraClippingRange()

    def pixels(self, name: str) -> np.ndarray:
        """Renders, saves <name>.png and returns the RGB pixels, row 0 at the top."""
        vtk = self.vtk
        self.window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.SetInputBufferTypeToRGB()
        grab.ReadFrontBufferOff()
        grab.Update()
        IMAGES.mkdir(parents=True, exist_ok=True)
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(str(IMAGES / f'{name}.png'))
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        from vtk.util.numpy_support import vtk_to_numpy
        image = grab.GetOutput()
        width, height, _ = image.GetDimensions()
        rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, 3)
        return rgb[::-1]

    def display_point(self, x, y, z):
        """Where VTK projects a world point: (column, row from the top)."""
        coordinate = self.vtk.vtkCoordinate()
        coordinate.SetCoordinateSystemToWorld()
        coordinate.SetValue(x, y, z)
        col, row = coordinate.GetComputedDisplayValue(self.renderer)
        return col, self.window.GetSize()[1] - 1 - row


def mask(rgb: np.ndarray, kind: str) -> np.ndarray:
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    if kind == 'red':
        return (r > 150) & (g < 90) & (b < 90)
    if kind == 'blue':
        return (b > 150) & (r < 90) & (g < 90)
    if kind == 'green':
        return (g > 150) & (r < 200) & (b < 200) & (g > r + 40)
    if kind == 'yellow':
        return (r > 150) & (g > 150) & (b < 90)
    raise ValueError(kind)


def centroid(m: np.ndarray):
    rows, cols = np.nonzero(m)
    return (cols.mean(), rows.mean()) if len(cols) else None


@pytest.fixture
def ros2vtk():
    import ros2vtk as module
    return module


@pytest.fixture
def logic(ros2vtk):
    created = ros2vtk.vtkROS2Logic()
    yield created
    created.GetScene().Clear()


@pytest.fixture
def peers():
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONUNBUFFERED='1')
    env.pop('ROS_LOCALHOST_ONLY', None)
    started: list[subprocess.Popen] = []

    def start(*args: str, tf: bool = False) -> subprocess.Popen:
        run_env = dict(env)
        if tf:
            for key, value in _interop_conftest().tf2_msgs_env().items():
                run_env[key] = os.pathsep.join(filter(None, [value, run_env.get(key)]))
        process = subprocess.Popen([str(VENV_PYTHON), str(PEER), *args], stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, env=run_env)
        started.append(process)
        return process

    yield start
    for process in started:
        if process.poll() is None:
            process.kill()
        process.communicate()


def spin_until(logic, done, seconds=15.0):
    from ros2vtk import spin_until as package_spin_until
    return package_spin_until(logic, done, seconds)


def make_display(ros2vtk, logic, view):
    dm = ros2vtk.vtkROS2DisplayManager()
    dm.SetScene(logic.GetScene())
    dm.SetRenderer(view.renderer)
    return dm


# ------------------------------------------------------------------------------ models, no ROS
def test_model_nodes_added_modified_removed(ros2vtk, logic, vtk):
    view = View(vtk)
    view.top_down()
    dm = make_display(ros2vtk, logic, view)
    scene = logic.GetScene()
    sphere = vtk.vtkSphereSource()
    sphere.SetRadius(40)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    sphere.Update()
    transform = ros2vtk.vtkROS2TransformNode()
    scene.AddNode(transform)
    model = ros2vtk.vtkROS2ModelNode()
    model.SetPolyData(sphere.GetOutput())
    model.SetColor(0, 0, 1)
    scene.AddNode(model)
    model.SetParentTransformNodeID(transform.GetID())
    assert dm.GetActorForNode(model) is None  # drawn on Update, not from the observer
    assert dm.Update() is True
    assert dm.Update() is False               # nothing changed: nothing to do
    actor = dm.GetActorForNode(model)
    assert actor is not None and view.renderer.HasViewProp(actor)
    assert dm.GetNumberOfDisplayedNodes() == 2  # the model and its transform (axes hidden)
    rgb = view.pixels('model_added')
    assert mask(rgb, 'blue').sum() > 500
    assert abs(centroid(mask(rgb, 'blue'))[0] - view.display_point(0, 0, 0)[0]) < 3

    # Moving the parent transform moves the actor.
    matrix = vtk.vtkMatrix4x4()
    matrix.SetElement(0, 3, 120.0)
    transform.SetMatrixTransformToParent(matrix)
    assert dm.Update() is True
    assert actor.GetUserMatrix().GetElement(0, 3) == 120.0
    rgb = view.pixels('model_moved')
    assert abs(centroid(mask(rgb, 'blue'))[0] - view.display_point(120, 0, 0)[0]) < 3

    # Display properties: colour, representation, opacity, visibility.
    model.SetColor(1, 1, 0)
    model.SetRepresentation(ros2vtk.vtkROS2ModelNode.Wireframe)
    assert dm.Update() is True
    assert actor.GetProperty().GetRepresentation() == vtk.VTK_WIREFRAME
    rgb = view.pixels('model_wireframe_yellow')
    assert mask(rgb, 'yellow').sum() > 50 and mask(rgb, 'blue').sum() == 0
    model.SetOpacity(0.25)
    model.VisibilityOff()
    dm.Update()
    assert actor.GetProperty().GetOpacity() == 0.25 and not actor.GetVisibility()
    assert mask(view.pixels('model_hidden'), 'yellow').sum() == 0

    # Removal takes the actor out at once.
    scene.RemoveNode(model)
    assert not view.renderer.HasViewProp(actor)
    assert dm.GetActorForNode(model) is None
    assert dm.Update() is True
    assert dm.GetNumberOfDisplayedNodes() == 1


def test_transform_axes_with_frame_name(ros2vtk, logic, vtk):
    view = View(vtk)
    view.top_down()
    dm = make_display(ros2vtk, logic, view)
    transform = ros2vtk.vtkROS2TransformNode()
    transform.SetName('probe')
    logic.GetScene().AddNode(transform)
    dm.Update()
    prop = dm.GetPropForNode(transform)
    assert prop is not None and not prop.GetVisibility()
    assert not mask(view.pixels('axes_hidden'), 'red').any()
    dm.SetAxesVisible(True)
    dm.SetAxesLength(150)
    assert dm.Update() is True
    rgb = view.pixels('axes_visible')
    # x axis red to the right of the origin, y axis green above it.
    red, green = centroid(mask(rgb, 'red')), centroid(mask(rgb, 'green'))
    origin = view.display_point(0, 0, 0)
    assert red[0] > origin[0] + 20 and abs(red[1] - origin[1]) < 10
    assert green[1] < origin[1] - 20 and abs(green[0] - origin[0]) < 10
    parts = prop.GetParts()
    assert parts.GetItemAsObject(1).GetInput() == 'probe'
    assert dm.GetNodeForProp(parts.GetItemAsObject(0)) == transform  # a picked part -> its node


def test_placeholder_is_drawn_as_a_wireframe_in_the_placeholder_colour(ros2vtk, logic, vtk):
    view = View(vtk)
    view.top_down(half_height=100)
    dm = make_display(ros2vtk, logic, view)
    robot = logic.GetDefaultROS2Node().CreateAndAddRobotNodeFromTopic('ph', '/ph/robot_description', '', '')
    assert robot.LoadRobotDescription("""<robot name="ph"><link name="base"><visual>
        <geometry><mesh filename="missing/part.stl"/></geometry></visual></link></robot>""", '')
    assert robot.GetNumberOfPlaceholders() == 1
    dm.Update()
    actor = dm.GetActorForNode(robot.GetNthModelNode(0))
    assert actor.GetProperty().GetRepresentation() == vtk.VTK_WIREFRAME
    assert actor.GetProperty().GetColor() == dm.GetPlaceholderColor()
    rgb = view.pixels('robot_placeholder')
    magenta = (rgb[..., 0] > 150) & (rgb[..., 1] < 90) & (rgb[..., 2] > 150)
    assert magenta.sum() > 20


# ------------------------------------------------------------------------------ with rclpy peers
def test_robot_link_untracked_then_follows_tf_from_an_rclpy_peer(ros2vtk, logic, vtk, peers):
    view = View(vtk)
    view.top_down()
    dm = make_display(ros2vtk, logic, view)
    robot = logic.GetDefaultROS2Node().CreateAndAddRobotNodeFromTopic('dm', '/dm/robot_description', 'base', '')
    assert robot.LoadRobotDescription(ROBOT, '')
    dm.Update()
    tool_model = robot.GetNthModelNode(1)
    tool = dm.GetActorForNode(tool_model)
    assert tool is not None
    # No tf yet: the tool link is untracked and drawn in the error colour; the base is not.
    assert tool.GetProperty().GetColor() == dm.GetUntrackedColor()
    assert dm.GetActorForNode(robot.GetNthModelNode(0)).GetProperty().GetColor() == (0.5, 0.5, 0.5)
    rgb = view.pixels('robot_untracked')
    assert mask(rgb, 'red').sum() > 100 and mask(rgb, 'blue').sum() == 0

    positions = []
    for n, x in enumerate((0.15, -0.12)):
        peer = peers('--node', f'tf_peer{n}', 'tf_pub', 'base', 'tool',
                     json.dumps({'t': [x, 0.0, 0.0], 'q': [0, 0, 0, 1]}), '--seconds', '30', tf=True)
        link = robot.GetLinkTransformNode('tool')

        def at_x():
            dm.Update()
            return abs(link.GetMatrixTransformToParent().GetElement(0, 3) - x * 1000.0) < 1e-6
        assert spin_until(logic, at_x, 20.0), peer.stderr.read() if peer.poll() is not None else 'no tf'
        dm.Update()
        assert tool.GetProperty().GetColor() == (0.0, 0.0, 1.0)
        assert abs(tool.GetUserMatrix().GetElement(0, 3) - x * 1000.0) < 1e-6
        rgb = view.pixels(f'robot_tool_at_{int(x * 1000)}mm')
        assert mask(rgb, 'red').sum() == 0
        blue = centroid(mask(rgb, 'blue'))
        assert blue is not None
        assert abs(blue[0] - view.display_point(x * 1000.0, 0, 80)[0]) < 3
        positions.append(blue[0])
        peer.kill()
        peer.communicate()
    assert positions[0] - positions[1] > 150  # 270 mm to the left, on a 400 mm / 300 px view


# A grey base box and a blue tool sphere (80 mm above its frame) on a prismatic joint along x whose
# range [0.1, 0.2] m excludes 0: its zero configuration puts the tool at x = 100 mm.
FILE_ROBOT = """<robot name="fk">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <link name="base"><visual><geometry><box size="0.05 0.05 0.05"/></geometry><material name="grey"/></visual></link>
  <link name="tool"><visual><origin xyz="0 0 0.08"/><geometry><sphere radius="0.02"/></geometry>
    <material name="blue"/></visual></link>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="tool"/><axis xyz="1 0 0"/>
    <limit lower="0.1" upper="0.2" effort="1" velocity="1"/></joint>
</robot>"""


def test_file_robot_without_tf_drawn_at_its_zero_configuration_then_at_joint_positions(ros2vtk, logic, vtk,
                                                                                       tmp_path):
    view = View(vtk)
    view.top_down()
    dm = make_display(ros2vtk, logic, view)
    urdf = tmp_path / 'fk.urdf'
    urdf.write_text(FILE_ROBOT)
    robot = logic.GetDefaultROS2Node().CreateAndAddRobotNodeFromFile('fk', str(urdf), '', '')
    assert spin_until(logic, lambda: robot.GetLinkPoseStatus('tool') != '')
    assert robot.GetLinkPoseStatus('tool') == 'zero configuration (no tf)'
    dm.Update()
    rgb = view.pixels('robot_file_zero_configuration')
    # Not at the origin: at the clamped zero (100 mm), in the untracked colour (nothing arrived).
    red = centroid(mask(rgb, 'red'))
    assert red is not None and mask(rgb, 'blue').sum() == 0
    assert abs(red[0] - view.display_point(100.0, 0, 80)[0]) < 3
    # Driven by a script (as by /joint_states): its own colour, where the joint puts it.
    assert robot.SetJointPosition('slide', 0.15)
    assert spin_until(logic, lambda: robot.GetLinkPoseStatus('tool') == 'joint positions (no tf)')
    dm.Update()
    rgb = view.pixels('robot_file_joint_position')
    blue = centroid(mask(rgb, 'blue'))
    assert blue is not None and mask(rgb, 'red').sum() == 0
    assert abs(blue[0] - view.display_point(150.0, 0, 80)[0]) < 3


def image_message(width=64, height=48):
    # Left half 40, right half 220: mono8, one byte per pixel.
    data = [40 if col < width // 2 else 220 for row in range(height) for col in range(width)]
    return {'header': {'frame_id': 'camera'}, 'height': height, 'width': width, 'encoding': 'mono8',
            'is_bigendian': 0, 'step': width, 'data': data}


def test_image_slice_shows_the_published_pixels(ros2vtk, logic, vtk, peers):
    view = View(vtk)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('Image', '/display_cam')
    subscriber.SetAttribute('ros2vtk.display.window', '255')
    subscriber.SetAttribute('ros2vtk.display.level', '127.5')
    dm.Update()
    prop = dm.GetPropForNode(subscriber)
    assert prop is not None
    slice_actor = prop.GetParts().GetItemAsObject(0)
    assert not slice_actor.GetVisibility()  # nothing received yet
    peers('pub', '/display_cam', 'sensor_msgs/Image', json.dumps(image_message()), '--count', '-1', '--rate', '5')
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    assert dm.Update() is True
    assert slice_actor.GetVisibility()
    bounds = slice_actor.GetBounds()
    assert bounds[1] - bounds[0] == 63 and bounds[3] - bounds[2] == 47
    view.top_down(center=(31.5, 23.5, 0), half_height=30)
    rgb = view.pixels('image_slice')
    for x, value in ((12, 40), (52, 220)):
        col, row = (int(round(v)) for v in view.display_point(x, 23.5, 0))
        assert list(rgb[row, col]) == [value] * 3, (x, rgb[row, col])

    # The same subscriber as the volume of a slice view (axial, through the image's plane).
    slice_view = View(vtk, size=(200, 200))
    slices = ros2vtk.vtkROS2SliceView()
    slices.SetRenderer(slice_view.renderer)
    slices.SetVolumeNode(subscriber)
    slices.SetWindowLevel(255, 127.5)
    slices.SetSliceCenter(31.5, 23.5, 0)
    assert slices.Update() is True
    rgb = slice_view.pixels('image_slice_view')
    for x, value in ((12, 40), (52, 220)):
        col, row = (int(round(v)) for v in slice_view.display_point(x, 23.5, 0))
        assert list(rgb[row, col]) == [value] * 3, (x, rgb[row, col])


def test_point_cloud_shows_its_points(ros2vtk, logic, vtk, peers):
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    dm.SetPointSize(9)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('PointCloud', '/display_cloud')
    points = [(0.1, 0.0), (-0.1, 0.05), (0.0, -0.1)]
    message = {'header': {'frame_id': 'base'},
               'points': [{'x': x, 'y': y, 'z': 0.0} for x, y in points]}
    peers('pub', '/display_cloud', 'sensor_msgs/PointCloud', json.dumps(message), '--count', '-1', '--rate', '5')
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    actor = dm.GetActorForNode(subscriber)
    assert actor is not None and actor.GetMapper().GetInput().GetNumberOfVerts() == 3
    rgb = view.pixels('point_cloud')
    green = mask(rgb, 'green')
    for x, y in points:
        col, row = (int(round(v)) for v in view.display_point(x * 1000.0, y * 1000.0, 0))
        assert green[row - 2:row + 3, col - 2:col + 3].any(), (x, y)
    assert green.sum() < 3 * 200  # points, not a surface


def test_pose_array_shows_one_arrow_per_pose(ros2vtk, logic, vtk, peers):
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('PoseArray', '/display_poses')
    message = {'header': {'frame_id': 'base'},
               'poses': [{'position': {'x': 0.05 * i, 'y': 0.0, 'z': 0.0},
                          'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}} for i in (-1, 1)]}
    peers('pub', '/display_poses', 'geometry_msgs/PoseArray', json.dumps(message), '--count', '-1', '--rate', '5')
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    actor = dm.GetActorForNode(subscriber)
    glyphs = actor.GetMapper().GetInputAlgorithm()
    assert glyphs.GetInput().GetNumberOfPoints() == 2
    rgb = view.pixels('pose_array')
    orange = (rgb[..., 0] > 150) & (rgb[..., 1] < 120) & (rgb[..., 2] < 90)
    # Each arrow starts at its pose and points along +x (50 mm long).
    for x in (-50.0, 50.0):
        col, row = (int(round(v)) for v in view.display_point(x + 25.0, 0, 0))
        assert orange[row - 2:row + 3, col - 2:col + 3].any(), x


def marker(ns, marker_id, kind, x, rgba, size=0.04):
    return {'header': {'frame_id': 'base'}, 'ns': ns, 'id': marker_id, 'type': kind, 'action': 0,
            'pose': {'position': {'x': x, 'y': 0.0, 'z': 0.0}, 'orientation': {'w': 1.0}},
            'scale': {'x': size, 'y': size, 'z': size},
            'color': dict(zip('rgba', rgba))}


def test_marker_array_shows_filled_shapes_in_their_colours(ros2vtk, logic, vtk, peers):
    """A MarkerArray subscriber (as the web app adds one) is drawn by the display manager as its
    markers' shapes, filled, each in its own RGBA colour: a red 40 mm cube left of the origin and
    a blue 40 mm sphere right of it (visualization_msgs/Marker CUBE 1, SPHERE 2), from rclpy."""
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/display_markers')
    message = {'markers': [marker('shapes', 1, 1, -0.05, (1.0, 0.0, 0.0, 1.0)),
                           marker('shapes', 2, 2, 0.05, (0.0, 0.0, 1.0, 1.0))]}
    peers('pub', '/display_markers', 'visualization_msgs/MarkerArray', json.dumps(message), '--count', '-1',
          '--rate', '5')
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    actor = dm.GetActorForNode(subscriber)
    assert actor is not None and actor.GetMapper().GetInput().GetNumberOfPolys() > 0
    rgb = view.pixels('marker_array')
    for kind, x in (('red', -50.0), ('blue', 50.0)):
        found = mask(rgb, kind)
        col, row = (int(round(v)) for v in view.display_point(x, 0, 0))
        assert found[row - 2:row + 3, col - 2:col + 3].all(), (kind, x)
        # Filled: a 40 mm cube seen from above is 40 x 40 px here (1 px per mm); the sphere's disc
        # about 1257 px, of which the lit middle passes the colour mask. Points would be a few.
        assert found.sum() > 600, (kind, found.sum())
        cx, cy = centroid(found)
        assert abs(cx - col) < 3 and abs(cy - row) < 3, (kind, cx, cy, col, row)



def test_marker_per_point_colours_and_a_two_point_arrow_are_drawn(ros2vtk, logic, vtk, peers):
    """RViz's per-point colours and point-to-point arrow, as drawn: a CUBE_LIST of two 40 mm
    cubes at x -50 and +50 mm whose `colors` are red and blue (its `color` yellow, unused), and a
    green ARROW from (-60, 60) to (60, 60) mm (shaft 10 mm, head 20 mm wide and long) whose pose
    is the origin: green along y 60 mm, none at its pose."""
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/display_colours')
    cubes = dict(marker('colours', 1, 6, 0.0, (1.0, 1.0, 0.0, 1.0)),
                 points=[{'x': -0.05, 'y': 0.0, 'z': 0.0}, {'x': 0.05, 'y': 0.0, 'z': 0.0}],
                 colors=[{'r': 1.0, 'g': 0.0, 'b': 0.0, 'a': 1.0}, {'r': 0.0, 'g': 0.0, 'b': 1.0, 'a': 1.0}])
    arrow = dict(marker('colours', 2, 0, 0.0, (0.0, 1.0, 0.0, 1.0)),
                 points=[{'x': -0.06, 'y': 0.06, 'z': 0.0}, {'x': 0.06, 'y': 0.06, 'z': 0.0}],
                 scale={'x': 0.01, 'y': 0.02, 'z': 0.02})
    peers('pub', '/display_colours', 'visualization_msgs/MarkerArray', json.dumps({'markers': [cubes, arrow]}),
          '--count', '-1', '--rate', '5')
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    rgb = view.pixels('marker_per_point_colours')
    assert not mask(rgb, 'yellow').any()
    for kind, x, y in (('red', -50.0, 0.0), ('blue', 50.0, 0.0), ('green', -40.0, 60.0), ('green', 45.0, 60.0)):
        col, row = (int(round(v)) for v in view.display_point(x, y, 0))
        assert mask(rgb, kind)[row - 1:row + 2, col - 1:col + 2].all(), (kind, x, y)
    green = mask(rgb, 'green')
    col, row = (int(round(v)) for v in view.display_point(0, 20.0, 0))
    assert not green[row - 3:row + 4, col - 3:col + 4].any()  # nothing drawn from the pose
    # The arrow spans x -60..60 mm (about 1 px per mm), no more.
    cols = np.nonzero(green.any(axis=0))[0]
    left, right = (view.display_point(x, 60.0, 0)[0] for x in (-60.0, 60.0))
    assert abs(cols.min() - left) <= 3 and abs(cols.max() - right) <= 3, (cols.min(), cols.max(), left, right)


def _wait_drawn(logic, dm, view, name, done, seconds=10.0):
    """Spins, updates the display and renders until done(pixels) holds; the last pixels."""
    import time
    deadline = time.monotonic() + seconds
    while True:
        logic.Spin()
        dm.Update()
        rgb = view.pixels(name)
        if done(rgb) or time.monotonic() > deadline:
            return rgb
        time.sleep(0.05)


def test_marker_lifetime_removes_the_marker_after_it_on_the_node_clock(ros2vtk, logic, vtk, peers):
    """RViz's `lifetime`: a red cube sent once with lifetime 1.5 s is drawn, then disappears with
    no further message (spins alone expire it); a blue sphere with lifetime 0 stays. rclpy sends
    the one MarkerArray."""
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/display_lifetime')
    red = marker('life', 1, 1, -0.05, (1.0, 0.0, 0.0, 1.0))
    red['lifetime'] = {'sec': 1, 'nanosec': 500_000_000}
    message = {'markers': [red, marker('life', 2, 2, 0.05, (0.0, 0.0, 1.0, 1.0))]}
    peers('pub', '/display_lifetime', 'visualization_msgs/MarkerArray', json.dumps(message))
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    rgb = view.pixels('marker_lifetime_drawn')
    assert mask(rgb, 'red').sum() > 600 and mask(rgb, 'blue').sum() > 600
    rgb = _wait_drawn(logic, dm, view, 'marker_lifetime_gone', lambda p: mask(p, 'red').sum() == 0)
    assert mask(rgb, 'red').sum() == 0, 'the cube outlived its lifetime'
    assert mask(rgb, 'blue').sum() > 600, 'the marker with lifetime 0 must stay'
    assert subscriber.GetNumberOfMessages() == 1  # gone by spinning alone


def test_text_marker_is_drawn_at_its_pose_facing_the_camera(ros2vtk, logic, vtk, peers):
    """TEXT_VIEW_FACING: yellow text 50 mm high centred at (0, 60 mm, 0), beside a red cube; seen
    from above AND from the side it shows text pixels there (text lying in a plane of the marker
    would be edge-on from one of the two)."""
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/display_text')
    text = marker('text', 1, 9, 0.0, (1.0, 1.0, 0.0, 1.0), size=0.05)
    text['pose']['position']['y'] = 0.06
    text['text'] = 'ROS'
    message = {'markers': [text, marker('text', 2, 1, -0.08, (1.0, 0.0, 0.0, 1.0))]}
    peers('pub', '/display_text', 'visualization_msgs/MarkerArray', json.dumps(message))
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    assert subscriber.GetLastConversionError() == ''
    col, row = (int(round(v)) for v in view.display_point(0.0, 60.0, 0.0))
    for name in ('marker_text_top', 'marker_text_side'):
        if name == 'marker_text_side':
            camera = view.renderer.GetActiveCamera()
            camera.SetPosition(0.0, -1000.0, 0.0)
            camera.SetFocalPoint(0.0, 0.0, 0.0)
            camera.SetViewUp(0, 0, 1)
            view.renderer.ResetCameraClippingRange()
            dm.Update()
            col, row = (int(round(v)) for v in view.display_point(0.0, 60.0, 0.0))
        rgb = view.pixels(name)
        found = mask(rgb, 'yellow')
        assert found.sum() > 150, (name, found.sum())
        cx, cy = centroid(found)
        # Centred on its position; three capitals 50 mm high are about 50 px high here.
        assert abs(cx - col) < 25 and abs(cy - row) < 15, (name, cx, cy, col, row)
        rows = np.nonzero(found.any(axis=1))[0]
        assert 35 <= rows.max() - rows.min() + 1 <= 65, (name, rows.min(), rows.max())
        assert mask(rgb, 'red').sum() > 300, name


def drawn_markers(dm, subscriber) -> list:
    """What the display draws for `subscriber`: per marker of its actor's poly data (MarkerIndex
    order), [RGBA of its first point, centre of its cells' bounds (mm, world)]."""
    actor = dm.GetActorForNode(subscriber)
    drawn = actor.GetMapper().GetInput()
    index = drawn.GetCellData().GetArray('MarkerIndex')
    color = drawn.GetPointData().GetScalars()
    boxes, colors = {}, {}
    for cell in range(drawn.GetNumberOfCells() if index is not None else 0):
        marker_index = int(index.GetValue(cell))
        ids = drawn.GetCell(cell).GetPointIds()
        colors.setdefault(marker_index, [int(color.GetComponent(ids.GetId(0), c)) for c in range(4)])
        box = boxes.setdefault(marker_index, [float('inf'), float('-inf')] * 3)
        for i in range(ids.GetNumberOfIds()):
            p = drawn.GetPoint(ids.GetId(i))
            for axis in range(3):
                box[2 * axis] = min(box[2 * axis], p[axis])
                box[2 * axis + 1] = max(box[2 * axis + 1], p[axis])
    # The actor's own matrix places the poly data (the subscriber's parent transform): identity here.
    matrix = actor.GetUserMatrix()
    assert all(matrix.GetElement(i, j) == (1.0 if i == j else 0.0) for i in range(4) for j in range(4))
    return [[colors[k], [0.5 * (boxes[k][2 * a] + boxes[k][2 * a + 1]) for a in range(3)]]
            for k in sorted(boxes)]


def assert_markers(found, expected, tol=0.5):
    """`found` (drawn_markers) is `expected`: [[RGBA, [x, y, z] mm], ...] in (ns, id) order."""
    assert len(found) == len(expected), (found, expected)
    for (color, centre), (want_color, want_centre) in zip(found, expected):
        assert color == want_color, (found, expected)
        assert all(abs(a - b) <= tol for a, b in zip(centre, want_centre)), (found, expected)


RED, GREEN, BLUE, YELLOW = [255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 0, 255]


def frame_marker(marker_id, frame, x, rgba, locked=False):
    m = marker('frames', marker_id, 1, x, rgba)  # CUBE, 40 mm
    m['header'] = {'frame_id': frame}
    m['frame_locked'] = locked
    return m


def test_markers_are_drawn_in_their_own_frames_and_frame_locked_ones_follow_tf(ros2vtk, logic, vtk, peers,
                                                                                tmp_path):
    """RViz's marker frames, on a plain Marker topic: with the subscriber's fixed frame 'world',
    each marker is drawn at its header frame's pose from tf (rclpy broadcasts world -> fa static at
    x 100 mm and world -> fb at y 50 mm). Red cube in fa; green in fb, frame_locked; blue in fb
    (x -60 mm in it), not locked; yellow in 'nowhere' is not drawn and its status says so. When fb
    moves to y 120 mm the green cube follows on spins alone, the blue stays where it arrived."""
    view = View(vtk)
    view.top_down(half_height=200)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('Marker', '/display_marker_frames')
    subscriber.SetFixedFrame('world')
    peers('tf_pub', 'world', 'fa', json.dumps({'t': [0.1, 0, 0], 'q': [0, 0, 0, 1]}), '--static',
          '--seconds', '30', tf=True)
    fb = peers('tf_pub', 'world', 'fb', json.dumps({'t': [0, 0.05, 0], 'q': [0, 0, 0, 1]}), '--seconds', '30',
               tf=True)
    markers = [frame_marker(1, 'fa', 0.0, (1.0, 0.0, 0.0, 1.0)),
               frame_marker(2, 'fb', 0.0, (0.0, 1.0, 0.0, 1.0), locked=True),
               frame_marker(3, 'fb', -0.06, (0.0, 0.0, 1.0, 1.0)),
               frame_marker(4, 'nowhere', 0.0, (1.0, 1.0, 0.0, 1.0))]
    peers('pub', '/display_marker_frames', 'visualization_msgs/Marker', json.dumps(markers), '--list',
          '--rate', '20')

    def placed():
        logic.Spin()
        dm.Update()
        return subscriber.GetNumberOfMessages() == 4 and len(drawn_markers(dm, subscriber)) == 3
    assert spin_until(logic, placed, 20.0), (subscriber.GetNumberOfMessages(), subscriber.GetLastConversionError())
    assert_markers(drawn_markers(dm, subscriber), [[RED, [100, 0, 0]], [GREEN, [0, 50, 0]], [BLUE, [-60, 50, 0]]])
    assert subscriber.GetFrameStatus().startswith("marker (ns 'frames', id 4): No transform from [nowhere] to "
                                                  "[world]"), subscriber.GetFrameStatus()
    subscriber.GetLastMessage()
    assert 'No transform from [nowhere] to [world]' in subscriber.GetLastConversionError()
    rgb = view.pixels('marker_frames')
    for kind, x, y in (('red', 100, 0), ('green', 0, 50), ('blue', -60, 50)):
        col, row = (int(round(v)) for v in view.display_point(x, y, 0))
        assert mask(rgb, kind)[row - 2:row + 3, col - 2:col + 3].all(), (kind, x, y)
    assert mask(rgb, 'yellow').sum() == 0

    # fb moves (a new rclpy broadcaster; no marker message is sent again).
    fb.kill()
    peers('tf_pub', 'world', 'fb', json.dumps({'t': [0, 0.12, 0], 'q': [0, 0, 0, 1]}), '--seconds', '30', tf=True)

    def moved():
        logic.Spin()
        dm.Update()
        found = drawn_markers(dm, subscriber)
        return len(found) == 3 and abs(found[1][1][1] - 120) < 0.5
    assert spin_until(logic, moved, 20.0), drawn_markers(dm, subscriber)
    assert_markers(drawn_markers(dm, subscriber), [[RED, [100, 0, 0]], [GREEN, [0, 120, 0]], [BLUE, [-60, 50, 0]]])
    assert subscriber.GetNumberOfMessages() == 4
    rgb = view.pixels('marker_frames_moved')
    col, row = (int(round(v)) for v in view.display_point(0, 120, 0))
    assert mask(rgb, 'green')[row - 2:row + 3, col - 2:col + 3].all()

    # The fixed frame is saved with the scene, only where it is set, and read back.
    other = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('Marker', '/display_marker_plain')
    text = logic.GetScene().WriteToXMLString()
    assert text.count('fixedFrame=') == 1 and 'fixedFrame="world"' in text, text
    logic.GetDefaultROS2Node().RemoveAndDeleteSubscriberNode(other.GetTopic())
    restored = ros2vtk.vtkROS2Logic()
    assert restored.GetScene().ReadFromXMLString(text)
    again = restored.GetDefaultROS2Node().GetSubscriberNodeByTopic('/display_marker_frames')
    assert again is not None and again.GetFixedFrame() == 'world'
    restored.GetScene().Clear()


def test_marker_topic_keeps_markers_by_namespace_and_id(ros2vtk, logic, vtk, peers):
    """A plain Marker topic is kept as RViz keeps it, by (ns, id): rclpy sends, a third of a second
    apart, ADD s/1 red at x -50 mm, ADD s/2 blue at x 50 mm, DELETE s/1, ADD s/2 again at y 60 mm
    (replaces it), DELETEALL, ADD t/5 green at the origin. After each message the display draws
    exactly the markers RViz would, where it would."""
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('Marker', '/display_marker_keys')
    view.pixels('marker_keys_empty')  # the first render is slow (shaders): not between two messages
    moved_blue = marker('s', 2, 2, 0.0, (0.0, 0.0, 1.0, 1.0))
    moved_blue['pose']['position']['y'] = 0.06
    messages = [marker('s', 1, 1, -0.05, (1.0, 0.0, 0.0, 1.0)), marker('s', 2, 2, 0.05, (0.0, 0.0, 1.0, 1.0)),
                dict(marker('s', 1, 1, 0.0, (0, 0, 0, 0)), action=2), moved_blue,
                dict(marker('', 0, 1, 0.0, (0, 0, 0, 0)), action=3), marker('t', 5, 1, 0.0, (0.0, 1.0, 0.0, 1.0))]
    peers('pub', '/display_marker_keys', 'visualization_msgs/Marker', json.dumps(messages), '--list',
          '--rate', '3')
    expected = [[[RED, [-50, 0, 0]]],
                [[RED, [-50, 0, 0]], [BLUE, [50, 0, 0]]],
                [[BLUE, [50, 0, 0]]],
                [[BLUE, [0, 60, 0]]],
                [],
                [[GREEN, [0, 0, 0]]]]
    seen = []
    import time
    deadline = time.monotonic() + 25.0
    while len(seen) < len(expected) and time.monotonic() < deadline:
        logic.Spin()
        count = subscriber.GetNumberOfMessages()
        if count != len(seen):
            assert count == len(seen) + 1, f'two messages in one spin: {count} after {len(seen)}'
            dm.Update()
            seen.append(drawn_markers(dm, subscriber))
            if count == 3:
                rgb = view.pixels('marker_keys_deleted')
                assert mask(rgb, 'red').sum() == 0 and mask(rgb, 'blue').sum() > 600
        time.sleep(0.01)
    assert len(seen) == len(expected), seen
    for found, want in zip(seen, expected):
        assert_markers(found, want)
    assert subscriber.GetLastConversionError() == ''


def _cube_package(vtk, folder: Path) -> Path:
    """<folder>/cubes (a ROS package) with meshes/cube.stl, a 1 m cube (scaled by the marker)."""
    package = folder / 'cubes'
    (package / 'meshes').mkdir(parents=True)
    (package / 'package.xml').write_text('<package format="3"><name>cubes</name></package>')
    source = vtk.vtkCubeSource()
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    writer = vtk.vtkSTLWriter()
    writer.SetFileName(str(package / 'meshes' / 'cube.stl'))
    writer.SetInputConnection(triangles.GetOutputPort())
    writer.Write()
    return package


def test_mesh_resource_marker_is_drawn_in_its_colour_and_a_bad_uri_is_refused(
        ros2vtk, logic, vtk, peers, tmp_path, monkeypatch):
    """MESH_RESOURCE: package://cubes/meshes/cube.stl (found through ROS_PACKAGE_PATH, as a robot's
    meshes are) scaled to 40 mm, drawn in the marker's green; a URI leaving the package and a
    missing file are refused with a reason naming them, while the other markers still draw."""
    _cube_package(vtk, tmp_path)
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(tmp_path))
    (tmp_path.parent / 'outside.stl').write_bytes((tmp_path / 'cubes' / 'meshes' / 'cube.stl').read_bytes())
    view = View(vtk)
    view.top_down(half_height=150)
    dm = make_display(ros2vtk, logic, view)
    subscriber = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/display_mesh')

    def mesh(marker_id, x, uri):
        m = marker('mesh', marker_id, 10, x, (0.0, 1.0, 0.0, 1.0))
        m['mesh_resource'] = uri
        return m

    message = {'markers': [mesh(1, 0.0, 'package://cubes/meshes/cube.stl'),
                           mesh(2, 0.08, 'package://cubes/../../outside.stl'),
                           mesh(3, -0.08, 'package://cubes/meshes/missing.stl'),
                           marker('mesh', 4, 1, 0.0, (1.0, 0.0, 0.0, 1.0))]}
    message['markers'][3]['pose']['position']['y'] = 0.08
    peers('pub', '/display_mesh', 'visualization_msgs/MarkerArray', json.dumps(message))
    assert spin_until(logic, lambda: subscriber.GetNumberOfMessages() > 0, 20.0)
    dm.Update()
    error = subscriber.GetLastConversionError()
    assert 'outside.stl' in error, error  # the first refusal of the spin is reported
    rgb = view.pixels('marker_mesh')
    green = mask(rgb, 'green')
    col, row = (int(round(v)) for v in view.display_point(0.0, 0.0, 0.0))
    assert green[row - 2:row + 3, col - 2:col + 3].all()
    assert 1200 < green.sum() < 2000, green.sum()  # one 40 x 40 mm cube at 1 px per mm
    cx, cy = centroid(green)
    assert abs(cx - col) < 3 and abs(cy - row) < 3, (cx, cy, col, row)
    assert mask(rgb, 'red').sum() > 600  # the cube marker beside them still draws
    polydata = dm.GetActorForNode(subscriber).GetMapper().GetInput()
    indices = polydata.GetCellData().GetArray('MarkerIndex')
    assert {int(indices.GetValue(i)) for i in range(indices.GetNumberOfTuples())} == {0, 1}


# ------------------------------------------------------------------------------ slice views
def test_slice_view_draws_the_intersection_of_a_model(ros2vtk, logic, vtk):
    volume = vtk.vtkImageData()
    volume.SetDimensions(101, 101, 101)
    volume.SetOrigin(-50, -50, -50)
    volume.SetSpacing(1, 1, 1)
    volume.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 1)
    from vtk.util.numpy_support import vtk_to_numpy
    values = vtk_to_numpy(volume.GetPointData().GetScalars())
    values[:] = 100
    # A needle: a thin yellow cylinder along z through (20, 0).
    needle_source = vtk.vtkCylinderSource()
    needle_source.SetRadius(3)
    needle_source.SetHeight(200)
    needle_source.SetResolution(24)
    rotate = vtk.vtkTransformPolyDataFilter()  # the cylinder source runs along y
    t = vtk.vtkTransform()
    t.RotateX(90)
    rotate.SetTransform(t)
    rotate.SetInputConnection(needle_source.GetOutputPort())
    rotate.Update()
    holder = ros2vtk.vtkROS2TransformNode()
    logic.GetScene().AddNode(holder)
    needle = ros2vtk.vtkROS2ModelNode()
    needle.SetPolyData(rotate.GetOutput())
    needle.SetColor(1, 1, 0)
    logic.GetScene().AddNode(needle)
    needle.SetParentTransformNodeID(holder.GetID())
    m = vtk.vtkMatrix4x4()
    m.SetElement(0, 3, 20.0)
    holder.SetMatrixTransformToParent(m)

    shots = {}
    for orientation in ('axial', 'sagittal', 'coronal'):
        view = View(vtk, size=(200, 200))
        slices = ros2vtk.vtkROS2SliceView()
        slices.SetRenderer(view.renderer)
        slices.SetScene(logic.GetScene())
        slices.SetImageData(volume)
        slices.SetWindowLevel(255, 127.5)  # grey values shown as they are
        assert slices.SetOrientation(orientation)
        slices.SetSliceCenter(20 if orientation == 'sagittal' else 0, 0, 0)
        assert slices.Update() is True
        assert slices.Update() is False  # nothing moved
        rgb = view.pixels(f'slice_{orientation}')
        shots[orientation] = (view, slices, rgb)
        grey = (rgb[..., 0] == rgb[..., 1]) & (rgb[..., 1] == rgb[..., 2]) & (abs(rgb[..., 0].astype(int) - 100) <= 1)
        assert grey.sum() > 200 * 200 * 0.5  # the slice fills the view
    # Axial: the needle crosses the plane: a ring at (20, 0).
    view, slices, rgb = shots['axial']
    assert slices.GetNumberOfIntersectedModels() == 1
    ring = centroid(mask(rgb, 'yellow'))
    expected = view.display_point(20, 0, 0)
    assert ring is not None and abs(ring[0] - expected[0]) < 2 and abs(ring[1] - expected[1]) < 2
    # Laid out as Slicer does: axial and coronal show +x (patient right) on the left.
    assert ring[0] < 100
    rows, cols = np.nonzero(mask(shots['coronal'][2], 'yellow'))
    assert cols.mean() < 100
    # Coronal (plane y = 0) cuts the needle lengthwise: lines, vertical on the screen.
    view, slices, rgb = shots['coronal']
    rows, cols = np.nonzero(mask(rgb, 'yellow'))
    assert len(rows) and rows.max() - rows.min() > 150 and cols.max() - cols.min() < 20
    # Moving the needle out of the axial plane's way (along x, out of view) and back updates it.
    view, slices, rgb = shots['axial']
    m.SetElement(0, 3, -30.0)
    holder.SetMatrixTransformToParent(m)
    assert slices.Update() is True
    ring = centroid(mask(view.pixels('slice_axial_needle_moved'), 'yellow'))
    assert abs(ring[0] - view.display_point(-30, 0, 0)[0]) < 2
    # A plane beyond the needle's end: nothing to cut.
    slices.SetSliceCenter(0, 0, 150)
    slices.Update()
    assert slices.GetNumberOfIntersectedModels() == 0
    assert not slices.SetOrientation('oblique')


def test_model_representation_is_saved_with_the_scene(ros2vtk, logic):
    model = ros2vtk.vtkROS2ModelNode()
    model.SetRepresentation(ros2vtk.vtkROS2ModelNode.Points)
    logic.GetScene().AddNode(model)
    xml = logic.GetScene().WriteToXMLString()
    assert 'representation="0"' in xml
    restored = ros2vtk.vtkROS2Scene()
    assert restored.ReadFromXMLString(xml)
    assert restored.GetNthNodeByClass(0, 'vtkROS2ModelNode').GetRepresentation() == 0
    assert not restored.ReadFromXMLString(xml.replace('representation="0"', 'representation="7"'))


def test_volume_node_drawn_as_a_volume_when_3d_and_a_slice_when_2d(ros2vtk, logic, vtk):
    view = View(vtk)
    view.top_down(half_height=80)
    dm = make_display(ros2vtk, logic, view)
    # A 3D phantom: a bright ball (r 30 mm) in a dark 101 mm cube centred on the origin.
    ball = vtk.vtkImageData()
    ball.SetDimensions(51, 51, 51)
    ball.SetSpacing(2, 2, 2)
    ball.SetOrigin(-50, -50, -50)
    ball.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 1)
    from vtk.util.numpy_support import vtk_to_numpy
    z, y, x = np.mgrid[-50:51:2, -50:51:2, -50:51:2]
    vtk_to_numpy(ball.GetPointData().GetScalars())[:] = np.where(x * x + y * y + z * z < 900, 255, 0).ravel()
    holder = ros2vtk.vtkROS2TransformNode()
    logic.GetScene().AddNode(holder)
    volume = ros2vtk.vtkROS2VolumeNode()
    volume.SetImageData(ball)
    volume.SetWindow(255)
    volume.SetLevel(127.5)
    logic.GetScene().AddNode(volume)
    volume.SetParentTransformNodeID(holder.GetID())
    assert dm.Update()
    prop = dm.GetPropForNode(volume)
    slice_actor, volume_actor = prop.GetParts().GetItemAsObject(0), prop.GetParts().GetItemAsObject(1)
    assert volume_actor.GetVisibility() and not slice_actor.GetVisibility()
    rgb = view.pixels('volume_3d')
    bright = rgb.sum(axis=2) > 150
    inside = view.display_point(0, 0, 0)
    assert bright[int(inside[1]), int(inside[0])]
    assert not bright[int(view.display_point(45, 45, 0)[1]), int(view.display_point(45, 45, 0)[0])]
    # The parent transform moves it.
    m = vtk.vtkMatrix4x4()
    m.SetElement(0, 3, 40.0)
    holder.SetMatrixTransformToParent(m)
    assert dm.Update()
    assert volume_actor.GetUserMatrix().GetElement(0, 3) == 40.0
    rgb = view.pixels('volume_3d_moved')
    bright = rgb.sum(axis=2) > 150
    cols = np.nonzero(bright)[1]
    assert abs(cols.mean() - view.display_point(40, 0, 0)[0]) < 4
    # A 2D image in a volume node is a slice.
    flat = vtk.vtkImageData()
    flat.SetDimensions(20, 10, 1)
    flat.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 1)
    vtk_to_numpy(flat.GetPointData().GetScalars())[:] = 200
    volume.SetImageData(flat)
    assert dm.Update()
    assert slice_actor.GetVisibility() and not volume_actor.GetVisibility()
    volume.VisibilityOff()
    dm.Update()
    assert not slice_actor.GetVisibility() and not volume_actor.GetVisibility()


def test_slice_view_reslices_a_volume_node_where_its_transform_puts_it(ros2vtk, logic, vtk):
    from vtk.util.numpy_support import vtk_to_numpy
    ball = vtk.vtkImageData()
    ball.SetDimensions(51, 51, 51)
    ball.SetSpacing(2, 2, 2)
    ball.SetOrigin(-50, -50, -50)
    ball.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 1)
    z, y, x = np.mgrid[-50:51:2, -50:51:2, -50:51:2]
    vtk_to_numpy(ball.GetPointData().GetScalars())[:] = np.where(x * x + y * y + z * z < 900, 200, 20).ravel()
    registration = ros2vtk.vtkROS2TransformNode()
    logic.GetScene().AddNode(registration)
    volume = ros2vtk.vtkROS2VolumeNode()
    volume.SetImageData(ball)
    logic.GetScene().AddNode(volume)
    volume.SetParentTransformNodeID(registration.GetID())
    view = View(vtk, size=(200, 200))
    slices = ros2vtk.vtkROS2SliceView()
    slices.SetRenderer(view.renderer)
    slices.SetVolumeNode(volume)
    slices.SetWindowLevel(255, 127.5)
    slices.SetFieldOfView(100)
    slices.SetSliceCenter(0, 0, 0)
    slices.Update()

    def value_at(rgb, x, y):
        col, row = (int(round(v)) for v in view.display_point(x, y, 0))
        return int(rgb[row, col, 0])
    rgb = view.pixels('slice_volume_node')
    assert value_at(rgb, 0, 0) == 200 and value_at(rgb, 40, 0) == 20
    m = vtk.vtkMatrix4x4()
    m.SetElement(0, 3, 40.0)  # the registration moves the phantom 40 mm along x
    registration.SetMatrixTransformToParent(m)
    assert slices.Update() is True
    rgb = view.pixels('slice_volume_node_registered')
    assert value_at(rgb, 40, 0) == 200 and value_at(rgb, 0, 0) == 20
    assert value_at(rgb, -30, 0) == 0  # beyond the moved phantom: nothing
    slices.SetVolumeNode(logic.GetDefaultROS2Node())  # not an image: refused
    assert slices.GetVolumeNode() == volume
