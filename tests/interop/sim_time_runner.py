#!/usr/bin/env python3
"""Our side of the simulated-time interop test (tests/interop/test_sim_time.py): the default ROS
node /slicer of the VTK-wrapped API, as a user's script drives it.

    sim_time_runner.py [--use-sim-time] [--seconds S] [--count N]

Waits until its use_sim_time is on (set here with --use-sim-time, else by another node through
the parameter services) and a /clock time has arrived, and only then, so that any wall-clock stamp
would be a bug, broadcasts world -> tool on /tf and publishes PoseStamped on /sim/pose at 20 Hz,
while a lookup node follows map -> base (broadcast by the simulator in simulated time), until it
sent N of each and the lookup succeeded, or S seconds passed. Prints {"ready": true} once created,
then one JSON object with what it saw.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import ros2vtk
import vtk


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--use-sim-time', action='store_true')
    parser.add_argument('--seconds', type=float, default=25.0)
    parser.add_argument('--count', type=int, default=80)
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    if args.use_sim_time and not node.SetUseSimTime(True):
        print(json.dumps({'error': 'SetUseSimTime refused'}), flush=True)
        return 1
    broadcaster = node.CreateAndAddTf2BroadcasterNode('world', 'tool')
    pose = node.CreateAndAddPublisherNode('PoseStamped', '/sim/pose')
    pose.SetFrameID('world')
    lookup = node.CreateAndAddTf2LookupNode('map', 'base')
    matrix = vtk.vtkMatrix4x4()
    matrix.SetElement(0, 3, 100.0)
    print(json.dumps({'ready': True, 'use_sim_time': node.GetUseSimTime()}), flush=True)

    switched_at = None
    sent = 0
    end = time.monotonic() + args.seconds
    next_send = 0.0
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.02)
        if not (node.GetUseSimTime() and node.GetSimTimeReceived()):
            continue
        if switched_at is None:
            switched_at = node.GetNodeTime()
        now = time.monotonic()
        if now >= next_send:
            next_send = now + 0.05
            broadcaster.Broadcast(matrix)
            pose.Publish(matrix)
            sent += 1
        if sent >= args.count and lookup.GetLookupStatus() == 'ok':
            break
    print(json.dumps({'use_sim_time': node.GetUseSimTime(), 'sim_time_received': node.GetSimTimeReceived(),
                      'first_sim_time': switched_at, 'node_time': node.GetNodeTime(), 'sent': sent,
                      'parameter': node.PrintOwnParameter('use_sim_time'),
                      'lookup_status': lookup.GetLookupStatus(), 'lookup_stamp': lookup.GetLastLookupTime(),
                      'lookup_age': lookup.GetLastLookupAge(),
                      'lookup_x_mm': lookup.GetMatrixTransformToParent().GetElement(0, 3)}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
