#!/usr/bin/env python3
"""Our side of scene-level interop tests: the VTK-wrapped `ros2vtk` API, driven like a user's
script, printing what it observed as one JSON object per line.

    scene_runner.py lookup PARENT CHILD [--seconds S]       tf2 lookup node -> matrices (mm)
    scene_runner.py broadcast PARENT CHILD [--static] [--seconds S]
    scene_runner.py params NODE NAME... [--seconds S]        parameter node -> values and events
    scene_runner.py serve [--seconds S]                      own parameters for rclpy clients
    scene_runner.py robot NAME [--source parameter|topic|file]  robot node -> link matrices (mm)
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import threading
import time

import ros2vtk
import vtk


def matrix_rows(matrix) -> list:
    return [[matrix.GetElement(i, j) for j in range(4)] for i in range(4)]


def run(logic, seconds: float, step) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.05)
        if step():
            return


def cmd_lookup(args, logic, node) -> int:
    lookup = node.CreateAndAddTf2LookupNode(args.parent, args.child)
    events = []
    lookup.AddObserver(ros2vtk.vtkROS2TransformNode.TransformModifiedEvent,
                       lambda caller, event: events.append(1))
    print(json.dumps({'ready': True, 'status': lookup.GetLookupStatus()}), flush=True)

    def step():
        return lookup.GetLookupStatus() == 'ok' and len(events) >= args.changes

    run(logic, args.seconds, step)
    run(logic, args.linger, lambda: False)  # more transforms, same matrix: no more events
    print(json.dumps({'status': lookup.GetLookupStatus(), 'error': lookup.GetLastLookupError(),
                      'events': len(events), 'matrix': matrix_rows(lookup.GetMatrixTransformToParent()),
                      'stamp': lookup.GetLastLookupTime()}), flush=True)
    return 0


def cmd_broadcast(args, logic, node) -> int:
    broadcaster = node.CreateAndAddTf2BroadcasterNode(args.parent, args.child)
    broadcaster.SetStatic(args.static)
    matrix = vtk.vtkMatrix4x4()
    # 90° about z, translated (100, -20, 300) mm: on the wire (0.1, -0.02, 0.3) m.
    for i, row in enumerate([[0, -1, 0, 100], [1, 0, 0, -20], [0, 0, 1, 300], [0, 0, 0, 1]]):
        for j, value in enumerate(row):
            matrix.SetElement(i, j, value)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    sent = 0
    while time.monotonic() < end:
        if not args.static or sent == 0:
            sent += 1 if broadcaster.Broadcast(matrix) else 0
        logic.SpinOnWakeUp(0.05)
    print(json.dumps({'sent': sent, 'broadcasts': broadcaster.GetNumberOfBroadcasts()}), flush=True)
    return 0


def cmd_params(args, logic, node) -> int:
    parameters = node.CreateAndAddParameterNode(args.node)
    for name in args.names:
        parameters.AddParameter(name)
    events = []
    parameters.AddObserver(ros2vtk.vtkROS2ParameterNode.ParameterModifiedEvent,
                           lambda caller, event: events.append(1))
    history = []

    def snapshot():
        values = {}
        for name in args.names:
            kind = parameters.GetParameterType(name)
            if kind == 'bool':
                values[name] = parameters.GetParameterAsBool(name)
            elif kind == 'integer':
                values[name] = parameters.GetParameterAsInteger(name)
            elif kind == 'double':
                values[name] = parameters.GetParameterAsDouble(name)
            elif kind == 'string':
                values[name] = parameters.GetParameterAsString(name)
            elif kind in ('bool_array', 'integer_array', 'double_array', 'string_array', 'byte_array'):
                array = {'bool_array': vtk.vtkIntArray, 'integer_array': vtk.vtkTypeInt64Array,
                         'double_array': vtk.vtkDoubleArray, 'string_array': vtk.vtkStringArray,
                         'byte_array': vtk.vtkUnsignedCharArray}[kind]()
                getter = {'bool_array': parameters.GetParameterAsVectorOfBools,
                          'integer_array': parameters.GetParameterAsVectorOfIntegers,
                          'double_array': parameters.GetParameterAsVectorOfDoubles,
                          'string_array': parameters.GetParameterAsVectorOfStrings,
                          'byte_array': parameters.GetParameterAsByteArray}[kind]
                getter(name, array)
                values[name] = [array.GetValue(i) for i in range(array.GetNumberOfValues())]
                if kind == 'bool_array':
                    values[name] = [bool(v) for v in values[name]]
            values[name] = {'type': kind, 'value': values.get(name)}
        if args.with_ready:
            values['_ready'] = parameters.IsMonitoredNodeReady()
        return values

    def step():
        current = snapshot()
        if not history or history[-1] != current:
            history.append(current)
        return args.until_changes and len(history) > args.until_changes

    run(logic, args.seconds, step)
    print(json.dumps({'ready': parameters.IsMonitoredNodeReady(), 'events': len(events),
                      'history': history}), flush=True)
    return 0


def to_plain(value):
    """A converted VTK value as JSON (what tests compare)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    name = value.GetClassName()
    if name == 'vtkMatrix4x4':
        return matrix_rows(value)
    if name == 'vtkTransformCollection':
        value.InitTraversal()
        return [matrix_rows(value.GetItemAsObject(i).GetMatrix()) for i in range(value.GetNumberOfItems())]
    if name == 'vtkTable':
        return {value.GetColumnName(c): [value.GetValue(r, c).ToString() if value.GetColumn(c).IsA('vtkStringArray')
                                         else value.GetValue(r, c).ToDouble() for r in range(value.GetNumberOfRows())]
                for c in range(value.GetNumberOfColumns())}
    if name == 'vtkImageData':
        scalars = value.GetPointData().GetScalars()
        return {'dimensions': list(value.GetDimensions()), 'components': scalars.GetNumberOfComponents(),
                'scalars': [scalars.GetComponent(i, c) for i in range(scalars.GetNumberOfTuples())
                            for c in range(scalars.GetNumberOfComponents())]}
    if name == 'vtkPoints':
        return [list(value.GetPoint(i)) for i in range(value.GetNumberOfPoints())]
    if name == 'vtkMatrix3x3':
        return [[value.GetElement(i, j) for j in range(3)] for i in range(3)]
    if name == 'vtkPolyData' and value.GetPointData().GetArray('Color'):  # a Marker
        lines, ids = [], vtk.vtkIdList()
        for c in range(value.GetLines().GetNumberOfCells()):
            value.GetLines().GetCellAtId(c, ids)
            lines.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
        color = value.GetPointData().GetArray('Color')
        return {'bounds': list(value.GetBounds()), 'color': list(color.GetTuple(0)) if color.GetNumberOfTuples() else [],
                'lines': lines, 'verts': value.GetNumberOfVerts(), 'polys': value.GetNumberOfPolys(),
                'points': [list(value.GetPoint(i)) for i in range(min(value.GetNumberOfPoints(), 10))]}
    if name == 'vtkPolyData' and value.GetNumberOfLines() > 0:  # a polyline: its points and line cells
        lines, ids = [], vtk.vtkIdList()
        for c in range(value.GetLines().GetNumberOfCells()):
            value.GetLines().GetCellAtId(c, ids)
            lines.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
        return {'points': [list(value.GetPoint(i)) for i in range(value.GetNumberOfPoints())], 'lines': lines}
    if name == 'vtkPolyData':
        return [list(value.GetPoint(i)) for i in range(value.GetNumberOfPoints())]
    if value.IsA('vtkDataArray'):
        return [value.GetComponent(i, c) for i in range(value.GetNumberOfTuples())
                for c in range(value.GetNumberOfComponents())]
    return repr(value)


