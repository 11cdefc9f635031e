#!/usr/bin/env bash
# Builds rclpy support for a ROS 2 interface package without a wheel from its .msg/.srv files,
# with the ROS 2 generators from the venv's wheels (scripts/make_rclpy_type.py says how).
#   scripts/make-rclpy-type.sh msg_specs/lab_msgs            # build, then print the exports
#   eval "$(scripts/make-rclpy-type.sh msg_specs/lab_msgs --print-env)"   # use it in this shell
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${ROS2VTK_VENV:-$ROOT/.venv}"  # as scripts/setup.sh
if [ ! -x "$VENV/bin/python" ]; then
  echo "make-rclpy-type: no venv at $VENV: run scripts/setup.sh first" >&2
  exit 1
fi
exec "$VENV/bin/python" "$ROOT/scripts/make_rclpy_type.py" "$@"
