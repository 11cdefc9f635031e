"""The downstream node classes from Python: this project's wrapped module (ros2vtk.needle_guide,
built with NEEDLE_GUIDE_PYTHON=ON) joins the installed ros2vtk package, and a NeedleGuide
publisher and subscriber, made by short name through the node-class registry, exchange one
guide pose over ROS 2 (the same process, loopback); the installed OpenIGTLink connector starts.

    PYTHONPATH=<build>/python:<ros2vtk prefix>/python /usr/bin/python3 needle_guide.py

Prints "NeedleGuide Python OK" and exits 0; any failure exits non-zero with the reason.
"""

from __future__ import annotations

import socket
import sys

import ros2vtk
from ros2vtk import spin_until
from vtkmodules.vtkCommonMath import vtkMatrix4x4


def main() -> int:
    if 'needle_guide' not in ros2vtk.extension_modules:
        print(f'the needle_guide module was not imported: {sorted(ros2vtk.extension_modules)} '
              f'from {list(ros2vtk.__path__)}', file=sys.stderr)
        return 1
    publisher_class = ros2vtk.vtkROS2PublisherNeedleGuideNode  # re-exported by the package

    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('NeedleGuide', '/needle_guide')
    sub = node.CreateAndAddSubscriberNode('NeedleGuide', '/needle_guide')
    if not isinstance(pub, publisher_class) \
            or type(sub).__name__ != 'vtkROS2SubscriberNeedleGuideNode':
        print(f'registry gave {type(pub).__name__} / {type(sub).__name__}', file=sys.stderr)
        return 1
    print(f'classes {type(pub).__name__} {type(sub).__name__} topic {pub.GetTopic()}')

    if not spin_until(logic, lambda: pub.GetNumberOfMatchedSubscriptions() > 0
                      and sub.GetNumberOfMatchedPublications() > 0):
        print('publisher and subscriber never matched', file=sys.stderr)
        return 1
    matrix = vtkMatrix4x4()
    matrix.SetElement(0, 3, 100.0)  # mm: 0.1 m on the wire
    matrix.SetElement(1, 3, -20.0)
    matrix.SetElement(2, 3, 35.0)
    if pub.Publish(matrix) != 1:
        print('Publish failed', file=sys.stderr)
        return 1
    if not spin_until(logic, lambda: sub.GetNumberOfMessages() >= 1):
        print('no NeedleGuide message arrived', file=sys.stderr)
        return 1
    received = sub.GetLastMessage()
    translation = [received.GetElement(row, 3) for row in range(3)]
    print('received_mm ' + ' '.join(f'{value:.1f}' for value in translation))
    if any(abs(got - want) > 1e-9 for got, want in zip(translation, (100.0, -20.0, 35.0))):
        print(f'wrong translation {translation}', file=sys.stderr)
        return 1
    if '0.1' not in sub.GetLastMessageYAML():  # metres on the wire
        print(f'unexpected YAML:\n{sub.GetLastMessageYAML()}', file=sys.stderr)
        return 1
    # The installed OpenIGTLink connector (ros2vtk::IGTLConnector): serve the scene on a free port.
    with socket.socket() as probe:  # a free port
        probe.bind(('127.0.0.1', 0))
        port = probe.getsockname()[1]
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    connector.SetPort(port)
    if not connector.Start(node):
        print(f'IGTL connector did not start: {connector.GetLastError()}', file=sys.stderr)
        return 1
    print(f'igtl connector {connector.GetState()}')
    connector.Stop()
    logic.GetScene().Clear()
    print('NeedleGuide Python OK')
    return 0


if __name__ == '__main__':
    sys.exit(main())