def cmd_sub(args, logic, node) -> int:
    sub = node.CreateAndAddSubscriberNode(args.type, args.topic)
    if args.qos and not sub.SetQoSProfile(args.qos):
        print(json.dumps({'error': f'QoS profile {args.qos} refused'}), flush=True)
        return 1
    print(json.dumps({'ready': True, 'class': sub.GetClassName()}), flush=True)
    next_status = [time.monotonic()]
    if args.status_every > 0:
        # What a panel observes instead of polling: the node's LinkStateChangedEvent (call data:
        # the new link state), with the thread it fired on.
        main_thread = threading.get_ident()

        @vtk.calldata_type(vtk.VTK_STRING)
        def on_link_state(caller, event, state):
            print(json.dumps({'link_event': {'t': time.time(), 'state': state,
                                             'participants': caller.GetNumberOfDiscoveredParticipants(),
                                             'spinning_thread': threading.get_ident() == main_thread}}),
                  flush=True)
        node.AddObserver(ros2vtk.vtkROS2NodeNode.LinkStateChangedEvent, on_link_state)

    def step() -> bool:
        if args.status_every > 0 and time.monotonic() >= next_status[0]:
            # The link status a panel shows (wall-clock stamped, for the test to place it).
            next_status[0] += args.status_every
            print(json.dumps({'status': {'t': time.time(), 'link': node.GetLinkState(),
                                         'participants': node.GetNumberOfDiscoveredParticipants(),
                                         'dropped': node.GetNumberOfDroppedParticipants(),
                                         'matched': sub.GetNumberOfMatchedPublications(),
                                         'since_last': sub.GetSecondsSinceLastMessage(),
                                         'count': sub.GetNumberOfMessages()}}), flush=True)
        return sub.GetNumberOfMessages() >= args.count
    run(logic, args.seconds, step)
    run(logic, args.linger, lambda: False)  # anything beyond --count would show up here
    # Empty carries no value; the VTK value also where Python's GetLastMessage() is SlicerROS2's
    # message object (PoseStamped, PoseArray, ...: GetLastVTKMessage).
    value = None if args.type == 'Empty' else getattr(sub, 'GetLastVTKMessage', sub.GetLastMessage)()
    print(json.dumps({'count': sub.GetNumberOfMessages(), 'rejected': sub.GetNumberOfRejectedMessages(),
                      'rejection': sub.GetLastRejectionReason(),
                      'conversion_error': sub.GetLastConversionError() if hasattr(sub, 'GetLastConversionError') else '',
                      'incompatible_qos': sub.GetNumberOfIncompatibleQoSPublishers(),
                      'incompatible_policy': sub.GetLastIncompatibleQoSPolicy(),
                      'value': to_plain(value), 'slicer_type': sub.GetSlicerType()}), flush=True)
    return 0


