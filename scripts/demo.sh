#!/usr/bin/env bash
# The ros2vtk demo: a live robot beside a CT phantom, with no ROS installed.
# Sets up (idempotent), builds, writes the phantom, starts the simulated robot(s) in their own
# process(es) on the loopback, then examples/demo/demo.py with our default ROS node: in the web app
# (prints its URL, http://127.0.0.1:8080/, until Ctrl-C), or with --window in a VTK window.
# Without a display the app stops after 20 s unless a browser opens the URL by then (it then serves
# until Ctrl-C; --duration 0: until Ctrl-C in any case), with PNG frames of its 3D view in
# build/demo-frames and a summary.
# Usage: scripts/demo.sh [--window] [--port N] [--robots N] [--spin timer|event] [--offscreen DIR]
#                        [--duration S] [--urdf FILE] [--motion FILE]
# --window without a display renders under Xvfb and writes PNG frames to build/demo-frames for 20 s
# (--duration S to change) and prints a summary.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$ROOT/build}"
URDF="$ROOT/examples/robots/surgical_arm/urdf/surgical_arm.urdf"
# The surgical arm's needle insertions (ros2vtk-sim-robot --motion); another --urdf moves with the
# simulator's default motion unless --motion FILE is given.
MOTION="$ROOT/examples/robots/surgical_arm/config/needle_insertion.motion"
MOTION_GIVEN=""
ROBOTS=1
WINDOW=0
ARGS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --urdf) URDF="$(readlink -f "$2")"; ARGS+=("$1" "$URDF"); MOTION="$MOTION_GIVEN"; shift 2 ;;
    --motion) MOTION="$(readlink -f "$2")"; MOTION_GIVEN="$MOTION"; shift 2 ;;
    --robots) ROBOTS="$2"; ARGS+=("$1" "$2"); shift 2 ;;
    --window|--offscreen) WINDOW=1; ARGS+=("$1"); shift ;;
    *) ARGS+=("$1"); shift ;;
  esac
done

"$ROOT/scripts/setup.sh"
echo "[demo] building in $BUILD"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPython3_EXECUTABLE=/usr/bin/python3 > /dev/null
cmake --build "$BUILD" -j "${ROS2VTK_JOBS:-2}" --target ros2vtk-sim-robot ros2vtk-make-phantom all

export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST      # the demo stays on this machine
export ROS_DOMAIN_ID="${ROS_DOMAIN_ID:-17}"
PHANTOM="$BUILD/demo/phantom.mha"
mkdir -p "$BUILD/demo"
[ -f "$PHANTOM" ] || "$BUILD/runtime/Viewer/ros2vtk-make-phantom" "$PHANTOM"

SIM=("$BUILD/runtime/Tools/ros2vtk-sim-robot" --urdf "$URDF" --rate 50)
if [ -n "$MOTION" ]; then SIM+=(--motion "$MOTION"); fi
PIDS=()
cleanup() { for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done; }
trap cleanup EXIT INT TERM
if [ "$ROBOTS" -le 1 ]; then
  "${SIM[@]}" & PIDS+=($!)
else
  for i in $(seq 1 "$ROBOTS"); do
    "${SIM[@]}" --namespace "/robot$i" \
      --frame-prefix "robot$i/" & PIDS+=($!)
  done
fi

# The venv's python: the app's packages (trame) live there; it sees Debian's VTK too.
VIEWER=("$ROOT/.venv/bin/python" "$ROOT/examples/demo/demo.py" --phantom "$PHANTOM")
# example-robot-data's robots (pip, in the venv): their package:// meshes resolve through the ament
# layout of its cmeel prefix, e.g. --urdf .venv/lib/python3.11/site-packages/cmeel.prefix/share/example-robot-data/robots/ur_description/urdf/ur5_robot.urdf
for prefix in "$ROOT"/.venv/lib/python3*/site-packages/cmeel.prefix; do
  [ -d "$prefix" ] && export AMENT_PREFIX_PATH="$prefix${AMENT_PREFIX_PATH:+:$AMENT_PREFIX_PATH}"
done
export PYTHONPATH="$BUILD/python"
if [ "$WINDOW" = 1 ] && [ -z "${DISPLAY:-}" ]; then
  case " ${ARGS[*]-} " in *" --offscreen "*) ;; *) ARGS+=(--offscreen "$BUILD/demo-frames") ;; esac
  echo "[demo] no DISPLAY: rendering offscreen under Xvfb"
  xvfb-run -a -s "-screen 0 1280x720x24" "${VIEWER[@]}" "${ARGS[@]}"
elif [ -z "${DISPLAY:-}" ]; then
  "${VIEWER[@]}" --frames "$BUILD/demo-frames" "${ARGS[@]}"   # the app starts its own Xvfb
else
  "${VIEWER[@]}" "${ARGS[@]}"
fi
