#!/usr/bin/env bash
# Runs every test of ros2vtk: set-up (idempotent), configure, build, then CTest (unit, golden,
# fuzz, Python and interop tests against real rclpy peers). Usage: scripts/test.sh [ctest args]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$ROOT/build}"
JOBS="${ROS2VTK_JOBS:-2}"
VENV="${ROS2VTK_VENV:-$ROOT/.venv}"  # as scripts/setup.sh
export ROS2VTK_VENV="$VENV"

"$ROOT/scripts/setup.sh"

# Tests never leave this machine: discovery stays on the loopback (ROS 2's own switch).
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
export ROS_DOMAIN_ID="${ROS_DOMAIN_ID:-42}"

echo "[test] configuring $BUILD"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DROS2VTK_VENV_PYTHON="$VENV/bin/python"
echo "[test] building with $JOBS jobs"
cmake --build "$BUILD" -j "$JOBS"
echo "[test] running tests"
cd "$BUILD"
# Default for tests without their own TIMEOUT (gtests have 120 s, interop and demo more).
# Three at a time on two cores: most ROS tests wait on discovery and peers (at -j2 the suite kept
# ~1.9 of 2 slots busy, mostly sleeping); tests that share a ROS domain share a RESOURCE_LOCK, and
# the app test runs alone (RUN_SERIAL).
ctest --output-on-failure --timeout 300 -j "${ROS2VTK_TEST_JOBS:-3}" "$@"