def vtk_array(array_class, values, name: str = ''):
    """A VTK array of `values` (named when `name` is given)."""
    array = array_class()
    if name:
        array.SetName(name)
    for value in values:
        array.InsertNextValue(value)
    return array


def vtk_table(columns):
    """A vtkTable from (array class, name, values) columns, in order."""
    table = vtk.vtkTable()
    for array_class, name, values in columns:
        table.AddColumn(vtk_array(array_class, values, name))
    return table


S = math.sqrt(0.5)


def vtk_sample(short: str):
    """What a user would publish for each mapped type (lengths in mm)."""
    def matrix(rows):
        m = vtk.vtkMatrix4x4()
        for i, row in enumerate(rows):
            for j, v in enumerate(row):
                m.SetElement(i, j, v)
        return m
    pose = matrix([[0, -1, 0, 100], [1, 0, 0, -250], [0, 0, 1, 1500], [0, 0, 0, 1]])
    if short in ('PoseStamped', 'TransformStamped', 'Pose', 'Transform', 'Odometry', 'PoseWithCovarianceStamped'):
        return pose
    if short in ('Twist', 'TwistStamped'):
        return vtk_array(vtk.vtkDoubleArray, (0.25, 0.0, -0.5, 0.0, 0.1, 1.5))
    if short == 'Imu':
        return vtk_array(vtk.vtkDoubleArray, (0.0, 0.0, S, S, 0.01, -0.02, 0.03, 0.0, 0.0, 9.81))
    if short == 'PointStamped':
        p = vtk.vtkPoints()
        p.InsertNextPoint(12.5, -40.0, 300.0)
        return p
    if short == 'PolygonStamped':
        p = vtk.vtkPoints()
        for point in ((0.0, 0.0, 0.0), (125.0, 0.0, 0.0), (125.0, 62.5, 0.0)):
            p.InsertNextPoint(*point)
        return p
    if short in ('PoseArray', 'Path'):
        collection = vtk.vtkTransformCollection()
        for m in (pose, matrix([[1, 0, 0, -200], [0, 1, 0, 0], [0, 0, 1, 300], [0, 0, 0, 1]])):
            t = vtk.vtkTransform()
            t.SetMatrix(m)
            collection.AddItem(t)
        return collection
    if short == 'CameraInfo':  # K in pixels, row-major
        k = vtk.vtkMatrix3x3()
        for i, row in enumerate(((525.0, 0.0, 319.5), (0.0, 526.5, 239.5), (0.0, 0.0, 1.0))):
            for j, v in enumerate(row):
                k.SetElement(i, j, v)
        return k
    if short == 'CameraDistortion':
        return vtk_array(vtk.vtkDoubleArray, (-0.28, 0.07, 0.0001, -0.0002, 0.0))
    if short == 'JoyAxes':
        return vtk_array(vtk.vtkFloatArray, (0.5, -1.0, 0.25))
    if short == 'JoyButtons':
        return vtk_array(vtk.vtkIntArray, (0, 1, 1, 0))
    if short in ('Marker', 'MarkerArray'):  # a red line through three points (mm)
        line = vtk.vtkPolyData()
        p = vtk.vtkPoints()
        for point in ((0.0, 0.0, 0.0), (100.0, 0.0, 0.0), (100.0, 200.0, 0.0)):
            p.InsertNextPoint(*point)
        line.SetPoints(p)
        cells = vtk.vtkCellArray()
        cells.InsertNextCell(3)
        for i in (0, 1, 2):
            cells.InsertCellPoint(i)
        line.SetLines(cells)
        color = vtk.vtkUnsignedCharArray()
        color.SetName('Color')
        color.SetNumberOfComponents(4)
        for _ in range(3):
            color.InsertNextTuple4(255, 0, 0, 255)
        line.GetPointData().AddArray(color)
        return line
    if short == 'PathPolyline':
        # points stored out of order; the line cell gives the path's order (mm)
        line = vtk.vtkPolyData()
        p = vtk.vtkPoints()
        for point in ((0.0, 0.0, 0.0), (100.0, -250.0, 1500.0), (-200.0, 0.0, 300.0)):
            p.InsertNextPoint(*point)
        line.SetPoints(p)
        cells = vtk.vtkCellArray()
        cells.InsertNextCell(3)
        for i in (1, 2, 0):
            cells.InsertCellPoint(i)
        line.SetLines(cells)
        return line
    if short == 'Vector3':
        return vtk_array(vtk.vtkDoubleArray, (0.5, -1.5, 2.25))
    if short in ('WrenchStamped', 'Wrench'):
        return vtk_array(vtk.vtkDoubleArray, (1.0, -2.0, 9.81, 0.1, 0.0, -0.05))
    if short == 'DoubleArray':
        return vtk_array(vtk.vtkDoubleArray, (0.5, -1.25, 1e-9, 12345.678))
    if short == 'IntArray':
        return vtk_array(vtk.vtkTypeInt64Array, (7, -9007199254740993, 0), 'ids')
    if short == 'DoubleTable':
        return vtk_table([(vtk.vtkDoubleArray, 'col_0', [0.5, 2.0]),
                          (vtk.vtkDoubleArray, 'col_1', [-1.25, 1e-9])])
    if short == 'PointCloud2':
        cloud = vtk.vtkPolyData()
        p = vtk.vtkPoints()  # float points: FLOAT32 x/y/z on the wire
        p.InsertNextPoint(500.0, 1500.0, -2000.0)
        p.InsertNextPoint(250.0, 0.0, 4000.0)
        cloud.SetPoints(p)
        cloud.GetPointData().AddArray(vtk_array(vtk.vtkFloatArray, (0.5, 1.0), 'intensity'))
        return cloud
    if short == 'JointState':
        # no effort column: an empty effort array
        return vtk_table([(vtk.vtkStringArray, 'name', ('shoulder', 'elbow')),
                          (vtk.vtkDoubleArray, 'position', [0.1, -0.5]),
                          (vtk.vtkDoubleArray, 'velocity', [0.0, 0.5])])
    if short == 'Empty':
        return None
    if short == 'IntTable':
        return vtk_table([(vtk.vtkTypeInt64Array, str(c), col) for c, col in enumerate(([1, 4], [-2, -5], [3, 6]))])
    if short == 'PointCloud':
        p = vtk.vtkPoints()
        p.InsertNextPoint(500.0, 1500.0, -2000.0)
        p.InsertNextPoint(250.0, 0.0, 4000.0)
        return p
    if short in ('Image', 'CompressedImage'):
        image = vtk.vtkImageData()
        image.SetDimensions(3, 2, 1)
        image.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 3)
        for i in range(6):
            for c in range(3):
                image.GetPointData().GetScalars().SetComponent(i, c, 10 * i + c)
        return image
    return {'String': 'Hello world.', 'Bool': True, 'Int': -9007199254740993, 'Double': 3.141592653589793}[short]


