"""RIHS01 type hashes against the values tabled in docs/wire-notes.md §2.6 (computed
there independently and partly cross-checked against third-party code)."""
import os

import pytest

from conftest import FIXTURES, MSG_SPECS, SHIPPED_PACKAGES
from ros2vtk_gen.msg_parser import parse_spec_file, resolve
from ros2vtk_gen.model import Action, Service
from ros2vtk_gen.typehash import (action_description, default_value_text, description_sources, hashable_description,
                                  message_description, own_source, service_description, type_hash)

EXPECTED = {
    "builtin_interfaces/msg/Time":
        "b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197",
    "builtin_interfaces/msg/Duration":
        "e8d009f659816f758b75334ee1a9ca5b5c0b859843261f14c7f937349599d93b",
    "std_msgs/msg/Header":
        "f49fb3ae2cf070f793645ff749683ac6b06203e41c891e17701b1cb597ce6a01",
    "std_msgs/msg/String":
        "df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18",
    "std_msgs/msg/Bool":
        "feb91e995ff9ebd09c0cb3d2aed18b11077585839fb5db80193b62d74528f6c9",
    "std_msgs/msg/Int64":
        "8cd1048c2f186b6bd9a92472dc1ce51723c0833a221e2b7aecfff111774f4b49",
    "std_msgs/msg/Float64":
        "705ba9c3d1a09df43737eb67095534de36fd426c0587779bda2bc51fe790182a",
    "std_msgs/msg/Empty":
        "20b625256f32d5dbc0d04fee44f43c41e51c70d3502f84b4a08e7a9c26a96312",
    "std_msgs/msg/MultiArrayDimension":
        "5e773a60a4c7fc8a54985f307c7837aa2994252a126c301957a24e31282c9cbe",
    "std_msgs/msg/MultiArrayLayout":
        "4c66e6f78e740ac103a94cf63259f968e48c617e7699e829b63c21a5cb50dac6",
    "std_msgs/msg/Int64MultiArray":
        "e60f9fe34d697f0939ad49d33158693c1277fbac0e2f04b7c2995dc21c89b422",
    "std_msgs/msg/Float64MultiArray":
        "1025ddc6b9552d191f89ef1a8d2f60f3d373e28b283d8891ddcc974e8c55397f",
    "geometry_msgs/msg/Point":
        "6963084842a9b04494d6b2941d11444708d892da2f4b09843b9c43f42a7f6881",
    "geometry_msgs/msg/Point32":
        "2fc4db7cae16a4582c79a56b66173a8d48d52c7dc520ddc55a0d4bcf2a4bfdbc",
    "geometry_msgs/msg/Quaternion":
        "8a765f66778c8ff7c8ab94afcc590a2ed5325a1d9a076ffff38fbce36f458684",
    "geometry_msgs/msg/Vector3":
        "cc12fe83e4c02719f1ce8070bfd14aecd40f75a96696a67a2a1f37f7dbb0765d",
    "geometry_msgs/msg/Pose":
        "d501954e9476cea2996984e812054b68026ae0bfae789d9a10b23daf35cc90fa",
    "geometry_msgs/msg/PoseStamped":
        "10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232d73b4cd8",
    "geometry_msgs/msg/PoseArray":
        "af0cc36d190e104d546d168d6b39df04fa4b4ccecf59cb4c9ed328d3d5004aa0",
    "geometry_msgs/msg/Transform":
        "beb83fbe698636351461f6f35d1abb20010c43d55374d81bd041f1ba2581fddc",
    "geometry_msgs/msg/TransformStamped":
        "0a241f87d04668d94099cbb5ba11691d5ad32c2f29682e4eb5653424bd275206",
    "geometry_msgs/msg/Wrench":
        "018e8519d57c16adbe97c9fe1460ef21fec7e31bc541de3d653a35895677ce52",
    "geometry_msgs/msg/WrenchStamped":
        "8dc3deaf06b2ab281f9f9a742a8961c328ca7cec16e3fd6586d3a5c83fa78f77",
    "sensor_msgs/msg/Image":
        "d31d41a9a4c4bc8eae9be757b0beed306564f7526c88ea6a4588fb9582527d47",
    "sensor_msgs/msg/ChannelFloat32":
        "92665437ddf39346f4ba39ee32e648390605b633cc077d40f4bd4d7b58af6cd4",
    "sensor_msgs/msg/PointCloud":
        "614593df71d3c2b9bd4604a71b750fd218f0d65c045ea988b713719455a65b3b",
    "sensor_msgs/msg/PointField":
        "5c6a4750728c2bcfbbf7037225b20b02d4429634732146b742dee1726637ef01",
    "sensor_msgs/msg/PointCloud2":
        "9198cabf7da3796ae6fe19c4cb3bdd3525492988c70522628af5daa124bae2b5",
    "sensor_msgs/msg/JointState":
        "a13ee3a330e346c9d87b5aa18d24e11690752bd33a0350f11c5882bc9179260e",
    "rmw_dds_common/msg/Gid":
        "ab6f21cfbb0a6dbb837161e1110c2051a2850ed9f9c53944d7115d9bcebedf71",
    "rmw_dds_common/msg/NodeEntitiesInfo":
        "8ffef65ee2d088c63b1e8fcd31e800ba9fc8dbe0ee15ca60d1676de5218087a7",
    "rmw_dds_common/msg/ParticipantEntitiesInfo":
        "91a0593bacdcc50ea9bdcf849a938b128412cc1ea821245c663bcd26f83c295e",
    "rcl_interfaces/msg/ParameterValue":
        "115fc089a387e23c7ecd3525c9189c379109119d6ab82e8dfbde0fdf6a7f9b68",
    "rcl_interfaces/msg/Parameter":
        "ddfe6442cffc462317adb5c92536a7b6dd55858c5c3e1e328165a6b73c2831af",
    "rcl_interfaces/msg/ParameterDescriptor":
        "52175dbfda6c51153101d33d2a9da05743f66f02d5ab2ca9ec4709b46b73d704",
    "rcl_interfaces/msg/SetParametersResult":
        "cfcc0fb0371ee5159b403960ef4300f8f9d2f1fd6117c8666b7f9654d528a9b1",
    "rcl_interfaces/msg/ListParametersResult":
        "237ae3428413dcbcfb452b510c42355f3a2b021dc091afa3e18526d57022f1cd",
    "rcl_interfaces/msg/ParameterEvent":
        "043e627780fcad87a22d225bc2a037361dba713fca6a6b9f4b869a5aa0393204",
    "rcl_interfaces/msg/Log":
        "e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac",
    "rcl_interfaces/srv/GetParameters_Request":
        "135a9e1c3d7cebef792f6687d7ddf99949b21a0bd9a320d863a9110a3f5cf4d6",
    "rcl_interfaces/srv/GetParameters_Response":
        "9fa773b46e39cc5d02db6224d8fd520bb9caeeffc2b27c96c1e59431baba9f2a",
    "rcl_interfaces/srv/GetParameterTypes_Request":
        "87d7ec5ef545d4daa289d500025d31fb2437bc8b8365ca367161c4dac4be33fd",
    "rcl_interfaces/srv/GetParameterTypes_Response":
        "ac1335dce67c478e669434f6ac2fbff34fcd529580f272d3006785ba8b54e47f",
    "rcl_interfaces/srv/SetParameters_Request":
        "130d46386b7e84ea9ecf60608a4d83cbe5e5cb7c6cc5b712b7a4e3a6c254e932",
    "rcl_interfaces/srv/SetParameters_Response":
        "7a0e8140a0b8d98308fa81a5403a766e610af29a239caf54b7553227906fc266",
    "rcl_interfaces/srv/SetParametersAtomically_Request":
        "db0bd950ed5ed867a0e90b225e44dea382d762c0762ff3e0ee842190042a59e5",
    "rcl_interfaces/srv/SetParametersAtomically_Response":
        "31b1a38c5b0b9d893ee24da45f69638f4561c78461d82d52750f429b534502b8",
    "rcl_interfaces/srv/DescribeParameters_Request":
        "05dd1c2bc87dec2627105c8070d6f9725c781a4f2ab852975bf105462b82b644",
    "rcl_interfaces/srv/DescribeParameters_Response":
        "ad6747319613c6131589e062e095b469a46cc764f7d0f12a001a49e6cd893995",
    "rcl_interfaces/srv/ListParameters_Request":
        "a1b0b5d6b967a5b8ac5bc8563c3ea678f349e312a6a4967227c5a96bc5ce38df",
    "rcl_interfaces/srv/ListParameters_Response":
        "31b937b82de3612426be79f231e386259f97e8dc843e3f2845288b4bfa296bdd",
    # From share/rosgraph_msgs/msg/Clock.json of the ros-rosgraph-msgs 2.3.0 wheel (rosidl's own).
    "rosgraph_msgs/msg/Clock":
        "692f7a66e93a3c83e71765d033b60349ba68023a8c689a79e48078bcb5c58564",
}


