#!/usr/bin/env python3
"""A real ROS 2 node (rclpy) that checks a robot_state_publisher (ours: ros2vtk-sim-robot) from the
outside: it listens to joint_states, /tf and /tf_static, and for each joint state chains the
transforms stamped with it into every link's pose in the root frame, compared with yourdfpy's
forward kinematics at those joint positions (mimic joints computed by yourdfpy).

    tf_fk_peer.py URDF [--namespace NS] [--frame-prefix P] [--seconds S]

Prints one JSON object: how many joint states were compared, the largest difference (m, or
unitless for rotation), and which child frames came on /tf and on /tf_static.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np
import rclpy
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
from yourdfpy import URDF

LATCHED = QoSProfile(depth=100, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE,
                     durability=DurabilityPolicy.TRANSIENT_LOCAL)


def matrix(transform) -> np.ndarray:
    t, q = transform.translation, transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    result = np.eye(4)
    result[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                      [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                      [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    result[:3, 3] = [t.x, t.y, t.z]
    return result


def stamp_key(stamp) -> tuple[int, int]:
    return stamp.sec, stamp.nanosec


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('urdf')
    parser.add_argument('--namespace', default='')
    parser.add_argument('--frame-prefix', default='')
    parser.add_argument('--seconds', type=float, default=3.0)
    args = parser.parse_args()
    robot = URDF.load(args.urdf, load_meshes=False, build_collision_scene_graph=False,
                      load_collision_meshes=False)
    rclpy.init()
    node = rclpy.create_node('tf_fk_checker')
    states, dynamic, static = [], [], []
    node.create_subscription(JointState, f'{args.namespace}/joint_states', states.append, 100)
    node.create_subscription(TFMessage, '/tf', dynamic.append, QoSProfile(depth=1000))
    node.create_subscription(TFMessage, '/tf_static', static.append, LATCHED)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    node.destroy_node()
    rclpy.try_shutdown()

    prefix = args.frame_prefix
    fixed = {}
    for message in static:
        for t in message.transforms:
            fixed[t.child_frame_id] = (t.header.frame_id, matrix(t.transform))
    by_stamp: dict = {}
    for message in dynamic:
        for t in message.transforms:
            by_stamp.setdefault(stamp_key(t.header.stamp), {})[t.child_frame_id] = (t.header.frame_id,
                                                                                    matrix(t.transform))
    root = prefix + robot.base_link
    compared, worst = 0, 0.0
    for state in states:
        moving = by_stamp.get(stamp_key(state.header.stamp))
        if moving is None:
            continue
        edges = dict(fixed, **moving)
        robot.update_cfg({name: position for name, position in zip(state.name, state.position)})
        for link in robot.link_map:
            pose, frame = np.eye(4), prefix + link
            while frame != root:
                parent, transform = edges[frame]  # KeyError: a link the tf tree misses
                pose = transform @ pose
                frame = parent
            worst = max(worst, float(np.abs(pose - robot.get_transform(link)).max()))
        compared += 1
    print(json.dumps({'states': len(states), 'compared': compared, 'worst': worst,
                      'static_children': sorted(fixed),
                      'dynamic_children': sorted({c for m in by_stamp.values() for c in m}),
                      'joint_names': list(states[0].name) if states else []}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
