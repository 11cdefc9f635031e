"""ros2vtk_gen: ROS 2 .msg/.srv specs -> C++ message types with CDR code and type-support tables."""

__version__ = "0.1.0"