# Service types, from share/<pkg>/srv/<Srv>.json of the Kilted wheels (rosidl's own; Jazzy's
# are the same): the hash of the synthesized service description (request_message,
# response_message, event_message).
EXPECTED_SERVICES = {
    "std_srvs/srv/SetBool": "abe9e4bb6b41b40e6789712c00ec8871923e089af3f667a79992a428cff2da0a",
    "std_srvs/srv/Trigger": "eeff2cd6fa5ad9d27cdf4dec64818317839b62f212a91e6b5304b634b2062c5f",
    "std_srvs/srv/Empty": "5888399dedec5ccc85ea6451949fd2c9f97bfdf963f9a588821639fcd31b5d19",
    "rcl_interfaces/srv/GetParameters":
        "bf9803d5c74cf989a5de3e0c2e99444599a627c7ff75f97b8c05b01003675cbc",
    "rcl_interfaces/srv/SetParametersAtomically":
        "0e192ef259c07fc3c07a13191d27002222e65e00ccec653ca05e856f79285fcd",
    "type_description_interfaces/srv/GetTypeDescription":
        "69b9c19c1021405984cc60dbbb1edceb147a6538b411d812ba6afabeed962cd5",
}


@pytest.fixture(scope="module")
def services():
    found = {}
    for package in SHIPPED_PACKAGES:
        folder = os.path.join(MSG_SPECS, package, "srv")
        if os.path.isdir(folder):
            for name in sorted(os.listdir(folder)):
                spec = parse_spec_file(os.path.join(folder, name))
                assert isinstance(spec, Service)
                found[spec.ros_type] = spec
    return found


