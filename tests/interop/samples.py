"""Sample values per ROS type for interop tests, as JSON-able dicts (fields by name).

Written by hand: they are inputs for both sides, never outputs of the code under test.
"""
from __future__ import annotations

STAMP = {'sec': 1700000123, 'nanosec': 456789012}
HEADER = {'stamp': STAMP, 'frame_id': 'ct_scanner'}
POSE = {'position': {'x': 0.1, 'y': -0.25, 'z': 1.5},
        'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.7071067811865476, 'w': 0.7071067811865476}}

SAMPLES: dict[str, dict] = {
    'std_msgs/msg/String': {'data': 'Hello world.'},
    'std_msgs/msg/Bool': {'data': True},
    'std_msgs/msg/Int64': {'data': -9007199254740993},
    'std_msgs/msg/Float64': {'data': 3.141592653589793},
    'std_msgs/msg/Empty': {},
    'std_msgs/msg/Int64MultiArray': {
        'layout': {'dim': [{'label': 'rows', 'size': 2, 'stride': 6},
                           {'label': 'cols', 'size': 3, 'stride': 3}], 'data_offset': 0},
        'data': [1, -2, 3, 4, -5, 6]},
    'std_msgs/msg/Float64MultiArray': {
        'layout': {'dim': [{'label': 'x', 'size': 4, 'stride': 4}], 'data_offset': 0},
        'data': [0.5, -1.25, 1e-9, 12345.678]},
    'geometry_msgs/msg/PoseStamped': {'header': HEADER, 'pose': POSE},
    'geometry_msgs/msg/TransformStamped': {
        'header': HEADER, 'child_frame_id': 'needle_tip',
        'transform': {'translation': {'x': 0.01, 'y': 0.02, 'z': -0.3},
                      'rotation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}},
    'geometry_msgs/msg/WrenchStamped': {
        'header': HEADER,
        'wrench': {'force': {'x': 1.0, 'y': -2.0, 'z': 9.81}, 'torque': {'x': 0.1, 'y': 0.0, 'z': -0.05}}},
    'geometry_msgs/msg/PoseArray': {'header': HEADER, 'poses': [POSE, {
        'position': {'x': -0.2, 'y': 0.0, 'z': 0.3},
        'orientation': {'x': 1.0, 'y': 0.0, 'z': 0.0, 'w': 0.0}}]},
    'sensor_msgs/msg/Image': {
        'header': HEADER, 'height': 2, 'width': 3, 'encoding': 'rgb8', 'is_bigendian': 0, 'step': 9,
        'data': [0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160, 255]},
    'sensor_msgs/msg/PointCloud': {
        'header': HEADER,
        'points': [{'x': 0.5, 'y': 1.5, 'z': -2.0}, {'x': 0.25, 'y': 0.0, 'z': 4.0}],
        'channels': [{'name': 'intensity', 'values': [0.5, 1.0]}]},
    'sensor_msgs/msg/PointCloud2': {
        'header': HEADER, 'height': 1, 'width': 2,
        'fields': [{'name': 'x', 'offset': 0, 'datatype': 7, 'count': 1},
                   {'name': 'y', 'offset': 4, 'datatype': 7, 'count': 1},
                   {'name': 'z', 'offset': 8, 'datatype': 7, 'count': 1}],
        'is_bigendian': False, 'point_step': 12, 'row_step': 24,
        'data': [0, 0, 128, 63, 0, 0, 0, 64, 0, 0, 64, 64, 0, 0, 128, 64, 0, 0, 160, 64, 0, 0, 192, 64],
        'is_dense': True},
    'sensor_msgs/msg/JointState': {
        'header': HEADER, 'name': ['shoulder', 'elbow', 'wrist'],
        'position': [0.1, -0.5, 1.25], 'velocity': [0.0, 0.5, -0.25], 'effort': []},
}
