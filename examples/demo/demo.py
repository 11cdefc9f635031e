#!/usr/bin/env python3
"""ros2vtk demo: a live robot beside a CT phantom, image-guided style, with no ROS installed.

Run it through scripts/demo.sh (it sets up, builds, starts the simulated robot and this viewer).
What happens here, with the ros2vtk Python API only:
  * our default ROS node (`/slicer`) gets a robot node per robot, fed by the simulated robot's
    `robot_description` topic (reliable + transient local, as RViz 2 subscribes); the robot node
    builds the robot from it: one transform node per link, kept equal to the tf lookup (fixed
    frame <- link) on every spin, and one model node per URDF visual (STL/OBJ/PLY/DAE meshes and
    primitives, with their origins, scales and colours), under a base transform that places it;
  * a CT-like phantom (gel block, tongue-like tissue, pseudotumour, fiducials) is shown as three
    orthogonal slices with a soft-tissue window, placed by an editable registration transform;
  * the phantom (2 mm voxels: 32 x 26 x 19 cm, its gel block about an abdomen) is registered to
    where the instrument works: its pseudotumour at the deepest needle tip position of the first
    descent it sees (the simulated robot's needle insertions,
    examples/robots/surgical_arm/config/needle_insertion.motion), so the tip reaches into it on
    every descent; the three slices follow the tip, as a CT navigation view does (in the window
    mode also axial, sagittal and coronal panes centred on the tip, the needle's cut drawn);
  * it shows everything in the web app (`ros2vtk.app`, prints the URL) or, with --window, in a
    VTK window; without a display the window mode writes PNG frames (--offscreen DIR) and, unless
    --duration says otherwise, stops after 20 s with a summary; the app mode without a display
    writes frames of its 3D view (--frames DIR) and stops after 20 s with a summary unless a
    browser has connected by then (it then serves until Ctrl-C; --duration 0: until Ctrl-C in any
    case). Ctrl-C stops it cleanly.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import ros2vtk
import vtk
from ros2vtk.framing import ViewFraming

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


# ------------------------------------------------------------------------------ viewer
TIP_LINK = 'needle_tip'
PHANTOM_SPACING_MM = 2.0  # ros2vtk-make-phantom's 1 mm voxels, scaled to a torso-sized block


class PhantomView:
    """The CT phantom in a renderer: three orthogonal slices (W400/L40, air see-through) that
    follow a point, the pseudotumour surface and the volume's outline, all placed by the
    registration transform; hidden until the phantom is registered (`set_visible`)."""

    def __init__(self, renderer, image, registration):
        self.image = image
        self.registration = registration
        self.slice_actors = []
        lut = vtk.vtkWindowLevelLookupTable()
        lut.SetWindow(400)
        lut.SetLevel(40)
        lut.Build()
        lut.SetBelowRangeColor(0, 0, 0, 0)  # air is see-through, so the robot stays visible
        lut.UseBelowRangeColorOn()
        for _axis in range(3):
            colors = vtk.vtkImageMapToColors()
            colors.SetInputData(image)
            colors.SetLookupTable(lut)
            actor = vtk.vtkImageActor()
            actor.GetMapper().SetInputConnection(colors.GetOutputPort())
            actor.SetUserMatrix(registration.GetMatrixTransformToParent())
            renderer.AddActor(actor)
            self.slice_actors.append(actor)
        surface = vtk.vtkFlyingEdges3D()
        surface.SetInputData(image)
        surface.SetValue(0, 110)
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(surface.GetOutputPort())
        mapper.ScalarVisibilityOff()
        self.tumour = vtk.vtkActor()
        self.tumour.SetMapper(mapper)
        self.tumour.GetProperty().SetColor(0.9, 0.3, 0.25)
        self.tumour.GetProperty().SetOpacity(0.6)
        self.tumour.SetUserMatrix(registration.GetMatrixTransformToParent())
        renderer.AddActor(self.tumour)
        # The volume's box, as Slicer outlines a volume in 3D: where the image is, at a glance.
        outline = vtk.vtkOutlineFilter()
        outline.SetInputData(image)
        outline_mapper = vtk.vtkPolyDataMapper()
        outline_mapper.SetInputConnection(outline.GetOutputPort())
        self.outline = vtk.vtkActor()
        self.outline.SetMapper(outline_mapper)
        self.outline.GetProperty().SetColor(0.95, 0.95, 0.6)
        self.outline.SetUserMatrix(registration.GetMatrixTransformToParent())
        renderer.AddActor(self.outline)
        extent = image.GetExtent()
        self.follow_index([(extent[2 * i] + extent[2 * i + 1]) // 2 for i in range(3)])
        self.tip_inside = False

    def set_visible(self, visible: bool) -> None:
        for actor in (*self.slice_actors, self.tumour, self.outline):
            actor.SetVisibility(visible)

    def world_to_index(self, point):
        """World (robot, mm) -> voxel index of the phantom, clamped to its extent."""
        inverse = vtk.vtkMatrix4x4()
        vtk.vtkMatrix4x4.Invert(self.registration.GetMatrixTransformToParent(), inverse)
        local = inverse.MultiplyPoint((*point, 1.0))
        origin, spacing, extent = self.image.GetOrigin(), self.image.GetSpacing(), self.image.GetExtent()
        return [min(max(int(round((local[i] - origin[i]) / spacing[i])), extent[2 * i]), extent[2 * i + 1])
                for i in range(3)]

    def follow_index(self, index) -> None:
        extent = self.image.GetExtent()
        for axis, actor in enumerate(self.slice_actors):
            e = list(extent)
            e[2 * axis] = e[2 * axis + 1] = index[axis]
            actor.SetDisplayExtent(*e)

    def follow(self, point) -> None:
        """Slices through `point` while it is inside the volume; they stay where they were when
        it leaves (clamped slices at the border would show only air)."""
        index = self.world_to_index(point)
        inverse = vtk.vtkMatrix4x4()
        vtk.vtkMatrix4x4.Invert(self.registration.GetMatrixTransformToParent(), inverse)
        local = inverse.MultiplyPoint((*point, 1.0))
        b = self.image.GetBounds()
        if all(b[2 * i] <= local[i] <= b[2 * i + 1] for i in range(3)):
            self.follow_index(index)
            self.tip_inside = True
        else:
            self.tip_inside = False

    def world_bounds(self):
        """The phantom's box in world mm, as drawn: the bounds of its outline actor."""
        return list(self.outline.GetBounds())

    def slice_planes(self):
        """Where the three slices are drawn (world mm, from their actors' bounds): the x of the
        sagittal one, the y of the coronal one, the z of the axial one."""
        names = ('sagittal', 'coronal', 'axial')
        planes = {}
        for axis, actor in enumerate(self.slice_actors):
            b = actor.GetBounds()
            planes[names[axis]] = (b[2 * axis] + b[2 * axis + 1]) / 2
        return planes


