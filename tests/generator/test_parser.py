"""The .msg/.srv grammar: every feature on the fixtures, and every malformed spec's error."""
import os

import pytest

from conftest import FIXTURES, MSG_SPECS
from ros2vtk_gen import errors
from ros2vtk_gen.errors import SpecError
from ros2vtk_gen.model import (ARRAY, BOUNDED_SEQUENCE, SCALAR, SEQUENCE, Action, Message,
                               Service)
from ros2vtk_gen.msg_parser import (parse_message_text, parse_service_text, parse_spec_file,
                                    resolve)


def fixture(name: str) -> Message:
    message = parse_spec_file(os.path.join(FIXTURES, "msg", name + ".msg"))
    assert isinstance(message, Message)
    return message


def fields(message: Message) -> dict:
    return {f.name: f for f in message.fields}


def test_every_primitive_type_in_declaration_order():
    message = fixture("Primitives")
    assert [f.type.name for f in message.fields] == [
        "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
        "int32", "uint32", "int64", "uint64", "string"]
    assert all(f.container == SCALAR and f.type.is_primitive for f in message.fields)
    assert message.fields[0].line == 2


def test_containers_fixed_bounded_and_unbounded():
    arrays = fields(fixture("Arrays"))
    assert (arrays["bool_values"].container, arrays["bool_values"].size) == (ARRAY, 3)
    bounded = fields(fixture("BoundedSequences"))
    assert (bounded["uint8_values"].container, bounded["uint8_values"].size) == (BOUNDED_SEQUENCE, 4)
    unbounded = fields(fixture("UnboundedSequences"))
    assert (unbounded["float64_values"].container, unbounded["float64_values"].size) == (SEQUENCE, 0)


def test_bounded_strings_alone_and_in_containers():
    strings = fields(fixture("Strings"))
    assert strings["plain"].type.string_bound == 0
    assert strings["bounded"].type.string_bound == 5
    assert (strings["bounded_array"].type.string_bound, strings["bounded_array"].container,
            strings["bounded_array"].size) == (3, ARRAY, 2)
    assert (strings["bounded_in_bounded_sequence"].type.string_bound,
            strings["bounded_in_bounded_sequence"].size) == (4, 2)
    assert strings["wide"].type.name == "wstring"


def test_nested_types_from_same_and_other_package():
    nested = fields(fixture("Nested"))
    assert (nested["stamp"].type.package, nested["stamp"].type.name) == ("builtin_interfaces", "Time")
    assert (nested["inner"].type.package, nested["inner"].type.name) == ("ros2vtk_test_msgs", "Inner")


def test_constants_values_and_comment_handling():
    constants = {c.name: c.value for c in fixture("Constants").constants}
    assert constants["FLAG"] is True
    assert constants["LOWEST_INT64"] == -2**63
    assert constants["TOP_UINT64"] == 2**64 - 1
    assert constants["HALF"] == 0.5
    assert constants["GREETING"] == "hello"      # the comment after it is not part of it
    assert constants["QUOTED"] == 'say "hi"'
    assert [f.name for f in fixture("Constants").fields] == ["value"]


def test_defaults_scalars_strings_and_arrays():
    defaults = {f.name: f.default for f in fixture("Defaults").fields}
    assert defaults == {
        "flag": True, "small": -5, "medium": 1000, "big": -9000000000, "ratio": 0.25,
        "scale": 1000.0, "name": 'a "quoted" name', "bare": "word", "short_name": "robot",
        "triple": (1, 2, 3), "weights": (0.5, -1.5), "switches": (True, False),
        "labels": ("x", "y")}


def test_empty_message_and_comment_only_lines():
    assert fixture("Empty").fields == ()
    assert fixture("Empty").is_empty


def test_service_request_and_response():
    service = parse_spec_file(os.path.join(FIXTURES, "srv", "Echo.srv"))
    assert isinstance(service, Service)
    assert service.request.name == "Echo_Request" and service.request.kind == "srv"
    assert [c.name for c in service.request.constants] == ["MODE_ECHO"]
    assert [f.name for f in service.response.fields] == ["reply", "ok"]
    assert service.response.fields[0].line == 6  # line numbers continue after '---'


def test_hash_inside_quotes_is_not_a_comment():
    message = parse_message_text('string tag "a#b"  # real comment\n', "pkg", "T")
    assert message.fields[0].default == "a#b"