@pytest.fixture(scope="module")
def table():
    paths = []
    for package in SHIPPED_PACKAGES:
        for root, _, files in os.walk(os.path.join(MSG_SPECS, package)):
            paths += [os.path.join(root, f) for f in files]
    return resolve([parse_spec_file(p) for p in sorted(paths)])


@pytest.mark.parametrize("ros_type", sorted(EXPECTED))
def test_type_hash_matches_rosidl(table, ros_type):
    assert type_hash(table[ros_type], table) == "RIHS01_" + EXPECTED[ros_type]


def test_every_tabled_type_is_shipped(table):
    assert len(EXPECTED) == 52
    assert set(EXPECTED) <= set(table)


def test_defaults_do_not_change_the_hash(table):
    # Quaternion has defaults (w = 1); the description carries no default values at all.
    description = hashable_description(table["geometry_msgs/msg/Quaternion"], table)
    assert "default_value" not in str(description)


def test_referenced_types_are_sorted_and_unique(table):
    description = hashable_description(table["tf2_msgs/msg/TFMessage"], table)
    names = [d["type_name"] for d in description["referenced_type_descriptions"]]
    assert names == sorted(set(names))
    assert names == ["builtin_interfaces/msg/Time", "geometry_msgs/msg/Quaternion",
                     "geometry_msgs/msg/Transform", "geometry_msgs/msg/TransformStamped",
                     "geometry_msgs/msg/Vector3", "std_msgs/msg/Header"]


def test_empty_message_hashes_its_dummy_member(table):
    description = hashable_description(table["std_msgs/msg/Empty"], table)
    assert description["type_description"]["fields"][0]["name"] == \
        "structure_needs_at_least_one_member"


@pytest.mark.parametrize("ros_type", sorted(EXPECTED_SERVICES))
def test_service_type_hash_matches_rosidl(table, services, ros_type):
    assert type_hash(services[ros_type], table) == "RIHS01_" + EXPECTED_SERVICES[ros_type]


