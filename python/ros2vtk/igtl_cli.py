"""`ros2vtk igtl` (`python -m ros2vtk igtl`): serve the ROS 2 scene to an unmodified 3D Slicer over OpenIGTLink.

    ros2vtk igtl --lookup world:tool --robot          # Slicer connects to 127.0.0.1:18944
    ros2vtk igtl --image /camera/image --map Target=tf:world:target

Scene → Slicer: tf lookups and robot links as TRANSFORM (mm), robot visuals as POLYDATA, images
as IMAGE, point clouds as POLYDATA points, strings as STRING, pose arrays as TDATA and a POINT list.
Slicer → ROS: --map DEVICE=tf:PARENT:CHILD or DEVICE=topic:TOPIC:TYPE (PoseStamped, TransformStamped,
PointCloud, PoseArray (from TDATA), Image, String); DEVICE may be a TDATA element's name.
--slicer-scene FILE.mrml: a Slicer scene to drag into Slicer (connector + robot models under their links).
Coordinates: --frame ras (default: ROS x, y, z become Slicer R, A, S) or lps (x, y negated).
Prints one JSON line per state change and a summary at the end.
"""
from __future__ import annotations

import argparse
import json
import time

import ros2vtk


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--port', type=int, default=18944)
    parser.add_argument('--host', default='127.0.0.1',
                        help='server: address to bind (other than 127.0.0.1 only on purpose); client: Slicer host')
    parser.add_argument('--client', action='store_true', help='connect to a Slicer server instead of serving')
    parser.add_argument('--lookup', action='append', default=[], metavar='PARENT:CHILD',
                        help='mirror the tf transform PARENT <- CHILD as TRANSFORM named CHILD')
    parser.add_argument('--robot', nargs='?', const='/robot_description', default='', metavar='TOPIC',
                        help='mirror the robot described on TOPIC (default /robot_description): links, visuals')
    parser.add_argument('--image', action='append', default=[], metavar='TOPIC')
    parser.add_argument('--cloud', action='append', default=[], metavar='TOPIC', help='sensor_msgs/PointCloud2')
    parser.add_argument('--text', action='append', default=[], metavar='TOPIC', help='std_msgs/String')
    parser.add_argument('--poses', action='append', default=[], metavar='TOPIC',
                        help='geometry_msgs/PoseArray as TDATA (one Slicer transform per pose) and a POINT list')
    parser.add_argument('--map', action='append', default=[], metavar='DEVICE=tf:PARENT:CHILD|DEVICE=topic:TOPIC:TYPE')
    parser.add_argument('--frame', choices=['ras', 'lps'], default='ras')
    parser.add_argument('--link-local', action='store_true',
                        help='send meshes once in link coordinates with metadata ros.parent (see docs/slicer.md)')
    parser.add_argument('--slicer-scene', default='', metavar='FILE.mrml',
                        help='write a 3D Slicer scene to open in Slicer (drag and drop): a connector to us and '
                             'the robot models under their link transforms; implies --link-local, and is '
                             'rewritten as the robot loads (see docs/slicer.md)')
    parser.add_argument('--seconds', type=float, default=0.0, help='stop after this long (0: run until Ctrl-C)')
    parser.add_argument('--save-scene', default='', metavar='FILE',
                        help='write the scene (connector settings, mappings, lookups, robot) to FILE once started')
    parser.add_argument('--scene', default='', metavar='FILE',
                        help='restore a scene written by --save-scene (or vtkROS2Scene.WriteToXMLFile) and serve '
                             'its connector; the other scene options are then not used')


def _restore(args: argparse.Namespace, logic):
    """The connector of the scene file args.scene, restored and started as it was saved (or None)."""
    scene = logic.GetScene()
    if not scene.ReadFromXMLFile(args.scene):
        print(json.dumps({'error': f'--scene {args.scene}: not a readable scene file'}), flush=True)
        return None
    connector = scene.GetNthNodeByClass(0, 'vtkROS2IGTLConnectorNode')
    if connector is None:
        print(json.dumps({'error': f'--scene {args.scene}: holds no vtkROS2IGTLConnectorNode'}), flush=True)
        return None
    if connector.GetState() == 'off':
        ros_node = connector.GetStartedROS2Node() or logic.GetDefaultROS2Node()
        connector.Start(ros_node)  # a connector saved while stopped starts now
    return connector


