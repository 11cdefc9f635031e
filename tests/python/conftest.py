"""Shared fixtures of the wrapped-API tests: the ros2vtk package from the build tree.

CTest runs these with PYTHONPATH=<build>/python, a ROS domain of their own and discovery on
the loopback (see CMakeLists.txt here)."""

from __future__ import annotations

import time
from typing import Callable, Iterator

import pytest


@pytest.fixture(scope='session')
def ros2vtk():
    import ros2vtk as module
    return module


@pytest.fixture
def logic(ros2vtk) -> Iterator[object]:
    created = ros2vtk.vtkROS2Logic()
    yield created
    created.GetScene().Clear()


def spin_until(logic, done: Callable[[], bool], seconds: float = 10.0) -> bool:
    """Spins `logic` until `done()` or the timeout; returns done()."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        logic.Spin()
        if done():
            return True
        time.sleep(0.005)
    return done()
