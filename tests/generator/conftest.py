"""Shared paths for the generator tests; makes `ros2vtk_gen` importable from the checkout."""
import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GENERATOR = os.path.join(REPO, "generator")
MSG_SPECS = os.path.join(REPO, "msg_specs")
FIXTURES = os.path.join(MSG_SPECS, "fixtures", "ros2vtk_test_msgs")
# Every folder of msg_specs/ holding msg/ or srv/ (as msg_specs/CMakeLists.txt finds them).
SHIPPED_PACKAGES = tuple(sorted(
    name for name in os.listdir(MSG_SPECS)
    if os.path.isdir(os.path.join(MSG_SPECS, name, "msg"))
    or os.path.isdir(os.path.join(MSG_SPECS, name, "srv"))))

if GENERATOR not in sys.path:
    sys.path.insert(0, GENERATOR)