def test_shipped_specs_parse_and_resolve():
    paths = []
    for root, _, files in os.walk(MSG_SPECS):
        if "fixtures" in root or "mappings" in root:
            continue
        paths += [os.path.join(root, f) for f in files
                  if f.endswith((".msg", ".srv", ".action"))]
    table = resolve([parse_spec_file(p) for p in sorted(paths)])
    # Derived from the folders, so adding a package needs no edit here: every spec file gives
    # one entry per message (a service its Request and Response too).
    messages = [p for p in paths if p.endswith(".msg")]
    services = [p for p in paths if p.endswith(".srv")]
    assert messages and services
    assert all(f"{os.path.basename(os.path.dirname(os.path.dirname(p)))}/msg/"
               f"{os.path.basename(p)[:-4]}" in table for p in messages)
    assert all(f"{os.path.basename(os.path.dirname(os.path.dirname(p)))}/srv/"
               f"{os.path.basename(p)[:-4]}_Request" in table for p in services)
    actions = [p for p in paths if p.endswith(".action")]
    assert actions and all(f"{os.path.basename(os.path.dirname(os.path.dirname(p)))}/action/"
                           f"{os.path.basename(p)[:-7]}_FeedbackMessage" in table for p in actions)
    assert [f.name for f in table["sensor_msgs/msg/PointCloud2"].fields] == [
        "header", "height", "width", "fields", "is_bigendian", "point_step", "row_step", "data",
        "is_dense"]
    gid = table["rmw_dds_common/msg/Gid"].fields[0]
    assert (gid.type.name, gid.container, gid.size) == ("char", ARRAY, 16)


BAD_SPECS = [
    ("int32 x\nfloat64\n", 2, errors.BAD_LINE, "expected 'TYPE NAME'"),
    ("int33 x\n", 1, errors.BAD_TYPE, "unknown primitive type 'int33'"),
    ("int32[<=] x\n", 1, errors.BAD_TYPE, "needs a size"),
    ("int32[0] x\n", 1, errors.BAD_TYPE, "array size must be positive"),
    ("int32<=3 x\n", 1, errors.BAD_TYPE, "only string and wstring take a bound"),
    ("int32 x[3]\n", 1, errors.BAD_NAME, "invalid field name"),
    ("int32 Bad\n", 1, errors.BAD_NAME, "invalid field name 'Bad'"),
    ("int32 a__b\n", 1, errors.BAD_NAME, "invalid field name"),
    ("int32 class\n", 1, errors.BAD_NAME, "reserved"),
    ("int32 x\n\nint64 x\n", 3, errors.DUPLICATE, "already defined on line 1"),
    ("uint8 x 256\n", 1, errors.BAD_VALUE, "out of range for uint8"),
    ("int8 x -129\n", 1, errors.BAD_VALUE, "out of range for int8"),
    ("bool x maybe\n", 1, errors.BAD_VALUE, "is not a bool"),
    ("float64 x abc\n", 1, errors.BAD_VALUE, "is not a number"),
    ("float32 x 1e39\n", 1, errors.BAD_VALUE, "out of range for float32"),
    ("int32[2] x [1, 2, 3]\n", 1, errors.BAD_VALUE, "needs 2"),
    ("int32[<=2] x [1, 2, 3]\n", 1, errors.BAD_VALUE, "the bound is 2"),
    ("int32[] x 1, 2\n", 1, errors.BAD_VALUE, "must be written [v1, v2, ...]"),
    ("string<=3 x \"long\"\n", 1, errors.BAD_VALUE, "longer than its bound 3"),
    ("string x \"open\n", 1, errors.BAD_VALUE, "unterminated string"),
    ("Other x 1\n", 1, errors.BAD_VALUE, "cannot have a default"),
    ("int32[] LIST=1\n", 1, errors.BAD_TYPE, "primitive, non-array"),
    ("int32 lower=1\n", 1, errors.BAD_NAME, "invalid constant name"),
    ("int32 X=\n", 1, errors.BAD_VALUE, "has no value"),
    ("Bad_Pkg/Type x\n", 1, errors.BAD_TYPE, "invalid package name"),
]


@pytest.mark.parametrize("text,line,code,words", BAD_SPECS)
def test_malformed_specs_report_file_line_and_code(tmp_path, text, line, code, words):
    path = tmp_path / "pkg" / "msg" / "Bad.msg"
    path.parent.mkdir(parents=True)
    path.write_text(text)
    with pytest.raises(SpecError) as caught:
        parse_spec_file(str(path))
    assert caught.value.line == line
    assert caught.value.code == code
    assert str(caught.value).startswith(f"{path}:{line}: ")
    assert words in str(caught.value)


@pytest.mark.parametrize("text,line,words", [
    ("string a\n", 1, "needs a '---'"),
    ("string a\n---\nstring b\n---\n", 4, "exactly one '---'"),
])
def test_malformed_services(tmp_path, text, line, words):
    path = tmp_path / "pkg" / "srv" / "Bad.srv"
    path.parent.mkdir(parents=True)
    path.write_text(text)
    with pytest.raises(SpecError) as caught:
        parse_spec_file(str(path))
    assert (caught.value.line, caught.value.code) == (line, errors.BAD_SERVICE)
    assert words in str(caught.value)


