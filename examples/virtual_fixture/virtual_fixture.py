#!/usr/bin/env python3
"""The SlicerROS2 paper's virtual fixture (Algorithm 1) on ros2vtk: a forbidden region around a
pseudotumour that holds the robot's tool in place when its tip gets too close.

    PYTHONPATH=build/python python3 examples/virtual_fixture/virtual_fixture.py --phantom P.mha \
        [--registration 'r00 r01 r02 tx  r10 ... tz'] [--margin MM] [--seconds S]

The scene (world = the image frame, millimetres):
  * the pseudotumour's surface, extracted from the CT-like phantom (iso-surface between tissue and
    tumour, fiducial beads left out, largest piece kept), is a model node in the image frame;
  * a registration transform node maps robot coordinates to image coordinates (what a fiducial
    registration of robot to image gives); the tool's transform node, kept equal to the robot's
    tool pose (a PoseStamped subscriber, metres on the wire, millimetres here), hangs under it;
  * the "breach warning": the tool tip's signed distance to the tumour surface, from VTK's
    vtkImplicitPolyDataDistance (negative inside the tumour).
Algorithm 1: for every received tool pose, if the tip is inside the forbidden region (distance <
margin) the example publishes a hold pose (PoseStamped, the last safe pose, in the robot's frame),
otherwise a null wrench (WrenchStamped, zeros) that releases the robot.

Prints one JSON object per line: {"ready": ...} once set up, one {"pose": ...} per received pose,
{"summary": ...} at the end.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

import ros2vtk
import vtk
from ros2vtk.guidance import DEFAULT_REGISTRATION, error_reporter, parse_rigid_matrix

# Hounsfield-like values of ros2vtk-make-phantom: tissue 60, tumour 160, fiducial beads 1500.
DEFAULT_THRESHOLD = 110.0
BEAD_VALUE = 1000.0

fail = error_reporter('virtual_fixture')


def tumour_surface(phantom_path: str, threshold: float) -> vtk.vtkPolyData:
    """The pseudotumour's surface (image frame, mm) from the phantom volume."""
    if not os.path.isfile(phantom_path):
        raise ValueError(f'phantom: no such file {phantom_path!r} (make one with ros2vtk-make-phantom OUT.mha)')
    reader = vtk.vtkMetaImageReader()
    if not reader.CanReadFile(phantom_path):
        raise ValueError(f'phantom: {phantom_path!r} is not a MetaImage (.mha/.mhd) file')
    reader.SetFileName(phantom_path)
    reader.Update()
    image = reader.GetOutput()
    if image is None or image.GetNumberOfPoints() == 0 or image.GetPointData().GetScalars() is None:
        raise ValueError(f'phantom: {phantom_path!r} holds no image')
    # Fiducial beads are denser than the tumour: fold them back to gel so only the tumour is cut.
    beads = vtk.vtkImageThreshold()
    beads.SetInputData(image)
    beads.ThresholdByUpper(BEAD_VALUE)
    beads.SetInValue(10.0)
    beads.ReplaceInOn()
    beads.ReplaceOutOff()
    contour = vtk.vtkFlyingEdges3D()
    contour.SetInputConnection(beads.GetOutputPort())
    contour.SetValue(0, threshold)
    contour.ComputeNormalsOff()
    largest = vtk.vtkPolyDataConnectivityFilter()
    largest.SetInputConnection(contour.GetOutputPort())
    largest.SetExtractionModeToLargestRegion()
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(largest.GetOutputPort())
    clean.Update()
    surface = vtk.vtkPolyData()
    surface.DeepCopy(clean.GetOutput())
    if surface.GetNumberOfCells() == 0:
        raise ValueError(f'phantom: nothing above {threshold} in {phantom_path!r}: no tumour to guard')
    return surface