def test_service_description_as_rosidl_synthesizes_it(table, services):
    # As share/std_srvs/srv/SetBool.json (type_description_msg) writes it.
    description = service_description(services["std_srvs/srv/SetBool"], table)
    assert [(f["name"], f["type"]["nested_type_name"])
            for f in description["type_description"]["fields"]] == [
        ("request_message", "std_srvs/srv/SetBool_Request"),
        ("response_message", "std_srvs/srv/SetBool_Response"),
        ("event_message", "std_srvs/srv/SetBool_Event")]
    referenced = {d["type_name"]: d for d in description["referenced_type_descriptions"]}
    assert list(referenced) == ["builtin_interfaces/msg/Time", "service_msgs/msg/ServiceEventInfo",
                                "std_srvs/srv/SetBool_Event", "std_srvs/srv/SetBool_Request",
                                "std_srvs/srv/SetBool_Response"]
    assert [(f["name"], f["type"]["type_id"], f["type"]["capacity"])
            for f in referenced["std_srvs/srv/SetBool_Event"]["fields"]] == [
        ("info", 1, 0), ("request", 97, 1), ("response", 97, 1)]
    assert [(f["name"], f["type"]["type_id"], f["type"]["capacity"])
            for f in referenced["service_msgs/msg/ServiceEventInfo"]["fields"]] == [
        ("event_type", 3, 0), ("stamp", 1, 0), ("client_gid", 51, 16), ("sequence_number", 8, 0)]


def test_served_description_keeps_default_values_as_rosidl_writes_them(table):
    # share/geometry_msgs/msg/Quaternion.json, rcl_interfaces/msg/ParameterDescriptor.json,
    # type_description_interfaces/srv/GetTypeDescription.json: Python's str() of the value.
    quaternion = message_description(table["geometry_msgs/msg/Quaternion"], table)
    assert [f["default_value"] for f in quaternion["type_description"]["fields"]] == \
        ["0.0", "0.0", "0.0", "1.0"]
    descriptor = message_description(table["rcl_interfaces/msg/ParameterDescriptor"], table)
    assert {f["name"]: f["default_value"] for f in descriptor["type_description"]["fields"]
            }["read_only"] == "False"
    request = message_description(
        table["type_description_interfaces/srv/GetTypeDescription_Request"], table)
    assert request["type_description"]["fields"][2]["default_value"] == "True"


def test_served_array_defaults_are_written_as_rosidl_writes_them(table):
    # share/test_msgs/msg/Arrays.json of the Kilted (and Jazzy) test_msgs wheel, type_description_msg:
    # rosidl_adapter writes an array default as repr() of a tuple, not of a list.
    arrays = message_description(table["test_msgs/msg/Arrays"], table)
    defaults = {f["name"]: f["default_value"] for f in arrays["type_description"]["fields"] if f["default_value"]}
    assert defaults == {
        "bool_values_default": "(False, True, False)",
        "byte_values_default": "(0, 1, 255)",
        "char_values_default": "(0, 1, 127)",
        "float32_values_default": "(1.125, 0.0, -1.125)",
        "float64_values_default": "(3.1415, 0.0, -3.1415)",
        "int8_values_default": "(0, 127, -128)",
        "uint8_values_default": "(0, 1, 255)",
        "int16_values_default": "(0, 32767, -32768)",
        "uint16_values_default": "(0, 1, 65535)",
        "int32_values_default": "(0, 2147483647, -2147483648)",
        "uint32_values_default": "(0, 1, 4294967295)",
        "int64_values_default": "(0, 9223372036854775807, -9223372036854775808)",
        "uint64_values_default": "(0, 1, 18446744073709551615)",
        "string_values_default": "('', 'max value', 'min value')",
    }


def test_one_element_array_default_keeps_the_tuple_comma():
    # rosidl_adapter.msg.to_idl_literal: repr(tuple(value)), so one element is '(1.5,)'.
    assert default_value_text((1.5,)) == "(1.5,)"
    assert default_value_text(("a'b",)) == '("a\'b",)'
    assert default_value_text(None) == ""


