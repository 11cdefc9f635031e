"""3D Slicer reach (issue 16): our OpenIGTLink connector (`python -m ros2vtk igtl`, its own process)
against pyigtl, an independent OpenIGTLink implementation standing in for Slicer's OpenIGTLinkIF
(in this pytest process), with real rclpy peers on the ROS side. Loopback only; every loop bounded.
Units: ROS metres in, OpenIGTLink millimetres out (and back).
"""
from __future__ import annotations

import json
import math
import signal
import socket
import struct
import time
from pathlib import Path

import numpy as np
import pyigtl
import pytest

from conftest import BUILD, HERE, REPO, VENV_PYTHON, tf2_msgs_env
from igtl_peer import (RawClient, frame, free_port, polydata_points, start_ours, tdata_body, tdata_elements,
                       v2_metadata)
from samples import SAMPLES

ARM = REPO / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'
QUARTER_TURN_Z = [0, 0, math.sqrt(0.5), math.sqrt(0.5)]


def wait_ready(process) -> None:
    line = process.stdout.readline()
    assert line and json.loads(line).get('ready') is True, line + process.stderr.read()


def stop(ros, process, timeout: float = 30.0):
    """Ctrl-C to our process (it prints its summary and exits 0), then its output."""
    if process.poll() is None:
        process.send_signal(signal.SIGINT)
    return ros.finish(process, timeout=timeout)


def wait_transform(client, device: str, seconds: float, predicate=lambda m: True):
    """Latest TRANSFORM of `device` satisfying `predicate`, or the last one seen (None if none)."""
    end = time.monotonic() + seconds
    last = None
    while time.monotonic() < end:
        message = client.wait_for_message(device, timeout=0.5)
        if message is not None and message.message_type == 'TRANSFORM':
            last = message
            if predicate(message.matrix):
                return message
    return last


