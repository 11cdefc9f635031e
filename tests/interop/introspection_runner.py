#!/usr/bin/env python3
"""Our side of the introspection parity test (tests/interop/test_introspection.py): the default
ROS node of the VTK-wrapped API (/slicer) with one endpoint of each kind `ros2 node info` lists,
the same kinds, names and types as introspection_peer.py's rclpy node:

    publisher   /introspect/chatter  std_msgs/msg/String
    subscriber  /introspect/pose     geometry_msgs/msg/PoseStamped
    subscriber  /introspect/image    sensor_msgs/msg/Image
    subscriber  /introspect/arrays   test_msgs/msg/Arrays (generic: its description has array defaults)
    service     /introspect/enable   std_srvs/srv/SetBool
    client      /introspect/trigger  std_srvs/srv/Trigger
    action server  /introspect/compute  test_msgs/action/Fibonacci
    action client  /introspect/request  test_msgs/action/Fibonacci

    introspection_runner.py [--seconds S]

and a second node, /slicer_quiet, created with start_type_description_service false (so it
serves no ~/get_type_description), publishing std_msgs/msg/String on /introspect/quiet.

Prints {"ready": true, ...} once everything is created, then spins for S seconds.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import ros2vtk


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--seconds', type=float, default=40.0)
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    created = {
        'publisher': node.CreateAndAddPublisherNode('String', '/introspect/chatter'),
        'subscriber': node.CreateAndAddSubscriberNode('PoseStamped', '/introspect/pose'),
        'image': node.CreateAndAddSubscriberNode('Image', '/introspect/image'),
        'arrays': node.CreateAndAddSubscriberNode('test_msgs/msg/Arrays', '/introspect/arrays'),
        'server': node.CreateAndAddServiceServerNode('std_srvs/srv/SetBool', '/introspect/enable'),
        'client': node.CreateAndAddServiceClientNode('std_srvs/srv/Trigger', '/introspect/trigger'),
        'action_server': node.CreateAndAddActionServerNode('test_msgs/action/Fibonacci', '/introspect/compute'),
        'action_client': node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', '/introspect/request'),
    }
    quiet = ros2vtk.vtkROS2NodeNode()
    logic.GetScene().AddNode(quiet)
    created['quiet_switch'] = quiet if quiet.SetStartTypeDescriptionService(False) else None
    created['quiet_node'] = quiet if quiet.Create('slicer_quiet') else None
    created['quiet_publisher'] = quiet.CreateAndAddPublisherNode('String', '/introspect/quiet')
    missing = [kind for kind, endpoint in created.items() if endpoint is None]
    print(json.dumps({'ready': not missing, 'missing': missing, 'node': node.GetROS2NodeName(),
                      'namespace': node.GetROS2NodeNamespace()}), flush=True)
    if missing:
        return 1
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.05)
    return 0


if __name__ == '__main__':
    sys.exit(main())
