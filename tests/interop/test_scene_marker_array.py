"""visualization_msgs/MarkerArray from an rclpy publisher into our MarkerArray subscriber
(mapping rule MarkerArray, kind marker_array): the subscriber keeps markers by (ns, id) across
messages as RViz does. The rclpy node publishes the three messages of the byte fixtures one
second apart (make_cdr_fixtures.py `_marker_array`): a red cube (ns a, id 1, x 1 m), a green
sphere (a/2, x 2 m) and a blue line (b/1, (0,0) -> (0.5,0) -> (0.5,0.5) m), all 0.1 x 0.2 x 0.3 m;
then DELETE a/1; then DELETEALL and a yellow cylinder (c/7, x -1 m). Expected values are those
messages' values, worked out here in mm."""
from __future__ import annotations

import json
import math
import os
import subprocess

import pytest

from conftest import BUILD, HERE, VENV_PYTHON, tf2_msgs_env

# A venv made before scripts/requirements-jazzy.txt pinned ros-jazzy-visualization-msgs has no
# MarkerArray for the peer: skipped there (rerun scripts/setup.sh), never failed.
_HAS_PEER = subprocess.run([str(VENV_PYTHON), '-c', 'import visualization_msgs.msg'],
                           capture_output=True).returncode == 0
pytestmark = pytest.mark.skipif(not _HAS_PEER, reason=f'{VENV_PYTHON} cannot import visualization_msgs')

RED, GREEN, BLUE, YELLOW = [255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 0, 255]
CUBE_POINTS = 24  # vtkCubeSource: 4 points per face, so that each face has its own normals


def close(a, b, tol=1e-6):
    assert len(a) == len(b) and all(math.isclose(x, y, abs_tol=tol) for x, y in zip(a, b)), (a, b)


def draw_one_marker_array(ros, topic: str, markers: list) -> dict:
    """What our MarkerArray subscriber on `topic` draws (marker_array_runner.py's snapshot) from
    an rclpy publisher repeating one MarkerArray of `markers`."""
    ours = ros.start(['/usr/bin/python3', str(HERE / 'marker_array_runner.py'), topic, '--count', '1',
                      '--seconds', '20'], dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    ros.wait_ready(ours)
    peer = ros.peer('pub', topic, 'visualization_msgs/msg/MarkerArray', json.dumps({'markers': markers}),
                    '--count', '-1', '--rate', '5')
    code, out, err = ros.finish(ours, timeout=30)
    ros.stop(peer)
    assert code == 0, err
    return json.loads(out.splitlines()[-1])['snapshots'][0]


def test_rclpy_marker_array_add_delete_deleteall(ros):
    topic = '/scene_in/marker_array'
    ours = ros.start(['/usr/bin/python3', str(HERE / 'marker_array_runner.py'), topic, '--count', '3',
                      '--seconds', '30'], dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    ros.wait_ready(ours)
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'marker_array_peer.py'), topic, '--gap', '1.0'])
    code, out, err = ros.finish(ours, timeout=45)
    ros.stop(peer)
    assert code == 0, err
    snapshots = json.loads(out.splitlines()[-1])['snapshots']
    # One snapshot per message (they come a second apart, so one spin each).
    assert [s['count'] for s in snapshots] == [1, 2, 3], snapshots
    added, deleted, replaced = snapshots

    # 1: three shapes in (ns, id) order a/1 cube, a/2 sphere, b/1 line; colours as sent.
    assert added['markers'] == 3 and added['colors'] == [RED, GREEN, BLUE], added
    assert added['scalars'] == 'Color' and added['lines'] == 1 and added['error'] == ''
    # x from the line's start (0) to the sphere's far side (2 m + 0.05 m); y down to the sphere's
    # -0.1 m and up to the line's 0.5 m; z: cube and sphere 0.3 m high about 0.
    close(added['bounds'], [0.0, 2050.0, -100.0, 500.0, -150.0, 150.0])

    # 2: DELETE a/1 drops the cube only: its colour and its 24 points are gone.
    assert deleted['markers'] == 2 and deleted['colors'] == [GREEN, BLUE], deleted
    assert deleted['points'] == added['points'] - CUBE_POINTS
    close(deleted['bounds'], [0.0, 2050.0, -100.0, 500.0, -150.0, 150.0])

    # 3: DELETEALL then the cylinder in the same message: the cylinder alone.
    assert replaced['markers'] == 1 and replaced['colors'] == [YELLOW] and replaced['lines'] == 0, replaced
    close(replaced['bounds'], [-1050.0, -950.0, -100.0, 100.0, -150.0, 150.0])


