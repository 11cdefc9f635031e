"""Kind `compressed_image`: sensor_msgs/CompressedImage-like fields (a format text and PNG or
JPEG bytes) <-> vtkImageData, decoded and encoded by VTK's PNG/JPEG readers and writers;
publishing takes the codec (the node's `Encoding`: "png", "" = png, or "jpeg")."""
from __future__ import annotations

from .base import Kind, prim

KIND = Kind(name="compressed_image", vtk_types=("vtkImageData",),
            roles=(("format", prim("string")), ("data", prim("uint8", sequence=True))),
            takes_encoding=True)