def target_centre(image):
    """The pseudotumour's centre in the image's own frame (mm): the centre of mass of the
    surface around the voxels of its grey range (110..1000 HU; the fiducial beads, 1500 HU, and
    the tissue, 60 HU, are left out)."""
    mask = vtk.vtkImageThreshold()
    mask.SetInputData(image)
    mask.ThresholdBetween(110, 1000)
    mask.SetInValue(1)
    mask.SetOutValue(0)
    mask.SetOutputScalarTypeToUnsignedChar()
    surface = vtk.vtkFlyingEdges3D()
    surface.SetInputConnection(mask.GetOutputPort())
    surface.SetValue(0, 0.5)
    centre = vtk.vtkCenterOfMass()
    centre.SetInputConnection(surface.GetOutputPort())
    centre.SetUseScalarsAsWeights(False)
    centre.Update()
    if surface.GetOutput().GetNumberOfPoints() == 0:  # no tumour: the volume's centre
        b = image.GetBounds()
        return [(b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)]
    return list(centre.GetCenter())


class TipPlacement:
    """Registers the phantom to the instrument's working area: it watches the needle tip (its tf
    lookup) until it has seen one descent (the tip down at least `stroke` mm to its lowest point
    and up again by as much; at most `seconds`), then places the phantom so that its pseudotumour
    is at the deepest tip position seen: the needle, lowered again, reaches into the phantom and
    its target, as in a navigated needle insertion."""

    def __init__(self, registration, image, seconds: float = 10.0, stroke: float = 30.0):
        self.registration, self.image, self.seconds, self.stroke = registration, image, seconds, stroke
        self.target = target_centre(image)
        self.deepest, self.highest, self.start, self.placed = None, None, None, False
        self.descended = 0.0  # mm from the highest point before the deepest down to it

    def add(self, tip, now: float) -> bool:
        """Adds a tip sample; True when the phantom has just been placed."""
        if self.placed:
            return False
        self.start = now if self.start is None else self.start
        self.highest = tip[2] if self.highest is None else max(self.highest, tip[2])
        if self.deepest is None or tip[2] < self.deepest[2]:
            self.deepest = list(tip)
            self.descended = self.highest - tip[2]
        one_descent = self.descended >= self.stroke and tip[2] - self.deepest[2] >= self.stroke
        if not one_descent and now - self.start < self.seconds:
            return False
        placement = vtk.vtkMatrix4x4()
        for i in range(3):
            placement.SetElement(i, 3, self.deepest[i] - self.target[i])
        self.registration.SetMatrixTransformToParent(placement)
        self.placed = True
        return True

    def why_not_placed(self, robot_loaded: bool) -> str:
        """Why the phantom is not placed yet, for the summary line."""
        if not robot_loaded:
            return 'robot not loaded'
        if self.start is None:
            return 'needle tip not tracked yet'
        return (f'needle watched for less than its first {self.stroke:.0f} mm descent and '
                f'{self.seconds:.0f} s')


