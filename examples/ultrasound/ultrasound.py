#!/usr/bin/env python3
"""The SlicerROS2 paper's simulated robotic ultrasound on ros2vtk: ultrasound frames
(sensor_msgs/Image) from a simulator and the probe's pose (geometry_msgs/PoseStamped) arrive over
ROS 2; each frame is shown as a slice placed at the probe's pose in the 3D view (what SlicerIGT's
"Volume Reslice Driver" does in the paper's Fig. 9).

    PYTHONPATH=build/python python3 examples/ultrasound/ultrasound.py [--phantom P.mha] \
        [--registration 'r00 ... tz'] [--pixel-spacing MM] [--offscreen OUT.png] [--seconds S]

The scene (world = the image frame, millimetres):
  * a registration transform node mapping robot coordinates to image coordinates; the probe's
    transform node, kept equal to the received probe pose (robot frame, metres on the wire), hangs
    under it;
  * the ultrasound frame: an Image subscriber's vtkImageData (mono8, rows as a picture: VTK row 0
    at the bottom), shown by a vtkImageActor whose user matrix is the probe's world matrix times the
    pixel -> probe placement: the transducer face is the picture's top row, centred on the probe's
    origin along its x axis; depth runs along the probe's +z; the image plane is the probe's x-z
    plane; pixels are --pixel-spacing mm square (an Image message carries no spacing);
  * for context (with --phantom): the phantom's outline and the pseudotumour's surface.
Frames are paired with the probe pose of the same header stamp (or the newest one not newer); when
several frames arrive within one spin the newest is shown (a viewer keeps up, it does not queue).
With --offscreen it renders without a window and writes the view to a PNG after every frame.

Prints JSON lines: {"ready": ...}, one {"frame": ...} per shown frame (dimensions, a pixel checksum
in picture order, where its corners are in the world), {"summary": ...} at the end.
"""
from __future__ import annotations

import argparse
import collections
import json
import math
import os
import sys
import time
import zlib

import ros2vtk
import vtk
from ros2vtk.guidance import DEFAULT_REGISTRATION, error_reporter, parse_rigid_matrix

fail = error_reporter('ultrasound')


def pixel_to_probe(width: int, height: int, spacing: float) -> vtk.vtkMatrix4x4:
    """vtkImageData coordinates (i*s, j*s, 0) -> probe frame (mm): x lateral, centred; z depth,
    the top row (VTK row height-1) on the transducer face; the image plane is the probe's x-z."""
    matrix = vtk.vtkMatrix4x4()
    matrix.DeepCopy([1, 0, 0, -(width - 1) * spacing / 2.0,
                     0, 0, 1, 0,
                     0, -1, 0, (height - 1) * spacing,
                     0, 0, 0, 1])
    return matrix


def transform_point(matrix: vtk.vtkMatrix4x4, point) -> list[float]:
    p = list(point) + [1.0]
    return [sum(matrix.GetElement(r, c) * p[c] for c in range(4)) for r in range(3)]


def picture_order_checksum(image: vtk.vtkImageData) -> dict:
    """Sum and CRC-32 of the pixels in picture order (top row first, as the ROS message has
    them), so they compare with the sender's."""
    scalars = image.GetPointData().GetScalars()
    data = bytes(memoryview(scalars))
    width, height = image.GetDimensions()[:2]
    row_bytes = len(data) // max(height, 1)
    rows = [data[r * row_bytes:(r + 1) * row_bytes] for r in range(height)]
    picture = b''.join(reversed(rows))
    return {'sum': sum(picture), 'crc32': zlib.crc32(picture), 'bytes': len(picture),
            'scalar_type': scalars.GetDataTypeAsString(), 'components': scalars.GetNumberOfComponents()}