def run(args: argparse.Namespace, logic, node) -> int:
    scene = logic.GetScene()
    if args.scene:
        connector = _restore(args, logic)
        if connector is None:
            return 1
        return _serve(args, logic, connector)
    for pair in args.lookup:
        parent, _, child = pair.partition(':')
        lookup = node.CreateAndAddTf2LookupNode(parent, child)
        lookup.SetName(child)
    if args.robot:
        node.CreateAndAddRobotNodeFromTopic('robot', args.robot)
    for topics, kind in ((args.image, 'Image'), (args.cloud, 'PointCloud2'), (args.text, 'String'),
                         (args.poses, 'PoseArray')):
        for topic in topics:
            subscriber = node.CreateAndAddSubscriberNode(kind, topic)
            if subscriber is None:
                return 1
            subscriber.SetName(topic.strip('/').replace('/', '_'))
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    connector.SetPort(args.port)
    connector.SetHostname(args.host)
    connector.SetClient(args.client)
    connector.SetModelsInWorld(not (args.link_local or args.slicer_scene))
    if args.frame == 'lps':
        import vtk
        lps = vtk.vtkMatrix4x4()
        lps.SetElement(0, 0, -1.0)
        lps.SetElement(1, 1, -1.0)
        connector.SetWorldToSlicer(lps)
    for entry in args.map:
        device, _, target = entry.partition('=')
        kind, _, rest = target.partition(':')
        first, _, second = rest.partition(':')
        ok = connector.MapDeviceToTf(device, first, second) if kind == 'tf' else \
            connector.MapDeviceToTopic(device, first, second) if kind == 'topic' else False
        if not ok:
            print(json.dumps({'error': f'--map {entry}: expected DEVICE=tf:PARENT:CHILD or DEVICE=topic:TOPIC:TYPE'}),
                  flush=True)
            return 2
    if not connector.Start(node):
        print(json.dumps({'error': connector.GetLastError()}), flush=True)
        return 1
    if args.save_scene and not scene.WriteToXMLFile(args.save_scene):
        print(json.dumps({'error': f'--save-scene {args.save_scene}: cannot write'}), flush=True)
        return 1
    return _serve(args, logic, connector)


def _serve(args: argparse.Namespace, logic, connector) -> int:
    """Spins until --seconds or Ctrl-C, printing state changes and events, then a summary."""
    scene = logic.GetScene()
    if connector.GetState() in ('off', 'error'):
        print(json.dumps({'error': connector.GetLastError() or 'the connector is not started'}), flush=True)
        return 1
    print(json.dumps({'ready': True, 'state': connector.GetState(), 'port': connector.GetPort()}), flush=True)
    end = time.monotonic() + args.seconds if args.seconds > 0 else float('inf')
    shown = (None, None)
    log_lines = 0
    slicer_scene = getattr(args, 'slicer_scene', '')
    scene_nodes = -1  # the Slicer scene is rewritten when the scene's node count changed (robot loaded)
    try:
        while time.monotonic() < end:
            logic.SpinOnWakeUp(0.01)
            logic.Spin()  # the connector's sockets are not in the wake-up set: spin at least at 100 Hz
            if slicer_scene and scene.GetNumberOfNodes() != scene_nodes:
                scene_nodes = scene.GetNumberOfNodes()
                models = connector.WriteSlicerScene(slicer_scene)
                if models < 0:
                    print(json.dumps({'error': connector.GetLastError()}), flush=True)
                    return 1
                print(json.dumps({'slicer_scene': slicer_scene, 'models': models}), flush=True)
            state = (connector.GetState(), connector.GetNumberOfClients())
            log = connector.GetEventLog().splitlines()  # the newest 200 lines
            for line in log[log_lines:] if len(log) < 200 else []:
                print(json.dumps({'event': line}), flush=True)
            log_lines = len(log)
            if state != shown:
                shown = state
                print(json.dumps({'state': state[0], 'clients': state[1]}), flush=True)
    except KeyboardInterrupt:
        pass
    received = {}
    for i in range(scene.GetNumberOfNodes()):
        n = scene.GetNthNode(i)
        if connector.GetReceivedNode(n.GetName()) is n:
            received[n.GetName()] = n.GetClassName()
    print(json.dumps({'state': connector.GetState(), 'sent': connector.GetNumberOfMessagesSent(),
                      'received': connector.GetNumberOfMessagesReceived(),
                      'bad': connector.GetNumberOfBadMessages(),
                      'dropped': connector.GetNumberOfDroppedMessages(),
                      'last_error': connector.GetLastError(), 'received_nodes': received}), flush=True)
    connector.Stop()
    return 0
