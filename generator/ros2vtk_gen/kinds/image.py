"""Kind `image`: sensor_msgs/Image-like fields <-> vtkImageData; publishing takes the encoding
(the node's `Encoding`, "" = from the scalar type)."""
from __future__ import annotations

from .base import Kind, prim

KIND = Kind(name="image", vtk_types=("vtkImageData",),
            roles=(("height", prim("uint32")), ("width", prim("uint32")),
                   ("encoding", prim("string")), ("is_bigendian", prim("uint8")),
                   ("step", prim("uint32")), ("data", prim("uint8", sequence=True))),
            takes_encoding=True)
