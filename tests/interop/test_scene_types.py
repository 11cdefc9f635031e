"""Every mapped type through our VTK-wrapped Python API against real rclpy nodes, both ways,
with the units policy: lengths in mm on our side, metres on the wire; nothing else scaled.
Expected values are written out by hand from tests/interop/samples.py."""
from __future__ import annotations

import io
import json
import math
import struct

import pytest
from PIL import Image as PILImage

from samples import HEADER, POSE, SAMPLES
from test_wire_topics import assert_matches

S = math.sqrt(0.5)
ROT_Z90 = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]


def rigid(rotation, translation):
    return [rotation[i] + [translation[i]] for i in range(3)] + [[0, 0, 0, 1]]


def close(expected, actual, tol=1e-9, path='value'):
    if isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), f'{path}: {actual!r}'
        for i, (e, a) in enumerate(zip(expected, actual)):
            close(e, a, tol, f'{path}[{i}]')
    elif isinstance(expected, dict):
        for key, e in expected.items():
            assert key in actual, f'{path}.{key} missing: {sorted(actual)}'
            close(e, actual[key], tol, f'{path}.{key}')
    elif isinstance(expected, float) or (isinstance(expected, int) and isinstance(actual, float)):
        assert math.isclose(actual, expected, rel_tol=1e-12, abs_tol=tol), f'{path}: {actual} != {expected}'
    else:
        assert actual == expected, f'{path}: {actual!r} != {expected!r}'