def test_our_poly_data_to_rclpy_marker_array(ros):
    """Publishing a vtkPolyData as MarkerArray: one marker, ADD, ns '' and id 0, the Marker rule's
    LINE_STRIP of the line's points in metres (scene_runner.py's red line: 0, 100 mm, 100 x 200 mm)."""
    echo = ros.peer('echo', '/scene_out/marker_array', 'visualization_msgs/msg/MarkerArray', '--count', '1',
                    '--timeout', '25')
    ros.wait_ready(echo)
    ours = ros.scene('--seconds', '8', 'pub', 'MarkerArray', '/scene_out/marker_array')
    code, out, err = ros.finish(echo, timeout=40)
    ros.stop(ours)
    assert code == 0, err
    message = json.loads(out.splitlines()[-1])
    assert len(message['markers']) == 1, message
    marker = message['markers'][0]
    assert marker['action'] == 0 and marker['ns'] == '' and marker['id'] == 0 and marker['type'] == 4
    assert [(p['x'], p['y'], p['z']) for p in marker['points']] == [(0.0, 0.0, 0.0), (0.1, 0.0, 0.0), (0.1, 0.2, 0.0)]
    assert marker['color'] == {'r': 1.0, 'g': 0.0, 'b': 0.0, 'a': 1.0}
    assert marker['pose']['orientation']['w'] == 1.0


def test_rclpy_list_markers_line_list_cube_list_sphere_list(ros):
    """RViz's list types from one rclpy MarkerArray, in metres, each marker at the origin pose: a
    LINE_LIST of 4 points is 2 separate segments (not one polyline), a CUBE_LIST a 0.1 m cube on
    each of its 2 points, a SPHERE_LIST a 0.1 m sphere on each of its 3 points; a LINE_LIST of 3
    points (odd) is refused with the reason, the others still drawn. Expected values are the
    published values in mm (a shape's extent: its points +- half the scale)."""
    def marker(ns, kind, points, rgb, size=0.1):
        return {'header': {'frame_id': 'base'}, 'ns': ns, 'id': 1, 'type': kind, 'action': 0,
                'pose': {'orientation': {'w': 1.0}}, 'scale': {'x': size, 'y': size, 'z': size},
                'color': dict(zip('rgba', (*rgb, 1.0))),
                'points': [{'x': float(x), 'y': float(y), 'z': float(z)} for x, y, z in points]}
    LINE_LIST, CUBE_LIST, SPHERE_LIST = 5, 6, 7  # visualization_msgs/msg/Marker
    markers = [marker('a_lines', LINE_LIST, [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 1, 1)], (1.0, 0.0, 0.0), 0.01),
               marker('b_cubes', CUBE_LIST, [(0, 0, 0), (1, 2, 3)], (0.0, 1.0, 0.0)),
               marker('c_spheres', SPHERE_LIST, [(-1, 0, 0), (1, 0, 0), (0, 0, 2)], (0.0, 0.0, 1.0)),
               marker('d_odd', LINE_LIST, [(0, 0, 0), (1, 0, 0), (0, 1, 0)], (1.0, 1.0, 0.0))]
    drawn = draw_one_marker_array(ros, '/scene_in/marker_lists', markers)
    assert drawn['markers'] == 3 and drawn['colors'] == [RED, GREEN, BLUE], drawn
    assert drawn['error'] == ("marker (ns 'd_odd', id 1): marker_to_poly_data: a line list needs an even "
                              "number of points (pairs), not 3"), drawn
    assert drawn['marker_lines'] == [2, 0, 0], drawn  # two segments; solids have no line cells
    lines, cubes, spheres = drawn['marker_bounds']
    close(lines, [0, 1000, 0, 1000, 0, 1000], tol=1e-3)
    close(cubes, [-50, 1050, -50, 2050, -50, 3050], tol=1e-3)
    close(spheres, [-1050, 1050, -50, 50, -50, 2050], tol=1e-3)
    # The line list's 4 points and one cube per point (vtkCubeSource: 24 points each) are all there
    # is besides the spheres.
    assert drawn['points'] > 4 + 2 * CUBE_POINTS