def test_unknown_referenced_type_names_the_field_line(tmp_path):
    path = tmp_path / "pkg" / "msg" / "Uses.msg"
    path.parent.mkdir(parents=True)
    path.write_text("# header\nint32 a\nother_pkg/Missing thing\n")
    with pytest.raises(SpecError) as caught:
        resolve([parse_spec_file(str(path))])
    assert str(caught.value).startswith(f"{path}:3: unknown type 'other_pkg/Missing'")
    assert caught.value.code == errors.UNKNOWN_TYPE


def test_a_message_that_contains_itself_is_rejected(tmp_path):
    folder = tmp_path / "pkg" / "msg"
    folder.mkdir(parents=True)
    (folder / "A.msg").write_text("B b\n")
    (folder / "B.msg").write_text("A[<=1] a\n")
    with pytest.raises(SpecError, match="contains itself"):
        resolve([parse_spec_file(str(folder / "A.msg")), parse_spec_file(str(folder / "B.msg"))])


@pytest.mark.parametrize("relative,words", [
    ("pkg/Type.msg", "laid out as"),
    ("pkg/msg/lower.msg", "invalid type name"),
    ("Pkg/msg/Type.msg", "invalid package name"),
    ("pkg/msg/Type.txt", "laid out as"),
])
def test_spec_paths_name_package_and_type(tmp_path, relative, words):
    path = tmp_path / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("int32 x\n")
    with pytest.raises(SpecError, match=words):
        parse_spec_file(str(path))


def test_action_blocks_and_synthesized_types():
    action = parse_spec_file(os.path.join(MSG_SPECS, "test_msgs", "action", "Fibonacci.action"))
    assert isinstance(action, Action)
    assert action.ros_type == "test_msgs/action/Fibonacci"
    # As rosidl_adapter's action.idl.em synthesizes them (docs/wire-notes.md §8.2).
    assert [(m.ros_type, [(f.name, f.type.ros_name(), f.container) for f in m.fields])
            for m in action.messages] == [
        ("test_msgs/action/Fibonacci_Goal", [("order", "int32", SCALAR)]),
        ("test_msgs/action/Fibonacci_Result", [("sequence", "int32", SEQUENCE)]),
        ("test_msgs/action/Fibonacci_Feedback", [("sequence", "int32", SEQUENCE)]),
        ("test_msgs/action/Fibonacci_SendGoal_Request",
         [("goal_id", "unique_identifier_msgs/msg/UUID", SCALAR),
          ("goal", "test_msgs/action/Fibonacci_Goal", SCALAR)]),
        ("test_msgs/action/Fibonacci_SendGoal_Response",
         [("accepted", "bool", SCALAR), ("stamp", "builtin_interfaces/msg/Time", SCALAR)]),
        ("test_msgs/action/Fibonacci_GetResult_Request",
         [("goal_id", "unique_identifier_msgs/msg/UUID", SCALAR)]),
        ("test_msgs/action/Fibonacci_GetResult_Response",
         [("status", "int8", SCALAR), ("result", "test_msgs/action/Fibonacci_Result", SCALAR)]),
        ("test_msgs/action/Fibonacci_FeedbackMessage",
         [("goal_id", "unique_identifier_msgs/msg/UUID", SCALAR),
          ("feedback", "test_msgs/action/Fibonacci_Feedback", SCALAR)]),
    ]
    assert action.send_goal.ros_type == "test_msgs/action/Fibonacci_SendGoal"
    assert action.get_result.ros_type == "test_msgs/action/Fibonacci_GetResult"
    assert action.result.fields[0].line == 5  # line numbers continue after each '---'


def test_action_short_names_mean_the_package_messages():
    action = parse_spec_file(os.path.join(MSG_SPECS, "test_msgs", "action",
                                          "NestedMessage.action"))
    assert [f.type.ros_name() for f in action.goal.fields] == [
        "test_msgs/msg/Builtins", "test_msgs/msg/BasicTypes", "builtin_interfaces/msg/Time"]


@pytest.mark.parametrize("text,line,words", [
    ("int32 a\n---\nint32 b\n", 3, "found 1"),
    ("int32 a\n", 1, "found 0"),
    ("int32 a\n---\n---\n---\n", 4, "found 3"),
])
def test_malformed_actions(tmp_path, text, line, words):
    path = tmp_path / "pkg" / "action" / "Bad.action"
    path.parent.mkdir(parents=True)
    path.write_text(text)
    with pytest.raises(SpecError) as caught:
        parse_spec_file(str(path))
    assert (caught.value.line, caught.value.code) == (line, errors.BAD_SERVICE)
    assert "exactly two '---'" in str(caught.value) and words in str(caught.value)


def test_action_without_unique_identifier_msgs_names_what_is_missing(tmp_path):
    path = tmp_path / "pkg" / "action" / "Go.action"
    path.parent.mkdir(parents=True)
    path.write_text("int32 a\n---\n---\n")
    with pytest.raises(SpecError) as caught:
        resolve([parse_spec_file(str(path))])
    assert "unknown type 'unique_identifier_msgs/UUID' of field 'goal_id'" in str(caught.value)
