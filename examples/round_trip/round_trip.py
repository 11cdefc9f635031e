#!/usr/bin/env python3
"""The SlicerROS2 paper's round-trip experiment, on ros2vtk: a Float64 subscriber whose observer
publishes every received value straight back. A ROS 2 client (e.g. tests/interop/ros_peer.py
`round_trip`) sends timestamps on /round_trip/out and measures when they return on
/round_trip/back.

    PYTHONPATH=build/python python3 examples/round_trip/round_trip.py [--spin timer|event] [--seconds S] [--depth N]

Every message of a spin is echoed (GetNewMessage(i)), not only the last one, so nothing is lost
when two arrive between spins.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import ros2vtk


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--spin', choices=('timer', 'event'), default='event')
    parser.add_argument('--rate', type=float, default=100.0)
    parser.add_argument('--seconds', type=float, default=30.0)
    parser.add_argument('--depth', type=int, default=0,
                        help='history depth of both endpoints (0: ROS\'s default keep-last 10); the benchmark '
                             'gives the lossy link the client\'s 1000')
    args = parser.parse_args()

    logic = ros2vtk.vtkROS2Logic()
    logic.SetSpinRate(args.rate)
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode('Double', '/round_trip/out')
    pub = node.CreateAndAddPublisherNode('Double', '/round_trip/back')
    if args.depth > 0 and not (sub.SetHistoryDepth(args.depth) and pub.SetHistoryDepth(args.depth)):
        print(f'round_trip: history depth {args.depth} refused (see the error above)', file=sys.stderr)
        return 2
    echoed = [0]

    def on_message(caller, event):
        for i in range(caller.GetNumberOfNewMessages()):
            pub.Publish(caller.GetNewMessage(i))
            echoed[0] += 1

    sub.AddObserver('ModifiedEvent', on_message)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        if args.spin == 'event':
            logic.SpinOnWakeUp(0.1)
        else:
            logic.SpinFor(0.1)
    print(json.dumps({'echoed': echoed[0], 'mean_spin_ms': logic.GetMeanSpinDuration()}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
