#!/usr/bin/env python3
"""Baseline of the throughput benchmarks: a plain rclpy subscriber (Kilted wheels) on the same
stream as bench_subscribe, same QoS (reliable, keep last 1000). Latency per message = time.time()
in the callback (the message converted to its rclpy Python object) − header stamp.

    ros_subscriber.py TYPE TOPIC [--seconds S] [--idle S]

Prints {"ready": true} once subscribed and {"received": N, "latency_ms": [...]} at the end
(--idle seconds after the last message, or at --seconds).
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

TYPES = {'PoseStamped': ('geometry_msgs.msg', 'PoseStamped'), 'PoseArray': ('geometry_msgs.msg', 'PoseArray'),
         'Image': ('sensor_msgs.msg', 'Image'), 'PointCloud2': ('sensor_msgs.msg', 'PointCloud2')}


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('type', choices=sorted(TYPES))
    parser.add_argument('topic')
    parser.add_argument('--seconds', type=float, default=60.0)
    parser.add_argument('--idle', type=float, default=3.0)
    args = parser.parse_args()
    module, name = TYPES[args.type]
    cls = getattr(__import__(module, fromlist=[name]), name)
    rclpy.init()
    node = rclpy.create_node('bench_rclpy_subscriber')
    latencies: list[float] = []
    last = [0.0]

    def on_message(message) -> None:
        now = time.time()
        stamp = message.header.stamp.sec + 1e-9 * message.header.stamp.nanosec
        latencies.append(1000.0 * (now - stamp))
        last[0] = time.monotonic()

    qos = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
    node.create_subscription(cls, args.topic, on_message, qos)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.1)
        if latencies and time.monotonic() - last[0] > args.idle:
            break
    print(json.dumps({'received': len(latencies), 'latency_ms': latencies}), flush=True)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
