#!/usr/bin/env python3
"""A real ROS 2 node (rclpy) that publishes only sensor_msgs/JointState (no tf, no
robot_state_publisher), for the robot-state tests (issue 15).

    joint_states_peer.py URDF CONFIGS_JSON [--topic T] [--hold S] [--rate HZ] [--wait S] [--subscribers N] [--settle S]

CONFIGS_JSON is a list of {joint: position} messages, published in turn (each --hold seconds at
--rate Hz, stamped now) once N subscribers are matched. A message may name a few joints only, or
names that are no joint. For each one it prints one JSON line with every link's pose in the root
link's frame (4x4, metres) from yourdfpy's forward kinematics: an implementation independent of
ros2vtk's, at the joint values a robot must show, i.e. the values so far with revolute and
prismatic joints clamped into their URDF limits (clamped here, not by yourdfpy nor by us).
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np
import rclpy
from sensor_msgs.msg import JointState
from yourdfpy import URDF


def clamped(robot: URDF, name: str, value: float) -> float:
    joint = robot.joint_map[name]
    limit = joint.limit
    if joint.type in ('revolute', 'prismatic') and limit is not None and limit.lower is not None \
            and limit.upper is not None and limit.lower < limit.upper:
        return min(max(value, limit.lower), limit.upper)
    return value


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('urdf')
    parser.add_argument('configs')
    parser.add_argument('--topic', default='/joint_states')
    parser.add_argument('--hold', type=float, default=2.0)
    parser.add_argument('--rate', type=float, default=20.0)
    parser.add_argument('--wait', type=float, default=30.0, help='seconds to wait for the subscribers')
    parser.add_argument('--subscribers', type=int, default=1, help='subscribers to wait for before publishing')
    parser.add_argument('--settle', type=float, default=0.0,
                        help='seconds to wait after that (other topics of the subscribers still matching)')
    args = parser.parse_args()
    robot = URDF.load(args.urdf, load_meshes=False, build_collision_scene_graph=False,
                      load_collision_meshes=False)
    configs = json.loads(args.configs)
    rclpy.init()
    node = rclpy.create_node('joint_states_only')
    publisher = node.create_publisher(JointState, args.topic, 10)
    end = time.monotonic() + args.wait
    while publisher.get_subscription_count() < args.subscribers and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    if publisher.get_subscription_count() < args.subscribers:
        print(json.dumps({'error': f'{publisher.get_subscription_count()} of {args.subscribers} subscribers '
                                   f'on {args.topic}'}), flush=True)
        return 1
    settle = time.monotonic() + args.settle
    while time.monotonic() < settle:
        rclpy.spin_once(node, timeout_sec=0.05)
    print(json.dumps({'ready': True, 'actuated': list(robot.actuated_joint_names)}), flush=True)
    # The robot starts at the zero configuration, zero clamped into each joint's limits.
    state = {name: clamped(robot, name, 0.0) for name in robot.actuated_joint_names}
    for index, config in enumerate(configs):
        for name, value in config.items():
            if name in state:
                state[name] = clamped(robot, name, value)
        robot.update_cfg(dict(state))
        links = {link: robot.get_transform(link).tolist() for link in robot.link_map}
        print(json.dumps({'config': index, 'state': state, 'links': links}), flush=True)
        message = JointState()
        message.name = list(config)
        message.position = [float(v) for v in config.values()]
        stop = time.monotonic() + args.hold
        while time.monotonic() < stop:
            message.header.stamp = node.get_clock().now().to_msg()
            publisher.publish(message)
            rclpy.spin_once(node, timeout_sec=1.0 / args.rate)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