def _marker(ns, marker_id, kind, x, rgba, **extra):
    marker = {'header': {'frame_id': 'base'}, 'ns': ns, 'id': marker_id, 'type': kind, 'action': 0,
              'pose': {'position': {'x': x, 'y': 0.0, 'z': 0.0}, 'orientation': {'w': 1.0}},
              'scale': {'x': 0.1, 'y': 0.1, 'z': 0.1}, 'color': dict(zip('rgba', rgba))}
    marker.update(extra)
    return marker


def test_rclpy_marker_lifetime_text_and_mesh_resource(ros):
    """One MarkerArray from rclpy: a red cube with lifetime 1 s, a blue sphere with lifetime 0, a
    TEXT_VIEW_FACING 'tool' 0.05 m high at x 0.3 m, and a MESH_RESOURCE naming a file outside
    every allowed root. Drawn at once: cube and sphere, the label, and the mesh refused by name;
    after 3 s of spins without messages the cube has expired and the rest is unchanged."""
    topic = '/scene_in/marker_lifetime'
    message = {'markers': [
        _marker('l', 1, 1, 1.0, (1.0, 0.0, 0.0, 1.0), lifetime={'sec': 1, 'nanosec': 0}),
        _marker('l', 2, 2, 2.0, (0.0, 0.0, 1.0, 1.0)),
        _marker('l', 3, 9, 0.3, (1.0, 1.0, 1.0, 1.0), text='tool',
                scale={'x': 0.0, 'y': 0.0, 'z': 0.05}),
        _marker('l', 4, 10, 0.0, (0.0, 1.0, 0.0, 1.0), mesh_resource='file:///etc/ros2vtk_no_mesh.stl')]}
    ours = ros.start(['/usr/bin/python3', str(HERE / 'marker_array_runner.py'), topic, '--count', '1',
                      '--seconds', '30', '--linger', '3'], dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    ros.wait_ready(ours)
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'ros_peer.py'), 'pub', topic,
                      'visualization_msgs/MarkerArray', json.dumps(message)])
    code, out, err = ros.finish(ours, timeout=45)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    first, after = result['snapshots'][0], result['after']
    assert first['markers'] == 2 and first['colors'] == [RED, BLUE], first
    assert first['labels'] == [['tool', 300.0, 0.0, 0.0, 50.0]], first
    assert 'ros2vtk_no_mesh.stl' in first['error'], first
    assert after['count'] == 1, after  # no message since: the spins alone expired the cube
    assert after['markers'] == 1 and after['colors'] == [BLUE], after
    assert after['labels'] == first['labels'], after


def _framed(marker_id, frame, x, rgba, locked=False, **extra):
    marker = _marker('frames', marker_id, 1, x, rgba, **extra)  # CUBE, 0.1 m
    marker['header'] = {'frame_id': frame}
    marker['frame_locked'] = locked
    return marker


