#!/usr/bin/env python3
"""ros2vtk demo: a live robot beside a CT phantom, image-guided style, with no ROS installed.

Run it through scripts/demo.sh (it sets up, builds, starts the simulated robot and this viewer).
What happens here, with the ros2vtk Python API only:
  * our default ROS node (`/slicer`) subscribes the simulated robot's `robot_description`
    (reliable + transient local, as RViz 2 does) and builds the robot from it: one transform node
    per link, kept equal to the tf lookup (fixed frame <- link) on every spin, and one model node
    per URDF visual (meshes and primitives, with their origins, scales and colours);
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
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import ros2vtk
import vtk

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


# ------------------------------------------------------------------------------ robot
def resolve_mesh(uri: str, urdf_dir: Path, package_paths: list[Path]) -> Path | None:
    """package://, file:// and relative mesh URIs (the C++ RobotLoader does the full job)."""
    if uri.startswith('package://'):
        package, _, rest = uri[len('package://'):].partition('/')
        for root in package_paths:
            for candidate in (root / package / rest, root / 'share' / package / rest):
                if candidate.exists():
                    return candidate
            if (root / 'package.xml').exists() and f'<name>{package}</name>' in (root / 'package.xml').read_text():
                if (root / rest).exists():
                    return root / rest
        return None
    if uri.startswith('file://'):
        return Path(uri[len('file://'):])
    path = Path(uri)
    return path if path.is_absolute() else (urdf_dir / path).resolve()


def visual_polydata(geometry, urdf_dir: Path, package_paths: list[Path]):
    """(vtkPolyData in metres, scale) for one <geometry>, or (None, reason)."""
    mesh = geometry.find('mesh')
    if mesh is not None:
        path = resolve_mesh(mesh.get('filename', ''), urdf_dir, package_paths)
        if path is None or not path.exists():
            return None, f"mesh '{mesh.get('filename')}' not found"
        reader = vtk.vtkSTLReader() if path.suffix.lower() == '.stl' else None
        if reader is None:
            return None, f'{path.suffix} meshes need the C++ robot loader'
        reader.SetFileName(str(path))
        reader.Update()
        scale = [float(v) for v in mesh.get('scale', '1 1 1').split()]
        return reader.GetOutput(), scale
    if geometry.find('box') is not None:
        sx, sy, sz = (float(v) for v in geometry.find('box').get('size').split())
        source = vtk.vtkCubeSource()
        source.SetXLength(sx), source.SetYLength(sy), source.SetZLength(sz)
    elif geometry.find('cylinder') is not None:
        c = geometry.find('cylinder')
        source = vtk.vtkCylinderSource()  # VTK's axis is y, URDF's is z
        source.SetRadius(float(c.get('radius'))), source.SetHeight(float(c.get('length')))
        source.SetResolution(32)
        rotate = vtk.vtkTransformPolyDataFilter()
        t = vtk.vtkTransform()
        t.RotateX(90)
        rotate.SetTransform(t)
        rotate.SetInputConnection(source.GetOutputPort())
        source = rotate
    elif geometry.find('sphere') is not None:
        source = vtk.vtkSphereSource()
        source.SetRadius(float(geometry.find('sphere').get('radius')))
        source.SetThetaResolution(24), source.SetPhiResolution(16)
    else:
        return None, 'unsupported geometry'
    source.Update()
    return source.GetOutput(), [1.0, 1.0, 1.0]


def rpy_matrix(xyz, rpy, scale, mm: float):
    """URDF origin (metres, roll-pitch-yaw) x mesh scale -> vtkMatrix4x4 in millimetres."""
    t = vtk.vtkTransform()
    t.PostMultiply()
    t.Scale(*(s * mm for s in scale))
    t.RotateX(math.degrees(rpy[0]))
    t.RotateY(math.degrees(rpy[1]))
    t.RotateZ(math.degrees(rpy[2]))
    t.Translate(*(v * mm for v in xyz))
    return t.GetMatrix()