def tip_position(robot):
    """The needle tip in world coordinates (mm), or None before the robot is loaded."""
    node = robot.GetLinkTransformNode(TIP_LINK) if robot.IsLoaded() else None
    if node is None:
        return None
    matrix = vtk.vtkMatrix4x4()
    node.GetMatrixTransformToWorld(matrix)
    return [matrix.GetElement(i, 3) for i in range(3)]


def display_point(renderer, point):
    coordinate = vtk.vtkCoordinate()
    coordinate.SetCoordinateSystemToWorld()
    coordinate.SetValue(*point)
    return coordinate.GetComputedDoubleDisplayValue(renderer)


def display_box(renderer, bounds):
    """The display-space box (x0, y0, x1, y1) of a world box's 8 corners."""
    points = [display_point(renderer, (x, y, z)) for x in bounds[0:2] for y in bounds[2:4] for z in bounds[4:6]]
    return [min(p[0] for p in points), min(p[1] for p in points), max(p[0] for p in points), max(p[1] for p in points)]


# The 2D panes of the window mode, top to bottom, with Slicer's view colours (red, yellow, green).
SLICE_PANES = (('axial', (0.95, 0.35, 0.35)), ('sagittal', (0.95, 0.85, 0.3)), ('coronal', (0.45, 0.8, 0.4)))
PANE_NORMAL_AXIS = {'axial': 2, 'sagittal': 0, 'coronal': 1}
TIP_FIELD_OF_VIEW = 80.0  # mm from a pane's centre to its top around the tip: the needle's way in the tissue


def plane_through(bounds, point, axis: int) -> list:
    """The centre of a box (xmin, xmax, ...) moved along `axis` to `point`'s coordinate, kept
    within the box."""
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    centre[axis] = min(max(point[axis], bounds[2 * axis]), bounds[2 * axis + 1])
    return centre
VIEW_WIDTH = 0.7  # of the window, for the 3D view; the panes share the rest


