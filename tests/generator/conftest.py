"""Shared paths for the generator tests; makes `ros2vtk_gen` importable from the checkout."""
import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GENERATOR = os.path.join(REPO, "generator")
MSG_SPECS = os.path.join(REPO, "msg_specs")
FIXTURES = os.path.join(MSG_SPECS, "fixtures", "ros2vtk_test_msgs")
SHIPPED_PACKAGES = ("builtin_interfaces", "std_msgs", "geometry_msgs", "sensor_msgs", "tf2_msgs",
                    "rcl_interfaces", "rmw_dds_common")

if GENERATOR not in sys.path:
    sys.path.insert(0, GENERATOR)