def test_rclpy_markers_in_their_own_frames_kept_by_ns_and_id(ros):
    """A plain Marker topic with the subscriber's fixed frame 'world', everything from rclpy: tf
    world -> fa (static, x 0.1 m) and world -> fb (y 0.05 m); seven Markers: blue f/3 in fb at x
    -0.03 m, red f/1 in fa, green f/2 in fb frame_locked, blue f/3 again at x -0.06 m (replaces
    it), yellow f/4 in 'nowhere', white f/5 in fa, DELETE f/5. Drawn: red (100, 0), green (0, 50),
    blue (-60, 50) mm, the yellow one not (its status says why), f/5 gone. Then fb moves to y
    0.12 m (a new rclpy broadcaster, no marker message): after spins alone the frame-locked green
    cube is at (0, 120) mm, the others where they were."""
    topic = '/scene_in/marker_frames'
    ours = ros.start(['/usr/bin/python3', str(HERE / 'marker_array_runner.py'), topic, '--type', 'Marker',
                      '--fixed-frame', 'world', '--count', '7', '--drawn', '3', '--seconds', '30', '--linger', '20'],
                     dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    ros.wait_ready(ours)
    ros.tf_peer('tf_pub', 'world', 'fa', json.dumps({'t': [0.1, 0, 0], 'q': [0, 0, 0, 1]}), '--static',
                '--seconds', '40')
    fb = ros.tf_peer('tf_pub', 'world', 'fb', json.dumps({'t': [0, 0.05, 0], 'q': [0, 0, 0, 1]}),
                     '--seconds', '40')
    markers = [_framed(3, 'fb', -0.03, (0.0, 0.0, 1.0, 1.0)), _framed(1, 'fa', 0.0, (1.0, 0.0, 0.0, 1.0)),
               _framed(2, 'fb', 0.0, (0.0, 1.0, 0.0, 1.0), locked=True),
               _framed(3, 'fb', -0.06, (0.0, 0.0, 1.0, 1.0)), _framed(4, 'nowhere', 0.0, (1.0, 1.0, 0.0, 1.0)),
               _framed(5, 'fa', 0.05, (1.0, 1.0, 1.0, 1.0)), dict(_framed(5, 'fa', 0.0, (0, 0, 0, 0)), action=2)]
    ros.peer('pub', topic, 'visualization_msgs/msg/Marker', json.dumps(markers), '--list', '--rate', '20')
    line = ours.stdout.readline()
    assert line, ours.stderr.read() if ours.poll() is not None else 'no output'
    drawn = json.loads(line)['drawn']
    assert drawn['count'] == 7 and drawn['markers'] == 3 and drawn['colors'] == [RED, [0, 255, 0, 255], BLUE], drawn
    for got, want in zip(drawn['centres'], [[100, 0, 0], [0, 50, 0], [-60, 50, 0]]):
        close(got, want, tol=0.5)
    assert drawn['frame_status'].startswith("marker (ns 'frames', id 4): No transform from [nowhere] to [world]"), drawn
    assert 'No transform from [nowhere] to [world]' in drawn['error'], drawn

    fb.kill()
    ros.tf_peer('tf_pub', 'world', 'fb', json.dumps({'t': [0, 0.12, 0], 'q': [0, 0, 0, 1]}), '--seconds', '40')
    code, out, err = ros.finish(ours, timeout=45)
    assert code == 0, err
    after = json.loads(out.splitlines()[-1])['after']
    assert after['count'] == 7 and after['markers'] == 3, after
    for got, want in zip(after['centres'], [[100, 0, 0], [0, 120, 0], [-60, 50, 0]]):
        close(got, want, tol=0.5)


def test_rclpy_stamped_tf_history_places_markers_at_their_stamps_in_the_scenes_fixed_frame(ros):
    """One rclpy node broadcasts a tf history (world -> fs at base time B: x 0.1 m, at B + 1 s: x
    0.3 m) and a MarkerArray of three cubes at fs's origin (marker_stamps_peer.py): red stamped B,
    green stamped B + 1 s, blue stamped B - 5 s. Our MarkerArray subscriber has no fixed frame of
    its own; the scene's is 'world'. Each cube is looked up at its own stamp: red at x 100 mm,
    green at x 300 mm (not the latest transform for both); blue is older than the tf history, so
    it is dropped (as RViz's tf filter drops it) and the status says so."""
    topic = '/scene_in/marker_stamps'
    ours = ros.start(['/usr/bin/python3', str(HERE / 'marker_array_runner.py'), topic, '--count', '1',
                      '--scene-fixed-frame', 'world', '--drawn', '2', '--seconds', '25'],
                     dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
    ros.wait_ready(ours)
    env = dict(ros.env)
    for key, value in tf2_msgs_env().items():  # the peer imports tf2_msgs
        env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
    peer = ros.start([str(VENV_PYTHON), str(HERE / 'marker_stamps_peer.py'), topic, '--seconds', '30'], env)
    line = ours.stdout.readline()
    assert line, ours.stderr.read() if ours.poll() is not None else 'no output'
    drawn = json.loads(line)['drawn']
    ros.stop(ours)
    ros.stop(peer)
    assert drawn['markers'] == 2 and drawn['colors'] == [RED, [0, 255, 0, 255]], drawn
    for got, want in zip(drawn['centres'], [[100, 0, 0], [300, 0, 0]]):
        close(got, want, tol=0.5)
    status = drawn['frame_status']
    assert status.startswith("marker (ns 's', id 3): dropped: its stamp is older than the tf history"), drawn
    assert 'No transform from [fs] to [world]' in status and 'extrapolation into the past' in status, drawn


def test_rclpy_per_point_colours_and_two_point_arrows(ros):
    """RViz's per-point colours and point-to-point arrows from one rclpy MarkerArray (markers at
    the origin pose): POINTS and LINE_STRIP with as many `colors` as points colour each point with
    its own (points_marker.cpp, line_marker_base.cpp), a CUBE_LIST each cube with its point's, a
    TRIANGLE_LIST with one colour per triangle each triangle (its alpha times color.a,
    triangle_list_marker.cpp); a LINE_LIST whose colors count differs from its points keeps
    `color`. An ARROW with two points goes from the first to the second (arrow_marker.cpp): shaft
    diameter scale.x, head diameter scale.y, head length scale.z, or 23% of the length when it is
    0; with one point it is refused. Expected values are the published ones, in mm and bytes."""
    def marker(ns, kind, points, color=(1.0, 1.0, 1.0, 1.0), colors=(), scale=(0.05, 0.05, 0.05)):
        return {'header': {'frame_id': 'base'}, 'ns': ns, 'id': 1, 'type': kind, 'action': 0,
                'pose': {'orientation': {'w': 1.0}}, 'scale': dict(zip('xyz', scale)),
                'color': dict(zip('rgba', color)), 'colors': [dict(zip('rgba', c)) for c in colors],
                'points': [{'x': float(x), 'y': float(y), 'z': float(z)} for x, y, z in points]}
    ARROW, LINE_STRIP, LINE_LIST, CUBE_LIST, POINTS, TRIANGLE_LIST = 0, 4, 5, 6, 8, 11
    r, g, b = (1.0, 0.0, 0.0, 1.0), (0.0, 1.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)
    markers = [
        marker('a_points', POINTS, [(0, 0, 0), (1, 0, 0), (0, 1, 0)], colors=[r, g, b]),
        marker('b_strip', LINE_STRIP, [(0, 0, 1), (1, 0, 1), (1, 1, 1)],
               colors=[(1.0, 1.0, 0.0, 1.0), (0.0, 1.0, 1.0, 1.0), (1.0, 0.0, 1.0, 0.5)]),
        marker('c_cubes', CUBE_LIST, [(0, 0, -1), (2, 0, -1)], colors=[r, b], scale=(0.1, 0.1, 0.1)),
        marker('d_lines', LINE_LIST, [(0, 0, 0), (0, 0, 1)], color=(1.0, 1.0, 0.0, 1.0), colors=[r]),
        marker('e_triangles', TRIANGLE_LIST, [(0, 0, 5), (1, 0, 5), (0, 1, 5), (0, 0, 6), (1, 0, 6), (0, 1, 6)],
               color=(1.0, 1.0, 1.0, 0.5), colors=[r, g], scale=(1.0, 1.0, 1.0)),
        marker('f_arrow', ARROW, [(0, 0, 2), (1, 0, 2)], color=(0.5, 0.5, 0.5, 1.0), scale=(0.1, 0.2, 0.3)),
        marker('g_arrow', ARROW, [(0, 0, 3), (0, -1, 3)], scale=(0.1, 0.2, 0.0)),
        marker('h_arrow_one_point', ARROW, [(0, 0, 4)], scale=(0.1, 0.2, 0.3)),
    ]
    drawn = draw_one_marker_array(ros, '/scene_in/marker_colours', markers)
    assert drawn['error'] == ("marker (ns 'h_arrow_one_point', id 1): marker_to_poly_data: an arrow marker "
                              "takes two points (start and end) or none, not 1"), drawn
    assert drawn['markers'] == 7, drawn
    points, strip, cubes, lines, triangles, arrow, arrow_down = drawn['marker_points']

    assert points == [[0, 0, 0, 255, 0, 0, 255], [1000, 0, 0, 0, 255, 0, 255], [0, 1000, 0, 0, 0, 255, 255]]
    assert strip == [[0, 0, 1000, 255, 255, 0, 255], [1000, 0, 1000, 0, 255, 255, 255],
                     [1000, 1000, 1000, 255, 0, 255, 128]]
    # Each 100 mm cube in its point's colour: red about x 0, blue about x 2000.
    assert len(cubes) == 2 * CUBE_POINTS
    assert {tuple(p[3:]) for p in cubes if p[0] < 1000} == {(255, 0, 0, 255)}
    assert {tuple(p[3:]) for p in cubes if p[0] > 1000} == {(0, 0, 255, 255)}
    # One colour for two points: not per point, the marker's yellow.
    assert lines == [[0, 0, 0, 255, 255, 0, 255], [0, 0, 1000, 255, 255, 0, 255]]
    # One colour per triangle, alpha 1 x color.a 0.5 (128 of 255).
    assert triangles == [[0, 0, 5000, 255, 0, 0, 128], [1000, 0, 5000, 255, 0, 0, 128], [0, 1000, 5000, 255, 0, 0, 128],
                         [0, 0, 6000, 0, 255, 0, 128], [1000, 0, 6000, 0, 255, 0, 128], [0, 1000, 6000, 0, 255, 0, 128]]

    # (0, 0, 2) -> (1, 0, 2) m: from x 0 to 1000 mm, head 200 mm wide, its base 300 mm from the tip,
    # shaft 100 mm wide; all grey.
    f_bounds, g_bounds = drawn['marker_bounds'][5], drawn['marker_bounds'][6]
    close(f_bounds, [0, 1000, -100, 100, 1900, 2100], tol=1e-3)
    shaft = [p for p in arrow if math.hypot(p[1], p[2] - 2000) < 75]  # shaft 50, head 100 mm from the axis
    head = [p for p in arrow if math.hypot(p[1], p[2] - 2000) > 75]
    assert head and min(p[0] for p in head) == pytest.approx(700, abs=1e-3)
    assert max(math.hypot(p[1], p[2] - 2000) for p in shaft) == pytest.approx(50, abs=1e-3)
    assert {tuple(p[3:]) for p in arrow} == {(128, 128, 128, 255)}
    # (0, 0, 3) -> (0, -1, 3) m, scale.z 0: along -y, head 23% of the length (230 mm).
    close(g_bounds, [-100, 100, -1000, 0, 2900, 3100], tol=1e-3)
    head = [p for p in arrow_down if math.hypot(p[0], p[2] - 3000) > 75]
    assert max(p[1] for p in head) == pytest.approx(-770, abs=1e-3)


def test_rclpy_arrow_strip_is_an_arrow_from_each_point_to_the_next(ros):
    """An ARROW_STRIP (12) from rclpy is drawn as RViz's ArrowStripMarker draws it
    (arrow_strip_marker.cpp): one arrow from each point to the next, each sized as a two-point
    ARROW (shaft diameter scale.x, head diameter scale.y, head length scale.z), all in `color`;
    one point is refused. Expected values are the published ones, in mm and bytes."""
    def marker(ns, kind, points, scale=(0.1, 0.2, 0.3)):
        return {'header': {'frame_id': 'base'}, 'ns': ns, 'id': 1, 'type': kind, 'action': 0,
                'pose': {'orientation': {'w': 1.0}}, 'scale': dict(zip('xyz', scale)),
                'color': {'r': 0.0, 'g': 1.0, 'b': 0.0, 'a': 1.0},
                'points': [{'x': float(x), 'y': float(y), 'z': float(z)} for x, y, z in points]}
    ARROW, ARROW_STRIP = 0, 12
    markers = [
        marker('a_arrow', ARROW, [(0, 0, 0), (1, 0, 0)]),
        marker('b_strip', ARROW_STRIP, [(0, 0, 1), (1, 0, 1), (1, 1, 1)]),
        marker('c_strip_one_point', ARROW_STRIP, [(0, 0, 2)]),
    ]
    drawn = draw_one_marker_array(ros, '/scene_in/marker_arrow_strip', markers)
    assert drawn['error'] == ("marker (ns 'c_strip_one_point', id 1): marker_to_poly_data: an arrow strip "
                              "needs two points or more, not 1"), drawn
    assert drawn['markers'] == 2, drawn
    arrow, strip = drawn['marker_points']
    # Two arrows, each drawn like the single one: (0, 0, 1) -> (1, 0, 1) along x, then
    # (1, 0, 1) -> (1, 1, 1) along y; heads 200 mm wide, so 100 mm beyond each axis.
    assert len(strip) == 2 * len(arrow)
    close(drawn['marker_bounds'][1], [0, 1100, -100, 1000, 900, 1100], tol=1e-3)
    first, second = strip[:len(arrow)], strip[len(arrow):]
    assert sorted((round(x), round(y), round(z - 1000)) for x, y, z, *_ in first) == \
        sorted((round(x), round(y), round(z)) for x, y, z, *_ in arrow)
    # The second arrow is the first turned 90 degrees about z and moved to (1000, 0): x -> y.
    assert sorted((round(y), round(1000 - x), round(z - 1000)) for x, y, z, *_ in second) == \
        sorted((round(x), round(y), round(z)) for x, y, z, *_ in arrow)
    assert {tuple(p[3:]) for p in strip} == {(0, 255, 0, 255)}