class Viewer:
    def __init__(self, scene, image, registration, offscreen_dir: str | None, size=(1280, 720), volume=None):
        self.scene = scene
        self.renderer = vtk.vtkRenderer()
        # Slicer's 3D view background, so the scene looks as Slicer users know it.
        self.renderer.SetBackground(0.7568, 0.7647, 0.9098)
        self.renderer.SetBackground2(0.4549, 0.4706, 0.7451)
        self.renderer.GradientBackgroundOn()
        self.window = vtk.vtkRenderWindow()
        self.window.SetSize(*size)
        self.window.AddRenderer(self.renderer)
        self.window.SetWindowName('ros2vtk demo')
        self.offscreen_dir = offscreen_dir
        if offscreen_dir:
            self.window.SetOffScreenRendering(1)
            Path(offscreen_dir).mkdir(parents=True, exist_ok=True)
        self.actors = {}
        self.registration = registration
        self.phantom = PhantomView(self.renderer, image, registration)
        self.phantom.set_visible(False)  # until it is placed at the tip
        self.tip = None            # the needle tip (world mm) once every link is tracked
        self.tip_link_id = None    # the tip link's transform node: its model is the tip marker
        self.tip_model_id = None
        self.framing = ViewFraming(scene, self.renderer)  # the robot's workspace and the phantom
        self.frame = 0
        # Axial, sagittal and coronal panes of the phantom (vtkROS2SliceView: resliced where the
        # registration puts it, the needle's cut drawn in its colour) right of the 3D view, centred
        # on the needle tip while it is inside the phantom.
        self.slice_views = {}
        if volume is not None and hasattr(ros2vtk, 'vtkROS2SliceView'):
            self.renderer.SetViewport(0.0, 0.0, VIEW_WIDTH, 1.0)
            for row, (orientation, colour) in enumerate(SLICE_PANES):
                pane = vtk.vtkRenderer()
                pane.SetViewport(VIEW_WIDTH, 1.0 - (row + 1) / 3, 1.0, 1.0 - row / 3)
                pane.SetBackground(0.0, 0.0, 0.0)
                self.window.AddRenderer(pane)
                view = ros2vtk.vtkROS2SliceView()
                view.SetRenderer(pane)
                view.SetScene(scene)
                view.SetOrientation(orientation)
                view.SetVolumeNode(volume)
                view.SetWindowLevel(400.0, 40.0)
                view.SetFieldOfView(TIP_FIELD_OF_VIEW)
                label = vtk.vtkTextActor()
                label.SetInput(orientation)
                label.GetTextProperty().SetColor(*colour)
                label.GetTextProperty().SetFontSize(16)
                label.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
                label.GetPositionCoordinate().SetValue(0.02, 0.04)
                pane.AddActor2D(label)
                self.slice_views[orientation] = view
            centre = [(b0 + b1) / 2 for b0, b1 in zip(self.phantom.world_bounds()[0::2], self.phantom.world_bounds()[1::2])]
            for view in self.slice_views.values():
                view.SetSliceCenter(*centre)

    def follow_tip(self) -> None:
        """The 3D slices and the 2D panes through the needle tip while it is inside the phantom
        (the panes centred on it, 16 cm tall); outside, each pane shows the whole phantom cut by
        the plane at the tip's coordinate (kept within the phantom), as Slicer's slice views
        driven by a tool: the needle approaching above the phantom in the sagittal and coronal
        panes, not black panes centred on a tip in the air."""
        if self.tip is None:
            return
        self.phantom.follow(self.tip)
        bounds = self.phantom.world_bounds()
        for orientation, view in self.slice_views.items():
            if self.phantom.tip_inside:
                view.SetFieldOfView(TIP_FIELD_OF_VIEW)
                view.SetSliceCenter(*self.tip)
            else:
                view.SetFieldOfView(0.0)  # the whole phantom
                view.SetSliceCenter(*plane_through(bounds, self.tip, PANE_NORMAL_AXIS[orientation]))

    def update(self) -> None:
        """Model nodes of the scene -> actors with their world matrices."""
        models = vtk.vtkCollection()
        self.scene.GetNodesByClass('vtkROS2ModelNode', models)
        present = set()
        for i in range(models.GetNumberOfItems()):
            model = models.GetItemAsObject(i)
            present.add(model.GetID())
            parent = model.GetParentTransformNode()
            if self.tip_link_id is not None and parent is not None and parent.GetID() == self.tip_link_id:
                self.tip_model_id = model.GetID()
            actor = self.actors.get(model.GetID())
            if actor is None:
                mapper = vtk.vtkPolyDataMapper()
                mapper.SetInputData(model.GetPolyData())
                # Per-vertex colours of a mesh (Collada, PLY) when the model asks for them.
                mapper.SetScalarVisibility(model.GetScalarVisibility())
                mapper.SetColorModeToDirectScalars()
                actor = vtk.vtkActor()
                actor.SetMapper(mapper)
                actor.GetProperty().SetColor(*model.GetColor())
                actor.GetProperty().SetOpacity(model.GetOpacity())
                actor.SetUserMatrix(vtk.vtkMatrix4x4())
                self.renderer.AddActor(actor)
                self.actors[model.GetID()] = actor
            model.GetMatrixModelToWorld(actor.GetUserMatrix())
            actor.GetUserMatrix().Modified()
            actor.Modified()
        for gone in set(self.actors) - present:
            self.renderer.RemoveActor(self.actors.pop(gone))

    def reset_camera(self) -> None:
        self.framing.frame()

    def render(self) -> str | None:
        # Framed on the robot's workspace and the phantom, again only when that changes.
        self.framing.update()
        # The robot moves: near/far planes computed once would clip links that swing towards or
        # away from the camera (seen as a needle guide missing from a frame).
        self.renderer.ResetCameraClippingRange()
        for view in self.slice_views.values():
            view.Update()
        self.window.Render()
        if not self.offscreen_dir:
            return None
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.Update()
        path = str(Path(self.offscreen_dir) / f'frame_{self.frame:04d}.png')
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        # What is where on this picture, read back from the scene and the renderer (for tests
        # and for a person checking a frame): each robot model's projected centre, the robot's
        # and the phantom's projected boxes (actor bounds), the needle tip (its tf lookup, and the
        # centre of its drawn marker), the phantom's box and the slice planes (their actors).
        projected = {}
        robot_box = vtk.vtkBoundingBox()
        for node_id, actor in self.actors.items():
            b = actor.GetBounds()
            robot_box.AddBounds(b)
            size = math.dist((b[0], b[2], b[4]), (b[1], b[3], b[5]))
            x, y = display_point(self.renderer, ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2))
            projected[node_id] = {'x': x, 'y': y, 'size_mm': size}
        info = {'models': projected, 'window': list(self.window.GetSize()),
                'phantom_visible': bool(self.phantom.outline.GetVisibility()),
                'phantom_bounds_mm': self.phantom.world_bounds(),
                'phantom_display_box': display_box(self.renderer, self.phantom.world_bounds()),
                'slice_planes_mm': self.phantom.slice_planes(),
                'voxel_mm': list(self.phantom.image.GetSpacing()),
                'view_viewport_px': [v * self.window.GetSize()[i % 2] for i, v in enumerate(self.renderer.GetViewport())],
                'camera_mm': list(self.renderer.GetActiveCamera().GetPosition())
                + list(self.renderer.GetActiveCamera().GetFocalPoint()),
                'framings': self.framing.frames}
        centre = [0.0, 0.0, 0.0]
        for orientation, view in self.slice_views.items():
            view.GetSliceCenter(centre)
            info.setdefault('slice_view_centres_mm', {})[orientation] = list(centre)
            info.setdefault('slice_view_cuts', {})[orientation] = view.GetNumberOfIntersectedModels()
        if robot_box.IsValid():
            bounds = [0.0] * 6
            robot_box.GetBounds(bounds)
            info['robot_bounds_mm'] = bounds
            info['robot_display_box'] = display_box(self.renderer, bounds)
        info['tip_inside_phantom'] = self.phantom.tip_inside
        if self.tip is not None:
            info['tip_mm'] = self.tip
            info['tip_display'] = list(display_point(self.renderer, self.tip))
        marker = self.actors.get(self.tip_model_id)
        if marker is not None:
            b = marker.GetBounds()
            info['tip_marker_mm'] = [(b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)]
        Path(path).with_suffix('.json').write_text(json.dumps(info))
        self.frame += 1
        return path


