#!/usr/bin/env python3
"""The rclpy side of test_scene_marker_array.py's stamped-tf test: one rclpy node that is both a
tf broadcaster with a history and a MarkerArray publisher, as a robot driver and its RViz
markers would be. Base time B (this node's clock at start, whole seconds). Every 0.2 s it sends
on /tf (tf2_ros's QoS) one TFMessage holding world -> fs at B (x 0.1 m) and at B + 1 s (x 0.3 m),
and on TOPIC one MarkerArray of three 0.1 m CUBEs in frame fs at its origin: red ns s id 1
stamped B, green id 2 stamped B + 1 s, blue id 3 stamped B - 5 s (older than any transform).
Prints {"ready": true, "base": B}; runs S seconds.

    marker_stamps_peer.py TOPIC [--seconds S]
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from builtin_interfaces.msg import Time
from geometry_msgs.msg import TransformStamped
from rclpy.qos import QoSProfile
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import Marker, MarkerArray


def transform(stamp: Time, x: float) -> TransformStamped:
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = 'world'
    t.child_frame_id = 'fs'
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


def cube(marker_id: int, stamp: Time, rgb: tuple) -> Marker:
    m = Marker()
    m.header.frame_id = 'fs'
    m.header.stamp = stamp
    m.ns, m.id, m.type, m.action = 's', marker_id, Marker.CUBE, Marker.ADD
    m.pose.orientation.w = 1.0
    m.scale.x = m.scale.y = m.scale.z = 0.1
    m.color.r, m.color.g, m.color.b = rgb
    m.color.a = 1.0
    return m


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('topic')
    parser.add_argument('--seconds', type=float, default=30.0)
    args = parser.parse_args()
    rclpy.init()
    node = rclpy.create_node('marker_stamps_peer')
    tf = node.create_publisher(TFMessage, '/tf', QoSProfile(depth=100))
    markers = node.create_publisher(MarkerArray, args.topic, 10)
    base = node.get_clock().now().to_msg().sec
    at = [Time(sec=base), Time(sec=base + 1), Time(sec=base - 5)]
    print(json.dumps({'ready': True, 'base': base}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        tf.publish(TFMessage(transforms=[transform(at[0], 0.1), transform(at[1], 0.3)]))
        markers.publish(MarkerArray(markers=[cube(1, at[0], (1.0, 0.0, 0.0)), cube(2, at[1], (0.0, 1.0, 0.0)),
                                             cube(3, at[2], (0.0, 0.0, 1.0))]))
        rclpy.spin_once(node, timeout_sec=0.2)
    node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