def test_rclpy_tf_arrives_in_pyigtl_as_transform_in_millimetres(ros):
    port = free_port()
    peer = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.1, -0.02, 0.3], 'q': QUARTER_TURN_Z}),
                       '--seconds', '25')
    ours = start_ours(ros, port, '--lookup', 'world:needle', '--seconds', '20')
    wait_ready(ours)
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    try:
        message = wait_transform(client, 'needle', 15, lambda m: abs(m[0, 3] - 100.0) < 1e-3)
    finally:
        client.stop()
    stop(ros, ours)
    assert message is not None, 'no TRANSFORM "needle" arrived'
    assert message.device_name == 'needle'
    m = message.matrix
    assert np.allclose(m[:3, 3], [100.0, -20.0, 300.0], atol=1e-3), m  # metres -> mm
    assert np.allclose(m[:3, :3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-6), m


def test_robot_links_arrive_as_transforms_and_visuals_once_as_polydata_with_their_bounds(ros):
    port = free_port()
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = ':'.join(filter(None, [value, env.get(key)]))
    rsp = ros.start([str(VENV_PYTHON), str(HERE / 'rsp_peer.py'), str(ARM), '--configs', '1', '--hold', '60'], env)
    assert json.loads(rsp.stdout.readline())['ready']
    ours = start_ours(ros, port, '--robot', '--seconds', '50')
    wait_ready(ours)
    # Printed once our robot's lookups listen to /tf: yourdfpy's forward kinematics (m).
    expected = json.loads(rsp.stdout.readline())['links']
    raw = RawClient(port)
    # Until the robot is loaded and its links placed by tf (each visual is resent as its link
    # moves into place), then 4 s of a robot standing still: nothing may be resent then.
    messages = []
    end = time.monotonic() + 30  # robot load under a loaded machine
    while time.monotonic() < end and not any(t == 'POLYDATA' and d == 'needle_tip:visual0' for t, d, _, _ in messages):
        messages += raw.read(0.5)
    messages += raw.read(3.0)
    still = raw.read(4.0)
    raw.close()
    stop(ros, ours)
    resent = [d for t, d, _, _ in still if t == 'POLYDATA']
    assert not resent, f'visuals resent while the robot stood still: {resent}'
    assert any(t == 'TRANSFORM' for t, _, _, _ in still), 'transforms stopped'
    messages += still
    transforms = {d: body for t, d, _, body in messages if t == 'TRANSFORM'}
    polydata = {d: (v, body) for t, d, v, body in messages if t == 'POLYDATA'}  # the latest of each
    # Every link, named by its node ("robot:<link>"), at yourdfpy's pose in mm.
    for link, rows in expected.items():
        device = f'robot:{link}' if len(f'robot:{link}') <= 20 else link
        assert device in transforms, (device, sorted(transforms))
        values = struct.unpack('>12f', transforms[device])  # R columns then translation (transform.md)
        translation = values[9:12]
        assert np.allclose(translation, [1000.0 * rows[i][3] for i in range(3)], atol=1e-3), (link, translation)
    # Every visual of the URDF (11), baked in world coordinates.
    assert len(polydata) == 11, sorted(polydata)
    tip = polydata['needle_tip:visual0'][1]
    points = np.array(polydata_points(tip))
    centre = [1000.0 * expected['needle_tip'][i][3] for i in range(3)]
    # A 4 mm box (URDF) around the tip link's origin.
    assert np.allclose(points.min(axis=0), np.array(centre) - 2.0, atol=1e-3), points.min(axis=0)
    assert np.allclose(points.max(axis=0), np.array(centre) + 2.0, atol=1e-3), points.max(axis=0)


# What stock Slicer reads from a scene file, per element: the attributes its ReadXMLAttributes
# parse (Slicer@583e9b3 Libs/MRML/Core/vtkMRMLNode.cxx, vtkMRMLLinearTransformNode.cxx,
# vtkMRMLModelDisplayNode/vtkMRMLDisplayNode.cxx; SlicerOpenIGTLink@d090ca4
# OpenIGTLinkIF/MRML/vtkMRMLIGTLConnectorNode.cxx), and OpenIGTLinkIF's states (igtlioConnector.h).
SLICER_READS = {
    'IGTLConnector': {'id', 'name', 'connectorType', 'serverHostname', 'serverPort', 'persistent', 'checkCRC',
                      'state', 'restrictDeviceName'},
    'LinearTransform': {'id', 'name', 'matrixTransformToParent'},
    'ModelDisplay': {'id', 'name', 'color', 'visibility'},
    'Model': {'id', 'name', 'references'},
}
PERSISTENT_ON, STATE_WAIT_CONNECTION = '1', '1'


def test_link_local_models_under_their_link_transforms_in_a_slicer_scene_file(ros, tmp_path):
    """--slicer-scene: a .mrml for stock Slicer (connector + each model under its link's transform,
    named as the devices), and link-local meshes sent once with metadata ros.parent. Composing each
    link's TRANSFORM with its link-local mesh, as Slicer does for a model under a transform, puts the
    mesh where yourdfpy's forward kinematics puts the link."""
    port = free_port()
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():
        env[key] = ':'.join(filter(None, [value, env.get(key)]))
    rsp = ros.start([str(VENV_PYTHON), str(HERE / 'rsp_peer.py'), str(ARM), '--configs', '1', '--hold', '60'], env)
    assert json.loads(rsp.stdout.readline())['ready']
    mrml = tmp_path / 'robot.mrml'
    ours = start_ours(ros, port, '--robot', '--slicer-scene', str(mrml), '--seconds', '50')
    wait_ready(ours)
    expected = json.loads(rsp.stdout.readline())['links']
    raw = RawClient(port)
    messages = []
    end = time.monotonic() + 30  # robot load under a loaded machine
    while time.monotonic() < end and not any(d == 'needle_tip:visual0' for _, d, _, _ in messages):
        messages += raw.read(0.5)
    messages += raw.read(1.5)
    raw.close()
    # A client that connects later (Slicer reconnecting) gets the meshes again, sent once above.
    again = RawClient(port)
    later = again.read(3.0)
    again.close()
    code, out, err = stop(ros, ours)
    assert code == 0, err
    written = [json.loads(l) for l in out.splitlines() if l.startswith('{"slicer_scene"')]
    assert written and written[-1]['models'] == 11, written  # the URDF's 11 visuals
    polydata = {d: (v, body) for t, d, v, body in messages if t == 'POLYDATA'}
    transforms = {d: body for t, d, _, body in messages if t == 'TRANSFORM'}
    assert len(polydata) == 11, sorted(polydata)
    assert [d for t, d, _, _ in later if t == 'POLYDATA'].count('needle_tip:visual0') == 1, later
    version, body = polydata['needle_tip:visual0']
    assert version == 2
    assert v2_metadata(body)['ros.parent'] == 'robot:needle_tip'
    points = np.array(polydata_points(body, version))
    assert np.allclose(points.min(axis=0), [-2, -2, -2], atol=1e-3)  # link-local: around 0
    assert np.allclose(points.max(axis=0), [2, 2, 2], atol=1e-3)
    # Slicer's view of it: TRANSFORM of the parent (transform.md: R by columns, then t) · local mesh.
    values = struct.unpack('>12f', transforms['robot:needle_tip'])
    link = np.eye(4)
    link[:3, :3] = np.array(values[:9]).reshape(3, 3).T
    link[:3, 3] = values[9:12]
    world = (link[:3, :3] @ points.T).T + link[:3, 3]
    centre = np.array([1000.0 * expected['needle_tip'][i][3] for i in range(3)])
    assert np.allclose(world.min(axis=0), centre - 2.0, atol=1e-2) and np.allclose(world.max(axis=0), centre + 2.0,
                                                                                    atol=1e-2), world
    # The scene file, read as Slicer reads it.
    import xml.etree.ElementTree as ET
    root = ET.parse(mrml).getroot()
    assert root.tag == 'MRML'
    for element in root:
        assert element.tag in SLICER_READS and set(element.attrib) <= SLICER_READS[element.tag], element.attrib
    by_id = {e.get('id'): e for e in root}
    assert len(by_id) == len(root), 'node ids are not unique'
    connector, = root.iter('IGTLConnector')
    assert (connector.get('connectorType'), connector.get('serverHostname'), connector.get('serverPort')) == \
        ('CLIENT', 'localhost', str(port))
    assert (connector.get('persistent'), connector.get('state')) == (PERSISTENT_ON, STATE_WAIT_CONNECTION)
    models = {m.get('name'): m for m in root.iter('Model')}
    assert set(models) == set(polydata), (sorted(models), sorted(polydata))  # OpenIGTLinkIF matches by name
    for name, model in models.items():
        refs = dict(r.split(':') for r in model.get('references').strip(';').split(';'))
        assert by_id[refs['display']].tag == 'ModelDisplay'
        parent = by_id[refs['transform']]
        assert parent.tag == 'LinearTransform'
        v, b = polydata[name]
        assert parent.get('name') == v2_metadata(b)['ros.parent'], name  # the link the mesh belongs to
        assert parent.get('name') in transforms, parent.get('name')  # ... and a TRANSFORM device we send


def test_rclpy_image_arrives_as_image_with_its_pixels_and_pose(ros):
    port = free_port()
    pixels = list(range(10, 22))  # 4 wide, 3 high, mono8
    image = {'header': {'frame_id': 'camera'}, 'height': 3, 'width': 4, 'encoding': 'mono8',
             'is_bigendian': 0, 'step': 4, 'data': pixels}
    tf = ros.tf_peer('tf_pub', 'world', 'camera', json.dumps({'t': [0.1, 0.0, 0.05], 'q': [0, 0, 0, 1]}),
                     '--seconds', '25')
    ours = start_ours(ros, port, '--image', '/camera/image', '--lookup', 'world:camera', '--seconds', '20')
    wait_ready(ours)
    pub = ros.peer('pub', '/camera/image', 'sensor_msgs/msg/Image', json.dumps(image), '--count', '40',
                   '--rate', '5', '--wait', '10')
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    message = None
    try:
        end = time.monotonic() + 15
        while time.monotonic() < end:
            got = client.wait_for_message('camera_image', timeout=0.5)
            if got is not None and got.message_type == 'IMAGE':
                message = got
                if abs(got.ijk_to_world_matrix[0, 3] - 100.0) < 10.0:  # posed once tf arrived
                    break
    finally:
        client.stop()
    stop(ros, ours)
    assert message is not None, 'no IMAGE "camera_image" arrived'
    data = np.asarray(message.image)
    assert data.shape in ((1, 3, 4), (3, 4)), data.shape
    rows = data.reshape(3, 4)
    ros_rows = np.array(pixels).reshape(3, 4)
    # VTK images start at the bottom row (runtime/Convert/README.md: ROS row 0 = top), and the j axis
    # points up (+A in Slicer), so the picture stands upright: the first row sent is ROS's last.
    assert np.array_equal(rows, ros_rows[::-1]), rows
    m = message.ijk_to_world_matrix
    spacing = np.linalg.norm(m[:3, :3], axis=0)
    assert np.all(spacing > 0)
    assert np.allclose(m[:3, 0] / spacing[0], [1, 0, 0]) and np.allclose(m[:3, 1] / spacing[1], [0, 1, 0]), m
    # pyigtl gives the first voxel's position (corner): the camera frame at (100, 0, 50) mm plus
    # the image's own origin, which for a ROS image is 0 within a pixel.
    assert np.allclose(m[:3, 3], [100.0, 0.0, 50.0], atol=float(max(spacing)) * 3 + 1e-6), m


def test_pyigtl_transform_and_points_come_out_on_ros_in_metres(ros):
    port = free_port()
    tf_echo = ros.tf_peer('tf_echo', '--count', '1', '--timeout', '25')
    wait_ready(tf_echo)
    points_echo = ros.peer('echo', '/slicer/points', 'sensor_msgs/msg/PointCloud', '--count', '1', '--timeout', '25')
    wait_ready(points_echo)
    ours = start_ours(ros, port, '--map', 'Target=tf:world:target', '--map', 'F=topic:/slicer/points:PointCloud',
                      '--seconds', '20')
    wait_ready(ours)
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    target = np.eye(4)
    target[:3, :3] = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    target[:3, 3] = [10.0, 20.0, 30.0]
    try:
        end = time.monotonic() + 15
        while time.monotonic() < end and (tf_echo.poll() is None or points_echo.poll() is None):
            # As Slicer sends: header v2 with its metadata (the notes, section 2).
            t = pyigtl.TransformMessage(target, device_name='Target')
            t.header_version = 2
            t.metadata = {'MRMLNodeName': 'LinearTransform', 'TransformStatus': 'OK'}
            client.send_message(t, wait=True)
            p = pyigtl.PointMessage(positions=[[1.0, 2.0, 3.0], [-4.0, 5.0, 600.0]], names=['F-1', 'F-2'],
                                    device_name='F')
            client.send_message(p, wait=True)
            time.sleep(0.2)
    finally:
        client.stop()
    code, out, err = ros.finish(tf_echo)
    assert code == 0, err
    t = json.loads(out.splitlines()[-1])['transforms'][0]
    assert (t['header']['frame_id'], t['child_frame_id']) == ('world', 'target')
    assert [round(v, 9) for v in t['transform']['translation'].values()] == [0.01, 0.02, 0.03]
    q = t['transform']['rotation']
    assert math.isclose(q['z'], math.sqrt(0.5), abs_tol=1e-6) and math.isclose(q['w'], math.sqrt(0.5), abs_tol=1e-6)
    code, out, err = ros.finish(points_echo)
    assert code == 0, err
    cloud = json.loads(out.splitlines()[-1])
    got = [[p['x'], p['y'], p['z']] for p in cloud['points']]
    assert np.allclose(got, [[0.001, 0.002, 0.003], [-0.004, 0.005, 0.6]], atol=1e-7), got
    code, out, err = stop(ros, ours)
    summary = json.loads(out.splitlines()[-1])
    assert summary['received_nodes'].get('Target') == 'vtkROS2TransformNode', summary


def test_bad_input_is_survived_explained_and_other_clients_keep_being_served(ros):
    port = free_port()
    peer = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.1, 0.0, 0.0], 'q': [0, 0, 0, 1]}),
                       '--seconds', '30')
    ours = start_ours(ros, port, '--lookup', 'world:needle', '--seconds', '22')
    wait_ready(ours)
    good = RawClient(port)
    assert any(d == 'needle' for _, d, _, _ in good.read(6.0)), 'the good client got nothing at first'
    bad_inputs = {
        'bad header': b'\x00\x07' + b'X' * 100,
        'oversized': frame('TRANSFORM', 'huge', b'', size=1 << 40),
        'CRC': frame('TRANSFORM', 'crc', b'\0' * 48, crc=12345),
        'short body': frame('TRANSFORM', 'short', b'\0' * 10),
        'bad v2': frame('TRANSFORM', 'v2', b'\x00\x0c' + b'\xff' * 10, version=2),
        'mid-stream': frame('TRANSFORM', 'cut', b'\0' * 48)[:70],
    }
    for name, data in bad_inputs.items():
        bad = RawClient(port)
        bad.sock.sendall(data)
        time.sleep(0.3)
        bad.close()
        # The good client is still served, with fresh messages.
        assert any(d == 'needle' for _, d, _, _ in good.read(1.0)), f'the good client stopped after {name}'
    # A pyigtl client can still connect and get the transform.
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    try:
        assert wait_transform(client, 'needle', 8) is not None
    finally:
        client.stop()
    good.close()
    code, out, err = stop(ros, ours, timeout=40)
    assert code == 0, err
    events = '\n'.join(json.loads(l).get('event', '') for l in out.splitlines() if l.startswith('{'))
    assert 'header version 7' in events
    assert 'exceeds the limit' in events
    assert 'CRC mismatch' in events
    assert 'body of 10 bytes, expected 48' in events + err
    assert 'header v2 sections' in events
    assert 'in the middle of a message (70 bytes of it read)' in events, events
    summary = json.loads(out.splitlines()[-1])
    assert summary['bad'] == 5, summary  # all but the cut message (a lost connection, not a message)


