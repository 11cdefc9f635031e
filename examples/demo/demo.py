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
  * it spins (timer-driven at 50 Hz, or event-driven), prints one status line a second, and
    renders: an interactive window on a display, PNG frames in --offscreen DIR otherwise.
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

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


# ------------------------------------------------------------------------------ viewer
class Viewer:
    def __init__(self, scene, image, registration, offscreen_dir: str | None, size=(1280, 720)):
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
        self.slice_actors = self._slices(image)
        self.frame = 0

    def _slices(self, image):
        """Three orthogonal slices through the phantom's centre, CT window W400/L40."""
        lut = vtk.vtkWindowLevelLookupTable()
        lut.SetWindow(400)
        lut.SetLevel(40)
        lut.Build()
        lut.SetBelowRangeColor(0, 0, 0, 0)  # air is see-through, so the robot stays visible
        lut.UseBelowRangeColorOn()
        actors = []
        extent = image.GetExtent()
        centre = [(extent[2 * i] + extent[2 * i + 1]) // 2 for i in range(3)]
        for axis in range(3):
            e = list(extent)
            e[2 * axis] = e[2 * axis + 1] = int(centre[axis] * (1.15 if axis == 2 else 1.0))
            colors = vtk.vtkImageMapToColors()
            colors.SetInputData(image)
            colors.SetLookupTable(lut)
            actor = vtk.vtkImageActor()
            actor.GetMapper().SetInputConnection(colors.GetOutputPort())
            actor.SetDisplayExtent(*e)
            actor.SetUserMatrix(self.registration.GetMatrixTransformToParent())
            self.renderer.AddActor(actor)
            actors.append(actor)
        # The pseudotumour as a translucent surface, so the target stands out.
        surface = vtk.vtkFlyingEdges3D()
        surface.SetInputData(image)
        surface.SetValue(0, 110)
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(surface.GetOutputPort())
        mapper.ScalarVisibilityOff()
        tumour = vtk.vtkActor()
        tumour.SetMapper(mapper)
        tumour.GetProperty().SetColor(0.9, 0.3, 0.25)
        tumour.GetProperty().SetOpacity(0.6)
        tumour.SetUserMatrix(self.registration.GetMatrixTransformToParent())
        self.renderer.AddActor(tumour)
        return actors

    def update(self) -> None:
        """Model nodes of the scene -> actors with their world matrices."""
        models = vtk.vtkCollection()
        self.scene.GetNodesByClass('vtkROS2ModelNode', models)
        present = set()
        for i in range(models.GetNumberOfItems()):
            model = models.GetItemAsObject(i)
            present.add(model.GetID())
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
        camera = self.renderer.GetActiveCamera()
        camera.SetViewUp(0, 0, 1)
        # Robot (about 1.5 m tall at the origin) and phantom (in front of it) in one view.
        camera.SetFocalPoint(280, 0, 600)
        camera.SetPosition(2300, -2500, 1600)
        camera.SetViewAngle(24.0)  # idempotent, unlike Zoom()
        self.renderer.ResetCameraClippingRange()

    def render(self) -> str | None:
        # The robot moves: near/far planes computed once would clip links that swing towards or
        # away from the camera (seen as a needle guide missing from a frame).
        self.renderer.ResetCameraClippingRange()
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
        # Where each robot model should be on the picture: the display position of the centre
        # of its world bounds (for tests and for a person checking a frame).
        projected = {}
        for node_id, actor in self.actors.items():
            b = actor.GetBounds()
            size = math.dist((b[0], b[2], b[4]), (b[1], b[3], b[5]))
            coordinate = vtk.vtkCoordinate()
            coordinate.SetCoordinateSystemToWorld()
            coordinate.SetValue((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2)
            x, y = coordinate.GetComputedDoubleDisplayValue(self.renderer)
            projected[node_id] = {'x': x, 'y': y, 'size_mm': size}
        Path(path).with_suffix('.json').write_text(json.dumps({'models': projected,
                                                               'window': list(self.window.GetSize())}))
        self.frame += 1
        return path


# ------------------------------------------------------------------------------ main
def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--phantom', required=True, help='MetaImage (.mha) made by ros2vtk-make-phantom')
    parser.add_argument('--robots', type=int, default=1, help='robots (namespaces /robot1, /robot2, ...)')
    parser.add_argument('--spin', choices=('timer', 'event'), default='timer')
    parser.add_argument('--rate', type=float, default=50.0, help='timer spin rate (Hz)')
    parser.add_argument('--offscreen', default='', help='write PNG frames here instead of a window')
    parser.add_argument('--duration', type=float, default=0.0, help='seconds (0: until interrupted)')
    parser.add_argument('--frames-per-second', type=float, default=2.0, help='PNG frames written per second')
    parser.add_argument('--urdf', default=str(REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'),
                        help='the URDF the simulated robot serves (its folder is the base of relative mesh paths)')
    parser.add_argument('--package-path', action='append', default=[],
                        help='folder searched for package:// meshes (besides AMENT_PREFIX_PATH, ROS_PACKAGE_PATH)')
    args = parser.parse_args()

    logic = ros2vtk.vtkROS2Logic()
    logic.SetSpinRate(args.rate)
    scene = logic.GetScene()
    node = logic.GetDefaultROS2Node()

    reader = vtk.vtkMetaImageReader()
    reader.SetFileName(args.phantom)
    reader.Update()
    image = reader.GetOutput()
    registration = ros2vtk.vtkROS2TransformNode()
    registration.SetName('registration:robot_to_image')
    placement = vtk.vtkMatrix4x4()
    placement.SetElement(0, 3, 350.0)   # the phantom lies on a table in front of the robot (mm)
    placement.SetElement(1, 3, -64.0)
    placement.SetElement(2, 3, 150.0)
    registration.SetMatrixTransformToParent(placement)
    scene.AddNode(registration)

    namespaces = ['/'] if args.robots == 1 else [f'/robot{i + 1}' for i in range(args.robots)]
    urdf_folder = Path(args.urdf).resolve().parent
    package_paths = args.package_path or [str(urdf_folder.parent)]  # <package>/urdf/robot.urdf
    robots = {}
    placements = {}
    for index, ns in enumerate(namespaces):
        name = 'robot' if ns == '/' else ns.strip('/')
        prefix = '' if ns == '/' else name + '/'  # ros2vtk-sim-robot --frame-prefix robotN/
        topic = '/robot_description' if ns == '/' else f'{ns}/robot_description'
        robot = node.CreateAndAddRobotNodeFromTopic(name, topic, '', prefix)
        robot.SetMeshBaseFolder(str(urdf_folder))
        for folder in package_paths:
            robot.AddMeshSearchPath(folder)
        # Several robots stand side by side along y, 700 mm apart, through their base transforms.
        placement = vtk.vtkMatrix4x4()
        placement.SetElement(1, 3, 700.0 * (index - (len(namespaces) - 1) / 2))
        placements[ns] = placement
        robots[ns] = robot
    announced = {}  # namespace -> the load last announced (a new description reloads the robot)
    viewer = Viewer(scene, image, registration, args.offscreen or None)
    viewer.reset_camera()
    interactor = None
    if not args.offscreen:
        interactor = vtk.vtkRenderWindowInteractor()
        interactor.SetRenderWindow(viewer.window)
        interactor.SetInteractorStyle(vtk.vtkInteractorStyleTrackballCamera())
        interactor.Initialize()
    if args.offscreen:
        print(f'[demo] no display: writing frames to {args.offscreen}', flush=True)

    start = time.monotonic()
    last_status = start
    last_frame = 0.0
    spins_since = 0
    spin_time = 0.0
    while args.duration <= 0 or time.monotonic() - start < args.duration:
        t0 = time.perf_counter()
        if args.spin == 'event':
            logic.SpinOnWakeUp(1.0 / args.rate)
        else:
            logic.Spin()
        spin_time += time.perf_counter() - t0
        spins_since += 1
        for ns, robot in robots.items():
            if robot.IsLoaded() and announced.get(ns) != robot.GetNumberOfLoads():
                announced[ns] = robot.GetNumberOfLoads()
                robot.GetBaseTransformNode().SetMatrixTransformToParent(placements[ns])
                for warning in robot.GetWarnings().splitlines():
                    print(f'[demo] {ns}: {warning}', flush=True)
                print(f'[demo] robot in {ns}: {robot.GetNumberOfLinks()} links, {robot.GetNumberOfModelNodes()} '
                      f'visuals, loaded in {1000 * robot.GetLastLoadDuration():.1f} ms', flush=True)
                viewer.update()
                viewer.reset_camera()  # frame the robots and the phantom together
        viewer.update()
        now = time.monotonic()
        if args.offscreen:
            if now - last_frame >= 1.0 / args.frames_per_second:
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
            state = '; '.join(f'{ns}: {r.GetRobotState()}, {r.GetNumberOfLinksTracked()}/{r.GetNumberOfLinks()} '
                              f'links tracked' for ns, r in robots.items())
            received = sum(node.GetSubscriberNodeByTopic(r.GetDescriptionTopic()).GetNumberOfMessages()
                           for r in robots.values())
            print(f'[demo] {spins_since / (now - last_status):5.1f} spins/s, spin '
                  f'{1000 * spin_time / max(spins_since, 1):.3f} ms, mean {logic.GetMeanSpinDuration():.3f} ms, '
                  f'robot_description msgs {received}, {state}', flush=True)
            last_status, spins_since, spin_time = now, 0, 0.0
    if args.offscreen:
        print(f'[demo] {viewer.frame} frames in {args.offscreen}', flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
