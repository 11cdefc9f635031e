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


# ------------------------------------------------------------------------------ ultrasound
def read_metaimage(path: str):
    """(voxels as a numpy array [z, y, x], spacing, offset) from a .mha with its data inline,
    plain or zlib-compressed: enough MetaImage for ros2vtk-make-phantom's files."""
    import numpy as np
    with open(path, 'rb') as stream:
        blob = stream.read()
    header, position = {}, 0
    while True:
        end = blob.index(b'\n', position)
        key, _, value = blob[position:end].decode('ascii').partition('=')
        header[key.strip()] = value.strip()
        position = end + 1
        if key.strip() == 'ElementDataFile':
            break
    if header['ElementDataFile'] != 'LOCAL':
        raise ValueError('only .mha with inline data')
    types = {'MET_SHORT': '<i2', 'MET_USHORT': '<u2', 'MET_UCHAR': 'u1', 'MET_CHAR': 'i1', 'MET_FLOAT': '<f4'}
    dtype = np.dtype(types[header['ElementType']])
    if header.get('BinaryDataByteOrderMSB', 'False') == 'True':
        dtype = dtype.newbyteorder('>')
    data = blob[position:]
    if header.get('CompressedData', 'False') == 'True':
        data = zlib.decompress(data)
    if [float(v) for v in header.get('TransformMatrix', '1 0 0 0 1 0 0 0 1').split()] != [1, 0, 0, 0, 1, 0, 0, 0, 1]:
        raise ValueError('only axis-aligned images')
    dims = [int(v) for v in header['DimSize'].split()]
    voxels = np.frombuffer(data, dtype=dtype, count=dims[0] * dims[1] * dims[2]).reshape(dims[2], dims[1], dims[0])
    spacing = np.array([float(v) for v in header.get('ElementSpacing', '1 1 1').split()])
    offset = np.array([float(v) for v in header.get('Offset', '0 0 0').split()])
    return voxels, spacing, offset


def quaternion_matrix(q):
    import numpy as np
    x, y, z, w = np.array(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def ultrasound_frame(voxels, spacing, offset, robot_to_image, pose, width: int, height: int, pixel: float):
    """A B-mode-like mono8 frame: the phantom cut by the probe's x-z plane, nearest voxel, soft
    tissue window (W 400 / L 40). Pixel (row r, column u) is at probe (x, y, z) = ((u - (w-1)/2) s,
    0, r s) mm: row 0 on the transducer face, depth along +z."""
    import numpy as np
    probe = np.eye(4)
    probe[:3, :3] = quaternion_matrix(pose['orientation'])
    probe[:3, 3] = np.array(pose['position']) * 1000.0
    to_image = robot_to_image @ probe
    u, r = np.meshgrid(np.arange(width), np.arange(height))
    points = np.stack([(u - (width - 1) / 2.0) * pixel, np.zeros_like(u, dtype=float), r * pixel,
                       np.ones_like(u, dtype=float)], axis=-1) @ to_image.T
    index = np.rint((points[..., :3] - offset) / spacing).astype(int)
    nz, ny, nx = voxels.shape
    inside = (index[..., 0] >= 0) & (index[..., 0] < nx) & (index[..., 1] >= 0) & (index[..., 1] < ny) & \
        (index[..., 2] >= 0) & (index[..., 2] < nz)
    hu = np.full((height, width), -1000.0)
    hu[inside] = voxels[index[..., 2][inside], index[..., 1][inside], index[..., 0][inside]]
    return np.clip(np.rint((hu - (40.0 - 200.0)) / 400.0 * 255.0), 0, 255).astype(np.uint8)


def cmd_ultrasound(args) -> int:
    """For each probe pose: --frames-per-pose frames, each a PoseStamped then an Image with
    the same stamp."""
    import numpy as np
    from sensor_msgs.msg import Image
    voxels, spacing, offset = read_metaimage(args.phantom)
    robot_to_image = np.array([float(v) for v in args.registration.split()]).reshape(4, 4)
    poses = json.loads(args.poses)
    node = rclpy.create_node('us_simulator')
    image_pub = node.create_publisher(Image, args.image_topic, QoSProfile(depth=10))
    pose_pub = node.create_publisher(PoseStamped, args.pose_topic, QoSProfile(depth=10))
    if not wait_for(node, lambda: image_pub.get_subscription_count() > 0 and pose_pub.get_subscription_count() > 0,
                    args.wait):
        print(json.dumps({'error': 'the example is not on the graph'}), flush=True)
        return 3
    time.sleep(0.5)
    sent = []
    for pose in poses:
        frame = ultrasound_frame(voxels, spacing, offset, robot_to_image, pose, args.width, args.height, args.pixel)
        for _ in range(args.frames_per_pose):
            stamp = node.get_clock().now().to_msg()
            message = pose_message(node, pose['position'], pose['orientation'], args.frame_id)
            message.header.stamp = stamp
            pose_pub.publish(message)
            image = Image()
            image.header.stamp = stamp
            image.header.frame_id = 'us_probe'
            image.height, image.width, image.encoding, image.step = args.height, args.width, 'mono8', args.width
            image.data = frame.tobytes()
            image_pub.publish(image)
            data = frame.tobytes()
            sent.append({'stamp': stamp.sec + 1e-9 * stamp.nanosec, 'sum': int(frame.astype(np.int64).sum()),
                         'crc32': zlib.crc32(data), 'bytes': len(data), 'width': args.width, 'height': args.height,
                         'max': int(frame.max())})
            rclpy.spin_once(node, timeout_sec=1.0 / args.rate)
    wait_for(node, lambda: False, 0.5)
    print(json.dumps({'sent': sent}), flush=True)
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
    us = sub.add_parser('ultrasound')
    us.add_argument('phantom')
    us.add_argument('poses', help='JSON list of probe poses {"position": [m], "orientation": [x, y, z, w]}, robot frame')
    us.add_argument('--registration', required=True, help='robot -> image, 16 numbers row-major, mm')
    us.add_argument('--width', type=int, default=128)
    us.add_argument('--height', type=int, default=96)
    us.add_argument('--pixel', type=float, default=0.5, help='pixel size (mm)')
    us.add_argument('--frames-per-pose', type=int, default=5)
    us.add_argument('--rate', type=float, default=10.0)
    us.add_argument('--frame-id', default='base')
    us.add_argument('--image-topic', default='/us/image')
    us.add_argument('--pose-topic', default='/us/probe_pose')
    us.add_argument('--wait', type=float, default=20.0)
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'vf': cmd_vf, 'trajectory': cmd_trajectory, 'ultrasound': cmd_ultrasound}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