IMAGE = SAMPLES['sensor_msgs/msg/Image']['data']
# rclpy -> our subscriber: (short name, ROS type, expected VTK value as JSON)
INCOMING = [
    ('String', 'std_msgs/msg/String', 'Hello world.'),
    ('Bool', 'std_msgs/msg/Bool', True),
    ('Int', 'std_msgs/msg/Int64', -9007199254740993),
    ('Double', 'std_msgs/msg/Float64', 3.141592653589793),
    ('PoseStamped', 'geometry_msgs/msg/PoseStamped', rigid(ROT_Z90, [100.0, -250.0, 1500.0])),
    ('TransformStamped', 'geometry_msgs/msg/TransformStamped',
     rigid([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [10.0, 20.0, -300.0])),
    ('PoseArray', 'geometry_msgs/msg/PoseArray',
     [rigid(ROT_Z90, [100.0, -250.0, 1500.0]), rigid([[1, 0, 0], [0, -1, 0], [0, 0, -1]], [-200.0, 0.0, 300.0])]),
    ('WrenchStamped', 'geometry_msgs/msg/WrenchStamped', [1.0, -2.0, 9.81, 0.1, 0.0, -0.05]),
    ('DoubleArray', 'std_msgs/msg/Float64MultiArray', [0.5, -1.25, 1e-9, 12345.678]),
    ('IntArray', 'std_msgs/msg/Int64MultiArray', [1, -2, 3, 4, -5, 6]),
    ('PointCloud', 'sensor_msgs/msg/PointCloud', [[500.0, 1500.0, -2000.0], [250.0, 0.0, 4000.0]]),
    ('PointCloud2', 'sensor_msgs/msg/PointCloud2', [[1000.0, 2000.0, 3000.0], [4000.0, 5000.0, 6000.0]]),
    # ROS row 0 is the top row; VTK's y goes up, so VTK row 0 is ROS row 1.
    ('Image', 'sensor_msgs/msg/Image', {'dimensions': [3, 2, 1], 'components': 3,
                                        'scalars': [float(v) for v in IMAGE[9:18] + IMAGE[0:9]]}),
    # dim[0] rows, dim[1] columns (labelled 'cols'): columns "cols_<j>", element [i][j] = data[3 i + j]
    ('IntTable', 'std_msgs/msg/Int64MultiArray', {'cols_0': [1, 4], 'cols_1': [-2, -5], 'cols_2': [3, 6]}),
    # unlabelled dim[1]: columns "<j>"; strides 4 and 2 over a 2 x 2 grid
    ('DoubleTable', 'std_msgs/msg/Float64MultiArray', {'0': [0.5, 1e-9], '1': [-1.25, 12345.678]}),
    ('Empty', 'std_msgs/msg/Empty', None),
    # the unstamped forms (SlicerROS2's Pose and Wrench examples)
    ('Pose', 'geometry_msgs/msg/Pose', rigid(ROT_Z90, [100.0, -250.0, 1500.0])),
    ('Transform', 'geometry_msgs/msg/Transform', rigid([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [10.0, 20.0, -300.0])),
    ('Wrench', 'geometry_msgs/msg/Wrench', [1.0, -2.0, 9.81, 0.1, 0.0, -0.05]),
    ('Vector3', 'geometry_msgs/msg/Vector3', [0.5, -1.5, 2.25]),  # any unit: never scaled
    # the common interfaces shipped with issue 13
    ('Twist', 'geometry_msgs/msg/Twist', [0.25, 0.0, -0.5, 0.0, 0.1, 1.5]),  # m/s, rad/s: never scaled
    ('TwistStamped', 'geometry_msgs/msg/TwistStamped', [0.25, 0.0, -0.5, 0.0, 0.1, 1.5]),
    ('PointStamped', 'geometry_msgs/msg/PointStamped', [[12.5, -40.0, 300.0]]),
    ('PoseWithCovarianceStamped', 'geometry_msgs/msg/PoseWithCovarianceStamped',
     rigid(ROT_Z90, [100.0, -250.0, 1500.0])),
    ('PolygonStamped', 'geometry_msgs/msg/PolygonStamped', [[0.0, 0.0, 0.0], [125.0, 0.0, 0.0], [125.0, 62.5, 0.0]]),
    ('Odometry', 'nav_msgs/msg/Odometry', rigid(ROT_Z90, [100.0, -250.0, 1500.0])),
    ('Path', 'nav_msgs/msg/Path',
     [rigid(ROT_Z90, [100.0, -250.0, 1500.0]), rigid([[1, 0, 0], [0, -1, 0], [0, 0, -1]], [-200.0, 0.0, 300.0])]),
    ('Imu', 'sensor_msgs/msg/Imu', [0.0, 0.0, S, S, 0.01, -0.02, 0.03, 0.0, 0.0, 9.81]),  # SI, never scaled
    # issue 13: K (pixels, row-major) and D of one CameraInfo, never scaled
    ('CameraInfo', 'sensor_msgs/msg/CameraInfo', [[525.0, 0.0, 319.5], [0.0, 526.5, 239.5], [0.0, 0.0, 1.0]]),
    ('CameraDistortion', 'sensor_msgs/msg/CameraInfo', [-0.28, 0.07, 0.0001, -0.0002, 0.0]),
    ('JoyAxes', 'sensor_msgs/msg/Joy', [0.5, -1.0, 0.25]),
    ('JoyButtons', 'sensor_msgs/msg/Joy', [0, 1, 1, 0]),
    # the Path above as a line: positions in mm, one polyline cell through them in order
    # PNG bytes decoded by vtkPNGReader: the same pixels as the raw Image above, VTK row 0 = bottom
    ('CompressedImage', 'sensor_msgs/msg/CompressedImage',
     {'dimensions': [3, 2, 1], 'components': 3, 'scalars': [float(v) for v in IMAGE[9:18] + IMAGE[0:9]]}),
    ('PathPolyline', 'nav_msgs/msg/Path', {'points': [[100.0, -250.0, 1500.0], [-200.0, 0.0, 300.0]],
                                           'lines': [[0, 1]]}),
]
CAMERA_INFO = {'header': HEADER, 'height': 480, 'width': 640, 'distortion_model': 'plumb_bob',
               'd': [-0.28, 0.07, 0.0001, -0.0002, 0.0],
               'k': [525.0, 0.0, 319.5, 0.0, 526.5, 239.5, 0.0, 0.0, 1.0],
               'r': [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
               'p': [525.0, 0.0, 319.5, 0.0, 0.0, 526.5, 239.5, 0.0, 0.0, 0.0, 1.0, 0.0]}


def png_bytes(width: int, height: int, rgb: list) -> list:
    """PNG made by Pillow (not by VTK, the code under test), rows top first."""
    out = io.BytesIO()
    PILImage.frombytes('RGB', (width, height), bytes(rgb)).save(out, format='PNG')
    return list(out.getvalue())


JOY = {'header': HEADER, 'axes': [0.5, -1.0, 0.25], 'buttons': [0, 1, 1, 0]}
# messages sent instead of SAMPLES[ros_type]
INCOMING_MESSAGES = {
    'Pose': SAMPLES['geometry_msgs/msg/PoseStamped']['pose'],
    'Transform': SAMPLES['geometry_msgs/msg/TransformStamped']['transform'],
    'Wrench': SAMPLES['geometry_msgs/msg/WrenchStamped']['wrench'],
    'Vector3': {'x': 0.5, 'y': -1.5, 'z': 2.25},
    'Twist': {'linear': {'x': 0.25, 'y': 0.0, 'z': -0.5}, 'angular': {'x': 0.0, 'y': 0.1, 'z': 1.5}},
    'TwistStamped': {'header': HEADER, 'twist': {'linear': {'x': 0.25, 'y': 0.0, 'z': -0.5},
                                                 'angular': {'x': 0.0, 'y': 0.1, 'z': 1.5}}},
    'PointStamped': {'header': HEADER, 'point': {'x': 0.0125, 'y': -0.04, 'z': 0.3}},
    'PoseWithCovarianceStamped': {'header': HEADER, 'pose': {'pose': POSE, 'covariance': [0.01] * 36}},
    'PolygonStamped': {'header': HEADER, 'polygon': {'points': [{'x': 0.0, 'y': 0.0, 'z': 0.0},
                                                                {'x': 0.125, 'y': 0.0, 'z': 0.0},
                                                                {'x': 0.125, 'y': 0.0625, 'z': 0.0}]}},
    'Odometry': {'header': HEADER, 'child_frame_id': 'base_link', 'pose': {'pose': POSE, 'covariance': [0.0] * 36},
                 'twist': {'twist': {'linear': {'x': 1.0}}, 'covariance': [0.0] * 36}},
    'Path': {'header': HEADER, 'poses': [
        {'header': HEADER, 'pose': POSE},
        {'header': HEADER, 'pose': {'position': {'x': -0.2, 'y': 0.0, 'z': 0.3},
                                    'orientation': {'x': 1.0, 'y': 0.0, 'z': 0.0, 'w': 0.0}}}]},
    'PathPolyline': {'header': HEADER, 'poses': [
        {'header': HEADER, 'pose': POSE},
        {'header': HEADER, 'pose': {'position': {'x': -0.2, 'y': 0.0, 'z': 0.3}}}]},
    'Imu': {'header': HEADER, 'orientation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S},
            'angular_velocity': {'x': 0.01, 'y': -0.02, 'z': 0.03},
            'linear_acceleration': {'x': 0.0, 'y': 0.0, 'z': 9.81}},
    'CameraInfo': CAMERA_INFO,
    'CompressedImage': {'header': HEADER, 'format': 'png', 'data': png_bytes(3, 2, IMAGE)},
    'CameraDistortion': CAMERA_INFO,
    'JoyAxes': JOY,
    'JoyButtons': JOY,
    'DoubleTable': {'layout': {'dim': [{'label': 'rows', 'size': 2, 'stride': 4},
                                       {'label': '', 'size': 2, 'stride': 2}], 'data_offset': 0},
                    'data': [0.5, -1.25, 1e-9, 12345.678]},
}
SENT = 40  # the peer waits for our subscription, then sends this many, reliably


@pytest.mark.parametrize('short,ros_type,expected', INCOMING, ids=[c[0] for c in INCOMING])
def test_rclpy_publisher_to_our_vtk_subscriber(ros, short, ros_type, expected):
    topic = '/scene_in/' + short.lower()
    ours = ros.scene('--seconds', '20', 'sub', short, topic, '--count', str(SENT), '--linger', '1')
    ros.wait_ready(ours)
    message = INCOMING_MESSAGES[short] if short in INCOMING_MESSAGES else SAMPLES[ros_type]
    peer = ros.peer('pub', topic, ros_type, json.dumps(message), '--count', str(SENT), '--rate', '20')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] == SENT and result['rejected'] == 0, result
    if isinstance(expected, dict) and 'Image' not in short:  # a table: exactly these columns
        assert sorted(result['value']) == sorted(expected), result['value']
    close(expected, result['value'])


def test_joint_state_becomes_a_table_without_scaling(ros):
    ours = ros.scene('--seconds', '20', 'sub', 'JointState', '/scene_in/joints')
    ros.wait_ready(ours)
    peer = ros.peer('pub', '/scene_in/joints', 'sensor_msgs/msg/JointState',
                    json.dumps(SAMPLES['sensor_msgs/msg/JointState']), '--count', '40', '--rate', '10')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    table = json.loads(out.splitlines()[-1])['value']
    names = next(v for v in table.values() if v and isinstance(v[0], str))
    assert names == ['shoulder', 'elbow', 'wrist']
    columns = [v for v in table.values() if v and not isinstance(v[0], str)]
    assert [0.1, -0.5, 1.25] in columns and [0.0, 0.5, -0.25] in columns


# our publisher -> rclpy subscriber: (short name, ROS type, expected JSON on the wire)
POSE_WIRE = {'position': {'x': 0.1, 'y': -0.25, 'z': 1.5}, 'orientation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S}}
OUTGOING = [
    ('String', 'std_msgs/msg/String', {'data': 'Hello world.'}),
    ('Bool', 'std_msgs/msg/Bool', {'data': True}),
    ('Int', 'std_msgs/msg/Int64', {'data': -9007199254740993}),
    ('Double', 'std_msgs/msg/Float64', {'data': 3.141592653589793}),
    ('PoseStamped', 'geometry_msgs/msg/PoseStamped', {'header': {'frame_id': 'ct_scanner'}, 'pose': POSE_WIRE}),
    ('TransformStamped', 'geometry_msgs/msg/TransformStamped',
     {'header': {'frame_id': 'ct_scanner'},
      'transform': {'translation': {'x': 0.1, 'y': -0.25, 'z': 1.5}, 'rotation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S}}}),
    ('WrenchStamped', 'geometry_msgs/msg/WrenchStamped',
     {'wrench': {'force': {'x': 1.0, 'y': -2.0, 'z': 9.81}, 'torque': {'x': 0.1, 'y': 0.0, 'z': -0.05}}}),
    ('DoubleArray', 'std_msgs/msg/Float64MultiArray', {'data': [0.5, -1.25, 1e-9, 12345.678]}),
    ('IntTable', 'std_msgs/msg/Int64MultiArray', {'data': [1, -2, 3, 4, -5, 6]}),
    ('PointCloud', 'sensor_msgs/msg/PointCloud',
     {'points': [{'x': 0.5, 'y': 1.5, 'z': -2.0}, {'x': 0.25, 'y': 0.0, 'z': 4.0}]}),
    ('Image', 'sensor_msgs/msg/Image',
     {'height': 2, 'width': 3, 'encoding': 'rgb8', 'step': 9,
      'data': [30, 31, 32, 40, 41, 42, 50, 51, 52, 0, 1, 2, 10, 11, 12, 20, 21, 22]}),
    # one dim named after the array
    ('IntArray', 'std_msgs/msg/Int64MultiArray',
     {'layout': {'dim': [{'label': 'ids', 'size': 3, 'stride': 3}], 'data_offset': 0},
      'data': [7, -9007199254740993, 0]}),
    # row-major; dim[0] "rows"; columns "col_<j>" give dim[1] back its label "col"
    ('DoubleTable', 'std_msgs/msg/Float64MultiArray',
     {'layout': {'dim': [{'label': 'rows', 'size': 2, 'stride': 4}, {'label': 'col', 'size': 2, 'stride': 2}],
                 'data_offset': 0},
      'data': [0.5, -1.25, 2.0, 1e-9]}),
    # float points -> FLOAT32 (datatype 7) x, y, z in metres, then the float "intensity" array
    ('PointCloud2', 'sensor_msgs/msg/PointCloud2',
     {'header': {'frame_id': 'ct_scanner'}, 'height': 1, 'width': 2, 'is_bigendian': False,
      'fields': [{'name': 'x', 'offset': 0, 'datatype': 7, 'count': 1},
                 {'name': 'y', 'offset': 4, 'datatype': 7, 'count': 1},
                 {'name': 'z', 'offset': 8, 'datatype': 7, 'count': 1},
                 {'name': 'intensity', 'offset': 12, 'datatype': 7, 'count': 1}],
      'point_step': 16, 'row_step': 32, 'is_dense': True,
      'data': list(struct.pack('<8f', 0.5, 1.5, -2.0, 0.5, 0.25, 0.0, 4.0, 1.0))}),
    # never scaled; no effort column -> empty effort
    ('JointState', 'sensor_msgs/msg/JointState',
     {'header': {'frame_id': 'ct_scanner'}, 'name': ['shoulder', 'elbow'], 'position': [0.1, -0.5],
      'velocity': [0.0, 0.5], 'effort': []}),
    ('Empty', 'std_msgs/msg/Empty', {}),
    ('Pose', 'geometry_msgs/msg/Pose', POSE_WIRE),
    ('Transform', 'geometry_msgs/msg/Transform',
     {'translation': {'x': 0.1, 'y': -0.25, 'z': 1.5}, 'rotation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S}}),
    ('Wrench', 'geometry_msgs/msg/Wrench',
     {'force': {'x': 1.0, 'y': -2.0, 'z': 9.81}, 'torque': {'x': 0.1, 'y': 0.0, 'z': -0.05}}),
    ('Vector3', 'geometry_msgs/msg/Vector3', {'x': 0.5, 'y': -1.5, 'z': 2.25}),
    ('Twist', 'geometry_msgs/msg/Twist',
     {'linear': {'x': 0.25, 'y': 0.0, 'z': -0.5}, 'angular': {'x': 0.0, 'y': 0.1, 'z': 1.5}}),
    ('TwistStamped', 'geometry_msgs/msg/TwistStamped',
     {'header': {'frame_id': 'ct_scanner'},
      'twist': {'linear': {'x': 0.25, 'y': 0.0, 'z': -0.5}, 'angular': {'x': 0.0, 'y': 0.1, 'z': 1.5}}}),
    ('PointStamped', 'geometry_msgs/msg/PointStamped',
     {'header': {'frame_id': 'ct_scanner'}, 'point': {'x': 0.0125, 'y': -0.04, 'z': 0.3}}),
    ('PoseWithCovarianceStamped', 'geometry_msgs/msg/PoseWithCovarianceStamped',
     {'header': {'frame_id': 'ct_scanner'}, 'pose': {'pose': POSE_WIRE}}),
    ('PolygonStamped', 'geometry_msgs/msg/PolygonStamped',
     {'polygon': {'points': [{'x': 0.0, 'y': 0.0, 'z': 0.0}, {'x': 0.125, 'y': 0.0, 'z': 0.0},
                             {'x': 0.125, 'y': 0.0625, 'z': 0.0}]}}),
    ('Odometry', 'nav_msgs/msg/Odometry', {'header': {'frame_id': 'ct_scanner'}, 'pose': {'pose': POSE_WIRE}}),
    ('Path', 'nav_msgs/msg/Path',
     {'header': {'frame_id': 'ct_scanner'},
      'poses': [{'pose': POSE_WIRE}, {'pose': {'position': {'x': -0.2, 'y': 0.0, 'z': 0.3}}}]}),
    ('Imu', 'sensor_msgs/msg/Imu',
     {'header': {'frame_id': 'ct_scanner'}, 'orientation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S},
      'angular_velocity': {'x': 0.01, 'y': -0.02, 'z': 0.03}, 'linear_acceleration': {'x': 0.0, 'y': 0.0, 'z': 9.81}}),
    # a typed publisher fills only its rule's fields: K, or D, the rest zero / empty
    ('CameraInfo', 'sensor_msgs/msg/CameraInfo',
     {'header': {'frame_id': 'ct_scanner'}, 'k': [525.0, 0.0, 319.5, 0.0, 526.5, 239.5, 0.0, 0.0, 1.0],
      'd': [], 'width': 0, 'height': 0, 'distortion_model': ''}),
    ('CameraDistortion', 'sensor_msgs/msg/CameraInfo',
     {'header': {'frame_id': 'ct_scanner'}, 'd': [-0.28, 0.07, 0.0001, -0.0002, 0.0], 'k': [0.0] * 9}),
    ('JoyAxes', 'sensor_msgs/msg/Joy', {'header': {'frame_id': 'ct_scanner'}, 'axes': [0.5, -1.0, 0.25], 'buttons': []}),
    ('JoyButtons', 'sensor_msgs/msg/Joy', {'header': {'frame_id': 'ct_scanner'}, 'buttons': [0, 1, 1, 0], 'axes': []}),
    # the points in the line cell's order (not their storage order), metres
    ('PathPolyline', 'nav_msgs/msg/Path',
     {'header': {'frame_id': 'ct_scanner'},
      'poses': [{'pose': {'position': {'x': 0.1, 'y': -0.25, 'z': 1.5}}},
                {'pose': {'position': {'x': -0.2, 'y': 0.0, 'z': 0.3}}},
                {'pose': {'position': {'x': 0.0, 'y': 0.0, 'z': 0.0}}}]}),
]


@pytest.mark.parametrize('short,ros_type,expected', OUTGOING, ids=[c[0] for c in OUTGOING])
def test_our_vtk_publisher_to_rclpy_subscriber(ros, short, ros_type, expected):
    topic = '/scene_out/' + short.lower()
    echo = ros.peer('echo', topic, ros_type, '--count', '2', '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '10', 'pub', short, topic)
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    message = json.loads(out.splitlines()[-1])
    close(expected, message)
    if 'header' in message:
        assert message['header']['stamp']['sec'] > 1600000000, 'stamped with the current time'


def test_malformed_compressed_image_is_refused_with_a_reason(ros):
    """Bytes that are no PNG/JPEG, and a truncated PNG: every message arrives, none converts, the
    reason names the problem, the process keeps running."""
    for name, data in (('garbage', [1, 2, 3, 4, 5]), ('truncated', png_bytes(3, 2, IMAGE)[:30])):
        topic = '/scene_in/bad_compressed_' + name
        ours = ros.scene('--seconds', '20', 'sub', 'CompressedImage', topic, '--count', '5', '--linger', '1')
        ros.wait_ready(ours)
        peer = ros.peer('pub', topic, 'sensor_msgs/msg/CompressedImage',
                        json.dumps({'header': HEADER, 'format': 'png', 'data': data}), '--count', '5', '--rate', '20')
        code, out, err = ros.finish(ours)
        ros.stop(peer)
        assert code == 0, err
        result = json.loads(out.splitlines()[-1])
        assert result['count'] == 5, result
        expected = 'neither PNG nor JPEG' if name == 'garbage' else 'cannot decode the PNG'
        assert expected in result['conversion_error'], result


def test_compressed_image_published_as_png_that_pillow_decodes(ros):
    echo = ros.peer('echo', '/scene_out/compressed', 'sensor_msgs/msg/CompressedImage', '--count', '1', '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '8', 'pub', 'CompressedImage', '/scene_out/compressed')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    message = json.loads(out.splitlines()[-1])
    assert message['format'] == 'png' and message['header']['frame_id'] == 'ct_scanner'
    picture = PILImage.open(io.BytesIO(bytes(message['data'])))
    assert picture.format == 'PNG' and picture.size == (3, 2) and picture.mode == 'RGB'
    # the raw Image's wire rows: VTK row 1 (pixels 3..5) is the top row
    assert list(picture.tobytes()) == [30, 31, 32, 40, 41, 42, 50, 51, 52, 0, 1, 2, 10, 11, 12, 20, 21, 22]


# visualization_msgs/Marker -> vtkPolyData in mm: (name, message, expected bounds in mm, extra checks).
# Bounds worked out by hand from the Marker conventions: a shape of size `scale` centred on
# `pose` (an arrow from the pose along its x, a cylinder's axis along its z).
MARKER_POSE = {'position': {'x': 0.1, 'y': -0.25, 'z': 1.5}, 'orientation': {'w': 1.0}}
MARKER_COLOR = {'r': 1.0, 'g': 0.5, 'b': 0.0, 'a': 1.0}
MARKERS = [
    ('cube', {'type': 1, 'pose': MARKER_POSE, 'scale': {'x': 0.02, 'y': 0.04, 'z': 0.06}},
     [90.0, 110.0, -270.0, -230.0, 1470.0, 1530.0], {'polys': 6}),
    # turned 90 degrees about z: the x size lies along y
    ('sphere', {'type': 2, 'pose': {'position': {'x': 0.1, 'y': -0.25, 'z': 1.5},
                                    'orientation': {'x': 0.0, 'y': 0.0, 'z': S, 'w': S}},
                'scale': {'x': 0.02, 'y': 0.04, 'z': 0.06}},
     [80.0, 120.0, -260.0, -240.0, 1470.0, 1530.0], {}),
    ('cylinder', {'type': 3, 'pose': MARKER_POSE, 'scale': {'x': 0.02, 'y': 0.02, 'z': 0.1}},
     [90.0, 110.0, -260.0, -240.0, 1450.0, 1550.0], {}),
    ('arrow', {'type': 0, 'pose': MARKER_POSE, 'scale': {'x': 0.2, 'y': 0.01, 'z': 0.04}},
     [100.0, 300.0, -270.0, -230.0, 1480.0, 1520.0], {}),
    ('line_strip', {'type': 4, 'pose': {'position': {'z': 1.0}, 'orientation': {'w': 1.0}},
                    'scale': {'x': 0.005}, 'points': [{'x': 0.0}, {'x': 0.1}, {'x': 0.1, 'y': 0.2}]},
     [0.0, 100.0, 0.0, 200.0, 1000.0, 1000.0],
     {'lines': [[0, 1, 2]], 'points': [[0.0, 0.0, 1000.0], [100.0, 0.0, 1000.0], [100.0, 200.0, 1000.0]]}),
    ('points', {'type': 8, 'pose': {'position': {'z': 1.0}, 'orientation': {'w': 1.0}},
                'scale': {'x': 0.005, 'y': 0.005}, 'points': [{'x': 0.0}, {'x': 0.1}, {'x': 0.1, 'y': 0.2}]},
     [0.0, 100.0, 0.0, 200.0, 1000.0, 1000.0], {'lines': [], 'verts': 3}),
]


@pytest.mark.parametrize('name,fields,bounds,extra', MARKERS, ids=[m[0] for m in MARKERS])
def test_rclpy_marker_to_our_poly_data(ros, name, fields, bounds, extra):
    topic = '/scene_in/marker_' + name
    ours = ros.scene('--seconds', '20', 'sub', 'Marker', topic, '--count', '5', '--linger', '1')
    ros.wait_ready(ours)
    message = dict(fields, header=HEADER, color=MARKER_COLOR)
    peer = ros.peer('pub', topic, 'visualization_msgs/msg/Marker', json.dumps(message), '--count', '5', '--rate', '20')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] == 5 and result['value'] is not None, result
    value = result['value']
    close(bounds, value['bounds'], tol=1e-6)
    assert value['color'] == [255.0, 128.0, 0.0, 255.0]  # 0.5 * 255 = 127.5, rounded half up
    close(extra, value)


def test_unsupported_marker_type_is_refused_with_a_reason(ros):
    ours = ros.scene('--seconds', '20', 'sub', 'Marker', '/scene_in/marker_text', '--count', '3', '--linger', '1')
    ros.wait_ready(ours)
    # 42: a type Marker does not define (every one it defines is drawn: tests/display,
    # test_scene_marker_array.py).
    message = {'header': HEADER, 'type': 42, 'pose': MARKER_POSE, 'scale': {'x': 0.1, 'y': 0.1, 'z': 0.1},
               'points': [{'x': 0.0}, {'x': 1.0}, {'y': 1.0}]}
    peer = ros.peer('pub', '/scene_in/marker_text', 'visualization_msgs/msg/Marker', json.dumps(message),
                    '--count', '3', '--rate', '20')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    # The topic's markers are kept by (ns, id): the refused one is not kept, so nothing is drawn
    # (an empty poly data, as for a MarkerArray; RViz shows none either) and the error says why.
    assert result['count'] == 3 and result['value'] == [], result
    assert 'marker type is not supported' in result['conversion_error'], result


def test_our_poly_data_line_to_rclpy_marker(ros):
    echo = ros.peer('echo', '/scene_out/marker', 'visualization_msgs/msg/Marker', '--count', '1', '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '8', 'pub', 'Marker', '/scene_out/marker')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    message = json.loads(out.splitlines()[-1])
    close({'header': {'frame_id': 'ct_scanner'}, 'type': 4, 'action': 0,
           'pose': {'position': {'x': 0.0, 'y': 0.0, 'z': 0.0}, 'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}},
           'scale': {'x': 0.001, 'y': 0.001, 'z': 0.001},
           'color': {'r': 1.0, 'g': 0.0, 'b': 0.0, 'a': 1.0},
           'points': [{'x': 0.0, 'y': 0.0, 'z': 0.0}, {'x': 0.1, 'y': 0.0, 'z': 0.0}, {'x': 0.1, 'y': 0.2, 'z': 0.0}]},
          message)


def test_pose_array_rotations_and_metres(ros):
    echo = ros.peer('echo', '/scene_out/poses', 'geometry_msgs/msg/PoseArray', '--count', '1', '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '8', 'pub', 'PoseArray', '/scene_out/poses')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    poses = json.loads(out.splitlines()[-1])['poses']
    close(POSE_WIRE, poses[0])
    close({'x': -0.2, 'y': 0.0, 'z': 0.3}, poses[1]['position'])
    q = poses[1]['orientation']  # the second matrix has no rotation
    close({'x': 0.0, 'y': 0.0, 'z': 0.0}, q)
    assert math.isclose(abs(q['w']), 1.0, abs_tol=1e-12)
