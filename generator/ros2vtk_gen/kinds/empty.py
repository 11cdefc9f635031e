"""Kind `empty`: a message without fields (std_msgs/Empty): nothing to convert; the nodes
publish and count it."""
from __future__ import annotations

from .base import EMPTY, Kind

KIND = Kind(name="empty", vtk_types=("void",), signature=EMPTY)
