"""The app's 3D view: a VTK render window streamed to the browser through trame-rca.

Debian's VTK 9.1 has no web modules, so trame-vtk's views and trame-rca's own VTK helper (both
import vtkWebCore) cannot be used; `RenderWindowArea` implements trame-rca's area protocol instead:
it reports the image size, resizes the window, renders and reads its pixels, and maps the browser's
mouse events onto the window's interactor. The renderer is filled by the display layer
(`ros2vtk.vtkROS2DisplayManager` when the build has it, otherwise `ModelActors`, a minimal
stand-in that draws the scene's model nodes under their transforms).
"""
from __future__ import annotations

import os
import shutil
import subprocess
import time

import numpy as np
import vtk

from .volumes import image_of

# Slicer's 3D view background (bottom, top), so the view looks as Slicer users know it.
BACKGROUND_BOTTOM = (0.7568, 0.7647, 0.9098)
BACKGROUND_TOP = (0.4549, 0.4706, 0.7451)


def ensure_x_display() -> subprocess.Popen | None:
    """Debian's VTK renders through GLX only: with no DISPLAY, starts an Xvfb server and points
    DISPLAY at it. Returns the Xvfb process (the caller ends it) or None when a display exists."""
    if os.environ.get('DISPLAY'):
        return None
    if not shutil.which('Xvfb'):
        raise RuntimeError('no DISPLAY and no Xvfb: install the Debian package xvfb (scripts/setup.sh does)')
    read_fd, write_fd = os.pipe()
    # -displayfd: Xvfb picks a free display number and writes it to the pipe once it listens.
    process = subprocess.Popen(['Xvfb', '-displayfd', str(write_fd), '-screen', '0', '1920x1080x24', '-nolisten', 'tcp'],
                               pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    number = b''
    deadline = time.monotonic() + 15
    while not number.endswith(b'\n') and time.monotonic() < deadline:
        chunk = os.read(read_fd, 16)
        if not chunk:
            break
        number += chunk
    os.close(read_fd)
    if not number.strip():
        process.kill()
        raise RuntimeError('Xvfb did not start (no display number reported)')
    os.environ['DISPLAY'] = ':' + number.decode().strip()
    return process


def make_display(logic, renderer):
    """The object that keeps `renderer` in step with the logic's scene: the C++ display manager
    when built, otherwise the Python stand-in. Call its Update() after each spin."""
    import ros2vtk
    manager_class = getattr(ros2vtk, 'vtkROS2DisplayManager', None)
    if manager_class is not None:
        manager = manager_class()
        manager.SetScene(logic.GetScene())
        manager.SetRenderer(renderer)
        manager.Update()
        return manager
    return ModelActors(logic.GetScene(), renderer)


class ModelActors:
    """Stand-in display layer until vtkROS2DisplayManager lands: one actor per model node of the
    scene (colour, opacity, per-vertex colours), placed by the node's model-to-world matrix."""

    def __init__(self, scene, renderer):
        self.scene = scene
        self.renderer = renderer
        self.actors = {}

    def Update(self) -> None:  # noqa: N802 (the display manager's VTK-style name)
        models = vtk.vtkCollection()
        self.scene.GetNodesByClass('vtkROS2ModelNode', models)
        present = set()
        for i in range(models.GetNumberOfItems()):
            model = models.GetItemAsObject(i)
            present.add(model.GetID())
            actor = self.actors.get(model.GetID())
            if actor is None or actor.GetMapper().GetInput() is not model.GetPolyData():
                if actor is not None:
                    self.renderer.RemoveActor(actor)
                mapper = vtk.vtkPolyDataMapper()
                mapper.SetInputData(model.GetPolyData())
                mapper.SetScalarVisibility(model.GetScalarVisibility())
                mapper.SetColorModeToDirectScalars()
                actor = vtk.vtkActor()
                actor.SetMapper(mapper)
                actor.SetUserMatrix(vtk.vtkMatrix4x4())
                self.renderer.AddActor(actor)
                self.actors[model.GetID()] = actor
            actor.GetProperty().SetColor(*model.GetColor())
            actor.GetProperty().SetOpacity(model.GetOpacity())
            model.GetMatrixModelToWorld(actor.GetUserMatrix())
            actor.GetUserMatrix().Modified()
            actor.Modified()
        for gone in set(self.actors) - present:
            self.renderer.RemoveActor(self.actors.pop(gone))


class RenderWindowArea:
    """trame-rca's remote controlled area over a plain vtkRenderWindow (no vtkWebCore).

    `frame_rate`: the frames per second the window is rendered for, given to VTK as its desired
    update rate, still or interacting: props that can trade quality for time (a volume's ray
    caster, through vtkSmartVolumeMapper) keep each frame within it. Without it, Mesa's software
    GL took 1-3 s per frame of a volume, and the app's one loop (its panels, the browser's size
    of the view) waited behind each. `render_seconds`: what the last frame took."""

    def __init__(self, render_window: vtk.vtkRenderWindow, style: vtk.vtkInteractorStyle | None = None,
                 frame_rate: float = 10.0):
        self.window = render_window
        self.window.SetOffScreenRendering(1)
        self.interactor = vtk.vtkRenderWindowInteractor()
        self.interactor.SetRenderWindow(render_window)
        self.style = style or vtk.vtkInteractorStyleTrackballCamera()
        self.interactor.SetInteractorStyle(self.style)
        self.interactor.EnableRenderOff()  # frames are rendered when trame-rca asks for one
        # The interactor's styles set the window's rate to one of these two when a drag starts and ends.
        self.interactor.SetDesiredUpdateRate(frame_rate)
        self.interactor.SetStillUpdateRate(frame_rate)
        self.window.SetDesiredUpdateRate(frame_rate)
        self.render_seconds = 0.0
        self.grab = vtk.vtkWindowToImageFilter()
        self.grab.SetInput(render_window)
        self.grab.ReadFrontBufferOff()
        self.grab.ShouldRerenderOff()
        self.grab.SetInputBufferTypeToRGB()
        self.frames = 0

    @property
    def img_cols_rows(self):
        """(rows x cols x 3 uint8 array, cols, rows) of a fresh render, top row first."""
        for renderer in _renderers(self.window):
            renderer.ResetCameraClippingRange()  # moving robots: planes computed once would clip
        started = time.monotonic()
        self.window.Render()
        self.grab.Modified()
        self.grab.Update()
        self.render_seconds = time.monotonic() - started
        image = self.grab.GetOutput()
        cols, rows, _ = image.GetDimensions()
        scalars = image.GetPointData().GetScalars()
        pixels = np.frombuffer(memoryview(scalars), dtype=np.uint8).reshape((rows, cols, -1))
        self.frames += 1
        return np.ascontiguousarray(pixels[::-1]), cols, rows

    def process_resize_event(self, width: int, height: int) -> None:
        self.window.SetSize(int(width), int(height))
        self.interactor.UpdateSize(int(width), int(height))

    def process_interaction_event(self, event: dict) -> None:
        kind = event.get('type', '')
        x, y = int(event.get('x', 0)), int(event.get('y', 0))
        self.interactor.SetEventInformation(x, y, int(bool(event.get('controlKey'))),
                                            int(bool(event.get('shiftKey'))))
        self.interactor.SetAltKey(int(bool(event.get('altKey'))))
        if kind == 'MouseWheel':
            spin = event.get('spinY', event.get('deltaY', 0)) or 0
            self.interactor.InvokeEvent('MouseWheelForwardEvent' if spin < 0 else 'MouseWheelBackwardEvent')
        elif kind in ('MouseMove', 'LeftButtonPress', 'LeftButtonRelease', 'RightButtonPress',
                      'RightButtonRelease', 'MiddleButtonPress', 'MiddleButtonRelease'):
            self.interactor.InvokeEvent(kind + 'Event')


def _renderers(window):
    renderers = window.GetRenderers()
    renderers.InitTraversal()
    renderer = renderers.GetNextItem()
    while renderer is not None:
        yield renderer
        renderer = renderers.GetNextItem()


def make_render_window(size=(1000, 620)):
    """A render window with one renderer on Slicer's gradient background."""
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(*BACKGROUND_BOTTOM)
    renderer.SetBackground2(*BACKGROUND_TOP)
    renderer.GradientBackgroundOn()
    window = vtk.vtkRenderWindow()
    window.SetSize(*size)
    window.AddRenderer(renderer)
    return window, renderer


class SlicePanes:
    """Axial, sagittal and coronal 2D views (Slicer's red, yellow and green) of a volume: the
    chosen source (`set_source`: a vtkROS2VolumeNode), else the scene's first vtkROS2VolumeNode; each a vtkROS2SliceView in its own offscreen window streamed as the 3D
    view is (`areas`, one RenderWindowArea per orientation). The models cut by each slice plane
    (a robot's needle) are drawn on it in their colours. As in Slicer, each pane stays centred
    on the volume and only its plane moves: through `point` (world mm) once a script calls
    set_point, through the volume's centre until then. `follow` (a navigation view: the demo
    follows the tool tip) centres the panes on the point too, zoomed to a field of view."""

    ORIENTATIONS = ('axial', 'sagittal', 'coronal')
    NORMAL_AXIS = {'axial': 2, 'sagittal': 0, 'coronal': 1}

    def __init__(self, scene, size=(360, 300)):
        import ros2vtk
        self.scene = scene
        self.views, self.windows, self.areas, self.centers = {}, {}, {}, {}
        for orientation in self.ORIENTATIONS:
            window, renderer = make_render_window(size)
            renderer.GradientBackgroundOff()
            renderer.SetBackground(0.0, 0.0, 0.0)
            view = ros2vtk.vtkROS2SliceView()
            view.SetRenderer(renderer)
            view.SetScene(scene)
            view.SetOrientation(orientation)
            # Image-style mouse: left drag window/level, right drag zoom, middle pan; no rotation.
            self.areas[orientation] = RenderWindowArea(window, vtk.vtkInteractorStyleImage())
            self.views[orientation], self.windows[orientation] = view, window
        self.volume = None
        self.source_id = ''  # the chosen source's node ID ('' : the scene's first volume node)
        self.point: tuple[float, float, float] | None = None
        self.centred = False  # panes centred on the point (follow) or on the volume
        self.window_level = None  # (window, level) given to the panes

    def set_point(self, x: float, y: float, z: float) -> None:
        """The point (world mm) the three slice planes go through (applied on the next update)."""
        self.point = (float(x), float(y), float(z))
        if self.centred:  # back to the whole volume in each pane
            for view in self.views.values():
                view.SetFieldOfView(0.0)
        self.centred = False

    def follow(self, x: float, y: float, z: float, half_height: float = 80.0) -> None:
        """The three planes through the point and each pane centred on it, `half_height` mm
        from its centre to its top (a navigation view following a tool tip)."""
        self.point = (float(x), float(y), float(z))
        if not self.centred:
            for view in self.views.values():
                view.SetFieldOfView(half_height)
        self.centred = True

    def set_source(self, node_id: str) -> None:
        """The volume node the panes show (by ID); '' for the scene's first volume node. Applied on
        the next update."""
        self.source_id = node_id or ''

    def _image_to_world(self) -> vtk.vtkMatrix4x4:
        """The volume node's parent transform to world (identity without one)."""
        matrix = vtk.vtkMatrix4x4()
        parent = self.volume.GetParentTransformNode() if self.volume is not None and hasattr(
            self.volume, 'GetParentTransformNode') else None
        if parent is not None:
            parent.GetMatrixTransformToWorld(matrix)
        return matrix

    def volume_center(self) -> tuple[float, float, float] | None:
        """The centre of the shown volume in world mm (under its parent transform)."""
        image = image_of(self.volume)
        if image is None:
            return None
        b = image.GetBounds()
        local = [(b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)] + [1.0]
        return tuple(self._image_to_world().MultiplyPoint(local)[:3])

    def clamped_point(self) -> tuple[float, float, float] | None:
        """The point kept one voxel inside the volume (a plane on or beyond its faces would show
        nothing), in world mm."""
        image = image_of(self.volume)
        if image is None or self.point is None:
            return self.point
        to_world = self._image_to_world()
        to_image = vtk.vtkMatrix4x4()
        vtk.vtkMatrix4x4.Invert(to_world, to_image)
        local = to_image.MultiplyPoint((*self.point, 1.0))
        b, spacing = image.GetBounds(), image.GetSpacing()
        inside = [min(max(local[i], b[2 * i] + spacing[i]), b[2 * i + 1] - spacing[i])
                  if b[2 * i + 1] - b[2 * i] > 2 * spacing[i] else (b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)]
        return tuple(to_world.MultiplyPoint((*inside, 1.0))[:3])

    def update(self) -> bool:
        """Follows the scene's first volume node and the point; returns whether a pane changed
        (render then)."""
        volume = self.scene.GetNodeByID(self.source_id) if self.source_id else None
        if volume is None:
            volumes = vtk.vtkCollection()
            self.scene.GetNodesByClass('vtkROS2VolumeNode', volumes)
            volume = volumes.GetItemAsObject(0) if volumes.GetNumberOfItems() else None
        if volume is not self.volume:
            self.volume = volume
            self.centers.clear()
            self.window_level = None
            for view in self.views.values():
                view.SetVolumeNode(volume)
            if volume is None:  # the panes are hidden: no cuts, no renders
                return True
        if volume is None:
            return False
        window = volume.GetWindow() if hasattr(volume, 'GetWindow') else 0.0
        window_level = (window, volume.GetLevel() if window > 0 else 0.0)  # window <= 0: its range
        if window_level != self.window_level:  # the node's window/level, set by a script or the panel
            self.window_level = window_level
            for view in self.views.values():
                view.SetWindowLevel(*window_level)
        middle, point = self.volume_center() or self.point, self.clamped_point()
        if self.centred and point is not None:
            middle = point
        if middle is not None:
            for orientation, view in self.views.items():
                center = list(middle)
                if point is not None:
                    axis = self.NORMAL_AXIS[orientation]
                    center[axis] = point[axis]
                if self.centers.get(orientation) != center:  # a new centre re-renders the pane
                    self.centers[orientation] = center
                    view.SetSliceCenter(*center)
        changed = [view.Update() for view in self.views.values()]  # every view, no short-circuit
        return any(changed)
