#!/usr/bin/env python3
"""The rclpy side of tests/interop/test_scene_marker_array.py: publishes on TOPIC the three
MarkerArray messages of the byte fixtures (tests/fixtures/make_cdr_fixtures.py `_marker_array`:
three markers added, the cube deleted, DELETEALL then a cylinder added), GAP seconds apart, once
a subscriber has matched. Prints {"ready": true} when it starts waiting, {"published": n} after each.

    marker_array_peer.py TOPIC [--gap S] [--wait S]
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import rclpy
from visualization_msgs.msg import MarkerArray

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'fixtures'))
from make_cdr_fixtures import _marker_array  # noqa: E402  (the fixtures' own messages)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('topic')
    parser.add_argument('--gap', type=float, default=1.0)
    parser.add_argument('--wait', type=float, default=20.0)
    args = parser.parse_args()
    rclpy.init()
    node = rclpy.create_node('marker_array_peer')
    publisher = node.create_publisher(MarkerArray, args.topic, 10)  # reliable, volatile
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.wait
    while publisher.get_subscription_count() == 0 and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    if publisher.get_subscription_count() == 0:
        print(json.dumps({'error': 'no subscriber matched'}), flush=True)
        return 1
    time.sleep(0.5)  # our reader has matched us too
    for number, message in enumerate(_marker_array(), start=1):
        publisher.publish(message)
        print(json.dumps({'published': number}), flush=True)
        stop = time.monotonic() + args.gap
        while time.monotonic() < stop:
            rclpy.spin_once(node, timeout_sec=0.05)
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
