#!/usr/bin/env python3
"""The SlicerROS2 paper's image-guided motion planning on ros2vtk: a path traced as markup points
in the image is sent to the robot as a geometry_msgs/PoseArray in the robot's frame (what the
paper hands to MoveIt 2 for the dVRK).

    PYTHONPATH=build/python python3 examples/trajectory/trajectory.py \
        [--entry X Y Z] [--target X Y Z] [--points N] [--markups 'x y z; x y z; ...'] \
        [--registration 'r00 r01 r02 tx  r10 ... tz'] [--topic /trajectory] [--seconds S]

The scene (world = the image frame, millimetres):
  * the markups: a model node holding the points (and the polyline through them) in the image
    frame, by default N points on the line from an entry fiducial bead of the phantom to the
    pseudotumour's centre (ros2vtk-make-phantom's layout);
  * a registration transform node mapping robot coordinates to image coordinates (what a fiducial
    registration of the robot to the CT beads gives, the paper's "CTtodVRK" the other way round);
  * the poses: each markup point brought into the robot frame through the registration's inverse,
    oriented with the tool's z axis along the path (entry -> target), collected in a
    vtkTransformCollection and published by a PoseArray publisher node, whose units policy turns
    millimetres into metres on the wire.
It publishes the array whenever a subscriber is matched, again every --period seconds (so late
joiners get it too), and prints JSON status lines.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time

import ros2vtk
import vtk
from ros2vtk.guidance import DEFAULT_REGISTRATION, error_reporter, parse_rigid_matrix

# ros2vtk-make-phantom's layout (160 x 128 x 96 voxels of 1 mm): the bead at (0.5, 0.15) of the
# block's top surface and the pseudotumour's centre, image coordinates in mm.
DEFAULT_ENTRY = [80.0, 19.2, 72.0]
DEFAULT_TARGET = [92.8, 58.88, 40.32]

fail = error_reporter('trajectory')


def markup_points(args) -> vtk.vtkPoints:
    """The traced path in image coordinates (mm): --markups, or --points on entry -> target."""
    points = vtk.vtkPoints()
    points.SetDataTypeToDouble()  # vtkPoints are float by default: 1e-6 mm matters to nobody, but be exact
    if args.markups:
        for item in args.markups.split(';'):
            if not item.strip():
                continue
            try:
                xyz = [float(v) for v in item.replace(',', ' ').split()]
            except ValueError:
                raise ValueError(f'--markups: {item.strip()!r} is not three numbers') from None
            if len(xyz) != 3 or not all(math.isfinite(v) for v in xyz):
                raise ValueError(f'--markups: {item.strip()!r} is not three finite numbers')
            points.InsertNextPoint(xyz)
        if points.GetNumberOfPoints() < 2:
            raise ValueError('--markups: a path needs at least two points')
        return points
    if args.points < 2:
        raise ValueError(f'--points must be at least 2, got {args.points}')
    if not all(math.isfinite(v) for v in args.entry + args.target):
        raise ValueError('--entry/--target must be finite numbers')
    if math.dist(args.entry, args.target) < 1e-6:
        raise ValueError('--entry and --target are the same point: no direction to follow')
    for i in range(args.points):
        t = i / (args.points - 1)
        points.InsertNextPoint([e + t * (g - e) for e, g in zip(args.entry, args.target)])
    return points


def path_model(points: vtk.vtkPoints) -> vtk.vtkPolyData:
    """The markups as polydata: one vertex per point and the polyline through them."""
    polydata = vtk.vtkPolyData()
    polydata.SetPoints(points)
    vertices, line = vtk.vtkCellArray(), vtk.vtkPolyLine()
    line.GetPointIds().SetNumberOfIds(points.GetNumberOfPoints())
    for i in range(points.GetNumberOfPoints()):
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(i)
        line.GetPointIds().SetId(i, i)
    lines = vtk.vtkCellArray()
    lines.InsertNextCell(line)
    polydata.SetVerts(vertices)
    polydata.SetLines(lines)
    return polydata


def frame_along(direction) -> list[list[float]]:
    """Columns x, y, z of a rotation whose z axis is `direction` (normalised), in plain Python."""
    def normalised(v):
        length = math.sqrt(sum(c * c for c in v))
        return [c / length for c in v]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    z = normalised(direction)
    helper = [1.0, 0.0, 0.0] if abs(z[0]) < 0.9 else [0.0, 1.0, 0.0]
    x = normalised(cross(helper, z))
    return [x, cross(z, x), z]


def robot_poses(model_node, registration, collection: vtk.vtkTransformCollection) -> list[list[float]]:
    """Markups (image frame) -> poses in the robot frame through the registration's inverse."""
    image_to_robot = vtk.vtkMatrix4x4()
    image_to_robot.DeepCopy(registration.GetMatrixTransformToParent())
    image_to_robot.Invert()
    # The markups node may itself sit under transforms: start from its world (image) coordinates.
    model_to_world = vtk.vtkMatrix4x4()
    model_node.GetMatrixModelToWorld(model_to_world)
    to_robot = vtk.vtkMatrix4x4()
    vtk.vtkMatrix4x4.Multiply4x4(image_to_robot, model_to_world, to_robot)
    points = model_node.GetPolyData().GetPoints()
    n = points.GetNumberOfPoints()
    # (In double precision all the way: element by element.)
    rows = [[to_robot.GetElement(r, c) for c in range(4)] for r in range(3)]
    robot_points = [[sum(row[c] * v for c, v in enumerate(list(points.GetPoint(i)) + [1.0])) for row in rows]
                    for i in range(n)]
    collection.RemoveAllItems()
    for i, p in enumerate(robot_points):
        a, b = (robot_points[i], robot_points[i + 1]) if i + 1 < n else (robot_points[i - 1], robot_points[i])
        axes = frame_along([bb - aa for aa, bb in zip(a, b)])
        matrix = vtk.vtkMatrix4x4()
        for r in range(3):
            for c in range(3):
                matrix.SetElement(r, c, axes[c][r])
            matrix.SetElement(r, 3, p[r])
        transform = vtk.vtkTransform()
        transform.SetMatrix(matrix)
        collection.AddItem(transform)
    return robot_points


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--entry', type=float, nargs=3, default=DEFAULT_ENTRY, metavar=('X', 'Y', 'Z'),
                        help='first point, image coordinates (mm); default: a fiducial bead of the phantom')
    parser.add_argument('--target', type=float, nargs=3, default=DEFAULT_TARGET, metavar=('X', 'Y', 'Z'),
                        help='last point, image coordinates (mm); default: the pseudotumour centre')
    parser.add_argument('--points', type=int, default=8, help='markup points from entry to target')
    parser.add_argument('--markups', default='', help="explicit path instead: 'x y z; x y z; ...' (image, mm)")
    parser.add_argument('--registration', default=' '.join(str(v) for v in DEFAULT_REGISTRATION),
                        help='robot -> image rigid transform, 12 or 16 numbers row-major, mm')
    parser.add_argument('--topic', default='/trajectory', help='PoseArray out')
    parser.add_argument('--frame-id', default='base', help="the robot frame's name (PoseArray header)")
    parser.add_argument('--period', type=float, default=1.0, help='republish every this many seconds')
    parser.add_argument('--seconds', type=float, default=0.0, help='run time (0: until interrupted)')
    args = parser.parse_args()
    if not (math.isfinite(args.period) and args.period > 0):
        return fail(f'--period must be a positive number, got {args.period}')
    try:
        registration_matrix = parse_rigid_matrix(args.registration)
        points = markup_points(args)
    except ValueError as error:
        return fail(str(error))

    logic = ros2vtk.vtkROS2Logic()
    scene = logic.GetScene()
    node = logic.GetDefaultROS2Node()
    publisher = node.CreateAndAddPublisherNode('PoseArray', args.topic)
    publisher.SetFrameID(args.frame_id)

    markups = ros2vtk.vtkROS2ModelNode()
    markups.SetName('trajectory_markups')
    markups.SetPolyData(path_model(points))
    markups.SetColor(0.2, 0.4, 1.0)
    scene.AddNode(markups)
    registration = ros2vtk.vtkROS2TransformNode()
    registration.SetName('registration:robot_to_image')
    registration.SetMatrixTransformToParent(registration_matrix)
    scene.AddNode(registration)

    collection = vtk.vtkTransformCollection()
    robot_points = robot_poses(markups, registration, collection)
    print(json.dumps({'ready': True, 'points_image_mm': [list(points.GetPoint(i)) for i in range(points.GetNumberOfPoints())],
                      'points_robot_mm': robot_points, 'topic': args.topic, 'frame_id': args.frame_id}), flush=True)

    # A changed registration or markups (e.g. by a script or another observer) re-plans the poses.
    def replan(caller, event) -> None:
        robot_poses(markups, registration, collection)
    registration.AddObserver(ros2vtk.vtkROS2TransformNode.TransformModifiedEvent, replan)

    end = time.monotonic() + args.seconds if args.seconds > 0 else math.inf
    last_sent, sent = -math.inf, 0
    try:
        while time.monotonic() < end:
            logic.SpinOnWakeUp(0.05)
            now = time.monotonic()
            if publisher.GetNumberOfMatchedSubscriptions() > 0 and now - last_sent >= args.period:
                if publisher.Publish(collection) == 1:
                    sent += 1
                    print(json.dumps({'published': sent, 'poses': collection.GetNumberOfItems()}), flush=True)
                else:
                    print(json.dumps({'error': publisher.GetLastConversionError()}), flush=True)
                last_sent = now
    except KeyboardInterrupt:
        pass
    print(json.dumps({'summary': {'published': sent}}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
