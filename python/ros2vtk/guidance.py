"""Helpers shared by the paper's image-guidance examples (examples/virtual_fixture, trajectory,
ultrasound), so the registration parsing, its default and the JSON error line live in one place
instead of a copy per example:

    from ros2vtk.guidance import DEFAULT_REGISTRATION, error_reporter, parse_rigid_matrix
    fail = error_reporter('trajectory')      # fail(message) -> 2, after printing the error

Pure Python on top of VTK; copied next to the wrapped modules by python/CMakeLists.txt.
"""
from __future__ import annotations

import json
import math
import sys
from typing import Callable

import vtk

__all__ = ['DEFAULT_REGISTRATION', 'error_reporter', 'parse_rigid_matrix']

# Where the demo puts the phantom in front of its robot: image -> robot is a translation of
# (350, -64, 150) mm, so robot -> image (the registration) is its inverse.
DEFAULT_REGISTRATION = [1, 0, 0, -350.0, 0, 1, 0, 64.0, 0, 0, 1, -150.0]


def error_reporter(program: str) -> Callable[[str], int]:
    """A `fail(message)` for `program`: prints {"error": message} on stdout (the JSON lines the
    examples' tests read) and "program: message" on stderr, and returns exit code 2."""
    def fail(message: str) -> int:
        print(json.dumps({'error': message}), flush=True)
        print(f'{program}: {message}', file=sys.stderr, flush=True)
        return 2
    return fail


def parse_rigid_matrix(text: str) -> vtk.vtkMatrix4x4:
    """12 or 16 numbers, row-major, millimetres -> vtkMatrix4x4; ValueError if not a rigid transform."""
    try:
        values = [float(v) for v in text.replace(',', ' ').split()]
    except ValueError as error:
        raise ValueError(f'registration: not a list of numbers ({error})') from None
    if len(values) not in (12, 16):
        raise ValueError(f'registration: expected 12 or 16 numbers (row-major 3x4 or 4x4), got {len(values)}')
    if len(values) == 12:
        values += [0.0, 0.0, 0.0, 1.0]
    if not all(math.isfinite(v) for v in values):
        raise ValueError('registration: numbers must be finite')
    matrix = vtk.vtkMatrix4x4()
    matrix.DeepCopy(values)
    for i in range(3):
        for j in range(3):
            dot = sum(matrix.GetElement(k, i) * matrix.GetElement(k, j) for k in range(3))
            if abs(dot - (1.0 if i == j else 0.0)) > 1e-6:
                raise ValueError('registration: the 3x3 part is not a rotation (columns not orthonormal)')
    if matrix.Determinant() < 0 or [matrix.GetElement(3, j) for j in range(4)] != [0, 0, 0, 1]:
        raise ValueError('registration: not a rigid transform (reflection, or bottom row not 0 0 0 1)')
    return matrix