def cmd_pub(args, logic, node) -> int:
    pub = node.CreateAndAddPublisherNode(args.type, args.topic)
    if hasattr(pub, 'SetFrameID'):
        pub.SetFrameID('ct_scanner')
    value = vtk_sample(args.type)
    print(json.dumps({'ready': True, 'class': pub.GetClassName()}), flush=True)
    end = time.monotonic() + args.seconds
    sent = 0
    while time.monotonic() < end:
        if pub.GetNumberOfMatchedSubscriptions() > 0:
            sent += pub.Publish(value) if args.type != 'Empty' else pub.Publish()
        logic.SpinOnWakeUp(0.1)
    print(json.dumps({'sent': sent}), flush=True)
    return 0


def cmd_serve(args, logic, node) -> int:
    node.SetParameterAsBool('use_registration', True)
    node.SetParameterAsInteger('frame_count', 42)
    node.SetParameterAsDouble('needle_depth_mm', 37.5)
    node.SetParameterAsString('image_frame', 'ct')

    def array(array_class, values, components=1):
        made = array_class()
        made.SetNumberOfComponents(components)
        for value in values:
            made.InsertNextValue(value)
        return made
    frames = vtk.vtkStringArray()
    for frame in ('ct', 'needle tip'):
        frames.InsertNextValue(frame)
    set_arrays = [node.SetParameterAsBoolArray('flags', array(vtk.vtkIntArray, [1, 0, 2])),
                  node.SetParameterAsIntegerArray('ids', array(vtk.vtkTypeInt64Array, [-2 ** 63, 7, 2 ** 63 - 1])),
                  node.SetParameterAsDoubleArray('weights', array(vtk.vtkDoubleArray, [0.25, -1.5])),
                  node.SetParameterAsByteArray('key', array(vtk.vtkIntArray, [0, 17, 255])),
                  node.SetParameterAsStringArray('frames', frames)]
    # Refused, each leaving the parameter as it was: not whole, not a byte, two components, no
    # array, another type than the parameter has.
    refused = [node.SetParameterAsIntegerArray('ids', array(vtk.vtkDoubleArray, [1.5])),
               node.SetParameterAsByteArray('key', array(vtk.vtkIntArray, [256])),
               node.SetParameterAsDoubleArray('weights', array(vtk.vtkDoubleArray, [1, 2], components=2)),
               node.SetParameterAsStringArray('frames', None),
               node.SetParameterAsIntegerArray('frames', array(vtk.vtkIntArray, [1]))]
    if args.value_limit >= 0:
        node.SetParameterValueSizeLimit(args.value_limit)
    print(json.dumps({'ready': True, 'value_limit': node.GetParameterValueSizeLimit(), 'set_arrays': set_arrays,
                      'refused_arrays': refused}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.05)
    print(json.dumps({'needle_depth_mm': node.PrintOwnParameter('needle_depth_mm'),
                      'image_frame': node.PrintOwnParameter('image_frame')[:200]}), flush=True)
    return 0


def cmd_robot(args, logic, node) -> int:
    """A robot node from a robot_state_publisher's parameter or topic; prints its state once
    loaded, then a snapshot of every link's world matrix (mm) every --every seconds."""
    if args.scene_fixed_frame:
        logic.GetScene().SetFixedFrame(args.scene_fixed_frame)
    if args.source == 'parameter':
        robot = node.CreateAndAddRobotNode(args.name, args.rsp_node, 'robot_description', '', args.tf_prefix)
    elif args.source == 'file':
        robot = node.CreateAndAddRobotNodeFromFile(args.name, args.urdf, '', args.tf_prefix)
    else:
        robot = node.CreateAndAddRobotNodeFromTopic(args.name, args.topic, '', args.tf_prefix)
    for folder in args.mesh_path:
        robot.AddMeshSearchPath(folder)
    robot.SetMeshBaseFolder(args.mesh_base_folder)
    if args.joint_states and not robot.SetJointStatesTopic(args.joint_states):
        print(json.dumps({'error': f'SetJointStatesTopic({args.joint_states}) failed'}), flush=True)
        return 1
    robot.SetPublishTf(args.publish_tf)
    others = {}
    for spec in args.also:  # NAME=TOPIC=PREFIX: more robots in the same scene
        name, topic, prefix = spec.split('=')
        others[name] = node.CreateAndAddRobotNodeFromTopic(name, topic, '', prefix)
        for folder in args.mesh_path:
            others[name].AddMeshSearchPath(folder)
        others[name].SetMeshBaseFolder(args.mesh_base_folder)
    loaded = []
    robot.AddObserver(ros2vtk.vtkROS2RobotNode.RobotLoadedEvent, lambda caller, event: loaded.append(1))
    print(json.dumps({'ready': True, 'state': robot.GetRobotState()}), flush=True)
    run(logic, args.seconds, lambda: robot.IsLoaded() and all(o.IsLoaded() for o in others.values()))
    models = [robot.GetNthModelNode(i) for i in range(robot.GetNumberOfModelNodes())]
    print(json.dumps({'state': robot.GetRobotState(), 'loaded_events': len(loaded),
                      'links': robot.GetLinkNames().split(), 'models': len(models),
                      'placeholders': robot.GetNumberOfPlaceholders(), 'warnings': robot.GetWarnings(),
                      'load_seconds': robot.GetLastLoadDuration(),
                      'model_links': [m.GetAttribute('ros2vtk.link') for m in models],
                      'others': {n: o.GetRobotState() for n, o in others.items()}}), flush=True)
    if args.base_y and robot.GetBaseTransformNode():  # placed by the user: kept across reloads and saved with the scene
        placement = vtk.vtkMatrix4x4()
        placement.SetElement(1, 3, args.base_y)
        robot.GetBaseTransformNode().SetMatrixTransformToParent(placement)
    matrix = vtk.vtkMatrix4x4()

    def world(r):
        links = {}
        for link in r.GetLinkNames().split():
            r.GetLinkTransformNode(link).GetMatrixTransformToWorld(matrix)
            links[link] = matrix_rows(matrix)
        return links

    # Follow until --loads descriptions were loaded, then --follow seconds more.
    start = time.monotonic()
    end = start + args.follow if robot.GetNumberOfLoads() >= args.loads else start + args.seconds + args.follow
    next_snapshot = start
    restored = False
    applied, applied_at = 0, start  # --joint-states-quiet: when the joint states stopped coming
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.02)
        now = time.monotonic()
        if args.restore_after and not restored and now - start >= args.restore_after:
            # The user saves the scene and opens it again: the robot comes back from the file and
            # loads again from its live source.
            xml = logic.GetScene().WriteToXMLString()
            if not logic.GetScene().ReadFromXMLString(xml):
                print(json.dumps({'error': 'scene file not restored'}), flush=True)
                return 1
            node = logic.GetDefaultROS2Node()
            robot = node.GetRobotNodeByName(args.name)
            restored = True
            print(json.dumps({'restored': True, 'state': robot.GetRobotState(),
                              'models_in_file': xml.count('vtkROS2ModelNode')}), flush=True)
        if robot.GetNumberOfLoads() >= args.loads and end > now + args.follow:
            end = now + args.follow
        if args.joint_states_quiet and robot.GetNumberOfJointStatesApplied() != applied:
            applied, applied_at = robot.GetNumberOfJointStatesApplied(), now
        if args.joint_states_quiet and applied and now - applied_at > args.joint_states_quiet:
            end = now  # the publisher is done: stop early (--follow is then only the upper bound)
        if now >= next_snapshot:
            next_snapshot += args.every
            print(json.dumps({'tracked': robot.GetNumberOfLinksTracked(), 'links': world(robot),
                              'loads': robot.GetNumberOfLoads(), 'restored': restored,
                              'state': robot.GetRobotState(), 'models': robot.GetNumberOfModelNodes(),
                              'placeholders': robot.GetNumberOfPlaceholders(),
                              'pose_status': {l: robot.GetLinkPoseStatus(l) for l in robot.GetLinkNames().split()},
                              'joint_states': robot.GetNumberOfJointStatesApplied(),
                              'others': {n: world(o) for n, o in others.items()}}), flush=True)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node-name', default='slicer')
    parser.add_argument('--seconds', type=float, default=15.0)
    parser.add_argument('--log-level', type=int, default=0, help='SetLogLevel of the node (/rosout)')
    parser.add_argument('--reopen', type=int, default=0,
                        help='save and reopen the scene this many times first (a new participant each time)')
    sub = parser.add_subparsers(dest='command', required=True)
    lookup = sub.add_parser('lookup')
    lookup.add_argument('parent')
    lookup.add_argument('child')
    lookup.add_argument('--changes', type=int, default=1)
    lookup.add_argument('--linger', type=float, default=0.0)
    broadcast = sub.add_parser('broadcast')
    broadcast.add_argument('parent')
    broadcast.add_argument('child')
    broadcast.add_argument('--static', action='store_true')
    params = sub.add_parser('params')
    params.add_argument('node')
    params.add_argument('names', nargs='+')
    params.add_argument('--until-changes', type=int, default=0)
    params.add_argument('--with-ready', action='store_true', help='record IsMonitoredNodeReady in the history')
    serve = sub.add_parser('serve')
    serve.add_argument('--value-limit', type=int, default=-1, help='bytes; -1 keeps the default')
    subscriber = sub.add_parser('sub')
    subscriber.add_argument('type')
    subscriber.add_argument('topic')
    subscriber.add_argument('--count', type=int, default=1)
    subscriber.add_argument('--linger', type=float, default=0.0)
    subscriber.add_argument('--qos', default='', help='a QoS profile name (default: the default profile)')
    subscriber.add_argument('--status-every', type=float, default=0.0,
                            help='print the link status (node and subscriber) every this many seconds')
    publisher = sub.add_parser('pub')
    publisher.add_argument('type')
    publisher.add_argument('topic')
    robot = sub.add_parser('robot')
    robot.add_argument('name')
    robot.add_argument('--source', choices=('parameter', 'topic', 'file'), default='parameter')
    robot.add_argument('--urdf', default='', help='the file of --source file')
    robot.add_argument('--rsp-node', default='/robot_state_publisher')
    robot.add_argument('--topic', default='/robot_description')
    robot.add_argument('--tf-prefix', default='')
    robot.add_argument('--mesh-path', action='append', default=[])
    robot.add_argument('--mesh-base-folder', default='')
    robot.add_argument('--also', action='append', default=[], help='NAME=TOPIC=PREFIX: another robot')
    robot.add_argument('--follow', type=float, default=8.0)
    robot.add_argument('--every', type=float, default=0.2)
    robot.add_argument('--loads', type=int, default=1, help='--follow counts from this many loads')
    robot.add_argument('--restore-after', type=float, default=0.0,
                       help='save and reopen the scene this many seconds into following')
    robot.add_argument('--joint-states', default='', help='SetJointStatesTopic: links from joint states (no tf)')
    robot.add_argument('--publish-tf', action='store_true', help='SetPublishTf(True)')
    robot.add_argument('--joint-states-quiet', type=float, default=0.0,
                       help='stop once joint states came and then none for this many seconds')
    robot.add_argument('--base-y', type=float, default=0.0, help='mm: place the robot with its base transform')
    robot.add_argument('--scene-fixed-frame', default='',
                       help="vtkROS2Scene::SetFixedFrame, used by a robot without its own fixed frame")
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    if args.log_level and not node.SetLogLevel(args.log_level):
        print(json.dumps({'error': f'log level {args.log_level} refused'}), flush=True)
        return 1
    for _ in range(args.reopen):
        if not logic.GetScene().ReadFromXMLString(logic.GetScene().WriteToXMLString()):
            print(json.dumps({'error': 'scene not reopened'}), flush=True)
            return 1
        node = logic.GetDefaultROS2Node()
    return {'lookup': cmd_lookup, 'broadcast': cmd_broadcast, 'params': cmd_params,
            'serve': cmd_serve, 'sub': cmd_sub, 'pub': cmd_pub, 'robot': cmd_robot}[args.command](args, logic, node)


if __name__ == '__main__':
    sys.exit(main())
