#!/usr/bin/env python3
"""Our side of tests/interop/test_scene_marker_array.py: a MarkerArray subscriber node (the
VTK-wrapped API) on TOPIC; after each spin that brought messages it records what
GetLastMessage() draws (markers kept, points, each marker's colour, bounds in mm, and each
marker's points with their colours). Prints
{"ready": true}, then one JSON object with the snapshots once COUNT messages arrived (or S seconds)
and, with --linger L, what it draws after L more seconds of spins without messages ("after").
--type Marker subscribes a plain Marker topic instead; --fixed-frame F sets the subscriber's fixed
frame (markers placed by tf), --scene-fixed-frame F the scene's (vtkROS2Scene::SetFixedFrame, used
by a subscriber without its own); --drawn N then waits, after COUNT messages, until N markers are
drawn and prints {"drawn": snapshot} before lingering (the test moves a frame meanwhile).

    marker_array_runner.py TOPIC [--count N] [--seconds S] [--linger L] [--type T]
                           [--fixed-frame F] [--scene-fixed-frame F] [--drawn N]

With --drawn, --linger L ends as soon as a marker moved.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import ros2vtk


def snapshot(sub) -> dict:
    drawn = sub.GetLastMessage()
    if drawn is None:
        return {'count': sub.GetNumberOfMessages(), 'drawn': None, 'error': sub.GetLastConversionError()}
    index = drawn.GetCellData().GetArray('MarkerIndex')
    color = drawn.GetPointData().GetScalars()
    colors, bounds, lines, point_ids = {}, {}, {}, {}
    for cell in range(drawn.GetNumberOfCells()):
        marker = int(index.GetValue(cell))
        ids = drawn.GetCell(cell).GetPointIds()
        point_ids.setdefault(marker, set()).update(ids.GetId(i) for i in range(ids.GetNumberOfIds()))
        if marker not in colors:
            colors[marker] = [int(color.GetComponent(ids.GetId(0), c)) for c in range(4)]
        if drawn.GetCellType(cell) in (3, 4):  # VTK_LINE, VTK_POLY_LINE
            lines[marker] = lines.get(marker, 0) + 1
        box = bounds.setdefault(marker, [float('inf'), float('-inf')] * 3)
        for i in range(ids.GetNumberOfIds()):
            p = drawn.GetPoint(ids.GetId(i))
            for axis in range(3):
                box[2 * axis] = min(box[2 * axis], p[axis])
                box[2 * axis + 1] = max(box[2 * axis + 1], p[axis])
    return {'count': sub.GetNumberOfMessages(), 'markers': len(colors),
            'colors': [colors[k] for k in sorted(colors)], 'points': drawn.GetNumberOfPoints(),
            'marker_bounds': [bounds[k] for k in sorted(bounds)],
            'marker_lines': [lines.get(k, 0) for k in sorted(colors)],
            'lines': drawn.GetNumberOfLines(), 'bounds': list(drawn.GetBounds()),
            'scalars': color.GetName() if color else None, 'error': sub.GetLastConversionError(),
            'labels': labels(drawn),
            # each marker's points in id order: x, y, z (mm) and the RGBA of its "Color" tuple
            'marker_points': [[[*drawn.GetPoint(i), *(int(color.GetComponent(i, c)) for c in range(4))]
                               for i in sorted(point_ids[k])] for k in sorted(colors)],
            'centres': [[0.5 * (b[2 * a] + b[2 * a + 1]) for a in range(3)]
                        for b in (bounds[k] for k in sorted(bounds))],
            'frame_status': sub.GetFrameStatus() if hasattr(sub, 'GetFrameStatus') else ''}


def labels(drawn) -> list:
    """The TEXT_VIEW_FACING labels of the drawn poly data: [text, x, y, z, height] (mm)."""
    text = drawn.GetFieldData().GetAbstractArray('LabelText')
    if text is None:
        return []
    position = drawn.GetFieldData().GetArray('LabelPosition')
    height = drawn.GetFieldData().GetArray('LabelHeight')
    return [[text.GetValue(i), *position.GetTuple3(i), height.GetTuple1(i)]
            for i in range(text.GetNumberOfValues())]


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('topic')
    parser.add_argument('--count', type=int, default=3)
    parser.add_argument('--seconds', type=float, default=30.0)
    parser.add_argument('--linger', type=float, default=0.0)
    parser.add_argument('--type', default='MarkerArray')
    parser.add_argument('--fixed-frame', default='')
    parser.add_argument('--scene-fixed-frame', default='')
    parser.add_argument('--drawn', type=int, default=-1)
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode(args.type, args.topic)
    if args.fixed_frame:
        sub.SetFixedFrame(args.fixed_frame)
    if args.scene_fixed_frame:
        logic.GetScene().SetFixedFrame(args.scene_fixed_frame)
    print(json.dumps({'ready': True, 'class': sub.GetClassName()}), flush=True)
    snapshots = []
    end = time.monotonic() + args.seconds
    seen = 0
    while time.monotonic() < end and seen < args.count:
        logic.SpinOnWakeUp(0.05)
        if sub.GetNumberOfMessages() != seen:
            seen = sub.GetNumberOfMessages()
            snapshots.append(snapshot(sub))
    drawn = None
    if args.drawn >= 0:
        while time.monotonic() < end:
            drawn = snapshot(sub)
            if drawn.get('markers') == args.drawn:
                break
            logic.SpinOnWakeUp(0.05)
        print(json.dumps({'drawn': drawn}), flush=True)
    # --linger: spin on without messages (lifetimes expire on spins alone), then draw again;
    # after --drawn, only until a marker moved (or L seconds).
    end = time.monotonic() + args.linger
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.05)
        if drawn is not None and snapshot(sub).get('centres') != drawn.get('centres'):
            break
    after = snapshot(sub) if args.linger > 0 else None
    print(json.dumps({'snapshots': snapshots, 'after': after}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