def test_several_clients_are_served_at_once_and_a_stalled_one_blocks_nobody(ros, tmp_path):
    """Two clients that read (pyigtl, and the raw reader) and one that never reads, all connected
    while an rclpy camera streams 64 KB images at 30 Hz: the readers keep getting fresh transforms
    and images, and the stalled one, read at the end, got fewer images than the readers (its queue
    kept the newest instead of blocking the spin or buffering everything)."""
    port = free_port()
    image = {'header': {'frame_id': 'camera'}, 'height': 256, 'width': 256, 'encoding': 'mono8', 'step': 256,
             'data': [i % 251 for i in range(256 * 256)]}
    (tmp_path / 'image.json').write_text(json.dumps(image))
    pub = ros.peer('pub', '/camera/image', 'sensor_msgs/msg/Image', '@' + str(tmp_path / 'image.json'),
                   '--count', '600', '--rate', '30', '--wait', '15')
    tf = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.1, 0.0, 0.0], 'q': [0, 0, 0, 1]}),
                     '--seconds', '30')
    ours = start_ours(ros, port, '--lookup', 'world:needle', '--image', '/camera/image', '--seconds', '25')
    wait_ready(ours)
    stalled = socket.socket()
    stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stalled.connect(('127.0.0.1', port))
    reader = RawClient(port)
    slicer = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    try:
        end = time.monotonic() + 15  # until images flow
        while time.monotonic() < end and not any(t == 'IMAGE' for t, _, _, _ in reader.read(0.5)):
            pass
        first = wait_transform(slicer, 'needle', 5)
        window = reader.read(4.0)  # the stalled client reads nothing meanwhile
        last = wait_transform(slicer, 'needle', 5)
        image_message = slicer.wait_for_message('camera_image', timeout=5)
        stalled.settimeout(0.1)
        got = b''
        end = time.monotonic() + 0.5  # what its socket and queue hold, and 0.5 s of new ones
        while time.monotonic() < end:
            try:
                got += stalled.recv(1 << 20)
            except socket.timeout:
                pass
    finally:
        slicer.stop()
        reader.close()
        stalled.close()
    code, out, err = stop(ros, ours)
    pub.kill()
    tf.kill()
    assert code == 0, err
    assert first is not None and last is not None, 'pyigtl got no TRANSFORM'
    assert last.timestamp - first.timestamp > 3.0, (first.timestamp, last.timestamp)  # fresh, not stuck
    assert image_message is not None and image_message.image.shape[-2:] == (256, 256)
    images = sum(1 for t, _, _, _ in window if t == 'IMAGE')
    transforms = sum(1 for t, d, _, _ in window if t == 'TRANSFORM' and d == 'needle')
    assert images >= 30 and transforms >= 100, (images, transforms)  # 4 s of 30 Hz images, 100 Hz spin
    stalled_images = got.count(b'IMAGE\0\0\0\0\0\0\0camera_image')
    assert stalled_images < images, (stalled_images, images)


