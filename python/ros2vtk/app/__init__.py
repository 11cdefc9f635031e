"""ros2vtk.app: the web app (trame) over a vtkROS2Logic — SlicerROS2's module panel in a browser.

    import ros2vtk, ros2vtk.app
    logic = ros2vtk.vtkROS2Logic()
    ros2vtk.app.serve(logic)             # http://127.0.0.1:8080/, spins the logic until Ctrl-C

Needs the packages of scripts/requirements-app.txt (trame, trame-vuetify, trame-rca, Pillow), in
the project's venv after scripts/setup.sh. `ros2vtk app` (python/ros2vtk/cli.py) starts it.
"""
from __future__ import annotations

from .server import App, serve

__all__ = ['App', 'serve']