# ------------------------------------------------------------------------------ main
HEADLESS_SECONDS = 20.0  # a run with no display and no --duration stops after this


class Demo:
    """The demo's scene: robots fed by the simulated robot(s), the phantom, the tip placement."""

    def __init__(self, args):
        self.args = args
        self.logic = ros2vtk.vtkROS2Logic()
        self.logic.SetSpinRate(args.rate)
        self.scene = self.logic.GetScene()
        self.node = self.logic.GetDefaultROS2Node()
        reader = vtk.vtkMetaImageReader()
        reader.SetFileName(args.phantom)
        reader.Update()
        if reader.GetErrorCode() or reader.GetOutput().GetNumberOfPoints() == 0:
            raise SystemExit(f'[demo] cannot read the phantom {args.phantom}')
        scale = vtk.vtkImageChangeInformation()
        scale.SetInputConnection(reader.GetOutputPort())
        scale.SetOutputSpacing(PHANTOM_SPACING_MM, PHANTOM_SPACING_MM, PHANTOM_SPACING_MM)
        scale.Update()
        self.image = scale.GetOutput()
        self.registration = ros2vtk.vtkROS2TransformNode()
        self.registration.SetName('registration:robot_to_image')
        placement = vtk.vtkMatrix4x4()
        placement.SetElement(0, 3, 350.0)   # until the tip placement (hidden in 3D): in front of the robot (mm)
        placement.SetElement(2, 3, 150.0)
        self.registration.SetMatrixTransformToParent(placement)
        self.scene.AddNode(self.registration)
        self.placement = TipPlacement(self.registration, self.image)
        # The 2D panes (the app's, the window mode's) show the phantom as a volume node under the
        # registration; hidden in the 3D view, where PhantomView draws its slices and the tumour.
        self.volume = None
        if hasattr(ros2vtk, 'vtkROS2VolumeNode'):
            self.volume = ros2vtk.vtkROS2VolumeNode()
            self.volume.SetName('phantom')
            self.volume.SetImageData(self.image)
            self.volume.SetWindow(400.0)
            self.volume.SetLevel(40.0)
            self.volume.SetVisibility(False)
            self.scene.AddNode(self.volume)
            self.volume.SetParentTransformNodeID(self.registration.GetID())
        namespaces = ['/'] if args.robots == 1 else [f'/robot{i + 1}' for i in range(args.robots)]
        urdf_folder = Path(args.urdf).resolve().parent
        package_paths = args.package_path or [str(urdf_folder.parent)]  # <package>/urdf/robot.urdf
        self.robots, self.placements, self.announced = {}, {}, {}
        for index, ns in enumerate(namespaces):
            name = 'robot' if ns == '/' else ns.strip('/')
            prefix = '' if ns == '/' else name + '/'  # ros2vtk-sim-robot --frame-prefix robotN/
            topic = '/robot_description' if ns == '/' else f'{ns}/robot_description'
            robot = self.node.CreateAndAddRobotNodeFromTopic(name, topic, '', prefix)
            robot.SetMeshBaseFolder(str(urdf_folder))
            for folder in package_paths:
                robot.AddMeshSearchPath(folder)
            # Several robots stand side by side along y, 700 mm apart, through their base transforms.
            placement = vtk.vtkMatrix4x4()
            placement.SetElement(1, 3, 700.0 * (index - (len(namespaces) - 1) / 2))
            self.placements[ns] = placement
            self.robots[ns] = robot
        self.first = next(iter(self.robots.values()))
        self.tip = None

    def after_spin(self) -> str:
        """Per spin: announces loads, places the phantom at the tool tip, returns 'loaded',
        'tracked', 'placed' or '' (what the view should re-frame for)."""
        event = ''
        for ns, robot in self.robots.items():
            if robot.IsLoaded() and self.announced.get(ns) != robot.GetNumberOfLoads():
                self.announced[ns] = robot.GetNumberOfLoads()
                robot.GetBaseTransformNode().SetMatrixTransformToParent(self.placements[ns])
                for warning in robot.GetWarnings().splitlines():
                    print(f'[demo] {ns}: {warning}', flush=True)
                print(f'[demo] robot in {ns}: {robot.GetNumberOfLinks()} links, {robot.GetNumberOfModelNodes()} '
                      f'visuals, loaded in {1000 * robot.GetLastLoadDuration():.1f} ms', flush=True)
                event = 'loaded'
        tracked = self.first.IsLoaded() and self.first.GetNumberOfLinksTracked() == self.first.GetNumberOfLinks()
        if tracked and self.tip is None:
            event = 'tracked'  # the arm in its pose (loaded links sit at the origin until tracked)
        self.tip = tip_position(self.first) if tracked else None
        if self.tip is not None and self.placement.add(self.tip, time.monotonic()):
            print('[demo] phantom placed at the needle tip: its pseudotumour at the deepest tip position of the '
                  f'first descent ({", ".join(f"{c:.0f}" for c in self.placement.deepest)} mm)', flush=True)
            event = 'placed'
        return event

    def tip_link_id(self):
        node = self.first.GetLinkTransformNode(TIP_LINK) if self.first.IsLoaded() else None
        return node.GetID() if node is not None else None

    def status(self, spins: int, seconds: float, spin_time: float) -> str:
        state = '; '.join(f'{ns}: {r.GetRobotState()}, {r.GetNumberOfLinksTracked()}/{r.GetNumberOfLinks()} '
                          f'links tracked' for ns, r in self.robots.items())
        received = sum(self.node.GetSubscriberNodeByTopic(r.GetDescriptionTopic()).GetNumberOfMessages()
                       for r in self.robots.values())
        return (f'[demo] {spins / seconds:5.1f} spins/s, spin {1000 * spin_time / max(spins, 1):.3f} ms, '
                f'mean {self.logic.GetMeanSpinDuration():.3f} ms, robot_description msgs {received}, {state}')


