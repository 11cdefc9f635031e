"""Kind `marker_array`: a sequence of Marker-like elements (visualization_msgs/MarkerArray) <->
one vtkPolyData of every marker a display keeps, as RViz keeps them: by (ns, id), ADD / MODIFY
replacing, DELETE dropping one, DELETEALL dropping all. The one stateful kind: its view names a
state class (ros2vtk::convert::MarkerSet) that the subscriber node owns and folds every received
message into (templates/node/subscriber.*.j2 `rule.state_class`); ROS2ToVTK of one message
draws that message alone (applied to an empty set). Each element reads the `marker` kind's roles
plus `ns`, `id` and `action` (the optional mesh roles too), and optionally `lifetime` (a Duration: the marker is dropped that
long after it arrived, on the subscriber's ROS node clock; 0 keeps it); positions, sizes and points are lengths (all three or none)."""
from __future__ import annotations

from .base import QUATERNION, XYZ_FLOAT64, Kind, Shape, prim
from .marker import COLOR, DURATION, MESH_ROLES, POINTS, shapes_of


def _view(rule, table):
    element = table[rule.roles["sequence"].field.type.ros_name()]
    return {"state_class": "::ros2vtk::convert::MarkerSet",
            "state_header": "ros2vtk/convert/Marker.hpp",
            # The state has set_time(ns) / expire(ns): the subscriber stamps each spin's
            # messages with its node clock and drops expired markers on every spin.
            "state_expires": True,
            "shapes": shapes_of(element)}


KIND = Kind(name="marker_array", vtk_types=("vtkPolyData",),
            roles=(("sequence", Shape(sequence=True)),),
            element_roles=(("ns", prim("string")), ("id", prim("int32")), ("action", prim("int32")),
                           ("type", prim("int32")), ("position", XYZ_FLOAT64),
                           ("orientation", QUATERNION), ("scale", XYZ_FLOAT64), ("color", COLOR),
                           ("points", POINTS), ("lifetime", DURATION)) + MESH_ROLES,
            optional_roles=("lifetime",) + tuple(name for name, _ in MESH_ROLES),
            scalable=("position", "scale", "points"),
            view=_view)
