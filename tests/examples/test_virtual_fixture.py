"""examples/virtual_fixture: the paper's Algorithm 1 against a real rclpy robot.

The rclpy peer moves the tool tip (robot frame, metres) along a line towards the pseudotumour:
outside the forbidden region, inside the margin, inside the tumour, and out again. Expected
answers come from the phantom's layout (ros2vtk-make-phantom prints the tumour centre and radius)
and the registration, computed here with numpy, not with the example's code: a null wrench for
every pose outside the margin, and while inside, a hold pose equal to the last safe pose sent.
"""
from __future__ import annotations

import json
import math

import numpy as np

from conftest import Process

MARGIN_MM = 5.0
# robot -> image: 30 deg about z, then 20 deg about x, then a translation (mm); row-major 4x4.


def registration() -> np.ndarray:
    a, b = math.radians(30), math.radians(20)
    rz = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    rx = np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])
    m = np.eye(4)
    m[:3, :3] = rx @ rz
    m[:3, 3] = [-420.0, 35.0, -180.0]
    return m


def matrix_text(m: np.ndarray) -> str:
    return ' '.join(repr(float(v)) for v in m[:3, :].ravel())


def test_virtual_fixture_holds_at_last_safe_pose_and_releases_outside(ros_domain, phantom):
    ros = ros_domain(220)
    robot_to_image = registration()
    image_to_robot = np.linalg.inv(robot_to_image)
    centre = np.array(phantom.tumour_centre)
    # The pseudotumour is lobulated (Phantom.cpp: radius R * (1 + 0.15 sin 3 theta) about the image
    # z axis). At theta = 30 deg in its equatorial plane a lobe peaks (radius 1.15 R) and the surface
    # is convex there, so along that ray the tip's distance to the surface is its height above it.
    direction = np.array([math.cos(math.radians(30)), math.sin(math.radians(30)), 0.0])
    lobe_radius = 1.15 * phantom.tumour_radius
    plan = [  # (distance to the tumour surface in mm, expected action)
        (25.0, 'release'), (11.0, 'release'), (2.5, 'hold'), (-4.0, 'hold'), (9.0, 'release'), (1.0, 'hold')]
    orientation = [math.sin(math.radians(15)), 0.0, 0.0, math.cos(math.radians(15))]  # 30 deg about x
    poses = []
    for distance, _ in plan:
        tip_image = centre + (lobe_radius + distance) * direction
        tip_robot_m = (image_to_robot @ np.append(tip_image, 1.0))[:3] / 1000.0
        poses.append({'position': tip_robot_m.tolist(), 'orientation': orientation})

    example = ros.example('virtual_fixture', '--phantom', str(phantom.path), '--registration',
                          matrix_text(robot_to_image), '--margin', str(MARGIN_MM), '--seconds', '40')
    ready = example.next_json(30, lambda o: 'ready' in o or 'error' in o)
    assert ready.get('ready') is True, ready
    # The extracted surface is the tumour (not a fiducial bead, not the tissue): its centre.
    assert np.allclose(ready['tumour_centre_image_mm'], centre, atol=1.0), ready

    peer = ros.peer('vf', json.dumps(poses))
    result = peer.next_json(45, lambda o: 'results' in o or 'error' in o)
    assert 'error' not in result, (result, ''.join(example.stdout), example.stderr)
    assert peer.finish(10) == 0

    last_safe = None
    for (distance, action), pose, answer in zip(plan, poses, result['results']):
        if action == 'release':
            assert answer['kind'] == 'wrench', (distance, answer)
            assert answer['values'] == [0.0] * 6, answer
            last_safe = pose
        else:
            assert answer['kind'] == 'hold', (distance, answer)
            assert np.allclose(answer['position'], last_safe['position'], atol=1e-9), (answer, last_safe)
            q = np.array(answer['orientation'])
            assert np.allclose(q, last_safe['orientation'], atol=1e-9) or \
                np.allclose(-q, last_safe['orientation'], atol=1e-9), answer
        assert answer['frame_id'] == 'base', answer
    assert len(result['results']) == len(plan)
    assert result['extra_answers'] == 0, result

    # The example's own report: the tip in the image frame and its distance to the surface.
    example.popen.terminate()
    example.finish(10)
    reports = [o for o in example.json_lines() if 'pose' in o]
    assert len(reports) == len(plan), reports
    for (distance, action), report in zip(plan, reports):
        expected_tip = centre + (lobe_radius + distance) * direction
        assert np.allclose(report['tip_image_mm'], expected_tip, atol=1e-6), report
        # The iso-surface lies between voxel centres: within a voxel of the analytic sphere.
        assert abs(report['distance_mm'] - distance) < 1.0, (distance, report)
        assert report['action'] == action


def test_virtual_fixture_bad_input_is_a_clear_message(ros_domain, phantom, tmp_path):
    ros = ros_domain(221)
    cases = [
        (['--phantom', str(tmp_path / 'missing.mha')], 'no such file'),
        (['--phantom', str(phantom.path), '--registration', '1 2 3'], 'expected 12 or 16 numbers'),
        (['--phantom', str(phantom.path), '--registration', '2 0 0 0 0 1 0 0 0 0 1 0'], 'not a rotation'),
        (['--phantom', str(phantom.path), '--margin', 'nan'], '--margin'),
    ]
    not_image = tmp_path / 'not_an_image.mha'
    not_image.write_text('hello\n')
    cases.append((['--phantom', str(not_image)], 'phantom'))
    for args, message in cases:
        process: Process = ros.example('virtual_fixture', *args, '--seconds', '1')
        code = process.finish(30)
        assert code == 2, (args, code, process.stderr)
        assert 'Traceback' not in process.stderr, process.stderr
        errors = [o['error'] for o in process.json_lines() if 'error' in o]
        assert errors and message in errors[0], (args, errors)
