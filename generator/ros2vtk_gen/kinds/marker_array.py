"""Kind `marker_array`: a sequence of Marker-like elements (visualization_msgs/MarkerArray) <->
one vtkPolyData of every marker a display keeps, as RViz keeps them: by (ns, id), ADD / MODIFY
replacing, DELETE dropping one, DELETEALL dropping all. The one stateful kind: its view names a
state class (ros2vtk::convert::MarkerSet) that the subscriber node owns and folds every received
message into (templates/node/subscriber.*.j2 `rule.state_class`); ROS2ToVTK of one message
draws that message alone (applied to an empty set). Each element reads the `marker` kind's roles
plus `ns`, `id` and `action` (the optional colors and mesh roles too), and optionally `lifetime` (a Duration: the marker is dropped that
long after it arrived, on the subscriber's ROS node clock; 0 keeps it); positions, sizes and points are lengths (all three or none).
With the optional roles `frame_id`, `stamp` and `frame_locked` (each element's header and flag),
markers are placed in the subscriber's fixed frame as the marker kind's are."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, Shape, prim
from .marker import (COLOR, COLOR_ROLES, DURATION, FRAME_ROLES, MESH_ROLES, POINTS, shapes_of,
                     state_view)


def _view(rule, table):
    element = table[rule.roles["sequence"].field.type.ros_name()]
    return dict(state_view(rule.element_roles), shapes=shapes_of(element), to_markers=True)


KIND = Kind(name="marker_array", vtk_types=("vtkPolyData",),
            roles=(("sequence", Shape(sequence=True)),),
            element_roles=(("ns", prim("string")), ("id", prim("int32")), ("action", prim("int32")),
                           ("type", prim("int32")), ("position", XYZ_FLOAT64),
                           ("orientation", QUATERNION), ("scale", XYZ_FLOAT64), ("color", COLOR),
                           ("points", POINTS), ("lifetime", DURATION)) + COLOR_ROLES
            + MESH_ROLES + FRAME_ROLES,
            optional_roles=("lifetime",) + tuple(name for name, _ in COLOR_ROLES + MESH_ROLES
                                                 + FRAME_ROLES),
            scalable=("position", "scale", "points"),
            view=_view)
