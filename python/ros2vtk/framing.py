"""A 3D view framed on what it shows, without a camera that follows every move (as Slicer's and
RViz 2's views behave): the camera frames the robots' workspaces (`vtkROS2RobotNode.
GetWorkspaceSphere`: the robot in every joint position within its limits) together with the bounds
of everything else drawn, and frames again only when something is added or removed, a robot is
(re)loaded or its base moves, something drawn leaves the framed region, or the view's shape
changes. Once the user has moved the camera (rotated, zoomed, panned), the camera is theirs: no
automatic framing at all, not even for a robot or volume added later (Slicer's 3D view keeps the
user's camera too; its "Center view" button brings new data into view), until `frame()` (the
view's "Reset view"), which also turns automatic framing back on. Used by the app's 3D view and by
the demo's --window view."""
from __future__ import annotations

import math

import vtk

VIEW_DIRECTION = (1.0, -1.1, 0.55)  # camera position from the focal point: front-right, z up
VIEW_ANGLE = 30.0  # degrees, vertical

Sphere = tuple  # (x, y, z, radius), world mm


def enclosing_sphere(a: Sphere | None, b: Sphere | None) -> Sphere | None:
    """The smallest sphere holding spheres a and b (either may be None)."""
    if a is None or b is None:
        return a if b is None else b
    distance = math.dist(a[:3], b[:3])
    if distance + b[3] <= a[3]:
        return a
    if distance + a[3] <= b[3]:
        return b
    radius = (distance + a[3] + b[3]) / 2
    t = (radius - a[3]) / distance
    return tuple(p + t * (q - p) for p, q in zip(a[:3], b[:3])) + (radius,)


def box_sphere(bounds) -> Sphere:
    """The sphere through the corners of a box (xmin, xmax, ymin, ymax, zmin, zmax)."""
    centre = tuple((bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3))
    return centre + (math.dist(bounds[0::2], bounds[1::2]) / 2,)


def robot_spheres(scene) -> list:
    """The workspace sphere of every loaded robot of the scene (None: no scene, no robots)."""
    if scene is None:
        return []
    robots = vtk.vtkCollection()
    scene.GetNodesByClass('vtkROS2RobotNode', robots)
    spheres = []
    for i in range(robots.GetNumberOfItems()):
        sphere = [0.0] * 4
        if robots.GetItemAsObject(i).GetWorkspaceSphere(sphere):
            spheres.append(tuple(sphere))
    return spheres


def visible_bounds(renderer):
    """The bounds of the renderer's visible props, or None when nothing is drawn."""
    bounds = renderer.ComputeVisiblePropBounds()
    return bounds if bounds[0] <= bounds[1] else None


def camera_state(camera) -> tuple:
    """What places a camera (position, focal point, view up, view angle, parallel scale and
    projection): a change of any is a moved camera; the clipping range, reset before each frame,
    is not part of it."""
    return (*camera.GetPosition(), *camera.GetFocalPoint(), *camera.GetViewUp(), camera.GetViewAngle(),
            camera.GetParallelScale(), float(camera.GetParallelProjection()))


def frame_sphere(renderer, sphere: Sphere) -> None:
    """Sphere whole in the view and filling its smaller side, seen along VIEW_DIRECTION, z up."""
    camera = renderer.GetActiveCamera()
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(VIEW_ANGLE)
    aspect = renderer.GetTiledAspectRatio()  # width / height
    half_vertical = math.radians(VIEW_ANGLE) / 2
    half_horizontal = math.atan(math.tan(half_vertical) * aspect)
    distance = max(sphere[3], 1e-3) / math.sin(min(half_vertical, half_horizontal))
    norm = math.hypot(*VIEW_DIRECTION)
    camera.SetFocalPoint(*sphere[:3])
    camera.SetPosition(*(c + distance * d / norm for c, d in zip(sphere[:3], VIEW_DIRECTION)))
    renderer.ResetCameraClippingRange()


