#!/usr/bin/env python3
"""Real ROS 2 peers (rclpy from the Kilted wheels) for the examples' tests, one role per process.

    peers.py vf POSES_JSON            tool poses out, one at a time; what came back for each
    peers.py trajectory               the PoseArray the trajectory example publishes
    peers.py ultrasound PHANTOM ...   sensor_msgs/Image slices of the phantom + the probe pose

Every role prints JSON lines; the last one is its result.
"""
from __future__ import annotations

import argparse
import json
import sys
import time
import zlib

import rclpy
from geometry_msgs.msg import PoseArray, PoseStamped, WrenchStamped
from rclpy.qos import QoSProfile


def wait_for(node, condition, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        rclpy.spin_once(node, timeout_sec=0.02)
    return condition()


def pose_message(node, position, quaternion, frame_id: str) -> PoseStamped:
    message = PoseStamped()
    message.header.frame_id = frame_id
    message.header.stamp = node.get_clock().now().to_msg()
    p, q = message.pose.position, message.pose.orientation
    p.x, p.y, p.z = (float(v) for v in position)
    q.x, q.y, q.z, q.w = (float(v) for v in quaternion)
    return message


# ------------------------------------------------------------------------------ virtual fixture
def cmd_vf(args) -> int:
    """Publishes each tool pose, waits for the example's answer (a WrenchStamped or a hold
    PoseStamped) before the next, and prints them all."""
    poses = json.loads(args.poses)
    node = rclpy.create_node('vf_robot')
    answers: list = []
    node.create_subscription(WrenchStamped, args.wrench_topic,
                             lambda m: answers.append({'kind': 'wrench', 'frame_id': m.header.frame_id,
                                                       'values': [m.wrench.force.x, m.wrench.force.y, m.wrench.force.z,
                                                                  m.wrench.torque.x, m.wrench.torque.y, m.wrench.torque.z]}),
                             QoSProfile(depth=100))
    node.create_subscription(PoseStamped, args.hold_topic,
                             lambda m: answers.append({'kind': 'hold', 'frame_id': m.header.frame_id,
                                                       'position': [m.pose.position.x, m.pose.position.y, m.pose.position.z],
                                                       'orientation': [m.pose.orientation.x, m.pose.orientation.y,
                                                                       m.pose.orientation.z, m.pose.orientation.w]}),
                             QoSProfile(depth=100))
    publisher = node.create_publisher(PoseStamped, args.pose_topic, QoSProfile(depth=100))
    matched = wait_for(node, lambda: publisher.get_subscription_count() > 0
                       and node.count_publishers(args.wrench_topic) > 0 and node.count_publishers(args.hold_topic) > 0,
                       args.wait)
    if not matched:
        print(json.dumps({'error': 'the example is not on the graph'}), flush=True)
        return 3
    time.sleep(0.3)  # let the other side's discovery settle too
    results = []
    for index, pose in enumerate(poses):
        before = len(answers)
        attempts = 0
        while len(answers) == before and attempts < (5 if index == 0 else 1):
            publisher.publish(pose_message(node, pose['position'], pose['orientation'], args.frame_id))
            attempts += 1
            wait_for(node, lambda: len(answers) > before, 2.0 if index == 0 else args.timeout)
        if len(answers) == before:
            print(json.dumps({'error': f'no answer to pose {index}', 'results': results}), flush=True)
            return 4
        if index == 0:  # a resent first pose may bring a second answer: take it in now
            wait_for(node, lambda: False, 0.5)
            del answers[before + 1:]
        results.append(answers[before])
        print(json.dumps({'pose': index, 'answer': answers[before]}), flush=True)
    wait_for(node, lambda: False, 0.5)
    print(json.dumps({'results': results, 'extra_answers': len(answers) - len(results)}), flush=True)
    node.destroy_node()
    return 0


# ------------------------------------------------------------------------------ trajectory
def cmd_trajectory(args) -> int:
    """Receives one PoseArray and prints it (positions in metres, quaternions x y z w)."""
    node = rclpy.create_node('motion_planner')
    received: list = []
    node.create_subscription(PoseArray, args.topic, received.append, QoSProfile(depth=10))
    print(json.dumps({'ready': True}), flush=True)
    if not wait_for(node, lambda: received, args.timeout):
        print(json.dumps({'error': f'no PoseArray on {args.topic} within {args.timeout} s'}), flush=True)
        return 4
    message = received[0]
    print(json.dumps({'frame_id': message.header.frame_id,
                      'stamp': message.header.stamp.sec + 1e-9 * message.header.stamp.nanosec,
                      'positions': [[p.position.x, p.position.y, p.position.z] for p in message.poses],
                      'orientations': [[p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w]
                                       for p in message.poses]}), flush=True)
    node.destroy_node()
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest='command', required=True)
    vf = sub.add_parser('vf')
    vf.add_argument('poses', help='JSON list of {"position": [x, y, z] (m), "orientation": [x, y, z, w]}')
    vf.add_argument('--pose-topic', default='/vf/tool_pose')
    vf.add_argument('--hold-topic', default='/vf/hold_pose')
    vf.add_argument('--wrench-topic', default='/vf/wrench')
    vf.add_argument('--frame-id', default='base')
    vf.add_argument('--wait', type=float, default=20.0)
    vf.add_argument('--timeout', type=float, default=5.0)
    trajectory = sub.add_parser('trajectory')
    trajectory.add_argument('--topic', default='/trajectory')
    trajectory.add_argument('--timeout', type=float, default=30.0)
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'vf': cmd_vf, 'trajectory': cmd_trajectory}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
