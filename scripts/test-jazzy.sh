#!/usr/bin/env bash
# Every interop test against ROS 2 Jazzy peers (rclpy from the Jazzy wheels in .venv-jazzy) instead
# of Kilted's. CI (scripts/test.sh) runs one cell per feature against Jazzy (CTest interop_jazzy);
# this runs them all (~12 min on 2 cores). Usage: scripts/test-jazzy.sh [pytest args, e.g. -k tf]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$ROOT/build}"
JAZZY_PYTHON="${ROS2VTK_JAZZY_VENV:-$ROOT/.venv-jazzy}/bin/python"

"$ROOT/scripts/setup.sh"
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
export ROS_DOMAIN_ID="${ROS_DOMAIN_ID:-42}"
echo "[test-jazzy] configuring and building $BUILD"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DROS2VTK_VENV_PYTHON="$ROOT/.venv/bin/python"
cmake --build "$BUILD" -j "${ROS2VTK_JOBS:-2}"
echo "[test-jazzy] every interop test against Jazzy peers ($("$JAZZY_PYTHON" -c 'import importlib.metadata as m; print("rclpy", m.version("ros-jazzy-rclpy"))'))"
cd "$BUILD"
ROS2VTK_BUILD_DIR="$BUILD" ROS2VTK_VENV_PYTHON="$JAZZY_PYTHON" \
  ROS2VTK_FIXTURES_BUILD_DIR="$BUILD/fixtures-jazzy" ROS2VTK_TEST_DOMAIN_BASE="${ROS2VTK_TEST_DOMAIN_BASE:-100}" \
  "$JAZZY_PYTHON" -m pytest -q -p no:cacheprovider "$ROOT/tests/interop" "$@"
