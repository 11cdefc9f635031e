"""Frame time of the app's 3D view with N robots moving (issue 17): what the app does per frame —
vtkROS2Logic.Spin(), the display manager's Update() (the scene's model nodes into actors), and
Render() of the 1000×620 view — beside a bare VTK render of the same actors moved by hand in a
window of the same size (the baseline: VTK and the GL driver alone, no ROS, no scene).

The robots are ros2vtk-sim-robot processes the driver (run_benchmarks.py) starts in namespaces
/robot1 .. /robotN with frame prefixes robot1/ .. robotN/, as for the spin benchmark. Debian's
python3 with <build>/python on PYTHONPATH; under Xvfb when there is no DISPLAY (GLX, llvmpipe).

    bench_frame.py --robots 10 --frames 300

Prints one JSON object: per-frame milliseconds of each part and of the baseline.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time

import vtk

import ros2vtk
from ros2vtk.app.view import ensure_x_display, make_display, make_render_window
from ros2vtk.framing import ViewFraming


def wait_loaded(logic, display, robots, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        logic.Spin()
        display.Update()
        if all(r.IsLoaded() and r.GetNumberOfLinksTracked() == r.GetNumberOfLinks() for r in robots):
            return True
        time.sleep(0.02)
    return False


def actors_of(renderer) -> list:
    actors = renderer.GetActors()
    actors.InitTraversal()
    found = []
    actor = actors.GetNextActor()
    while actor is not None:
        found.append(actor)
        actor = actors.GetNextActor()
    return found


def bare_frames(live_actors: list, frames: int, period: float) -> list[float]:
    """The same mappers and properties in a bare renderer, each actor turned a little every frame
    (every actor moves, as every link of a moving robot does), Render() timed."""
    window, renderer = make_render_window()
    for live in live_actors:
        actor = vtk.vtkActor()
        actor.SetMapper(live.GetMapper())
        actor.SetProperty(live.GetProperty())
        if live.GetUserMatrix() is not None:
            actor.SetUserMatrix(live.GetUserMatrix())
        renderer.AddActor(actor)
    ViewFraming(None, renderer).frame()
    window.Render()
    actors = actors_of(renderer)
    times = []
    next_frame = time.monotonic()
    for k in range(frames):
        next_frame += period
        for index, actor in enumerate(actors):
            actor.SetOrientation(0.0, 0.0, 5.0 * math.sin(0.05 * k + index))
        start = time.perf_counter()
        window.Render()
        times.append((time.perf_counter() - start) * 1e3)
        time.sleep(max(0.0, next_frame - time.monotonic()))
    window.Finalize()
    return times


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--robots', type=int, default=1)
    parser.add_argument('--frames', type=int, default=300)
    parser.add_argument('--rate', type=float, default=30.0, help='frames per second asked for')
    parser.add_argument('--wait', type=float, default=60.0)
    args = parser.parse_args()
    xvfb = ensure_x_display()
    try:
        logic = ros2vtk.vtkROS2Logic()
        node = logic.GetDefaultROS2Node()
        robots = [node.CreateAndAddRobotNodeFromTopic(f'robot{i}', f'/robot{i}/robot_description', '', f'robot{i}/')
                  for i in range(1, args.robots + 1)]
        window, renderer = make_render_window()
        display = make_display(logic, renderer)
        loaded = wait_loaded(logic, display, robots, args.wait)
        ViewFraming(logic.GetScene(), renderer).frame()
        window.Render()
        period = 1.0 / args.rate
        spin_ms, update_ms, render_ms, frame_ms, messages = [], [], [], [], []
        next_frame = time.monotonic()
        for k in range(args.frames + 30):  # 30 warm-up frames, not kept
            next_frame += period
            t0 = time.perf_counter()
            handled = logic.Spin()
            t1 = time.perf_counter()
            display.Update()
            t2 = time.perf_counter()
            window.Render()
            t3 = time.perf_counter()
            if k >= 30:
                spin_ms.append((t1 - t0) * 1e3)
                update_ms.append((t2 - t1) * 1e3)
                render_ms.append((t3 - t2) * 1e3)
                frame_ms.append((t3 - t0) * 1e3)
                messages.append(handled)
            time.sleep(max(0.0, next_frame - time.monotonic()))
        gl = [line.strip() for line in window.ReportCapabilities().splitlines()
              if line.strip().startswith(('OpenGL renderer string', 'OpenGL version string'))]
        live_actors = actors_of(renderer)
        links = sum(r.GetNumberOfLinks() for r in robots)
        bare_ms = bare_frames(live_actors, args.frames, period)
        window.Finalize()
        print(json.dumps({'robots': args.robots, 'loaded': loaded, 'links': links, 'actors': len(live_actors),
                          'size': list(window.GetSize()), 'gl': gl,
                          'spin_ms': spin_ms, 'update_ms': update_ms, 'render_ms': render_ms, 'frame_ms': frame_ms,
                          'messages': messages, 'bare_render_ms': bare_ms}), flush=True)
        return 0 if loaded else 3
    finally:
        if xvfb is not None:
            xvfb.terminate()


if __name__ == '__main__':
    sys.exit(main())
