#!/usr/bin/env python3
"""The rclpy side of the simulated-time interop test: a simulator and an observer in one node.

    sim_time_peer.py TARGET --epoch SEC [--seconds S] [--count N]

- Publishes rosgraph_msgs/Clock on /clock every 10 ms, best effort as simulators do, starting at
  `--epoch` seconds and advancing with the wall clock (a simulator at real-time speed).
- Broadcasts map -> base on /tf stamped with that simulated time (our lookup must take it).
- Switches use_sim_time on for node TARGET with rclpy's SetParameters call (AsyncParameterClient),
  as `ros2 param set TARGET use_sim_time true` does.
- Records the stamps of what TARGET sends: /tf transforms with child frame `tool`, and
  geometry_msgs/PoseStamped on /sim/pose, until it has N of each or S seconds passed.
- Records TARGET's parameter events (the use_sim_time change among them) with their stamps.
Prints one JSON object: the set result, use_sim_time read back, the simulated time range
published, and every stamp received (seconds as floats).
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
import rclpy.parameter_client
from builtin_interfaces.msg import Time
from geometry_msgs.msg import PoseStamped, TransformStamped
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rcl_interfaces.msg import ParameterEvent
from rosgraph_msgs.msg import Clock
from tf2_msgs.msg import TFMessage


def to_seconds(stamp: Time) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('target')
    parser.add_argument('--epoch', type=float, required=True)
    parser.add_argument('--seconds', type=float, default=30.0)
    parser.add_argument('--count', type=int, default=20)
    args = parser.parse_args()

    rclpy.init()
    node = rclpy.create_node('sim_time_peer')
    start = time.monotonic()
    published = {'first': None, 'last': None}

    def sim_now() -> Time:
        seconds = args.epoch + (time.monotonic() - start)
        return Time(sec=int(seconds), nanosec=int((seconds % 1.0) * 1e9))

    clock_pub = node.create_publisher(Clock, '/clock', QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))
    tf_pub = node.create_publisher(TFMessage, '/tf', QoSProfile(depth=100))

    def tick() -> None:
        stamp = sim_now()
        clock_pub.publish(Clock(clock=stamp))
        published['first'] = published['first'] if published['first'] is not None else to_seconds(stamp)
        published['last'] = to_seconds(stamp)
        transform = TransformStamped()
        transform.header.stamp = stamp
        transform.header.frame_id = 'map'
        transform.child_frame_id = 'base'
        transform.transform.translation.x = 0.5
        transform.transform.rotation.w = 1.0
        tf_pub.publish(TFMessage(transforms=[transform]))

    node.create_timer(0.01, tick)
    tf_stamps: list = []
    pose_stamps: list = []

    def on_tf(message: TFMessage) -> None:
        tf_stamps.extend(to_seconds(t.header.stamp) for t in message.transforms if t.child_frame_id == 'tool')

    node.create_subscription(TFMessage, '/tf', on_tf, QoSProfile(depth=100))
    node.create_subscription(PoseStamped, '/sim/pose', lambda m: pose_stamps.append(to_seconds(m.header.stamp)), 10)
    events: list = []  # TARGET's parameter events: (changed names, stamp)

    def on_event(event: ParameterEvent) -> None:
        if event.node == args.target:
            events.append({'changed': [p.name for p in event.changed_parameters], 'stamp': to_seconds(event.stamp)})

    node.create_subscription(ParameterEvent, '/parameter_events', on_event, QoSProfile(depth=1000))

    result: dict = {}
    client = rclpy.parameter_client.AsyncParameterClient(node, args.target)
    if not client.wait_for_services(timeout_sec=20.0):
        print(json.dumps({'error': f'parameter services of {args.target} not found'}), flush=True)
        return 4

    def call(future):
        rclpy.spin_until_future_complete(node, future, timeout_sec=10.0)
        return future.result()

    results = call(client.set_parameters([Parameter('use_sim_time', value=True)])).results
    result['set'] = [{'successful': r.successful, 'reason': r.reason} for r in results]
    values = call(client.get_parameters(['use_sim_time'])).values
    result['use_sim_time'] = parameter_value_to_python(values[0]) if values else None

    end = time.monotonic() + args.seconds
    while time.monotonic() < end and (len(tf_stamps) < args.count or len(pose_stamps) < args.count):
        rclpy.spin_once(node, timeout_sec=0.05)
    result.update({'clock_first': published['first'], 'clock_last': published['last'],
                   'tf_stamps': tf_stamps, 'pose_stamps': pose_stamps, 'events': events})
    print(json.dumps(result), flush=True)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