class DemoRobot:
    """A robot in the scene from its URDF: transform nodes per link driven by tf lookups from
    the fixed frame, model nodes per visual. (The C++ vtkROS2RobotNode does this with every mesh
    format; this stand-in covers the shipped arm's STL meshes and primitives.)"""

    def __init__(self, node, scene, urdf: str, urdf_dir: Path, package_paths: list[Path], prefix: str = ''):
        root = ElementTree.fromstring(urdf)
        materials = {m.get('name'): [float(v) for v in m.find('color').get('rgba').split()]
                     for m in root.findall('material') if m.find('color') is not None}
        children = {j.find('child').get('link') for j in root.findall('joint')}
        links = [l.get('name') for l in root.findall('link')]
        self.fixed_frame = prefix + next(l for l in links if l not in children)
        self.lookups = {}
        self.models = []
        self.warnings = []
        for link in root.findall('link'):
            name = link.get('name')
            lookup = node.CreateAndAddTf2LookupNode(self.fixed_frame, prefix + name) \
                if prefix + name != self.fixed_frame else None
            self.lookups[name] = lookup
            for visual in link.findall('visual'):
                polydata, info = visual_polydata(visual.find('geometry'), urdf_dir, package_paths)
                if polydata is None:
                    self.warnings.append(f"link '{name}': {info}")
                    continue
                origin = visual.find('origin')
                xyz = [float(v) for v in (origin.get('xyz', '0 0 0') if origin is not None else '0 0 0').split()]
                rpy = [float(v) for v in (origin.get('rpy', '0 0 0') if origin is not None else '0 0 0').split()]
                model = ros2vtk.vtkROS2ModelNode()
                model.SetName(f'{prefix}{name}_model')
                model.SetPolyData(polydata)
                model.SetMatrixModelToParent(rpy_matrix(xyz, rpy, info, 1000.0))
                material = visual.find('material')
                if material is not None:
                    color = material.find('color')
                    rgba = [float(v) for v in color.get('rgba').split()] if color is not None \
                        else materials.get(material.get('name'), [0.8, 0.8, 0.8, 1])
                    model.SetColor(*rgba[:3])
                scene.AddNode(model)
                if lookup is not None:
                    model.SetParentTransformNodeID(lookup.GetID())
                self.models.append(model)

    def state(self) -> str:
        lookups = [l for l in self.lookups.values() if l is not None]
        ok = sum(1 for l in lookups if l.GetLookupStatus() == 'ok')
        return f'{ok}/{len(lookups)} links tracked'


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
        for i in range(models.GetNumberOfItems()):
            model = models.GetItemAsObject(i)
            actor = self.actors.get(model.GetID())
            if actor is None:
                mapper = vtk.vtkPolyDataMapper()
                mapper.SetInputData(model.GetPolyData())
                actor = vtk.vtkActor()
                actor.SetMapper(mapper)
                actor.GetProperty().SetColor(*model.GetColor())
                actor.SetUserMatrix(vtk.vtkMatrix4x4())
                self.renderer.AddActor(actor)
                self.actors[model.GetID()] = actor
            model.GetMatrixModelToWorld(actor.GetUserMatrix())
            actor.GetUserMatrix().Modified()
            actor.Modified()

    def reset_camera(self) -> None:
        camera = self.renderer.GetActiveCamera()
        camera.SetViewUp(0, 0, 1)
        # Robot (about 1.5 m tall at the origin) and phantom (in front of it) in one view.
        camera.SetFocalPoint(280, 0, 600)
        camera.SetPosition(2300, -2500, 1600)
        camera.SetViewAngle(24.0)  # idempotent, unlike Zoom()
        self.renderer.ResetCameraClippingRange()

    def render(self) -> str | None:
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
    parser.add_argument('--package-path', action='append', default=[str(REPO / 'examples' / 'robots' / 'surgical_arm')])
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
    descriptions = {}
    for ns in namespaces:
        topic = '/robot_description' if ns == '/' else f'{ns}/robot_description'
        sub = node.CreateAndAddSubscriberNode('String', topic)
        sub.SetQoSProfile('transient_local')
        descriptions[ns] = sub
    robots = {}
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
        for index, (ns, sub) in enumerate(descriptions.items()):
            if ns not in robots and sub.GetNumberOfMessages() > 0:
                prefix = '' if ns == '/' else ns.strip('/') + '/'
                robots[ns] = DemoRobot(node, scene, sub.GetLastMessage(),
                                       REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf',
                                       [Path(p) for p in args.package_path], prefix)
                for w in robots[ns].warnings:
                    print(f'[demo] {ns}: {w}', flush=True)
                print(f'[demo] robot in {ns}: {len(robots[ns].models)} visuals, fixed frame '
                      f'{robots[ns].fixed_frame}', flush=True)
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
            received = sum(s.GetNumberOfMessages() for s in descriptions.values())
            state = '; '.join(f'{ns}: {r.state()}' for ns, r in robots.items()) or 'waiting for robot_description'
            print(f'[demo] {spins_since / (now - last_status):5.1f} spins/s, spin '
                  f'{1000 * spin_time / max(spins_since, 1):.3f} ms, mean {logic.GetMeanSpinDuration():.3f} ms, '
                  f'robot_description msgs {received}, {state}', flush=True)
            last_status, spins_since, spin_time = now, 0, 0.0
    if args.offscreen:
        print(f'[demo] {viewer.frame} frames in {args.offscreen}', flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
