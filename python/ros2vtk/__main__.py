"""`python -m ros2vtk` — the first commands a user reaches for, on the VTK-wrapped API:

    python -m ros2vtk nodes                     ROS nodes on the graph (like `ros2 node list`)
    python -m ros2vtk topics                    topics with their types (`ros2 topic list -t`)
    python -m ros2vtk types                     node classes by short name, both directions
    python -m ros2vtk echo TOPIC TYPE [-n N]    messages as YAML, plus the VTK value they become
    python -m ros2vtk params NODE NAME...       parameters of another node
    python -m ros2vtk igtl [...]                serve the scene to 3D Slicer (OpenIGTLink; see igtl -h)

TYPE is a short name (PoseStamped, Image, ...) or a ROS type (geometry_msgs/msg/Point).
ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE apply as in ROS 2.
"""
from __future__ import annotations

import argparse
import sys
import time

import ros2vtk


def _spin(logic, seconds: float, until=lambda: False) -> None:
    ros2vtk.spin_until(logic, until, seconds)


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


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog='python -m ros2vtk', description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--wait', type=float, default=2.0, help='seconds of discovery before listing')
    sub = parser.add_subparsers(dest='command', required=True)
    sub.add_parser('nodes')
    sub.add_parser('topics')
    sub.add_parser('types')
    echo = sub.add_parser('echo')
    echo.add_argument('topic')
    echo.add_argument('type')
    echo.add_argument('-n', '--count', type=int, default=1)
    echo.add_argument('--timeout', type=float, default=30.0)
    params = sub.add_parser('params')
    params.add_argument('node')
    params.add_argument('names', nargs='+')
    from ros2vtk import igtl_cli
    igtl_cli.add_arguments(sub.add_parser('igtl', description=igtl_cli.__doc__,
                                          formatter_class=argparse.RawDescriptionHelpFormatter))
    args = parser.parse_args(argv)

    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    if args.command == 'nodes':
        _spin(logic, args.wait)
        print(node.GetNodeNamesAndNamespaces(), end='')
    elif args.command == 'topics':
        _spin(logic, args.wait)
        print(node.GetTopicNamesAndTypes(), end='')
    elif args.command == 'types':
        print('publishers:  ' + node.GetRegisteredROS2PublisherNodes())
        print('subscribers: ' + node.GetRegisteredROS2SubscriberNodes())
    elif args.command == 'echo':
        subscriber = node.CreateAndAddSubscriberNode(args.type, args.topic)
        if subscriber is None:
            return 1
        printed = 0
        end = time.monotonic() + args.timeout
        while printed < args.count and time.monotonic() < end:
            logic.SpinOnWakeUp(0.1)
            if subscriber.GetNumberOfMessages() > printed:
                printed = subscriber.GetNumberOfMessages()
                print(subscriber.GetLastMessageYAML(), end='')
                print(f'# as {_describe(subscriber.GetLastMessage())}')
                print('---', flush=True)
        if printed < args.count:
            print(f'timeout: {printed} of {args.count} messages on {args.topic}', file=sys.stderr)
            return 3
    elif args.command == 'igtl':
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
