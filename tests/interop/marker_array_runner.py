#!/usr/bin/env python3
"""Our side of tests/interop/test_scene_marker_array.py: a MarkerArray subscriber node (the
VTK-wrapped API) on TOPIC; after each spin that brought messages it records what
GetLastMessage() draws (markers kept, points, each marker's colour, bounds in mm). Prints
{"ready": true}, then one JSON object with the snapshots once COUNT messages arrived (or S seconds)
and, with --linger L, what it draws after L more seconds of spins without messages ("after").

    marker_array_runner.py TOPIC [--count N] [--seconds S] [--linger L]
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
    colors, bounds, lines = {}, {}, {}
    for cell in range(drawn.GetNumberOfCells()):
        marker = int(index.GetValue(cell))
        ids = drawn.GetCell(cell).GetPointIds()
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
            'labels': labels(drawn)}


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
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode('MarkerArray', args.topic)
    print(json.dumps({'ready': True, 'class': sub.GetClassName()}), flush=True)
    snapshots = []
    end = time.monotonic() + args.seconds
    seen = 0
    while time.monotonic() < end and seen < args.count:
        logic.SpinOnWakeUp(0.05)
        if sub.GetNumberOfMessages() != seen:
            seen = sub.GetNumberOfMessages()
            snapshots.append(snapshot(sub))
    # --linger: spin on without messages (lifetimes expire on spins alone), then draw again.
    end = time.monotonic() + args.linger
    while time.monotonic() < end:
        logic.SpinOnWakeUp(0.05)
    after = snapshot(sub) if args.linger > 0 else None
    print(json.dumps({'snapshots': snapshots, 'after': after}), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
