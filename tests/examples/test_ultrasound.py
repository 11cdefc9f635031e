"""examples/ultrasound: an rclpy ultrasound simulator (tests/examples/peers.py ultrasound: the
phantom read with numpy, cut by the probe's plane) sends frames and the probe pose; the example
shows each frame as a slice at the probe's pose.

Checked against what the peer sent, computed here independently: the frame's dimensions and pixel
checksum (transport and row order), the world (image-frame) position of its corners from the
registration and the probe pose (numpy), and the offscreen PNG showing the slice where the
camera projection says.
"""
from __future__ import annotations

import json
import math

import numpy as np

WIDTH, HEIGHT, PIXEL_MM = 128, 96, 0.5


def registration() -> np.ndarray:
    """robot -> image: 20 deg about z, then a translation (mm)."""
    a = math.radians(20)
    m = np.eye(4)
    m[:3, :3] = [[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]
    m[:3, 3] = [-300.0, 90.0, -140.0]
    return m


def quaternion(r: np.ndarray) -> list[float]:
    """(x, y, z, w) of a rotation matrix (Shepperd's method, the w >= 0 branch suffices here)."""
    w = math.sqrt(max(0.0, 1 + r[0, 0] + r[1, 1] + r[2, 2])) / 2
    if w > 1e-3:
        return [(r[2, 1] - r[1, 2]) / (4 * w), (r[0, 2] - r[2, 0]) / (4 * w), (r[1, 0] - r[0, 1]) / (4 * w), w]
    i = int(np.argmax(np.diag(r)))
    j, k = (i + 1) % 3, (i + 2) % 3
    s = math.sqrt(max(0.0, 1 + r[i, i] - r[j, j] - r[k, k])) * 2
    q = [0.0, 0.0, 0.0, (r[k, j] - r[j, k]) / s]
    q[i], q[j], q[k] = s / 4, (r[j, i] + r[i, j]) / s, (r[k, i] + r[i, k]) / s
    return q


def probe_in_image(centre: np.ndarray, spin_deg: float) -> np.ndarray:
    """A probe above the tumour looking down (-z of the image), turned `spin_deg` about its axis."""
    a = math.radians(spin_deg)
    x = np.array([math.cos(a), math.sin(a), 0.0])
    z = np.array([0.0, 0.0, -1.0])
    m = np.eye(4)
    m[:3, :3] = np.column_stack([x, np.cross(z, x), z])
    m[:3, 3] = [centre[0], centre[1], 80.0]  # 8 mm above the gel block's top (72 mm)
    return m


def test_ultrasound_frames_shown_at_the_probe_pose(ros_domain, phantom, tmp_path):
    ros = ros_domain(228)
    robot_to_image = registration()
    image_to_robot = np.linalg.inv(robot_to_image)
    centre = np.array(phantom.tumour_centre)
    probes_image = [probe_in_image(centre, 0.0), probe_in_image(centre + [4.0, -3.0, 0.0], 35.0)]
    poses = []
    for probe in probes_image:
        robot = image_to_robot @ probe
        poses.append({'position': (robot[:3, 3] / 1000.0).tolist(), 'orientation': quaternion(robot[:3, :3])})
    png = tmp_path / 'ultrasound.png'
    frames_per_pose = 6
    example = ros.example('ultrasound', '--registration', ' '.join(repr(float(v)) for v in robot_to_image.ravel()),
                          '--pixel-spacing', str(PIXEL_MM), '--phantom', str(phantom.path), '--offscreen', str(png),
                          '--idle-exit', '3', '--seconds', '45', display=True)
    ready = example.next_json(30, lambda o: 'ready' in o or 'error' in o)
    assert ready.get('ready') is True, ready
    peer = ros.peer('ultrasound', str(phantom.path), json.dumps(poses), '--registration',
                    ' '.join(repr(float(v)) for v in robot_to_image.ravel()), '--width', str(WIDTH),
                    '--height', str(HEIGHT), '--pixel', str(PIXEL_MM), '--frames-per-pose', str(frames_per_pose))
    sent = peer.next_json(45, lambda o: 'sent' in o or 'error' in o)
    assert 'error' not in sent, sent
    sent = sent['sent']
    assert example.finish(30) == 0, example.stderr
    frames = [o for o in example.json_lines() if 'frame' in o]
    # A viewer shows the newest frame of a spin: some may be skipped, never the last one, and every
    # probe pose is seen.
    assert frames and abs(frames[-1]['stamp'] - sent[-1]['stamp']) < 1e-6, (frames, example.stderr)
    shown_poses = set()

    # The simulated frame cuts the tumour (bright: 160 HU -> 204 in the W400/L40 window).
    assert sent[0]['max'] >= 190, sent[0]
    for frame in frames:
        match = [s for s in sent if abs(s['stamp'] - frame['stamp']) < 1e-6]
        assert match, (frame['stamp'], [s['stamp'] for s in sent])
        index = sent.index(match[0])
        pixels = frame['encoding_checksum']
        assert frame['dimensions'] == [WIDTH, HEIGHT, 1]
        assert pixels['scalar_type'] == 'unsigned char' and pixels['components'] == 1
        assert (pixels['bytes'], pixels['sum'], pixels['crc32']) == (match[0]['bytes'], match[0]['sum'], match[0]['crc32'])
        assert abs(frame['pose_stamp'] - frame['stamp']) < 1e-6, frame  # paired with its own pose
        # Where its corners are: row 0 (top) on the transducer face, columns along the probe's x.
        probe = probes_image[index // frames_per_pose]
        shown_poses.add(index // frames_per_pose)
        half = (WIDTH - 1) * PIXEL_MM / 2
        expected = {'top_left': [-half, 0, 0], 'top_right': [half, 0, 0],
                    'bottom_left': [-half, 0, (HEIGHT - 1) * PIXEL_MM]}
        for name, local in expected.items():
            world = (probe @ np.append(local, 1.0))[:3]
            np.testing.assert_allclose(frame['corners_world_mm'][name], world, rtol=0, atol=1e-6, err_msg=name)

    assert shown_poses == {0, 1}, shown_poses

    # The picture: the slice's centre projects onto grey ultrasound pixels, not the background.
    last = frames[-1]
    assert png.exists() and last['png'] == str(png)
    width, height, rgb = read_png_rgb(png)
    x, y = (int(round(v)) for v in last['centre_display'][:2])
    assert 0 <= x < width and 0 <= y < height, last
    r, g, b = rgb[height - 1 - y][x]  # display y goes up, PNG rows go down
    assert abs(r - g) < 8 and abs(g - b) < 8 and r > 40, ((x, y), (r, g, b))  # grey, not the dark-blue background


def read_png_rgb(path):
    """A minimal PNG reader (8-bit RGB/RGBA, non-interlaced: what vtkPNGWriter writes)."""
    import struct
    import zlib
    data = path.read_bytes()
    assert data[:8] == b'\x89PNG\r\n\x1a\n'
    position, chunks, header = 8, b'', None
    while position < len(data):
        length, kind = struct.unpack('>I4s', data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            chunks += body
        position += 12 + length
    width, height, depth, colour = header[:4]
    assert depth == 8 and colour in (2, 6), header
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(chunks)
    stride = width * channels
    rows, previous, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for k in range(stride):
            left = line[k - channels] if k >= channels else 0
            up, corner = previous[k], previous[k - channels] if k >= channels else 0
            if kind == 1:
                line[k] = (line[k] + left) & 255
            elif kind == 2:
                line[k] = (line[k] + up) & 255
            elif kind == 3:
                line[k] = (line[k] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[k] = (line[k] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[k:k + 3]) for k in range(0, stride, channels)])
        previous = line
    return width, height, rows
