"""`ros2vtk` — the one command line (also `python -m ros2vtk`), on the VTK-wrapped API:

    ros2vtk app [--port N] [--volume FILE] [--host H --allow-remote]   the web app (http://127.0.0.1:8080/)
    ros2vtk demo [demo options]                    the demo: simulated robot + CT phantom (scripts/demo.sh)
    ros2vtk nodes                                  ROS nodes on the graph (like `ros2 node list`)
    ros2vtk topics                                 topics with their types (`ros2 topic list -t`)
    ros2vtk types                                  node classes by short name, both directions
    ros2vtk echo TOPIC TYPE [-n N]                 messages as YAML, plus the VTK value they become
    ros2vtk pub TOPIC TYPE YAML [-r HZ] [-t TIMES]  publish YAML (`ros2 topic pub` syntax)
    ros2vtk params NODE NAME...                    parameters of another node
    ros2vtk igtl [...]                             serve the scene to 3D Slicer (OpenIGTLink; igtl -h)

TYPE is a short name (PoseStamped, Image, ...) or a ROS type (geometry_msgs/msg/Point); `pub` takes
a ROS type. ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE apply as in ROS 2.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

import ros2vtk


def _spin(logic, seconds: float, until=lambda: False) -> bool:
    return ros2vtk.spin_until(logic, until, seconds)


def _describe(value) -> str:
    """One line about what a subscriber's GetLastMessage() returned."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return repr(value)
    name = value.GetClassName()
    if name == 'vtkMatrix4x4':
        return 'vtkMatrix4x4 translation (mm): ' + ', '.join(f'{value.GetElement(i, 3):g}' for i in range(3))
    if name == 'vtkImageData':
        scalars = value.GetPointData().GetScalars()
        return (f'vtkImageData {value.GetDimensions()} x {scalars.GetNumberOfComponents()} '
                f'{scalars.GetDataTypeAsString()}')
    if hasattr(value, 'GetNumberOfPoints'):
        return f'{name} with {value.GetNumberOfPoints()} points (mm)'
    if hasattr(value, 'GetNumberOfRows'):
        return f'vtkTable {value.GetNumberOfRows()} rows x {value.GetNumberOfColumns()} columns'
    if hasattr(value, 'GetNumberOfTuples'):
        return f'{name} of {value.GetNumberOfTuples()} x {value.GetNumberOfComponents()}'
    if hasattr(value, 'GetNumberOfItems'):
        return f'{name} of {value.GetNumberOfItems()}'
    return name


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog='ros2vtk', description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--wait', type=float, default=2.0, help='seconds of discovery before listing')
    sub = parser.add_subparsers(dest='command', required=True)
    app = sub.add_parser('app', help='the web app')
    app.add_argument('--host', default='127.0.0.1', help='address to bind (default: loopback only)')
    app.add_argument('--port', type=int, default=8080, help='port (0: any free one)')
    app.add_argument('--allow-remote', action='store_true', help='allow a --host other than the loopback')
    app.add_argument('--scene', default='', help='a scene file to load at start')
    app.add_argument('--volume', action='append', default=[], metavar='FILE',
                     help='a CT/MRI volume to show in the slice panes and the 3D view (NRRD .nrrd/.nhdr, '
                          'MetaImage .mha/.mhd, NIfTI .nii/.nii.gz); repeatable')
    sub.add_parser('demo', help='the demo (all further arguments go to it)', add_help=False)
    sub.add_parser('nodes', help='ROS nodes on the graph')
    sub.add_parser('topics', help='topics and their types')
    sub.add_parser('types', help='registered node classes')
    echo = sub.add_parser('echo', help='print messages as YAML')
    echo.add_argument('topic')
    echo.add_argument('type')
    echo.add_argument('-n', '--count', type=int, default=1)
    echo.add_argument('--timeout', type=float, default=30.0)
    pub = sub.add_parser('pub', help='publish a message given as YAML')
    pub.add_argument('topic')
    pub.add_argument('type', help='ROS type, e.g. std_msgs/msg/String')
    pub.add_argument('yaml', nargs='?', default='{}', help="the message, e.g. \"{data: 'hi'}\"")
    pub.add_argument('-r', '--rate', type=float, default=1.0, help='messages per second')
    pub.add_argument('-t', '--times', type=int, default=1, help='how many (0: until Ctrl-C)')
    pub.add_argument('--wait-matching', type=float, default=2.0,
                     help='seconds to wait for a subscriber before the first message')
    params = sub.add_parser('params', help="another node's parameters")
    params.add_argument('node')
    params.add_argument('names', nargs='+')
    from ros2vtk import igtl_cli
    igtl_cli.add_arguments(sub.add_parser('igtl', help='serve the scene to 3D Slicer over OpenIGTLink',
                                          description=igtl_cli.__doc__,
                                          formatter_class=argparse.RawDescriptionHelpFormatter))
    return parser


def _say_if_alone(node, waited: float) -> None:
    """A graph listing with nobody in it: what the node uses and what to check (stderr)."""
    advice = node.GetNoPeersAdvice()
    if advice:
        print(f'ros2vtk: found no other ROS 2 participant in {waited:g} s: {advice}', file=sys.stderr)


def _run_demo(argv) -> int:
    """The demo is scripts/demo.sh (it builds, starts the simulated robot and the viewer)."""
    script = Path(__file__).resolve().parents[3] / 'scripts' / 'demo.sh'  # <repo>/build/python/ros2vtk
    if not script.is_file():
        print(f'ros2vtk demo: {script} not found (run it from a source checkout)', file=sys.stderr)
        return 2
    return subprocess.call([str(script), *argv])


