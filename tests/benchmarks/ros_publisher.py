#!/usr/bin/env python3
"""A real ROS 2 publisher (rclpy, the venv's Kilted wheels) for the throughput benchmarks.

    ros_publisher.py TYPE TOPIC --rate HZ --seconds S [--width W --height H --encoding E]
                     [--points N] [--poses N]

TYPE is PoseStamped, Image, PointCloud2 or PoseArray. The message is built once; every publish
writes header.stamp = time.time() just before publish(), so the subscriber's latency is
publish call (rclpy conversion + serialization) + transport + our spin and conversion.
QoS: reliable, volatile, keep last 1000 (as the subscriber). Paced by an absolute schedule
(sleeps only, no busy wait: the machine has two cores and the subscriber needs one).
Prints {"sent": N, "seconds": S, "rate": achieved} on stdout.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time

import rclpy
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy


def build(args):
    if args.type == 'PoseStamped':
        from geometry_msgs.msg import PoseStamped
        msg = PoseStamped()
        msg.header.frame_id = 'world'
        msg.pose.position.x = 0.1
        msg.pose.orientation.w = 1.0
        return msg
    if args.type == 'Image':
        from sensor_msgs.msg import Image
        channels, depth = {'rgb8': (3, 1), 'bgr8': (3, 1), 'mono8': (1, 1), 'mono16': (1, 2)}[args.encoding]
        msg = Image(height=args.height, width=args.width, encoding=args.encoding, is_bigendian=0,
                    step=args.width * channels * depth)
        msg.header.frame_id = 'camera'
        msg.data = os.urandom(msg.step * args.height)
        return msg
    if args.type == 'PointCloud2':
        from sensor_msgs.msg import PointCloud2, PointField
        fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
                  for i, n in enumerate('xyz')]
        msg = PointCloud2(height=1, width=args.points, fields=fields, is_bigendian=False,
                          point_step=12, row_step=12 * args.points, is_dense=True)
        msg.header.frame_id = 'lidar'
        # Finite floats (random bytes could be NaNs): a ramp of float32 values.
        import array
        values = array.array('f', (float(i % 1000) * 0.001 for i in range(3 * args.points)))
        msg.data = values.tobytes()
        return msg
    if args.type == 'PoseArray':
        from geometry_msgs.msg import Pose, PoseArray
        msg = PoseArray()
        msg.header.frame_id = 'world'
        poses = []
        for i in range(args.poses):
            pose = Pose()
            pose.position.x = 0.001 * i
            pose.orientation.w = 1.0
            poses.append(pose)
        msg.poses = poses
        return msg
    raise SystemExit(f'unknown type {args.type}')


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('type')
    parser.add_argument('topic')
    parser.add_argument('--rate', type=float, default=30.0)
    parser.add_argument('--seconds', type=float, default=5.0)
    parser.add_argument('--width', type=int, default=640)
    parser.add_argument('--height', type=int, default=480)
    parser.add_argument('--encoding', default='rgb8')
    parser.add_argument('--points', type=int, default=100000)
    parser.add_argument('--poses', type=int, default=1000)
    parser.add_argument('--wait', type=float, default=20.0)
    args = parser.parse_args()

    rclpy.init()
    node = rclpy.create_node('bench_publisher')
    msg = build(args)
    qos = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
    publisher = node.create_publisher(type(msg), args.topic, qos)
    deadline = time.monotonic() + args.wait
    while publisher.get_subscription_count() == 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    matched = publisher.get_subscription_count()
    time.sleep(0.5)  # let the reliable writer learn the reader's locators before the first sample
    count = int(round(args.rate * args.seconds))
    period = 1.0 / args.rate
    start = next_time = time.monotonic()
    for _ in range(count):
        now_ns = time.time_ns()
        msg.header.stamp.sec = now_ns // 1_000_000_000
        msg.header.stamp.nanosec = now_ns % 1_000_000_000
        publisher.publish(msg)
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    elapsed = time.monotonic() - start
    time.sleep(1.0)  # reliable: give retransmissions time before the writer goes away
    print(json.dumps({'sent': count, 'matched': matched, 'seconds': elapsed,
                      'rate': count / elapsed if elapsed > 0 else 0.0}), flush=True)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
