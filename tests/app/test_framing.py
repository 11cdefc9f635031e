"""ViewFraming (python/ros2vtk/framing.py) and a camera the user moved: the view frames itself
while the camera is where framing left it; once the user drags in the view (mouse events on the
render window's interactor, as the app's RenderWindowArea delivers the browser's), nothing frames
it again (a prop added, the view's shape changed, something outside the framed region) until
frame() ("Reset view"), after which framing is automatic again. No ROS, no robot: plain VTK props."""
from __future__ import annotations

import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get('ROS2VTK_BUILD_DIR', REPO / 'build'))
sys.path.insert(0, str(BUILD / 'python'))

import vtk  # noqa: E402

from ros2vtk.framing import ViewFraming, camera_state  # noqa: E402
from ros2vtk.app.view import RenderWindowArea  # noqa: E402


def sphere_actor(centre, radius=50.0) -> vtk.vtkActor:
    source = vtk.vtkSphereSource()
    source.SetCenter(*centre)
    source.SetRadius(radius)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    return actor


def view():
    """A renderer in a 400 x 300 window whose mouse events go to a trackball style (the app's)."""
    renderer = vtk.vtkRenderer()
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(400, 300)
    window.AddRenderer(renderer)
    renderer.AddActor(sphere_actor((0.0, 0.0, 0.0)))
    return renderer, window, RenderWindowArea(window)


def drag(area: RenderWindowArea, start, end, button='Left') -> None:
    """A mouse drag as the browser sends it: press, moves, release (window pixels)."""
    steps = 5
    area.process_interaction_event({'type': f'{button}ButtonPress', 'x': start[0], 'y': start[1]})
    for k in range(1, steps + 1):
        x = start[0] + (end[0] - start[0]) * k // steps
        y = start[1] + (end[1] - start[1]) * k // steps
        area.process_interaction_event({'type': 'MouseMove', 'x': x, 'y': y})
    area.process_interaction_event({'type': f'{button}ButtonRelease', 'x': end[0], 'y': end[1]})


def test_framing_follows_the_scene_while_the_camera_is_its_own():
    renderer, window, _ = view()
    framing = ViewFraming(None, renderer)
    assert framing.update() and framing.frames == 1  # first frame
    assert not framing.update()  # nothing changed
    renderer.AddActor(sphere_actor((600.0, 0.0, 0.0)))
    assert framing.update() and framing.frames == 2  # a prop shown: framed again
    window.SetSize(300, 400)
    assert framing.update() and framing.frames == 3  # the view's shape changed
    assert not framing.camera_moved_by_user()


def test_a_camera_the_user_moved_is_kept_until_reset_view():
    renderer, window, area = view()
    framing = ViewFraming(None, renderer)
    assert framing.update()
    framed = camera_state(renderer.GetActiveCamera())
    drag(area, (200, 150), (260, 170))  # rotate
    moved = camera_state(renderer.GetActiveCamera())
    assert moved != framed, 'the drag did not move the camera'
    wheel = {'type': 'MouseWheel', 'x': 200, 'y': 150, 'spinY': -1}
    area.process_interaction_event(wheel)  # zoom
    moved = camera_state(renderer.GetActiveCamera())
    # What used to frame the view again: a prop added, the view's shape changed, something drawn
    # outside the framed region. The user's camera stays.
    renderer.AddActor(sphere_actor((0.0, 900.0, 0.0)))
    assert not framing.update()
    window.SetSize(300, 400)
    assert not framing.update()
    renderer.AddActor(sphere_actor((0.0, 0.0, 5000.0)))
    assert not framing.update()
    assert camera_state(renderer.GetActiveCamera()) == moved
    assert framing.camera_moved_by_user() and framing.frames == 1
    # "Reset view": framed at once, and automatic again.
    assert framing.frame() and framing.frames == 2
    assert not framing.camera_moved_by_user()
    window.SetSize(400, 300)
    assert framing.update() and framing.frames == 3


def test_a_pan_is_a_moved_camera_too():
    renderer, _, area = view()
    framing = ViewFraming(None, renderer)
    framing.frame()
    drag(area, (200, 150), (230, 150), button='Middle')  # pan
    renderer.AddActor(sphere_actor((700.0, 0.0, 0.0)))
    assert not framing.update() and framing.camera_moved_by_user()
