#!/usr/bin/env bash
# Fresh-machine set-up for ros2vtk, safe to run again (every step is skipped when already done):
#   1. Debian packages (apt-get update runs only when something is missing),
#   2. a venv at <repo>/.venv (with Debian's site-packages visible, for vtk, yaml and pytest),
#   3. the pinned ROS 2 Kilted wheels of scripts/requirements-ros.txt into it,
#   4. a second venv at <repo>/.venv-jazzy with the ROS 2 Jazzy wheels (scripts/requirements-jazzy.txt).
# Runs as root (no sudo); as another user it uses sudo for apt-get only.
set -euo pipefail

# The project's Debian packages. One list; append here when the project needs a new one.
DEBIAN_PACKAGES=(
  build-essential
  cmake
  ninja-build
  libfastrtps-dev
  libfastcdr-dev
  libvtk9-dev
  python3-vtk9
  libeigen3-dev
  liburdfdom-dev
  liburdfdom-headers-dev
  python3-jinja2
  libassimp-dev
  python3-dev
  python3-venv
  python3-pytest
  libgtest-dev
  nlohmann-json3-dev
  libyaml-cpp-dev
  xvfb
  xauth
  libtinyxml2-dev
  libconsole-bridge-dev
  python3-yaml
  python3-numpy
  chromium
  chromium-driver
  iproute2
  nftables
  libopenigtlink-dev
  clang-format
)

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${ROS2VTK_VENV:-$ROOT/.venv}"
# The ROS 2 Jazzy peers (the LTS most labs run) live in a venv of their own: their wheels pin other
# versions of the same ROS packages than Kilted's.
JAZZY_VENV="${ROS2VTK_JAZZY_VENV:-$ROOT/.venv-jazzy}"

log() { echo "[setup] $*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  else
    sudo "$@"
  fi
}

install_debian_packages() {
  local missing=()
  local pkg status
  for pkg in "${DEBIAN_PACKAGES[@]}"; do
    status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
    if [ "$status" != "install ok installed" ]; then
      missing+=("$pkg")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    log "Debian packages: all ${#DEBIAN_PACKAGES[@]} installed"
    return
  fi
  log "Debian packages missing: ${missing[*]}"
  log "apt-get update"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
  log "apt-get install -y ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

make_venv() {  # make_venv DIR
  local venv="$1"
  if [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import sys; sys.exit(0)' 2>/dev/null; then
    log "venv: $venv exists"
    return
  fi
  log "venv: creating $venv (/usr/bin/python3 -m venv --system-site-packages)"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
}

install_wheels() {  # install_wheels VENV REQUIREMENTS CHECK_IMPORTS
  # The stamp holds a hash of the requirement list (and of the venv's python), so pip runs
  # again exactly when the pinned set changes.
  local venv="$1" requirements="$2" imports="$3"
  local stamp="$venv/.ros2vtk-$(basename "$requirements" .txt).sha256"
  local wanted
  wanted="$( (cat "$requirements"; readlink -f "$venv/bin/python") | sha256sum | cut -d' ' -f1)"
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$wanted" ]; then
    log "wheels: pinned set of $(basename "$requirements") already installed in $venv"
    return
  fi
  log "wheels: pip install -r $(basename "$requirements") into $venv (a few minutes the first time)"
  "$venv/bin/python" -m pip install --disable-pip-version-check --no-input -q -r "$requirements"
  log "wheels: checking that $imports import"
  "$venv/bin/python" -c "import $imports"
  echo "$wanted" > "$stamp"
}

install_command() {
  # `ros2vtk` on PATH once the venv is active (or as .venv/bin/ros2vtk). The package lives in the
  # build tree (<repo>/build/python, next to its VTK-wrapped modules): the launcher finds the
  # checkout from its own path (<repo>/.venv/bin/ros2vtk), or ROS2VTK_BUILD_DIR, and sets PYTHONPATH.
  local launcher="$VENV/bin/ros2vtk"
  cat > "$launcher.tmp" <<'LAUNCHER'
#!/usr/bin/env bash
# ros2vtk command line (written by scripts/setup.sh): runs the package built in <repo>/build.
BIN="$(cd "$(dirname "$0")" && pwd)"
BUILD="${ROS2VTK_BUILD_DIR:-$(dirname "$(dirname "$BIN")")/build}"
if [ ! -d "$BUILD/python/ros2vtk" ]; then
  echo "ros2vtk: no build in $BUILD (run scripts/demo.sh, or set ROS2VTK_BUILD_DIR)" >&2
  exit 2
fi
export PYTHONPATH="$BUILD/python${PYTHONPATH:+:$PYTHONPATH}"
exec "$BIN/python" -m ros2vtk "$@"
LAUNCHER
  chmod +x "$launcher.tmp"
  mv "$launcher.tmp" "$launcher"
  log "command: $launcher (ros2vtk app|demo|nodes|topics|types|echo|pub|params)"
}

log "ros2vtk set-up in $ROOT"
install_debian_packages
make_venv "$VENV"
install_wheels "$VENV" "$ROOT/scripts/requirements-ros.txt" \
  'rclpy, std_msgs.msg, geometry_msgs.msg, sensor_msgs.msg, rcl_interfaces.msg, rmw_dds_common.msg, xacro'
install_wheels "$VENV" "$ROOT/scripts/requirements-app.txt" 'trame, trame_vuetify, trame_rca, PIL, selenium'
install_command
make_venv "$JAZZY_VENV"
install_wheels "$JAZZY_VENV" "$ROOT/scripts/requirements-jazzy.txt" \
  'rclpy, std_msgs.msg, geometry_msgs.msg, sensor_msgs.msg, rcl_interfaces.msg, rmw_dds_common.msg'
install_wheels "$VENV" "$ROOT/scripts/requirements-test.txt" 'pyigtl, IPython'  # the 3D Slicer stand-in; the IPython prompt
# The interop tests' own imports (pyigtl) for the Jazzy peers too: scripts/test-jazzy.sh runs them all.
install_wheels "$JAZZY_VENV" "$ROOT/scripts/requirements-test.txt" 'pyigtl, IPython'
log "done: venv python is $VENV/bin/python (Jazzy peers: $JAZZY_VENV/bin/python)"