# Action types, from share/test_msgs/action/Fibonacci.json and NestedMessage.json of the Kilted
# ros-test-msgs wheel (rosidl's own type_hashes): the action, its three blocks, the synthesized
# services and messages. These are the hashes an rclpy action server and client advertise.
EXPECTED_ACTIONS = {
    "test_msgs/action/Fibonacci": {
        "test_msgs/action/Fibonacci":
            "be9273e3557225044b4a040811112491f7079326e3a573f83258b0b4c30bd069",
        "test_msgs/action/Fibonacci_Feedback":
            "7d1110f2efa019ad5ad8ad2244db98d862f39dc9fae8c976814b0065fa2f32d5",
        "test_msgs/action/Fibonacci_FeedbackMessage":
            "37487bae8cea358366b97003c1ef1ca7ce7c08df36f9e8cca496624226aee64e",
        "test_msgs/action/Fibonacci_GetResult":
            "5d30fdeb21d20e117aa5f36c7b4f0b6874f1a8cf7a9c038d58f1156c5737b209",
        "test_msgs/action/Fibonacci_GetResult_Request":
            "c65e93c4c4328d7f1abd6ace83dba8e5fa0f32de76b4d2c96b5c655d94803b92",
        "test_msgs/action/Fibonacci_GetResult_Response":
            "ef88159d47a3d21d9bf4bec690cf668939d9542db28a9cfd77dbcd97eaf1add2",
        "test_msgs/action/Fibonacci_Goal":
            "e58ef5a8f4f039ab522a740823547c460b1d5aed8031c8b7825d33d345d90df8",
        "test_msgs/action/Fibonacci_Result":
            "0774b095467813c6904d475498b5486b7ebd4cda6a4569f97e8de8c862689049",
        "test_msgs/action/Fibonacci_SendGoal":
            "d807633803e38e164276573cd97e9fbd71e109c290bbf4cc312a0a1c9da7bbd9",
        "test_msgs/action/Fibonacci_SendGoal_Request":
            "dfe75c73dc2c090cbc8fd8c45039bfa279d16aa6aadd348f812c6adad26e669e",
        "test_msgs/action/Fibonacci_SendGoal_Response":
            "1e7e84f7edf1fb020d9e51c7842bceef4cbdbd847f354125f3227cf4f314a683",
    },
    "test_msgs/action/NestedMessage": {
        "test_msgs/action/NestedMessage":
            "edd4bac361b0ee01c5e228d7c065f1d64e1b11aa55c5c6efb4e5e10e40fde40a",
        "test_msgs/action/NestedMessage_Feedback":
            "d03aaba098e33076c53560da77017d777a79d45d135bb72886da6e5d8357718e",
        "test_msgs/action/NestedMessage_FeedbackMessage":
            "72ee5828e8083f3c42a56bc5d99fd9e7d5c86389850fc006f254ecdcaecb7d03",
        "test_msgs/action/NestedMessage_GetResult":
            "0272bc330d08cbb96e6947dd9c2731c12ad7252823c7086978d117a802119e2b",
        "test_msgs/action/NestedMessage_GetResult_Request":
            "687ebbfa75d95d5d0f23ca800c213b4777fef311028d94a5d353ef7377f25741",
        "test_msgs/action/NestedMessage_GetResult_Response":
            "663ca16d674f9c9557884d2cfa74b51e3d4720a8fd305d87d89369a087791c80",
        "test_msgs/action/NestedMessage_Goal":
            "88928767537b27c7f9c7c78442e95b78c8a9b8f35877496ec9ca40c3a4a14176",
        "test_msgs/action/NestedMessage_Result":
            "c3356da873cd9b6f11cafaa25d6a9269a68751b937715cee506c3dbc051cdcfd",
        "test_msgs/action/NestedMessage_SendGoal":
            "8dea947216740e5b9e00eb537306bfe75af96492c688927d4f803afa5d81359b",
        "test_msgs/action/NestedMessage_SendGoal_Request":
            "e8d6d6d151e1b899137319c7784c420e6cae65767c10ca02cd129f76c5d7ea1b",
        "test_msgs/action/NestedMessage_SendGoal_Response":
            "e78d269a75544304ab7f6d700ba1cb718875360bb84007906227267f9b124381",
    },
}


