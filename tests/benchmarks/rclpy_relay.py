#!/usr/bin/env python3
"""Baseline of the round-trip benchmark: the same hop as examples/round_trip/round_trip.py, done
by a plain rclpy node (Kilted wheels, rmw_fastrtps on Fast DDS 3): every Float64 received on
/round_trip/out is published back on /round_trip/back from the subscription callback, with
rclpy.spin (event-driven). Same QoS as the client (reliable, keep last 1000).

    rclpy_relay.py [--seconds S]
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from rclpy.qos import QoSProfile
from std_msgs.msg import Float64


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--seconds', type=float, default=60.0)
    args = parser.parse_args()
    rclpy.init()
    node = rclpy.create_node('rclpy_relay')
    publisher = node.create_publisher(Float64, '/round_trip/back', QoSProfile(depth=1000))
    echoed = [0]

    def relay(message: Float64) -> None:
        publisher.publish(message)
        echoed[0] += 1

    node.create_subscription(Float64, '/round_trip/out', relay, QoSProfile(depth=1000))
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    try:
        while time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.1)
    except KeyboardInterrupt:
        pass
    print(json.dumps({'echoed': echoed[0]}), flush=True)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