def test_client_mode_reaches_a_pyigtl_server(ros):
    port = free_port()
    peer = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.0, 0.25, 0.0], 'q': [0, 0, 0, 1]}),
                       '--seconds', '25')
    server = pyigtl.OpenIGTLinkServer(port=port, local_server=True)
    try:
        ours = start_ours(ros, port, '--client', '--lookup', 'world:needle', '--seconds', '15')
        wait_ready(ours)
        message = wait_transform(server, 'needle', 12, lambda m: abs(m[1, 3] - 250.0) < 1e-3)
    finally:
        server.stop()
    stop(ros, ours)
    assert message is not None and np.allclose(message.matrix[:3, 3], [0.0, 250.0, 0.0], atol=1e-3)


def test_position_message_comes_out_as_pose_stamped_in_metres(ros):
    """POSITION (position.md: 3 float32 mm + quaternion x, y, z, w), framed by the test's own
    encoder since pyigtl's PositionMessage does not follow the spec layout."""
    port = free_port()
    echo = ros.peer('echo', '/slicer/probe', 'geometry_msgs/msg/PoseStamped', '--count', '1', '--timeout', '25')
    wait_ready(echo)
    ours = start_ours(ros, port, '--map', 'Probe=topic:/slicer/probe:PoseStamped', '--seconds', '20')
    wait_ready(ours)
    raw = RawClient(port)
    body = struct.pack('>7f', 5.0, -6.0, 70.0, *QUARTER_TURN_Z)
    end = time.monotonic() + 15
    while time.monotonic() < end and echo.poll() is None:
        raw.sock.sendall(frame('POSITION', 'Probe', body))
        raw.read(0.2)
    raw.close()
    code, out, err = ros.finish(echo)
    stop(ros, ours)
    assert code == 0, err
    pose = json.loads(out.splitlines()[-1])['pose']
    assert np.allclose([pose['position'][k] for k in 'xyz'], [0.005, -0.006, 0.07], atol=1e-7), pose
    q = pose['orientation']
    assert np.allclose([q['x'], q['y'], q['z'], q['w']], QUARTER_TURN_Z, atol=1e-6), q


