#!/usr/bin/env bash
# The two-host network tests (tests/network) including what CI leaves out: the 2-minute link cut and
# the packet-loss comparisons with an rclpy subscriber, and the discovery server without an id
# (~6 min). Needs root for the network namespaces. Usage: scripts/test-network-long.sh [pytest args]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$ROOT/build}"
"$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DROS2VTK_VENV_PYTHON="$ROOT/.venv/bin/python"
cmake --build "$BUILD" -j "${ROS2VTK_JOBS:-2}"
cd "$BUILD"
ROS2VTK_LONG_NETWORK_TESTS=1 ROS2VTK_BUILD_DIR="$BUILD" \
  "$ROOT/.venv/bin/python" -m pytest -q -s -p no:cacheprovider "$ROOT/tests/network" "$@"
