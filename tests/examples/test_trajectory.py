"""examples/trajectory: markup points in the image frame reach an rclpy motion planner as a
PoseArray in the robot frame, in metres.

Expected poses are computed here with numpy from the registration and the input points (not with
the example's code): position = inverse(robot -> image) applied to each point, / 1000; the tool's
z axis along the path, rotated into the robot frame.
"""
from __future__ import annotations

import math
import time

import numpy as np

ENTRY_BEAD = [80.0, 19.2, 72.0]  # Phantom.cpp: the bead at (0.5, 0.15) of the block top, 160x128x96 mm


def registration() -> np.ndarray:
    """robot -> image: -40 deg about y, 25 deg about z, then a translation (mm)."""
    a, b = math.radians(-40), math.radians(25)
    ry = np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])
    rz = np.array([[math.cos(b), -math.sin(b), 0], [math.sin(b), math.cos(b), 0], [0, 0, 1]])
    m = np.eye(4)
    m[:3, :3] = rz @ ry
    m[:3, 3] = [-310.0, 120.0, -95.0]
    return m


def matrix_text(m: np.ndarray) -> str:
    return ' '.join(repr(float(v)) for v in m.ravel())  # all 16 numbers


def z_axis(q) -> np.ndarray:
    """Third column of the rotation matrix of quaternion (x, y, z, w)."""
    x, y, z, w = np.array(q) / np.linalg.norm(q)
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def run(ros, *example_args: str) -> tuple[dict, dict]:
    example = ros.example('trajectory', *example_args, '--seconds', '30', '--period', '0.5')
    ready = example.next_json(30, lambda o: 'ready' in o or 'error' in o)
    assert ready.get('ready') is True, ready
    peer = ros.peer('trajectory', '--timeout', '30')
    received = peer.next_json(40, lambda o: 'positions' in o or 'error' in o)
    assert 'error' not in received, (received, ''.join(example.stdout), example.stderr)
    assert peer.finish(10) == 0
    return ready, received


def test_trajectory_from_entry_bead_to_tumour_in_robot_frame(ros_domain, phantom):
    ros = ros_domain(224)
    robot_to_image = registration()
    image_to_robot = np.linalg.inv(robot_to_image)
    entry, target = np.array(ENTRY_BEAD), np.array(phantom.tumour_centre)
    n = 6
    _, received = run(ros, '--registration', matrix_text(robot_to_image), '--entry', *map(str, entry),
                      '--target', *map(str, target), '--points', str(n), '--frame-id', 'psm_base')

    assert received['frame_id'] == 'psm_base'
    assert abs(received['stamp'] - time.time()) < 30, received['stamp']  # stamped now, not zero
    points_image = [entry + (i / (n - 1)) * (target - entry) for i in range(n)]
    expected = [(image_to_robot @ np.append(p, 1.0))[:3] / 1000.0 for p in points_image]
    assert len(received['positions']) == n
    np.testing.assert_allclose(received['positions'], expected, rtol=0, atol=1e-9)
    # The robot is 30 cm or so away: metres on the wire, not millimetres.
    assert all(0.05 < np.linalg.norm(p) < 2.0 for p in received['positions'])
    direction = image_to_robot[:3, :3] @ (target - entry)
    direction /= np.linalg.norm(direction)
    for q in received['orientations']:
        assert abs(np.linalg.norm(q) - 1.0) < 1e-9
        np.testing.assert_allclose(z_axis(q), direction, rtol=0, atol=1e-9)


def test_trajectory_explicit_markups_with_a_bend(ros_domain):
    ros = ros_domain(225)
    robot_to_image = registration()
    image_to_robot = np.linalg.inv(robot_to_image)
    markups = np.array([[20.0, 30.0, 70.0], [60.0, 30.0, 50.0], [60.0, 90.0, 50.0]])
    ready, received = run(ros, '--registration', matrix_text(robot_to_image),
                          '--markups', '; '.join(' '.join(str(v) for v in p) for p in markups))
    assert received['frame_id'] == 'base'
    expected = [(image_to_robot @ np.append(p, 1.0))[:3] / 1000.0 for p in markups]
    np.testing.assert_allclose(received['positions'], expected, rtol=0, atol=1e-9)
    # Each pose's z axis points to the next markup (the last one keeps the last segment's).
    segments = [markups[1] - markups[0], markups[2] - markups[1], markups[2] - markups[1]]
    for q, segment in zip(received['orientations'], segments):
        d = image_to_robot[:3, :3] @ segment
        np.testing.assert_allclose(z_axis(q), d / np.linalg.norm(d), rtol=0, atol=1e-9)


def test_trajectory_bad_input_is_a_clear_message(ros_domain):
    ros = ros_domain(226)
    for args, message in [(['--points', '1'], '--points'),
                          (['--markups', '1 2 3; 4 5'], 'three'),
                          (['--markups', '1 2 3'], 'at least two'),
                          (['--entry', '1', '2', '3', '--target', '1', '2', '3'], 'same point'),
                          (['--registration', '1 0 0 0 0 1 0 0 0 0 -1 0'], 'not a rigid transform')]:
        process = ros.example('trajectory', *args, '--seconds', '1')
        assert process.finish(30) == 2, (args, process.stderr)
        assert 'Traceback' not in process.stderr, process.stderr
        errors = [o['error'] for o in process.json_lines() if 'error' in o]
        assert errors and message in errors[0], (args, errors)