def test_pyigtl_string_and_image_come_out_on_ros_topics(ros):
    port = free_port()
    text_echo = ros.peer('echo', '/slicer/note', 'std_msgs/msg/String', '--count', '1', '--timeout', '25')
    wait_ready(text_echo)
    image_echo = ros.peer('echo', '/slicer/scan', 'sensor_msgs/msg/Image', '--count', '1', '--timeout', '25')
    wait_ready(image_echo)
    ours = start_ours(ros, port, '--map', 'Note=topic:/slicer/note:String',
                      '--map', 'Scan=topic:/slicer/scan:Image', '--seconds', '20')
    wait_ready(ours)
    pixels = np.arange(12, dtype=np.uint8).reshape(1, 3, 4) * 7  # (k, j, i): 4 wide, 3 high
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    try:
        end = time.monotonic() + 15
        while time.monotonic() < end and (text_echo.poll() is None or image_echo.poll() is None):
            client.send_message(pyigtl.StringMessage('needle inserted', device_name='Note'), wait=True)
            client.send_message(pyigtl.ImageMessage(pixels, device_name='Scan'), wait=True)
            time.sleep(0.2)
    finally:
        client.stop()
    code, out, err = ros.finish(text_echo)
    assert code == 0, err
    assert json.loads(out.splitlines()[-1])['data'] == 'needle inserted'
    code, out, err = ros.finish(image_echo)
    assert code == 0, err
    image = json.loads(out.splitlines()[-1])
    assert (image['width'], image['height'], image['encoding']) == (4, 3, 'mono8'), image
    # OpenIGTLink's j runs up like VTK's; ROS row 0 is the top: rows come out reversed.
    assert np.array_equal(np.array(image['data'], dtype=np.uint8).reshape(3, 4), pixels[0][::-1]), image['data']
    stop(ros, ours)


