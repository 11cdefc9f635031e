#!/usr/bin/env python3
"""A real ROS 2 node (rclpy) playing robot_state_publisher for a URDF, for the robot tests:
the `robot_description` parameter, the transient-local `robot_description` topic, fixed joints on
/tf_static and movable joints on /tf (stamped now), like robot_state_publisher does.

    rsp_peer.py URDF [--namespace NS] [--frame-prefix P] [--configs N] [--hold S] [--rate HZ] [--wait S]

It walks through N joint configurations (zeros first, then seeded random values within the joint
limits), holding each for --hold seconds, and prints one JSON line per configuration with every
link's pose in the root link's frame (4x4, metres) as yourdfpy's forward kinematics computes it:
an implementation independent of ros2vtk's, against which the tests check our scene.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np
import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage
from yourdfpy import URDF

LATCHED = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE,
                     durability=DurabilityPolicy.TRANSIENT_LOCAL)


def configurations(robot: URDF, count: int, seed: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    lows, highs = [], []
    for name in robot.actuated_joint_names:
        limit = robot.joint_map[name].limit
        low = limit.lower if limit is not None and limit.lower is not None else -np.pi
        high = limit.upper if limit is not None and limit.upper is not None else np.pi
        if high <= low:  # continuous joints often state 0/0
            low, high = -np.pi, np.pi
        lows.append(low)
        highs.append(high)
    lows, highs = np.array(lows), np.array(highs)
    configs = [np.clip(np.zeros(len(lows)), lows, highs)]
    while len(configs) < count:
        configs.append(lows + (highs - lows) * rng.uniform(0.1, 0.9, len(lows)))
    return configs


def quaternion(rotation: np.ndarray) -> tuple[float, float, float, float]:
    """x, y, z, w of a rotation matrix (Shepperd's method)."""
    m = rotation
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * np.sqrt(trace + 1.0)
        return ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    i = int(np.argmax([m[0, 0], m[1, 1], m[2, 2]]))
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * np.sqrt(1.0 + m[i, i] - m[j, j] - m[k, k])
    q = [0.0, 0.0, 0.0, 0.0]
    q[i] = 0.25 * s
    q[j] = (m[j, i] + m[i, j]) / s
    q[k] = (m[k, i] + m[i, k]) / s
    q[3] = (m[k, j] - m[j, k]) / s
    return tuple(float(v) for v in q)


def joint_transforms(robot: URDF, prefix: str, stamp, fixed: bool) -> list[TransformStamped]:
    """parent link -> child link of every (fixed or movable) joint at the current configuration."""
    transforms = []
    for joint in robot.robot.joints:
        if (joint.type == 'fixed') != fixed:
            continue
        parent = robot.get_transform(joint.parent)
        child = robot.get_transform(joint.child)
        relative = np.linalg.inv(parent) @ child
        t = TransformStamped()
        t.header.stamp = stamp
        t.header.frame_id = prefix + joint.parent
        t.child_frame_id = prefix + joint.child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = \
            (float(v) for v in relative[:3, 3])
        (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
         t.transform.rotation.w) = quaternion(relative[:3, :3])
        transforms.append(t)
    return transforms


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('urdf')
    parser.add_argument('--namespace', default='')
    parser.add_argument('--frame-prefix', default='')
    parser.add_argument('--configs', type=int, default=3)
    parser.add_argument('--hold', type=float, default=2.5)
    parser.add_argument('--rate', type=float, default=50.0)
    parser.add_argument('--seed', type=int, default=7, help='of the random configurations')
    parser.add_argument('--first-hold', type=float, default=0.0, help='seconds for the first configuration (0: --hold)')
    parser.add_argument('--wait', type=float, default=20.0, help='seconds to wait for a /tf subscriber')
    args = parser.parse_args()

    text = open(args.urdf, encoding='utf-8').read()
    robot = URDF.load(args.urdf, load_meshes=False, build_collision_scene_graph=False,
                      load_collision_meshes=False)
    rclpy.init()
    node = rclpy.create_node('robot_state_publisher', namespace=args.namespace or None)
    node.declare_parameter('robot_description', text)
    description = node.create_publisher(String, 'robot_description', LATCHED)
    description.publish(String(data=text))
    static = node.create_publisher(TFMessage, '/tf_static', LATCHED)
    dynamic = node.create_publisher(TFMessage, '/tf', QoSProfile(depth=100))
    print(json.dumps({'ready': True, 'root': robot.base_link,
                      'links': [link.name for link in robot.robot.links]}), flush=True)
    try:
        # The clock of the configurations starts once someone listens to /tf (our robot node's
        # lookups), so a slow start on a loaded machine cannot skip a configuration.
        deadline = time.monotonic() + args.wait
        while dynamic.get_subscription_count() == 0 and time.monotonic() < deadline:
            rclpy.spin_once(node, timeout_sec=0.05)
        for index, config in enumerate(configurations(robot, args.configs, args.seed)):
            robot.update_cfg(config)
            links = {link.name: robot.get_transform(link.name).tolist() for link in robot.robot.links}
            print(json.dumps({'config': index, 'joints': config.tolist(), 'links': links}), flush=True)
            static.publish(TFMessage(transforms=joint_transforms(robot, args.frame_prefix,
                                                                 node.get_clock().now().to_msg(), True)))
            end = time.monotonic() + (args.first_hold if index == 0 and args.first_hold > 0 else args.hold)
            while time.monotonic() < end:
                dynamic.publish(TFMessage(transforms=joint_transforms(
                    robot, args.frame_prefix, node.get_clock().now().to_msg(), False)))
                rclpy.spin_once(node, timeout_sec=1.0 / args.rate)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
    print(json.dumps({'done': True}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