@pytest.fixture(scope="module")
def actions():
    found = {}
    for package in SHIPPED_PACKAGES:
        folder = os.path.join(MSG_SPECS, package, "action")
        if os.path.isdir(folder):
            for name in sorted(os.listdir(folder)):
                spec = parse_spec_file(os.path.join(folder, name))
                assert isinstance(spec, Action)
                found[spec.ros_type] = spec
    return found


def _action_hashes(action, table):
    hashes = {action.ros_type: type_hash(action, table)}
    hashes.update({m.ros_type: type_hash(m, table) for m in action.messages})
    hashes.update({s.ros_type: type_hash(s, table) for s in (action.send_goal, action.get_result)})
    return hashes


@pytest.mark.parametrize("ros_type", sorted(EXPECTED_ACTIONS))
def test_action_type_hashes_match_rosidl(table, actions, ros_type):
    hashes = _action_hashes(actions[ros_type], table)
    for name, expected in EXPECTED_ACTIONS[ros_type].items():
        assert hashes[name] == "RIHS01_" + expected, name


def test_action_description_as_rosidl_synthesizes_it(table, actions):
    # As share/test_msgs/action/Fibonacci.json (type_description_msg) writes it.
    description = action_description(actions["test_msgs/action/Fibonacci"], table)
    assert [(f["name"], f["type"]["type_id"], f["type"]["nested_type_name"])
            for f in description["type_description"]["fields"]] == [
        ("goal", 1, "test_msgs/action/Fibonacci_Goal"),
        ("result", 1, "test_msgs/action/Fibonacci_Result"),
        ("feedback", 1, "test_msgs/action/Fibonacci_Feedback"),
        ("send_goal_service", 1, "test_msgs/action/Fibonacci_SendGoal"),
        ("get_result_service", 1, "test_msgs/action/Fibonacci_GetResult"),
        ("feedback_message", 1, "test_msgs/action/Fibonacci_FeedbackMessage")]
    assert [d["type_name"] for d in description["referenced_type_descriptions"]] == [
        "builtin_interfaces/msg/Time", "service_msgs/msg/ServiceEventInfo",
        "test_msgs/action/Fibonacci_Feedback", "test_msgs/action/Fibonacci_FeedbackMessage",
        "test_msgs/action/Fibonacci_GetResult", "test_msgs/action/Fibonacci_GetResult_Event",
        "test_msgs/action/Fibonacci_GetResult_Request",
        "test_msgs/action/Fibonacci_GetResult_Response", "test_msgs/action/Fibonacci_Goal",
        "test_msgs/action/Fibonacci_Result", "test_msgs/action/Fibonacci_SendGoal",
        "test_msgs/action/Fibonacci_SendGoal_Event",
        "test_msgs/action/Fibonacci_SendGoal_Request",
        "test_msgs/action/Fibonacci_SendGoal_Response", "unique_identifier_msgs/msg/UUID"]


def test_service_sources_as_rcl_serves_them(table, services):
    """The type_sources served with SetBool's description (what rclpy's node answered, checked
    by tests/interop/test_introspection.py): the .srv file, then per referenced type in order its
    .msg file or 'implicit' for what the .srv synthesizes; texts without the last newline."""
    service = services["std_srvs/srv/SetBool"]
    description = service_description(service, table)
    sources = description_sources(description, own_source(service), table)
    assert [s["encoding"] for s in sources] == ["srv", "msg", "msg", "implicit", "implicit", "implicit"]
    with open(os.path.join(MSG_SPECS, "std_srvs", "srv", "SetBool.srv"), encoding="utf-8") as handle:
        text = handle.read()
    assert text.endswith("\n") and sources[0]["raw_file_contents"] == text[:-1]
    assert sources[2]["raw_file_contents"].startswith("uint8 REQUEST_SENT = 0\n")
    assert all(s["raw_file_contents"] == "" for s in sources[3:])


def test_an_actions_own_source_and_its_synthesized_types(table):
    action = parse_spec_file(os.path.join(MSG_SPECS, "test_msgs", "action", "Fibonacci.action"))
    assert own_source(action)["encoding"] == "action"
    assert own_source(action)["raw_file_contents"].startswith("#goal definition\nint32 order\n---")
    assert own_source(action.goal) == {"encoding": "implicit", "raw_file_contents": ""}
    assert own_source(action.send_goal) == {"encoding": "implicit", "raw_file_contents": ""}