def test_a_connector_restored_from_a_saved_scene_serves_its_port_lookups_and_mappings(ros, tmp_path):
    """`ros2vtk igtl ... --save-scene F` then, in a new process, `ros2vtk igtl --scene F`: the
    restored connector listens on the saved port, sends the saved tf lookup to pyigtl and routes
    the saved device mapping to tf, read by rclpy."""
    port = free_port()
    saved = tmp_path / 'slicer_link.xml'
    first = start_ours(ros, port, '--lookup', 'world:needle', '--map', 'Target=tf:world:target',
                       '--save-scene', str(saved), '--seconds', '0.2')
    code, out, err = ros.finish(first)
    assert code == 0 and saved.exists(), out + err
    peer = ros.tf_peer('tf_pub', 'world', 'needle', json.dumps({'t': [0.0, 0.0, 0.125], 'q': [0, 0, 0, 1]}),
                       '--seconds', '25')
    tf_echo = ros.tf_peer('tf_echo', '--count', '1', '--timeout', '25', '--child', 'target')
    wait_ready(tf_echo)
    ours = ros.start(['/usr/bin/python3', '-m', 'ros2vtk', 'igtl', '--scene', str(saved), '--seconds', '20'],
                     dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    wait_ready(ours)
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port)  # the port came from the file only
    target = np.eye(4)
    target[:3, 3] = [0.0, 40.0, 0.0]
    try:
        message = wait_transform(client, 'needle', 15, lambda m: abs(m[2, 3] - 125.0) < 1e-3)
        end = time.monotonic() + 10
        while time.monotonic() < end and tf_echo.poll() is None:
            client.send_message(pyigtl.TransformMessage(target, device_name='Target'), wait=True)
            time.sleep(0.2)
    finally:
        client.stop()
    stop(ros, ours)
    assert message is not None and np.allclose(message.matrix[:3, 3], [0.0, 0.0, 125.0], atol=1e-3)
    code, out, err = ros.finish(tf_echo)
    assert code == 0, err
    t = [t for t in json.loads(out.splitlines()[-1])['transforms'] if t['child_frame_id'] == 'target'][0]
    assert t['header']['frame_id'] == 'world'
    assert [round(v, 9) for v in t['transform']['translation'].values()] == [0.0, 0.04, 0.0]


