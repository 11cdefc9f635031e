"""`python -m ros2vtk ...` — the same command line as `ros2vtk` (python/ros2vtk/cli.py)."""
import sys

from ros2vtk.cli import main

if __name__ == '__main__':
    sys.exit(main())