class View:
    def __init__(self, offscreen: str, phantom: str | None, size=(800, 600)) -> None:
        self.renderer = vtk.vtkRenderer()
        self.renderer.SetBackground(0.1, 0.1, 0.2)
        self.window = vtk.vtkRenderWindow()
        self.window.SetSize(*size)
        self.window.AddRenderer(self.renderer)
        self.window.SetWindowName('ros2vtk ultrasound')
        self.offscreen = offscreen
        if offscreen:
            self.window.SetOffScreenRendering(1)
        self.slice = vtk.vtkImageActor()
        self.slice.SetUserMatrix(vtk.vtkMatrix4x4())
        self.slice.GetProperty().SetColorWindow(255)
        self.slice.GetProperty().SetColorLevel(127.5)
        self.slice.VisibilityOff()
        self.renderer.AddActor(self.slice)
        if phantom:
            self._context(phantom)
        self.interactor = None
        if not offscreen:
            self.interactor = vtk.vtkRenderWindowInteractor()
            self.interactor.SetRenderWindow(self.window)
            self.interactor.SetInteractorStyle(vtk.vtkInteractorStyleTrackballCamera())
            self.interactor.Initialize()
        self.framed = False

    def _context(self, phantom: str) -> None:
        reader = vtk.vtkMetaImageReader()
        reader.SetFileName(phantom)
        outline = vtk.vtkOutlineFilter()
        outline.SetInputConnection(reader.GetOutputPort())
        tumour = vtk.vtkFlyingEdges3D()
        tumour.SetInputConnection(reader.GetOutputPort())
        tumour.SetValue(0, 110)
        largest = vtk.vtkPolyDataConnectivityFilter()  # the tumour, not the (denser) fiducial beads
        largest.SetInputConnection(tumour.GetOutputPort())
        largest.SetExtractionModeToLargestRegion()
        for source, colour, opacity in ((outline, (1, 1, 1), 1.0), (largest, (0.9, 0.3, 0.25), 0.5)):
            mapper = vtk.vtkPolyDataMapper()
            mapper.SetInputConnection(source.GetOutputPort())
            mapper.ScalarVisibilityOff()
            actor = vtk.vtkActor()
            actor.SetMapper(mapper)
            actor.GetProperty().SetColor(*colour)
            actor.GetProperty().SetOpacity(opacity)
            self.renderer.AddActor(actor)

    def show(self, image: vtk.vtkImageData, to_world: vtk.vtkMatrix4x4) -> dict:
        self.slice.GetMapper().SetInputData(image)
        self.slice.SetUserMatrix(to_world)
        self.slice.VisibilityOn()
        self.slice.Modified()
        if not self.framed:
            # From the front, a little above and to the side, image z up (the CT's superior).
            camera = self.renderer.GetActiveCamera()
            camera.SetFocalPoint(0, 0, 0)
            camera.SetPosition(-0.45, -1.0, 0.55)
            camera.SetViewUp(0, 0, 1)
            self.renderer.ResetCamera()
            self.framed = True
        self.renderer.ResetCameraClippingRange()
        self.window.Render()
        if self.interactor is not None:
            self.interactor.ProcessEvents()
        return self.write_png()

    def write_png(self) -> dict:
        if not self.offscreen:
            return {}
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.Update()
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(self.offscreen)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        return {'png': self.offscreen, 'window': list(self.window.GetSize())}

    def display_point(self, world) -> list[float]:
        coordinate = vtk.vtkCoordinate()
        coordinate.SetCoordinateSystemToWorld()
        coordinate.SetValue(*world)
        return list(coordinate.GetComputedDoubleDisplayValue(self.renderer))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--image-topic', default='/us/image', help='sensor_msgs/Image in (the ultrasound frames)')
    parser.add_argument('--pose-topic', default='/us/probe_pose', help='PoseStamped in (the probe, robot frame)')
    parser.add_argument('--registration', default=' '.join(str(v) for v in DEFAULT_REGISTRATION),
                        help='robot -> image rigid transform, 12 or 16 numbers row-major, mm')
    parser.add_argument('--pixel-spacing', type=float, default=0.5, help='ultrasound pixel size (mm)')
    parser.add_argument('--phantom', default='', help='MetaImage shown for context (outline, tumour)')
    parser.add_argument('--offscreen', default='', help='render without a window, into this PNG')
    parser.add_argument('--frames', type=int, default=0, help='stop after this many frames (0: no limit)')
    parser.add_argument('--idle-exit', type=float, default=0.0,
                        help='stop this many seconds after the last frame (0: never)')
    parser.add_argument('--seconds', type=float, default=0.0, help='run time (0: until interrupted)')
    args = parser.parse_args()
    if not (math.isfinite(args.pixel_spacing) and args.pixel_spacing > 0):
        return fail(f'--pixel-spacing must be a positive number of mm, got {args.pixel_spacing}')
    if args.phantom and not os.path.isfile(args.phantom):
        return fail(f'phantom: no such file {args.phantom!r}')
    if args.offscreen and not os.path.isdir(os.path.dirname(os.path.abspath(args.offscreen))):
        return fail(f'--offscreen: no directory for {args.offscreen!r}')
    try:
        registration_matrix = parse_rigid_matrix(args.registration)
    except ValueError as error:
        return fail(str(error))

    logic = ros2vtk.vtkROS2Logic()
    scene = logic.GetScene()
    node = logic.GetDefaultROS2Node()
    image_sub = node.CreateAndAddSubscriberNode('Image', args.image_topic)
    pose_sub = node.CreateAndAddSubscriberNode('PoseStamped', args.pose_topic)
    registration = ros2vtk.vtkROS2TransformNode()
    registration.SetName('registration:robot_to_image')
    registration.SetMatrixTransformToParent(registration_matrix)
    scene.AddNode(registration)
    probe = ros2vtk.vtkROS2TransformNode()
    probe.SetName('us_probe')
    scene.AddNode(probe)
    probe.SetParentTransformNodeID(registration.GetID())
    view = View(args.offscreen, args.phantom or None)
    view.window.Render()  # builds the context pipeline now, not on the first frame

    poses: collections.deque = collections.deque(maxlen=100)  # (stamp, matrix in mm, robot frame)
    pending = None  # (stamp, vtkImageData, arrival time): a frame newer than every pose so far
    shown = 0
    last_frame_time = math.inf
    frame_image = vtk.vtkImageData()
    print(json.dumps({'ready': True, 'topics': [args.image_topic, args.pose_topic],
                      'pixel_spacing_mm': args.pixel_spacing}), flush=True)

    def pose_for(stamp: float):
        """The probe pose of this stamp, or the newest not newer; None if all are newer or none."""
        best = None
        for pose_stamp, matrix in poses:
            if pose_stamp <= stamp + 1e-6 and (best is None or pose_stamp >= best[0]):
                best = (pose_stamp, matrix)
        return best

    def show(stamp: float, image: vtk.vtkImageData, pose) -> None:
        nonlocal shown, last_frame_time
        last_frame_time = time.monotonic()
        pose_stamp, pose_matrix = pose
        probe.SetMatrixTransformToParent(pose_matrix)
        probe_to_world = vtk.vtkMatrix4x4()
        probe.GetMatrixTransformToWorld(probe_to_world)
        width, height = image.GetDimensions()[:2]
        s = args.pixel_spacing
        image.SetSpacing(s, s, 1.0)
        image.SetOrigin(0.0, 0.0, 0.0)
        to_world = vtk.vtkMatrix4x4()
        vtk.vtkMatrix4x4.Multiply4x4(probe_to_world, pixel_to_probe(width, height, s), to_world)
        rendered = view.show(image, to_world)
        # Picture corners (centres of the corner pixels) where the actor puts them.
        actor_matrix = view.slice.GetMatrix()
        corners = {'top_left': transform_point(actor_matrix, (0, (height - 1) * s, 0)),
                   'top_right': transform_point(actor_matrix, ((width - 1) * s, (height - 1) * s, 0)),
                   'bottom_left': transform_point(actor_matrix, (0, 0, 0))}
        centre = transform_point(actor_matrix, ((width - 1) * s / 2, (height - 1) * s / 2, 0))
        shown += 1
        report = {'frame': shown, 'stamp': stamp, 'pose_stamp': pose_stamp,
                  'dimensions': list(image.GetDimensions()), 'encoding_checksum': picture_order_checksum(image),
                  'corners_world_mm': corners, 'centre_world_mm': centre}
        if rendered:
            report.update(rendered)
            report['centre_display'] = view.display_point(centre)
        print(json.dumps(report), flush=True)

    end = time.monotonic() + args.seconds if args.seconds > 0 else math.inf
    try:
        while time.monotonic() < end and (args.frames <= 0 or shown < args.frames) and \
                not (args.idle_exit > 0 and time.monotonic() - last_frame_time > args.idle_exit):
            logic.SpinOnWakeUp(0.05)
            if pose_sub.GetNumberOfNewMessages() > 0:
                matrix = vtk.vtkMatrix4x4()
                if pose_sub.GetLastMessage(matrix):
                    poses.append((pose_sub.GetLastMessageTime(), matrix))
            if image_sub.GetNumberOfNewMessages() > 0:
                image = vtk.vtkImageData()
                if image_sub.GetLastMessage(image):
                    pending = (image_sub.GetLastMessageTime(), image, time.monotonic())
                else:
                    print(json.dumps({'rejected_frame': image_sub.GetLastConversionError()}), flush=True)
            if pending is not None:
                stamp, image, arrived = pending
                pose = pose_for(stamp)
                newest = poses[-1][0] if poses else None
                # Its own pose may still be on the way: wait for it a little, then take the newest.
                if pose is not None and (abs(pose[0] - stamp) < 1e-6 or time.monotonic() - arrived > 0.3
                                         or (newest is not None and newest > stamp)):
                    frame_image.DeepCopy(image)
                    show(stamp, frame_image, pose)
                    pending = None
                elif pose is None and poses and time.monotonic() - arrived > 0.3:
                    frame_image.DeepCopy(image)
                    show(stamp, frame_image, poses[-1])
                    pending = None
            if view.interactor is not None:
                view.interactor.ProcessEvents()
    except KeyboardInterrupt:
        pass
    print(json.dumps({'summary': {'frames_shown': shown, 'frames_received': image_sub.GetNumberOfMessages(),
                                  'poses_received': pose_sub.GetNumberOfMessages(),
                                  'rejected': image_sub.GetNumberOfRejectedMessages()}}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
