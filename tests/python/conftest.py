"""Shared fixtures of the wrapped-API tests: the ros2vtk package from the build tree.

CTest runs these with PYTHONPATH=<build>/python, a ROS domain of their own and discovery on
the loopback (see CMakeLists.txt here)."""

from __future__ import annotations

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
    """Spins `logic` until `done()` or the timeout; returns done() (the package's helper)."""
    from ros2vtk import spin_until as package_spin_until
    return package_spin_until(logic, done, seconds)