def run_window(demo: Demo, args, duration: float) -> int:
    """A VTK window (or PNG frames offscreen) driven by this loop."""
    viewer = Viewer(demo.scene, demo.image, demo.registration, args.offscreen or None, volume=demo.volume)
    viewer.reset_camera()
    interactor = None
    if not args.offscreen:
        interactor = vtk.vtkRenderWindowInteractor()
        interactor.SetRenderWindow(viewer.window)
        interactor.SetInteractorStyle(vtk.vtkInteractorStyleTrackballCamera())
        interactor.Initialize()
    else:
        print(f'[demo] no display: writing frames to {args.offscreen}'
              + (f' for {duration:g} s' if duration > 0 else ''), flush=True)
    start = last_status = time.monotonic()
    last_frame, spins_since, spin_time = 0.0, 0, 0.0
    try:
        while duration <= 0 or time.monotonic() - start < duration:
            t0 = time.perf_counter()
            if args.spin == 'event':
                demo.logic.SpinOnWakeUp(1.0 / args.rate)
            else:
                demo.logic.Spin()
            spin_time += time.perf_counter() - t0
            spins_since += 1
            event = demo.after_spin()
            viewer.tip_link_id = demo.tip_link_id()
            viewer.update()
            viewer.tip = demo.tip
            viewer.phantom.set_visible(demo.placement.placed)
            if demo.placement.placed:
                viewer.follow_tip()
            now = time.monotonic()
            if args.offscreen:
                if event == 'placed' or now - last_frame >= 1.0 / args.frames_per_second:
                    viewer.render()
                    last_frame = now
                elif args.spin == 'timer':
                    time.sleep(max(0.0, 1.0 / args.rate - (time.perf_counter() - t0)))
            else:
                viewer.render()
                interactor.ProcessEvents()
                if args.spin == 'timer':
                    time.sleep(max(0.0, 1.0 / args.rate - (time.perf_counter() - t0)))
            if now - last_status >= 1.0:
                print(demo.status(spins_since, now - last_status, spin_time), flush=True)
                last_status, spins_since, spin_time = now, 0, 0.0
    except KeyboardInterrupt:
        print('[demo] interrupted (Ctrl-C): stopping', flush=True)
    summary = (f'[demo] summary: {time.monotonic() - start:.1f} s, {demo.logic.GetNumberOfSpins()} spins, '
               f'mean spin {demo.logic.GetMeanSpinDuration():.3f} ms, '
               + ', '.join(f'{ns}: {r.GetRobotState()} {r.GetNumberOfLinksTracked()}/{r.GetNumberOfLinks()} links'
                           for ns, r in demo.robots.items())
               + (', phantom placed at the tip' if demo.placement.placed
                  else f', phantom not placed ({demo.placement.why_not_placed(demo.first.IsLoaded())})'))
    if args.offscreen:
        summary += f', {viewer.frame} frames in {args.offscreen}'
    print(summary, flush=True)
    return 0