def _pub(logic, node, args) -> int:
    publisher = ros2vtk.vtkROS2PublisherGenericNode()
    if '/' not in args.type or not publisher.SetROSType(args.type):
        print(f"ros2vtk pub: '{args.type}' is not a registered ROS type (e.g. std_msgs/msg/String; "
              "`ros2vtk types` lists the short names)", file=sys.stderr)
        return 2
    publisher.SetName(args.topic)
    logic.GetScene().AddNode(publisher)
    if not publisher.AddToROS2Node(node.GetID(), args.topic):
        print(f'ros2vtk pub: cannot publish on {args.topic!r}', file=sys.stderr)
        return 2
    print(f'[pub] waiting up to {args.wait_matching:g} s for a subscriber on {args.topic}', flush=True)
    _spin(logic, args.wait_matching, lambda: publisher.GetNumberOfMatchedSubscriptions() > 0)
    sent = 0
    try:
        while args.times <= 0 or sent < args.times:
            if not publisher.PublishYAML(args.yaml):
                print('ros2vtk pub: the message is not valid for this type (see the error above)', file=sys.stderr)
                return 2
            sent += 1
            print(f'publishing #{sent}: {args.yaml}', flush=True)
            if args.times <= 0 or sent < args.times:
                logic.SpinFor(1.0 / max(args.rate, 1e-3))
        logic.SpinFor(0.3)  # lets reliable delivery finish before the node goes away
    except KeyboardInterrupt:
        print(f'[pub] interrupted after {sent} messages', flush=True)
    return 0


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] == 'demo':
        return _run_demo(argv[1:])
    args = _parser().parse_args(argv)

    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    if node is None:  # the node's error above says why (e.g. a ROS_DISCOVERY_SERVER it cannot use)
        print(f'ros2vtk {args.command}: no ROS node could be created (see the error above)', file=sys.stderr)
        return 2
    if args.command == 'app':
        try:
            import ros2vtk.app as app
        except ImportError as error:
            print(f'ros2vtk app: {error}; run scripts/setup.sh (it installs scripts/requirements-app.txt '
                  'into .venv) and start it with .venv/bin/ros2vtk', file=sys.stderr)
            return 2
        if args.scene and not logic.GetScene().ReadFromXMLFile(args.scene):
            print(f'ros2vtk app: cannot load the scene {args.scene}', file=sys.stderr)
            return 2
        from ros2vtk.app import volumes
        read = []
        for path in args.volume:
            try:
                read.append((volumes.volume_name(path), *volumes.read_volume(path)))
            except ValueError as error:
                print(f'ros2vtk app: {error}', file=sys.stderr)
                return 2

        def add_volumes(served) -> None:
            for name, image, file_to_world in read:
                node = volumes.add_volume_node(logic.GetScene(), image, file_to_world, name)
                served.state.slice_source = node.GetID()
                dims = image.GetDimensions()
                print(f'[app] volume {name}: {dims[0]} x {dims[1]} x {dims[2]} voxels', flush=True)
        print('[app] starting (the first start imports trame and VTK: a few seconds)', flush=True)
        try:
            app.serve(logic, host=args.host, port=args.port, allow_remote=args.allow_remote, on_app=add_volumes)
        except (ValueError, RuntimeError) as error:
            print(f'ros2vtk app: {error}', file=sys.stderr)
            return 2
        except KeyboardInterrupt:
            pass
        print('[app] stopped', flush=True)
    elif args.command == 'nodes':
        _spin(logic, args.wait)
        print(node.GetNodeNamesAndNamespaces(), end='')
        _say_if_alone(node, args.wait)
    elif args.command == 'topics':
        _spin(logic, args.wait)
        print(node.GetTopicNamesAndTypes(), end='')
        _say_if_alone(node, args.wait)
    elif args.command == 'types':
        # Class names, as SlicerROS2's Registered...Nodes(); the short name is the part between
        # vtkROS2Publisher/vtkROS2Subscriber and Node (what CreateAndAdd...Node takes).
        print('publishers:  ' + node.GetRegisteredROS2PublisherNodes())
        print('subscribers: ' + node.GetRegisteredROS2SubscriberNodes())
    elif args.command == 'pub':
        return _pub(logic, node, args)
    elif args.command == 'echo':
        subscriber = node.CreateAndAddSubscriberNode(args.type, args.topic)
        if subscriber is None:
            return 1
        printed = 0
        # The VTK value also where GetLastMessage() is SlicerROS2's message object.
        vtk_value = getattr(subscriber, 'GetLastVTKMessage', subscriber.GetLastMessage)
        end = time.monotonic() + args.timeout
        try:
            while printed < args.count and time.monotonic() < end:
                logic.SpinOnWakeUp(0.1)
                if subscriber.GetNumberOfMessages() > printed:
                    printed = subscriber.GetNumberOfMessages()
                    print(subscriber.GetLastMessageYAML(), end='')
                    print(f'# as {_describe(vtk_value())}')
                    print('---', flush=True)
        except KeyboardInterrupt:
            return 0
        if printed < args.count:
            print(f'timeout: {printed} of {args.count} messages on {args.topic}', file=sys.stderr)
            return 3
    elif args.command == 'igtl':
        from ros2vtk import igtl_cli
        return igtl_cli.run(args, logic, node)
    elif args.command == 'params':
        parameters = node.CreateAndAddParameterNode(args.node)
        for name in args.names:
            parameters.AddParameter(name)
        _spin(logic, max(args.wait, 5.0),
              until=lambda: all(parameters.IsParameterSet(n, True) for n in args.names))
        if not parameters.IsMonitoredNodeReady():
            print(f'{args.node}: not reachable', file=sys.stderr)
            return 3
        for name in args.names:
            print(parameters.PrintParameter(name))
    return 0


if __name__ == '__main__':
    sys.exit(main())
