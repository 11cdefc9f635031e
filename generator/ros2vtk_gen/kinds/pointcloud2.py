"""Kind `pointcloud2`: PointCloud2-like fields <-> vtkPolyData; `lengths` may name `<data>.xyz`,
the x/y/z fields inside the bytes."""
from __future__ import annotations

from typing import Dict

from .base import Kind, prim, struct


def _scalable_paths(roles, element_roles) -> Dict[str, str]:
    return {f"{roles['data'].path}.xyz": "data"}


KIND = Kind(
    name="pointcloud2", vtk_types=("vtkPolyData",),
    roles=(("height", prim("uint32")), ("width", prim("uint32")),
           ("fields", struct(sequence=True, name=prim("string"), offset=prim("uint32"),
                             datatype=prim("uint8"), count=prim("uint32"))),
           ("is_bigendian", prim("bool")), ("point_step", prim("uint32")),
           ("row_step", prim("uint32")), ("data", prim("uint8", sequence=True)),
           ("is_dense", prim("bool"))),
    scalable=("data",), scalable_paths=_scalable_paths, pseudo_length_suffix=".xyz")