class ViewFraming:
    """Keeps `renderer`'s camera framed on the scene's robots' workspaces and what is drawn.
    `frame()` frames now (the view's "Reset view") and turns automatic framing on; `update()`,
    called after each spin, frames again only when needed (see the module's text) and says
    whether it did; never once the camera differs from where framing left it (`user_camera`:
    the user moved it)."""

    def __init__(self, scene, renderer):
        self.scene, self.renderer = scene, renderer
        self.sphere: Sphere | None = None  # what the camera frames now
        self.robots: list = []  # the robots' workspace spheres when it was framed
        self.key = None  # what was drawn then: props visible, robot loads
        self.aspect = 0.0
        self.frames = 0  # how many times it framed (for tests and the terminal)
        self.framed_camera = None  # camera_state() as the last framing left it
        self.user_camera = False  # the user moved the camera since: no automatic framing

    def frame(self) -> bool:
        """Frames the robots' workspaces and everything drawn now; False when there is nothing."""
        self.robots = robot_spheres(self.scene)
        sphere = None
        for robot in self.robots:
            sphere = enclosing_sphere(sphere, robot)
        bounds = visible_bounds(self.renderer)
        if bounds is not None:
            sphere = enclosing_sphere(sphere, box_sphere(bounds))
        self.key, self.aspect = self._key(), self.renderer.GetTiledAspectRatio()
        self.user_camera = False
        if sphere is None:
            self.sphere = self.framed_camera = None
            return False
        self.sphere = sphere
        frame_sphere(self.renderer, sphere)
        self.framed_camera = camera_state(self.renderer.GetActiveCamera())
        self.frames += 1
        return True

    def camera_moved_by_user(self) -> bool:
        """Whether the camera was moved since the last framing (by the user's mouse, or a script);
        stays True until `frame()`."""
        if not self.user_camera and self.framed_camera is not None:
            now = camera_state(self.renderer.GetActiveCamera())
            scale = max(self.sphere[3], 1.0) if self.sphere is not None else 1.0
            self.user_camera = any(abs(a - b) > 1e-6 * scale for a, b in zip(now, self.framed_camera))
        return self.user_camera

    def describe(self) -> str:
        """What the camera frames now, in one line."""
        if self.sphere is None:
            return 'nothing drawn'
        x, y, z, r = self.sphere
        robots = len(self.robots)
        return (f'centre ({x:.0f}, {y:.0f}, {z:.0f}) mm, radius {r:.0f} mm '
                f'({robots} robot workspace{"" if robots == 1 else "s"} and what is drawn)')

    def update(self) -> bool:
        """Frames again when something was added or removed, a robot was loaded or moved its base,
        something drawn left the framed region, or the view changed shape; never after the user
        moved the camera (until `frame()`)."""
        if self.camera_moved_by_user():
            return False
        if self.sphere is None or self.key != self._key() or self._shape_changed() or \
                self._robots_moved() or self._outside():
            return self.frame()
        return False

    def _key(self):
        return (self.renderer.VisibleActorCount(), self.renderer.VisibleVolumeCount())

    def _shape_changed(self) -> bool:
        return abs(self.renderer.GetTiledAspectRatio() - self.aspect) > 0.01 * self.aspect

    def _robots_moved(self) -> bool:
        now = robot_spheres(self.scene)
        return len(now) != len(self.robots) or any(
            math.dist(a[:3], b[:3]) > 0.01 * b[3] or abs(a[3] - b[3]) > 0.01 * b[3]
            for a, b in zip(now, self.robots))

    def _outside(self) -> bool:
        """Something drawn reaches past the cube around the framed sphere (a robot within its
        workspace never does: its box stays in that cube)."""
        bounds = visible_bounds(self.renderer)
        if bounds is None:
            return False
        x, y, z, r = self.sphere
        margin = 1e-3 * r
        return any(bounds[2 * i] < c - r - margin or bounds[2 * i + 1] > c + r + margin
                   for i, c in enumerate((x, y, z)))
