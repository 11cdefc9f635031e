#!/usr/bin/env bash
# Runs the benchmark suite (targets and results: docs/benchmarks.md): set-up (idempotent), configure,
# build, then tests/benchmarks/run_benchmarks.py, which runs every measurement beside its baseline
# (rclpy relay, bare Fast DDS echo, rclpy subscriber) in this same invocation and writes
# build/bench/results.json and docs/benchmarks.md. A few minutes on a 2-core machine.
# Benchmarks measure and report; they never fail on a time. Not part of scripts/test.sh.
#   scripts/bench.sh                    # everything
#   scripts/bench.sh --quick            # tiny sample counts: a smoke run of the driver
#   scripts/bench.sh --only spin,round_trip,throughput,robot_load,robot_load_traffic,generator,services,igtl,network,sender_split  (network: root)
# ROS2VTK_BENCH_NO_BUILD=1 skips set-up and build (the build must be current).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$ROOT/build}"
JOBS="${ROS2VTK_JOBS:-2}"
VENV="${ROS2VTK_VENV:-$ROOT/.venv}"  # as scripts/setup.sh
export ROS2VTK_VENV="$VENV"

if [ "${ROS2VTK_BENCH_NO_BUILD:-0}" != "1" ]; then
  "$ROOT/scripts/setup.sh"
  echo "[bench] configuring $BUILD"
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPython3_EXECUTABLE=/usr/bin/python3 -DROS2VTK_VENV_PYTHON="$VENV/bin/python"
  # Everything: the round trip's echo side is examples/round_trip/round_trip.py on the Python
  # wrapping, so the wrapped modules are needed besides the bench programs.
  echo "[bench] building with $JOBS jobs"
  cmake --build "$BUILD" -j "$JOBS"
fi

# Every DDS process of the suite stays on the loopback; the driver gives each its own domain.
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
export ROS2VTK_BUILD_DIR="$BUILD"
exec "$VENV/bin/python" "$ROOT/tests/benchmarks/run_benchmarks.py" --build "$BUILD" "$@"
