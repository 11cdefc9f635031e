#!/usr/bin/env python3
"""Our side of the robot load-time measurement (issue 15): loads a robot from a
robot_state_publisher's `robot_description` parameter again and again, each time from nothing
(a new robot node, hence a new parameter client: new DDS endpoints to discover), and prints one
JSON line per load with the time of each phase, measured from the CreateAndAddRobotNode call
(with --new-participant: from the creation of the participant):

    available  the remote node's get_parameters server matched (IsMonitoredNodeReady)
    loaded     the robot is loaded (IsLoaded)
    build      of which parsing and building the robot (GetLastLoadDuration)

'at' is the wall-clock start, to line a load up with a packet capture.

    robot_load_loop.py [--loads N] [--rsp-node /robot_state_publisher] [--timeout S]

Run with Debian's python3 and build/python on PYTHONPATH (run_benchmarks.py does it).
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import ros2vtk


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--loads', type=int, default=50)
    parser.add_argument('--rsp-node', default='/robot_state_publisher')
    parser.add_argument('--timeout', type=float, default=60.0, help='seconds for one load')
    parser.add_argument('--mesh-base-folder', default='', help='SetMeshBaseFolder (relative meshes)')
    parser.add_argument('--new-participant', action='store_true',
                        help='each load in a new vtkROS2Logic (a new DDS participant: discovery from nothing, '
                             'as a newly started program)')
    parser.add_argument('--pause', type=float, default=0.05, help='seconds between loads')
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    print(json.dumps({'ready': True}), flush=True)
    for index in range(args.loads):
        if args.new_participant and index:
            del node, logic
            logic = ros2vtk.vtkROS2Logic()
        start, started_at = time.monotonic(), time.time()
        if args.new_participant:
            node = logic.GetDefaultROS2Node()  # the participant is created here
        robot = node.CreateAndAddRobotNode('loop', args.rsp_node, 'robot_description', '', '')
        robot.SetMeshBaseFolder(args.mesh_base_folder)
        parameters = node.GetParameterNodeByNode(args.rsp_node)
        marks: dict = {}
        while not robot.IsLoaded() and time.monotonic() - start < args.timeout:
            logic.SpinOnWakeUp(0.01)
            if 'available' not in marks and parameters.IsMonitoredNodeReady():
                marks['available'] = time.monotonic() - start
        marks['loaded'] = time.monotonic() - start if robot.IsLoaded() else None
        marks['build'] = robot.GetLastLoadDuration()
        marks['state'] = robot.GetRobotState()
        print(json.dumps(dict(marks, load=index, at=started_at)), flush=True)
        node.RemoveAndDeleteRobotNode('loop')
        logic.SpinFor(args.pause)
    return 0


if __name__ == '__main__':
    sys.exit(main())