def run_app(demo: Demo, args, duration: float) -> int:
    """The web app on the demo's logic, with the phantom in its 3D view. Without a display and
    without --duration, nobody may be watching: it stops after HEADLESS_SECONDS unless a browser
    connects by then (it serves on until Ctrl-C once one has), and writes PNG frames of its 3D
    view (--frames DIR) while no browser is connected."""
    import ros2vtk.app
    wait = HEADLESS_SECONDS if not os.environ.get('DISPLAY') and args.duration is None else None
    frames = {'written': 0, 'next': 0.0}
    frames_dir = Path(args.frames or 'demo-frames').resolve()

    def write_frame(app) -> None:
        """A PNG of the app's 3D view (rendered here: no browser asks for frames)."""
        from PIL import Image
        pixels, _cols, _rows = app.area.img_cols_rows
        Image.fromarray(pixels).save(frames_dir / f'app_frame_{frames["written"]:04d}.png')
        frames['written'] += 1

    def setup(app):
        phantom = PhantomView(app.renderer, demo.image, demo.registration)
        phantom.set_visible(False)  # until it is placed at the tip

        def after_spin():
            if demo.after_spin():
                phantom.set_visible(demo.placement.placed)
            if demo.tip is not None and demo.placement.placed:
                phantom.follow(demo.tip)
                if app.slices is not None and phantom.tip_inside:  # as in --window: centred on the tip
                    app.slices.follow(*demo.tip, half_height=TIP_FIELD_OF_VIEW)
                elif app.slices is not None:  # the whole phantom, cut at the tip's coordinates
                    app.slices.set_point(*demo.tip)
            now = time.monotonic()
            if wait and not app.browsers.seen and now >= frames['next']:
                frames['next'] = now + 1.0 / args.frames_per_second
                write_frame(app)
        app.add_spin_callback(after_spin)
        app.state.robot_selected = demo.first.GetRobotName()
    if wait:
        frames_dir.mkdir(parents=True, exist_ok=True)
        print(f'[demo] no display: the app stops after {wait:g} s unless a browser opens it by then (it then '
              f'serves until Ctrl-C; --duration 0 serves until Ctrl-C anyway); frames of its 3D view go to '
              f'{frames_dir} until a browser connects', flush=True)
    else:
        print('[demo] starting the app (Ctrl-C stops it)', flush=True)
    start = time.monotonic()
    interrupted = False
    try:
        app = ros2vtk.app.serve(demo.logic, port=args.port, title='ros2vtk demo', on_app=setup,
                                duration=duration if duration > 0 else None, slices=True, browser_wait=wait)
        interrupted = not app.stopped_for
    except KeyboardInterrupt:
        app, interrupted = None, True
    summary = (f'[demo] summary: {time.monotonic() - start:.1f} s, {demo.logic.GetNumberOfSpins()} spins, '
               f'mean spin {demo.logic.GetMeanSpinDuration():.3f} ms, '
               + ', '.join(f'{ns}: {r.GetRobotState()} {r.GetNumberOfLinksTracked()}/{r.GetNumberOfLinks()} links'
                           for ns, r in demo.robots.items())
               + (', phantom placed at the tip' if demo.placement.placed
                  else f', phantom not placed ({demo.placement.why_not_placed(demo.first.IsLoaded())})')
               + (f', browsers connected: {app.browsers.seen}' if app is not None else '')
               + (f', {frames["written"]} frames in {frames_dir}' if frames['written'] else ''))
    print(summary, flush=True)
    if interrupted:
        print('[demo] interrupted (Ctrl-C): stopped', flush=True)
    elif app.stopped_for == 'no browser':
        print(f'[demo] no browser connected within {wait:g} s: stopped. To keep it serving, open the URL within '
              f'{wait:g} s or run with --duration 0 (until Ctrl-C)', flush=True)
    else:
        print('[demo] stopped', flush=True)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--phantom', required=True, help='MetaImage (.mha) made by ros2vtk-make-phantom')
    parser.add_argument('--robots', type=int, default=1, help='robots (namespaces /robot1, /robot2, ...)')
    parser.add_argument('--spin', choices=('timer', 'event'), default='timer')
    parser.add_argument('--rate', type=float, default=50.0, help='timer spin rate (Hz)')
    parser.add_argument('--window', action='store_true', help='a VTK window (PNG frames without a display) '
                        'instead of the web app')
    parser.add_argument('--port', type=int, default=8080, help='the web app\'s port (127.0.0.1 only)')
    parser.add_argument('--offscreen', default='', help='window mode: write PNG frames here')
    parser.add_argument('--duration', type=float, default=None,
                        help='seconds; 0: until Ctrl-C. Default without a display: the window mode stops after '
                             f'{HEADLESS_SECONDS:g} s; the app stops after {HEADLESS_SECONDS:g} s unless a browser '
                             'has connected (then until Ctrl-C). With a display: until Ctrl-C')
    parser.add_argument('--frames-per-second', type=float, default=0.75, help='PNG frames written per second')
    parser.add_argument('--frames', default='', help='app mode without a display: where the frames of the 3D view '
                        'go while no browser is connected (default ./demo-frames)')
    parser.add_argument('--urdf', default=str(REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'),
                        help='the URDF the simulated robot serves (its folder is the base of relative mesh paths)')
    parser.add_argument('--package-path', action='append', default=[],
                        help='folder searched for package:// meshes (besides AMENT_PREFIX_PATH, ROS_PACKAGE_PATH)')
    args = parser.parse_args()
    window_mode = args.window or bool(args.offscreen)
    duration = args.duration
    if duration is None:
        duration = HEADLESS_SECONDS if args.offscreen else 0.0
    try:
        demo = Demo(args)
        if window_mode:
            return run_window(demo, args, duration)
        return run_app(demo, args, duration)
    except KeyboardInterrupt:
        print('[demo] interrupted (Ctrl-C): stopping', flush=True)
        return 0


if __name__ == '__main__':
    sys.exit(main())