def test_rclpy_pose_array_arrives_as_tdata_and_a_point_list_in_millimetres(ros):
    """PoseArray → TDATA (Slicer makes one linear transform per element), read with the test's own
    decoder (pyigtl drops TDATA) from tdata.md's layout, and → POINT (Slicer makes a markups point
    list), read by pyigtl, connected at the same time."""
    port = free_port()
    sample = SAMPLES['geometry_msgs/msg/PoseArray']
    pub = ros.peer('pub', '/targets', 'geometry_msgs/msg/PoseArray', json.dumps(sample),
                   '--count', '60', '--rate', '5', '--wait', '15')
    ours = start_ours(ros, port, '--poses', '/targets', '--seconds', '20')
    wait_ready(ours)
    client = RawClient(port)
    slicer = pyigtl.OpenIGTLinkClient('127.0.0.1', port)
    points = None
    try:
        end = time.monotonic() + 15
        tdata = None
        while tdata is None and time.monotonic() < end:
            tdata = next((m for m in client.read(0.5) if m[0] == 'TDATA'), None)
        while points is None and time.monotonic() < end:
            message = slicer.wait_for_message('targets', timeout=0.5)
            points = message if message is not None and message.message_type == 'POINT' else None
    finally:
        client.close()
        slicer.stop()
    stop(ros, ours)
    pub.kill()
    assert points is not None, 'no POINT "targets" arrived'
    assert list(points.names) == ['targets_0', 'targets_1']
    assert np.allclose(points.positions, [[100.0, -250.0, 1500.0], [-200.0, 0.0, 300.0]], atol=1e-3)
    assert list(points.groups) == ['Selected', 'Selected']  # Slicer: anything but "Unselected"
    assert all(c[3] == 255 for c in points.rgba_colors)  # alpha 0 would hide the point in Slicer
    assert tdata is not None, 'no TDATA arrived'
    assert tdata[1] == 'targets'
    elements = tdata_elements(tdata[3])
    assert [(name, kind) for name, kind, _ in elements] == [('targets_0', 2), ('targets_1', 2)]
    first, second = (np.array(m) for _, _, m in elements)
    assert np.allclose(first[:3, 3], [100.0, -250.0, 1500.0], atol=1e-3), first  # m -> mm
    assert np.allclose(first[:3, :3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-6), first
    assert np.allclose(second[:3, 3], [-200.0, 0.0, 300.0], atol=1e-3), second
    assert np.allclose(second[:3, :3], [[1, 0, 0], [0, -1, 0], [0, 0, -1]], atol=1e-6), second


def test_tdata_from_slicer_becomes_transform_nodes_a_pose_array_and_tf_in_metres(ros):
    port = free_port()
    echo = ros.peer('echo', '/slicer/targets', 'geometry_msgs/msg/PoseArray', '--count', '1', '--timeout', '20')
    wait_ready(echo)
    tf_echo = ros.tf_peer('tf_echo', '--count', '1', '--timeout', '25')
    wait_ready(tf_echo)
    # The bundle to a PoseArray, and one element (Slicer names its transform node by it) to tf.
    ours = start_ours(ros, port, '--map', 'Targets=topic:/slicer/targets:PoseArray', '--map', 'Tip=tf:world:tip',
                      '--seconds', '15')
    wait_ready(ours)
    turn = [[0, -1, 0, 10.0], [1, 0, 0, 20.0], [0, 0, 1, 30.0], [0, 0, 0, 1]]
    shift = [[1, 0, 0, -5.0], [0, 1, 0, 0.0], [0, 0, 1, 250.0], [0, 0, 0, 1]]
    body = tdata_body([('Tip', turn), ('Entry', shift)])
    client = RawClient(port)
    try:
        end = time.monotonic() + 12
        while time.monotonic() < end and (echo.poll() is None or tf_echo.poll() is None):
            client.sock.sendall(frame('TDATA', 'Targets', body))
            time.sleep(0.2)
    finally:
        client.close()
    code, out, err = ros.finish(echo)
    assert code == 0, err
    poses = json.loads(out.splitlines()[-1])['poses']
    got = [[p['position'][k] for k in 'xyz'] for p in poses]
    assert np.allclose(got, [[0.01, 0.02, 0.03], [-0.005, 0.0, 0.25]], atol=1e-7), got
    q = poses[0]['orientation']
    assert np.allclose([q['x'], q['y'], q['z'], q['w']], [0, 0, math.sqrt(0.5), math.sqrt(0.5)], atol=1e-6)
    code, out, err = ros.finish(tf_echo)
    assert code == 0, err
    t = json.loads(out.splitlines()[-1])['transforms'][0]
    assert (t['header']['frame_id'], t['child_frame_id']) == ('world', 'tip')
    assert np.allclose(list(t['transform']['translation'].values()), [0.01, 0.02, 0.03], atol=1e-7), t
    q = t['transform']['rotation']
    assert np.allclose([q['x'], q['y'], q['z'], q['w']], [0, 0, math.sqrt(0.5), math.sqrt(0.5)], atol=1e-6)
    code, out, err = stop(ros, ours)
    summary = json.loads(out.splitlines()[-1])
    assert summary['received_nodes'].get('Tip') == 'vtkROS2TransformNode', summary
    assert summary['received_nodes'].get('Entry') == 'vtkROS2TransformNode', summary
