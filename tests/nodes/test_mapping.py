"""The mapping-rule loader (generator/ros2vtk_gen/mapping.py): the shipped rules load, and every
kind of mistake is reported as `file:line: message [code]` with exit 1 and no traceback."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import tomllib
from typing import Dict, List

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "generator"))

from ros2vtk_gen.emit import expand_spec_paths  # noqa: E402
from ros2vtk_gen.mapping import MappingError, load_rules, short_names_of  # noqa: E402
from ros2vtk_gen.model import Message  # noqa: E402
from ros2vtk_gen.msg_parser import parse_spec_file, resolve  # noqa: E402

MSG_SPECS = os.path.join(REPO, "msg_specs")
SHIPPED_MAPPINGS = sorted(os.path.join(MSG_SPECS, "mappings", name)
                          for name in os.listdir(os.path.join(MSG_SPECS, "mappings"))
                          if name.endswith(".toml"))
# Every folder of msg_specs/ holding msg/ or srv/ (as msg_specs/CMakeLists.txt finds them).
SHIPPED_PACKAGES = sorted(name for name in os.listdir(MSG_SPECS)
                          if os.path.isdir(os.path.join(MSG_SPECS, name, "msg"))
                          or os.path.isdir(os.path.join(MSG_SPECS, name, "srv")))

GOOD_POSE = """\
[[mapping]]
short_name = "PoseStamped"
ros_type = "geometry_msgs/msg/PoseStamped"
vtk_type = "vtkMatrix4x4"
kind = "rigid_transform"
fields = { translation = "pose.position", rotation = "pose.orientation" }
header = "header"
lengths = ["pose.position"]
"""


@pytest.fixture(scope="module")
def table() -> Dict[str, Message]:
    paths = expand_spec_paths([os.path.join(MSG_SPECS, p) for p in SHIPPED_PACKAGES])
    return resolve([parse_spec_file(p) for p in paths])


def write(tmp_path, text: str, name: str = "rules.toml") -> str:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return str(path)


def error_of(tmp_path, table, text: str) -> MappingError:
    with pytest.raises(MappingError) as caught:
        load_rules([write(tmp_path, text)], table)
    return caught.value


def test_shipped_rules_load_with_their_kinds_and_scaling(table):
    rules = {rule.short_name: rule for rule in load_rules(SHIPPED_MAPPINGS, table)}
    # One rule per [[mapping]] table of the shipped files (read as plain TOML, not by the loader).
    expected = []
    for path in SHIPPED_MAPPINGS:
        with open(path, "rb") as handle:
            expected += [entry["short_name"] for entry in tomllib.load(handle)["mapping"]]
    assert sorted(rules) == sorted(expected)
    assert rules["PoseStamped"].scaled_roles == ("translation",)
    assert rules["PoseArray"].scaled_roles == ("translation",)
    assert rules["PointCloud"].scaled_roles == ("sequence",)
    assert rules["PointCloud2"].scaled_roles == ("data",)
    assert rules["WrenchStamped"].scaled_roles == ()
    assert rules["Image"].aliases == ("UInt8Image",)
    assert rules["Image"].header is not None and rules["Image"].header.path == "header"
    assert rules["String"].header is None
    assert rules["TransformStamped"].child_frame.path == "child_frame_id"
    assert rules["PoseStamped"].child_frame is None


def test_good_rule_loads_with_line_of_its_table(tmp_path, table):
    (rule,) = load_rules([write(tmp_path, "# comment\n\n" + GOOD_POSE)], table)
    assert rule.line == 3
    assert rule.roles["translation"].path == "pose.position"
    assert rule.blank_message == "vtk"  # the default: GetBlankMessage is the VTK value


def test_blank_message_key_reaches_the_rule(tmp_path, table):
    text = GOOD_POSE.replace('header = "header"', 'header = "header"\nblank_message = "message"')
    (rule,) = load_rules([write(tmp_path, text)], table)
    assert rule.blank_message == "message"


@pytest.mark.parametrize("change, line, fragment, code", [
    (('ros_type = "geometry_msgs/msg/PoseStamped"', 'ros_type = "geometry_msgs/msg/Posed"'),
     3, "unknown ROS type 'geometry_msgs/msg/Posed'", "R2V203"),
    (('kind = "rigid_transform"', 'kind = "rigid"'), 5, "unknown kind 'rigid'", "R2V204"),
    (('vtk_type = "vtkMatrix4x4"', 'vtk_type = "vtkTransform"'), 4,
     "kind rigid_transform makes vtkMatrix4x4, not 'vtkTransform'", "R2V204"),
    (('"pose.position", rotation', '"pose.positon", rotation'), 6,
     "geometry_msgs/msg/Pose has no field 'positon'", "R2V205"),
    (('translation = "pose.position"', 'translation = "header"'), 6,
     "field 'header' (std_msgs/msg/Header) lacks member 'x'", "R2V205"),
    (('translation = "pose.position"', 'translation = "pose.position.x"'), 6,
     "field 'x' must be a message with x, y, z, it is float64", "R2V205"),
    (('translation = "pose.position", ', ''), 6, "needs role(s) translation", "R2V205"),
    (('rotation = "pose.orientation"', 'rotation = "pose.orientation", scale = "pose"'), 6,
     "has no role(s) scale", "R2V205"),
    (('header = "header"', 'header = "pose"'), 7, "is not a std_msgs/msg/Header", "R2V205"),
    (('lengths = ["pose.position"]', 'lengths = ["pose.orientation"]'), 8,
     "'pose.orientation' is not a length of kind rigid_transform", "R2V207"),
    (('lengths = ["pose.position"]', 'lengths = ["pose.nowhere"]'), 8,
     "has no field 'nowhere'", "R2V207"),
    (('short_name = "PoseStamped"', 'short_name = "pose stamped"'), 2,
     "'pose stamped' is not a valid short name", "R2V202"),
    (('kind = "rigid_transform"', 'kind = "rigid_transform"\ncolour = "red"'), 6,
     "unknown key(s) colour", "R2V202"),
    (('header = "header"', 'header = "header"\nchild_frame = "header.frame_id.x"'), 8,
     "child_frame", "R2V205"),
    (('header = "header"', 'header = "header"\nchild_frame = "pose"'), 8,
     "child_frame 'pose' is not a string", "R2V205"),
    (('header = "header"', 'child_frame = "header.frame_id"'), 7,
     "'child_frame' needs a 'header'", "R2V202"),
    (('header = "header"', 'header = "header"\nblank_message = "object"'), 8,
     "'blank_message' must be one of vtk, message, not 'object'", "R2V202"),
])
def test_each_mistake_names_file_line_and_reason(tmp_path, table, change, line, fragment, code):
    old, new = change
    assert old in GOOD_POSE
    error = error_of(tmp_path, table, GOOD_POSE.replace(old, new))
    text = str(error)
    assert text.startswith(f"{error.path}:{line}: "), text
    assert fragment in text
    assert error.code == code


POINT_RULE = """\
[[mapping]]
short_name = "Target"
ros_type = "geometry_msgs/msg/PoseStamped"
vtk_type = "vtkPoints"
kind = "point"
fields = { point = "pose.position" }
lengths = ["pose.position"]
"""


def test_point_kind_reads_one_xyz_and_scales_it(tmp_path, table):
    (rule,) = load_rules([write(tmp_path, POINT_RULE)], table)
    assert rule.kind == "point"
    assert rule.roles["point"].path == "pose.position"
    assert rule.scaled_roles == ("point",)


def test_points_kind_on_a_single_message_names_the_point_kind(tmp_path, table):
    """The message once read 'a sequence of message with , it is ...' (issue 20, item 4)."""
    text = POINT_RULE.replace('kind = "point"', 'kind = "points"').replace(
        'point = "pose.position"', 'sequence = "pose.position"')
    error = str(error_of(tmp_path, table, text))
    assert "field 'position' must be a sequence of messages, it is geometry_msgs/msg/Point" \
        in error, error
    assert 'use kind "point"' in error
    assert "with ," not in error


def test_marker_array_kind_reads_each_marker_and_names_its_state(table):
    """kind marker_array: the Marker roles plus ns, id and action inside each element of the
    sequence; lengths inside the elements; its view names the state class a subscriber keeps."""
    from ros2vtk_gen.nodes import rule_view
    rules = {rule.short_name: rule for rule in load_rules(SHIPPED_MAPPINGS, table)}
    rule = rules["MarkerArray"]
    assert rule.kind == "marker_array" and rule.roles["sequence"].path == "markers"
    assert {name: role.path for name, role in rule.element_roles.items()} == {
        "ns": "ns", "id": "id", "action": "action", "type": "type", "position": "pose.position",
        "orientation": "pose.orientation", "scale": "scale", "color": "color", "points": "points",
        "colors": "colors", "lifetime": "lifetime", "text": "text", "mesh_resource": "mesh_resource",
        "mesh_use_embedded_materials": "mesh_use_embedded_materials",
        "frame_id": "header.frame_id", "stamp": "header.stamp", "frame_locked": "frame_locked"}
    assert sorted(rule.scaled_roles) == ["points", "position", "scale"]
    view = rule_view(rule, table)
    assert view["state_class"] == "::ros2vtk::convert::MarkerSet"
    assert view["state_header"] == "ros2vtk/convert/Marker.hpp"
    assert view["state_expires"] is True  # lifetimes: the subscriber expires markers each spin
    assert view["state_frames"] is True  # frame_id mapped: the subscriber gets a FixedFrame
    # A Marker topic is kept by (ns, id) too (the rule maps ns, id and action), with frames.
    marker = rule_view(rules["Marker"], table)
    assert marker["state_class"] == view["state_class"] and marker["state_frames"] is True
    assert rule_view(rules["PathPolyline"], table)["state_class"] == ""  # other kinds: stateless


def test_marker_kind_keys_and_frames_come_together(tmp_path, table):
    """kind marker: without ns/id/action a rule draws one message (stateless, as before); ns, id
    and action come together; frame_id needs them; a rule with the key and no frame_id keeps
    markers without a FixedFrame."""
    from ros2vtk_gen.nodes import rule_view
    base = """\
    [[mapping]]
    short_name = "One"
    ros_type = "visualization_msgs/msg/Marker"
    vtk_type = "vtkPolyData"
    kind = "marker"
    fields = { type = "type", position = "pose.position", orientation = "pose.orientation", scale = "scale", color = "color", points = "points" }
    """
    one = load_rules([write(tmp_path, base)], table)[0]
    assert rule_view(one, table)["state_class"] == ""
    keyed = base.replace('points = "points" }', 'points = "points", ns = "ns", id = "id", action = "action" }')
    view = rule_view(load_rules([write(tmp_path, keyed)], table)[0], table)
    assert view["state_class"] == "::ros2vtk::convert::MarkerSet" and view["state_frames"] is False
    error = error_of(tmp_path, table, base.replace('points = "points" }', 'points = "points", ns = "ns" }')).message
    assert "roles ns, id and action go together (this rule maps only ns)" in error, error
    error = error_of(tmp_path, table, base.replace('points = "points" }',
                                                   'points = "points", frame_id = "header.frame_id" }')).message
    assert "role frame_id needs ns, id and action" in error, error


def test_marker_kinds_optional_roles_may_be_left_out_but_not_misnamed(tmp_path, table):
    """lifetime, text, mesh_resource and mesh_use_embedded_materials are optional roles (a lab's
    Marker-like type may lack them): a rule without them loads and its view has none; a wrong
    field for one is refused like any role; an unknown role is still an error."""
    from ros2vtk_gen.nodes import rule_view
    rule = """\
    [[mapping]]
    short_name = "Kept"
    ros_type = "visualization_msgs/msg/MarkerArray"
    vtk_type = "vtkPolyData"
    kind = "marker_array"
    fields = { sequence = "markers", ns = "ns", id = "id", action = "action", type = "type", position = "pose.position", orientation = "pose.orientation", scale = "scale", color = "color", points = "points" }
    """
    loaded = load_rules([write(tmp_path, rule)], table)[0]
    assert "lifetime" not in loaded.element_roles and "text" not in loaded.element_roles
    view = rule_view(loaded, table)
    assert "lifetime" not in view["element_roles"]
    error = error_of(tmp_path, table, rule.replace('points = "points" }',
                                                   'points = "points", lifetime = "ns" }')).message
    assert "role lifetime" in error, error
    error = error_of(tmp_path, table, rule.replace('points = "points" }',
                                                   'points = "points", colour = "color" }')).message
    assert "has no role(s) colour" in error, error
    error = error_of(tmp_path, table, rule.replace('type = "type", ', '')).message
    assert "needs role(s) type" in error, error


def test_matrix3x3_sequence_array_and_polyline_kinds(tmp_path, table):
    """CameraInfo's K (float64[9]) <-> vtkMatrix3x3, its D (float64[]) and Joy's axes
    (float32[]) and buttons (int32[]) <-> the VTK array of their element type, a Path's
    positions <-> a polyline vtkPolyData scaled as lengths."""
    rules = {rule.short_name: rule for rule in load_rules(SHIPPED_MAPPINGS, table)}
    assert rules["CameraInfo"].kind == "matrix3x3" and rules["CameraInfo"].vtk_type == "vtkMatrix3x3"
    assert rules["CameraInfo"].roles["elements"].path == "k"
    assert rules["CameraInfo"].scaled_roles == ()
    assert rules["CameraDistortion"].vtk_type == "vtkDoubleArray"
    assert rules["JoyAxes"].vtk_type == "vtkFloatArray"
    assert rules["JoyButtons"].vtk_type == "vtkIntArray"
    assert rules["PathPolyline"].kind == "polyline"
    assert rules["PathPolyline"].scaled_roles == ("point",)
    camera = """\
    [[mapping]]
    short_name = "Cam"
    ros_type = "sensor_msgs/msg/CameraInfo"
    vtk_type = "vtkMatrix3x3"
    kind = "matrix3x3"
    fields = { elements = "p" }
    """
    error = error_of(tmp_path, table, camera).message
    assert "field 'p' must be a float64[9], it is float64[12]" in error, error
    error = error_of(tmp_path, table, camera.replace('"p"', '"d"')).message
    assert "field 'd' must be a float64[9], it is sequence of float64" in error, error
    joy = """\
    [[mapping]]
    short_name = "Buttons"
    ros_type = "sensor_msgs/msg/Joy"
    vtk_type = "vtkFloatArray"
    kind = "sequence_array"
    fields = { data = "buttons" }
    """
    error = error_of(tmp_path, table, joy)
    assert error.code == "R2V204" and "int32 values go into vtkIntArray" in error.message, error
    error = error_of(tmp_path, table, joy.replace('"buttons"', '"header"')).message
    assert "field 'header' must be a sequence of" in error, error
    path = """\
    [[mapping]]
    short_name = "Line"
    ros_type = "nav_msgs/msg/Path"
    vtk_type = "vtkPolyData"
    kind = "polyline"
    fields = { sequence = "poses", point = "pose.position" }
    lengths = ["poses.pose.orientation"]
    """
    assert error_of(tmp_path, table, path).code == "R2V207"


def test_missing_required_key_points_at_the_rule(tmp_path, table):
    error = error_of(tmp_path, table, "\n" + GOOD_POSE.replace('kind = "rigid_transform"\n', ""))
    assert error.line == 2 and "'kind' is required" in error.message


def test_duplicate_short_names_and_aliases(tmp_path, table):
    second = GOOD_POSE.replace('ros_type = "geometry_msgs/msg/PoseStamped"',
                               'ros_type = "geometry_msgs/msg/TransformStamped"').replace(
        "pose.position", "transform.translation").replace("pose.orientation",
                                                           "transform.rotation")
    error = error_of(tmp_path, table, GOOD_POSE + "\n" + second)
    assert error.code == "R2V206" and "already used by rule PoseStamped" in error.message
    assert error.line == 10
    aliased = second.replace('short_name = "PoseStamped"',
                             'short_name = "Transform"\naliases = ["PoseStamped"]')
    assert "'PoseStamped' is already used" in error_of(tmp_path, table, GOOD_POSE + aliased).message


def test_same_ros_and_vtk_type_twice_would_clash(tmp_path, table):
    twice = GOOD_POSE + GOOD_POSE.replace('short_name = "PoseStamped"', 'short_name = "Pose2"')
    assert "the converters would clash" in error_of(tmp_path, table, twice).message


def test_kind_specific_type_rules(tmp_path, table):
    value = """\
    [[mapping]]
    short_name = "Text"
    ros_type = "std_msgs/msg/String"
    vtk_type = "double"
    kind = "value"
    fields = { value = "data" }
    """
    assert "a string field cannot be held in 'double'" in error_of(tmp_path, table, value).message
    array = """\
    [[mapping]]
    short_name = "Ints"
    ros_type = "std_msgs/Int64MultiArray"
    vtk_type = "vtkDoubleArray"
    kind = "multiarray_array"
    fields = { layout = "layout", data = "data" }
    """
    assert "int64 data goes into vtkTypeInt64Array" in error_of(tmp_path, table, array).message
    image = """\
    [[mapping]]
    short_name = "Picture"
    ros_type = "sensor_msgs/msg/Image"
    vtk_type = "vtkImageData"
    kind = "image"
    fields = { height = "width", width = "width", encoding = "encoding", is_bigendian = "step", step = "step", data = "data" }
    """
    assert "field 'step' must be a uint8, it is uint32" in error_of(tmp_path, table, image).message


def test_scaled_plain_value_only_for_floats(tmp_path, table):
    length = """\
    [[mapping]]
    short_name = "Distance"
    ros_type = "std_msgs/msg/Float64"
    vtk_type = "double"
    kind = "value"
    fields = { value = "data" }
    lengths = ["data"]
    """
    (rule,) = load_rules([write(tmp_path, length)], table)
    assert rule.scaled_roles == ("value",)
    counted = length.replace("Float64", "Int64").replace('"double"', '"vtkTypeInt64"')
    assert "kind value has no length to scale" in error_of(tmp_path, table, counted).message


def test_toml_syntax_error_has_its_line(tmp_path, table):
    error = error_of(tmp_path, table, '[[mapping]]\nshort_name = "A"\nkind = \n')
    assert error.code == "R2V201" and error.line == 3 and "not valid TOML" in error.message


def test_short_names_of_reads_only_the_toml(tmp_path):
    path = write(tmp_path, GOOD_POSE.replace("geometry_msgs/msg/PoseStamped", "no/msg/Such"))
    assert short_names_of([path]) == ["PoseStamped"]


def run_cli(tmp_path, mapping: str) -> subprocess.CompletedProcess:
    args = tmp_path / "args.json"
    specs = [os.path.join(MSG_SPECS, p) for p in ("builtin_interfaces", "std_msgs",
                                                  "geometry_msgs")]
    import json
    args.write_text(json.dumps({"family": "nodes", "target": "t", "output_dir": str(tmp_path / "o"),
                                "specs": specs, "mappings": [mapping]}))
    return subprocess.run([sys.executable, "-m", "ros2vtk_gen", "--args-file", str(args)],
                          capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=os.path.join(REPO, "generator")))


def test_cli_reports_one_line_and_exit_1(tmp_path):
    bad = write(tmp_path, GOOD_POSE.replace("pose.orientation", "pose.orient"))
    result = run_cli(tmp_path, bad)
    assert result.returncode == 1
    assert "Traceback" not in result.stderr
    lines: List[str] = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"{bad}:6: rule PoseStamped: role rotation")
    assert not (tmp_path / "o").exists(), "nothing is written when a rule is bad"


def test_cli_generates_the_classes_of_a_good_rule(tmp_path):
    result = run_cli(tmp_path, write(tmp_path, GOOD_POSE))
    assert result.returncode == 0, result.stderr
    out = tmp_path / "o"
    assert (out / "vtk" / "vtkROS2PublisherPoseStampedNode.h").is_file()
    assert (out / "vtk" / "vtkROS2SubscriberPoseStampedNode.cxx").is_file()
    assert "ros2vtk_register_t_nodes" in (out / "src" / "tRegistration.cxx").read_text()


@pytest.mark.parametrize("blank_message", ["vtk", "message"])
def test_subscriber_returns_message_objects_only_when_the_rule_says(tmp_path, blank_message):
    """blank_message = "message" flags the subscriber too (Python's GetLastMessage is then a
    VTKFieldMessage); every object subscriber converts a message object (its fields' converter)."""
    rule = GOOD_POSE.replace('header = "header"', f'header = "header"\nblank_message = "{blank_message}"')
    result = run_cli(tmp_path, write(tmp_path, rule))
    assert result.returncode == 0, result.stderr
    header = (tmp_path / "o" / "vtk" / "vtkROS2SubscriberPoseStampedNode.h").read_text()
    assert "bool ConvertMessageToObject(vtkROS2Message* message, vtkObject* value);" in header
    assert ("bool GetLastMessageIsMessageObject() const { return true; }" in header) == \
        (blank_message == "message")

# ---------------------------------------------------------------- one place per kind

def test_every_kind_has_its_module_and_its_template_and_nothing_else():
    """Kinds are found by scanning generator/ros2vtk_gen/kinds/ (one module each); an object
    kind's converter bodies are templates/convert/kinds/<kind>.j2. A template without a kind,
    or an object kind without a template, is a half-added kind."""
    from ros2vtk_gen.kinds import KINDS
    from ros2vtk_gen.kinds.base import OBJECT
    templates_dir = os.path.join(REPO, "templates", "convert", "kinds")
    templates = {name[:-len(".j2")] for name in os.listdir(templates_dir)
                 if name.endswith(".j2") and not name.startswith("_")}
    object_kinds = {name for name, kind in KINDS.items() if kind.signature == OBJECT}
    assert object_kinds == templates
    assert {"value", "empty"} <= set(KINDS) - object_kinds
    for name, kind in KINDS.items():
        assert kind.name == name
        assert kind.vtk_types, name


def test_a_rule_of_each_kind_reports_the_kind_hooks_errors(tmp_path, table):
    """The hooks moved into the kind modules still speak: value's type check, multiarray_array's
    class check, points' element check and hint, pointcloud2's `.xyz` length."""
    cases = [
        ('short_name = "V"\nros_type = "std_msgs/msg/Float64"\nvtk_type = "bool"\n'
         'kind = "value"\nfields = { value = "data" }\n', "cannot be held in 'bool'"),
        ('short_name = "A"\nros_type = "std_msgs/msg/Float64MultiArray"\n'
         'vtk_type = "vtkTypeInt64Array"\nkind = "multiarray_array"\n'
         'fields = { layout = "layout", data = "data" }\n', "data goes into vtkDoubleArray"),
        ('short_name = "P"\nros_type = "geometry_msgs/msg/PoseStamped"\nvtk_type = "vtkPoints"\n'
         'kind = "points"\nfields = { sequence = "pose.position" }\n',
         'use kind "point" with role point'),
        ('short_name = "C"\nros_type = "sensor_msgs/msg/PointCloud2"\nvtk_type = "vtkPolyData"\n'
         'kind = "pointcloud2"\nfields = { height = "height", width = "width", '
         'fields = "fields", is_bigendian = "is_bigendian", point_step = "point_step", '
         'row_step = "row_step", data = "data", is_dense = "is_dense" }\n'
         'lengths = ["height.xyz"]\n', "is not a length of kind pointcloud2"),
    ]
    for number, (rule, wanted) in enumerate(cases):
        path = tmp_path / f"rule{number}.toml"
        path.write_text("[[mapping]]\n" + rule)
        with pytest.raises(MappingError) as caught:
            load_rules([str(path)], table)
        assert wanted in str(caught.value), str(caught.value)