class BreachWarning:
    """The tool tip's signed distance to a closed surface (negative inside), like SlicerIGT's
    breach warning node, with vtkImplicitPolyDataDistance."""

    def __init__(self, surface: vtk.vtkPolyData, margin: float) -> None:
        self.margin = margin
        self.distance = vtk.vtkImplicitPolyDataDistance()
        self.distance.SetInput(surface)
        # The sign comes from the surface's orientation: make inside negative, whatever the
        # triangle winding of the iso-surface, by checking the centre of mass (inside a tumour).
        centre = vtk.vtkCenterOfMass()
        centre.SetInputData(surface)
        centre.SetUseScalarsAsWeights(False)
        centre.Update()
        self.centre = centre.GetCenter()
        self.sign = -1.0 if self.distance.EvaluateFunction(self.centre) > 0 else 1.0

    def signed_distance(self, point) -> float:
        return self.sign * self.distance.EvaluateFunction(point)

    def breached(self, distance: float) -> bool:
        return distance < self.margin


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--phantom', required=True, help='MetaImage (.mha) made by ros2vtk-make-phantom')
    parser.add_argument('--registration', default=' '.join(str(v) for v in DEFAULT_REGISTRATION),
                        help='robot -> image rigid transform, 12 or 16 numbers row-major, mm')
    parser.add_argument('--margin', type=float, default=5.0, help='forbidden region: within this of the tumour (mm)')
    parser.add_argument('--threshold', type=float, default=DEFAULT_THRESHOLD, help='tumour iso-value')
    parser.add_argument('--pose-topic', default='/vf/tool_pose', help='PoseStamped in: the tool tip in the robot frame')
    parser.add_argument('--hold-topic', default='/vf/hold_pose', help='PoseStamped out: where to hold the tool')
    parser.add_argument('--wrench-topic', default='/vf/wrench', help='WrenchStamped out: null wrench (free motion)')
    parser.add_argument('--seconds', type=float, default=0.0, help='run time (0: until interrupted)')
    args = parser.parse_args()
    if not math.isfinite(args.margin) or args.margin < 0:
        return fail(f'--margin must be a finite number >= 0, got {args.margin}')

    try:
        registration_matrix = parse_rigid_matrix(args.registration)
        surface = tumour_surface(args.phantom, args.threshold)
    except ValueError as error:
        return fail(str(error))

    # Steps 1-5 of Algorithm 1: logic, node, subscriber S1, publishers P1 and P2.
    logic = ros2vtk.vtkROS2Logic()
    scene = logic.GetScene()
    node = logic.GetDefaultROS2Node()
    pose_sub = node.CreateAndAddSubscriberNode('PoseStamped', args.pose_topic)
    hold_pub = node.CreateAndAddPublisherNode('PoseStamped', args.hold_topic)
    wrench_pub = node.CreateAndAddPublisherNode('WrenchStamped', args.wrench_topic)

    # The scene: tumour model (image frame), registration (robot -> image), tool under it.
    tumour = ros2vtk.vtkROS2ModelNode()
    tumour.SetName('pseudotumour')
    tumour.SetPolyData(surface)
    tumour.SetColor(0.9, 0.3, 0.25)
    scene.AddNode(tumour)
    registration = ros2vtk.vtkROS2TransformNode()
    registration.SetName('registration:robot_to_image')
    registration.SetMatrixTransformToParent(registration_matrix)
    scene.AddNode(registration)
    tool = ros2vtk.vtkROS2TransformNode()
    tool.SetName('tool_tip')
    scene.AddNode(tool)
    tool.SetParentTransformNodeID(registration.GetID())

    # Step 6: the breach warning on the tumour surface.
    warning = BreachWarning(surface, args.margin)
    state = {'poses': 0, 'holds': 0, 'releases': 0, 'breached': False, 'last_safe': None}
    tip_world = vtk.vtkMatrix4x4()
    zero_wrench = vtk.vtkDoubleArray()
    for _ in range(6):
        zero_wrench.InsertNextValue(0.0)

    def on_pose(caller, event) -> None:
        """Step 7: every tool pose of the spin, in order (so the last safe pose is exact)."""
        frame_id = caller.GetLastMessageFrameID() or 'base'
        for i in range(caller.GetNumberOfNewMessages()):
            pose = caller.GetNewMessage(i)
            if pose is None:
                continue
            tool.SetMatrixTransformToParent(pose)
            tool.GetMatrixTransformToWorld(tip_world)
            tip = [tip_world.GetElement(r, 3) for r in range(3)]
            distance = warning.signed_distance(tip)
            breached = warning.breached(distance)
            state['poses'] += 1
            if breached:
                # Hold in place: the last pose outside the forbidden region (the current one if
                # the very first pose is already inside).
                hold = state['last_safe'] if state['last_safe'] is not None else pose
                hold_pub.SetFrameID(frame_id)
                sent = hold_pub.Publish(hold)
                state['holds'] += 1
                action = 'hold'
                command = [hold.GetElement(r, 3) for r in range(3)]
            else:
                safe = vtk.vtkMatrix4x4()
                safe.DeepCopy(pose)
                state['last_safe'] = safe
                wrench_pub.SetFrameID(frame_id)
                sent = wrench_pub.Publish(zero_wrench)
                state['releases'] += 1
                action = 'release'
                command = None
            state['breached'] = breached
            print(json.dumps({'pose': state['poses'], 'tip_image_mm': tip, 'distance_mm': distance,
                              'action': action, 'hold_robot_mm': command, 'sent': sent}), flush=True)

    pose_sub.AddObserver('ModifiedEvent', on_pose)
    bounds = surface.GetBounds()
    print(json.dumps({'ready': True, 'tumour_centre_image_mm': list(warning.centre),
                      'tumour_bounds_image_mm': list(bounds), 'tumour_triangles': surface.GetNumberOfCells(),
                      'margin_mm': args.margin, 'topics': [args.pose_topic, args.hold_topic, args.wrench_topic]}),
          flush=True)
    end = time.monotonic() + args.seconds if args.seconds > 0 else math.inf
    try:
        while time.monotonic() < end:
            logic.SpinOnWakeUp(0.05)
    except KeyboardInterrupt:
        pass
    print(json.dumps({'summary': {'poses': state['poses'], 'holds': state['holds'],
                                  'releases': state['releases'], 'rejected': pose_sub.GetNumberOfRejectedMessages()}}),
          flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
