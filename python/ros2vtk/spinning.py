"""Spinning a ros2vtk logic from a script until something happened (a message came, a robot
loaded), without a render window's timer: the loop sleeps in SpinOnWakeUp until data arrives
(or `step` seconds pass, for conditions no message signals), so it neither busy-waits nor adds
a fixed delay to every message.

    from ros2vtk import spin_until
    assert spin_until(logic, lambda: robot.IsLoaded(), seconds=10)

(For a fixed time, vtkROS2Logic.SpinFor(seconds) spins at the logic's rate.)
"""
from __future__ import annotations

import time
from typing import Callable


def spin_until(logic, done: Callable[[], bool], seconds: float = 10.0, step: float = 0.05) -> bool:
    """Spins `logic` (a vtkROS2Logic) until `done()` is true or `seconds` have passed; returns
    `done()`. `seconds <= 0` checks once after one spin."""
    end = time.monotonic() + max(seconds, 0.0)
    while True:
        logic.SpinOnWakeUp(step)
        if done():
            return True
        if time.monotonic() >= end:
            return bool(done())

