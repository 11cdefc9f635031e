"""Introspection parity (issue 19): what `ros2 node info` shows for an rclpy node —
publishers, subscribers, service servers and clients with their types, read through rclpy's
graph API (get_*_names_and_types_by_node) — comes out the same for our node.

Our node (introspection_runner.py: the VTK-wrapped API's default node /slicer) and an rclpy node
(introspection_peer.py node) create the same endpoints; a third rclpy process queries the graph
for both and the lists are compared: first the endpoints we created, then the ones every rclpy
node has by default (/rosout, /parameter_events, the parameter services), with the node's own
name replaced by `~` so /slicer/get_parameters compares with /rclpy_introspect/get_parameters.

Then the REP 2011 type description service both serve (~/get_type_description): the same rclpy
process asks both nodes for every type they use, with the hash rosidl made for it, and our
answers must equal rclpy's and hash (rosidl's calculate_type_hash) to rosidl's hash.
"""
from __future__ import annotations

import json

import pytest

from conftest import BUILD, HERE, VENV_PYTHON, Ros, _domains

OURS = '/slicer'
QUIET = '/slicer_quiet'  # ours, created with start_type_description_service false
RCLPY = '/rclpy_introspect'
KINDS = ('publishers', 'subscribers', 'services', 'clients')


def is_default(name: str, node: str) -> bool:
    """Endpoints an rclpy node has without asking: /rosout, /parameter_events and its services
    under its own name (parameter services, and get_type_description from Jazzy on)."""
    return name in ('/rosout', '/parameter_events') or name.startswith(node + '/')


def split(info: dict, node: str) -> tuple[dict, dict]:
    """(created, default) per kind, default names with `node` replaced by `~`."""
    created = {kind: {n: t for n, t in info[kind].items() if not is_default(n, node)} for kind in KINDS}
    default = {kind: {n.replace(node + '/', '~/', 1): t for n, t in info[kind].items() if is_default(n, node)}
               for kind in KINDS}
    return created, default


@pytest.fixture(scope='module')
def graph():
    """Both nodes up (and our /slicer_quiet), one query of the graph for both:
    {node: {kind: {name: [types]}}}, and under 'descriptions' what the `describe` query got
    from each node's ~/get_type_description (introspection_peer.py)."""
    ros = Ros(next(_domains))
    try:
        ours = ros.start(['/usr/bin/python3', str(HERE / 'introspection_runner.py'), '--seconds', '120'],
                         dict(ros.env, PYTHONPATH=str(BUILD / 'python')))
        ros.wait_ready(ours)
        peer = ros.start([str(VENV_PYTHON), str(HERE / 'introspection_peer.py'), '--node', RCLPY[1:], 'node',
                          '--seconds', '120'])
        ros.wait_ready(peer)
        query = ros.start([str(VENV_PYTHON), str(HERE / 'introspection_peer.py'), 'query', OURS, RCLPY,
                           '--wait', '30', '--settle', '3'])
        code, out, err = ros.finish(query, timeout=60)
        assert code == 0 and out.strip(), err
        result = json.loads(out.strip().splitlines()[-1])
        for node in (OURS, RCLPY):
            assert 'error' not in result[node], f'{node}: {result[node]}'
        query = ros.start([str(VENV_PYTHON), str(HERE / 'introspection_peer.py'), 'describe', OURS, RCLPY, QUIET,
                           '--types', *DESCRIBED])
        code, out, err = ros.finish(query, timeout=120)
        assert code == 0 and out.strip(), err
        result['descriptions'] = json.loads(out.strip().splitlines()[-1])
        yield result
    finally:
        ros.close()


def test_rclpy_reference_node_shows_what_it_created(graph):
    theirs, _ = split(graph[RCLPY], RCLPY)
    assert theirs == {
        'publishers': {'/introspect/chatter': ['std_msgs/msg/String']},
        'subscribers': {'/introspect/pose': ['geometry_msgs/msg/PoseStamped'],
                        '/introspect/image': ['sensor_msgs/msg/Image'],
                        '/introspect/arrays': ['test_msgs/msg/Arrays']},
        'services': {'/introspect/enable': ['std_srvs/srv/SetBool']},
        'clients': {'/introspect/trigger': ['std_srvs/srv/Trigger']},
    }


@pytest.mark.parametrize('kind', KINDS)
def test_created_endpoints_match_rclpy(graph, kind):
    ours, _ = split(graph[OURS], OURS)
    theirs, _ = split(graph[RCLPY], RCLPY)
    assert ours[kind] == theirs[kind]


# The REP 2011 type description service rclpy nodes serve (start_type_description_service,
# default true, on Kilted and Jazzy).
TYPE_DESCRIPTION = '~/get_type_description'
# Every type both nodes use: what they created, then what every node has (/rosout,
# /parameter_events, the parameter and type description services).
DESCRIBED = (
    'std_msgs/msg/String', 'geometry_msgs/msg/PoseStamped', 'sensor_msgs/msg/Image',
    'std_srvs/srv/SetBool', 'std_srvs/srv/Trigger',
    'rcl_interfaces/msg/Log', 'rcl_interfaces/msg/ParameterEvent', 'rcl_interfaces/srv/GetParameters',
    'rcl_interfaces/srv/SetParameters', 'type_description_interfaces/srv/GetTypeDescription',
    'test_msgs/msg/Arrays',
)


@pytest.mark.parametrize('kind', KINDS)
def test_default_endpoints_match_rclpy(graph, kind):
    """/rosout, /parameter_events, the parameter and type description services, as rclpy shows them."""
    _, ours = split(graph[OURS], OURS)
    _, theirs = split(graph[RCLPY], RCLPY)
    assert ours[kind] == theirs[kind], (
        f'missing on ours: {sorted(set(theirs[kind]) - set(ours[kind]))}; '
        f'extra on ours: {sorted(set(ours[kind]) - set(theirs[kind]))}')


def test_type_description_service_like_rclpy(graph):
    _, ours = split(graph[OURS], OURS)
    _, theirs = split(graph[RCLPY], RCLPY)
    assert theirs['services'].get(TYPE_DESCRIPTION) == ['type_description_interfaces/srv/GetTypeDescription']
    assert ours['services'].get(TYPE_DESCRIPTION) == theirs['services'][TYPE_DESCRIPTION]


@pytest.mark.parametrize('ros_type', DESCRIBED)
def test_our_type_description_equals_rclpys(graph, ros_type):
    """Our node's answer for a type it uses is rclpy's answer for the same type, field for field
    (nested types, their references sorted by name, default values), and rosidl's
    calculate_type_hash of it is rosidl's hash of the type."""
    descriptions = graph['descriptions']
    assert descriptions[RCLPY]['available'] and descriptions[OURS]['available'], descriptions
    theirs = descriptions[RCLPY]['types'][ros_type]
    ours = descriptions[OURS]['types'][ros_type]
    assert theirs['successful'], theirs  # the reference itself knows the type
    assert ours['successful'], ours['failure_reason']
    assert ours['type_description'] == theirs['type_description']
    assert ours['rclpy_hash'] == theirs['rclpy_hash'] == ours['asked_hash']
    assert ours['type_description']['type_description']['type_name'] == ros_type
    # type_sources were not asked for (include_type_sources false): empty on both.
    assert ours['type_sources'] == theirs['type_sources'] == []
    assert ours['extra_information'] == theirs['extra_information']


def test_array_default_values_are_written_as_rclpy_writes_them(graph):
    """rclpy serves an array default as rosidl_adapter's repr() of a tuple, '(False, True, False)';
    ours wrote '[False, True, False]' before. The whole description is compared above; this
    names the fields, so a difference says which."""
    descriptions = graph['descriptions']
    defaults = {}
    for node in (RCLPY, OURS):
        fields = descriptions[node]['types']['test_msgs/msg/Arrays']['type_description']['type_description']['fields']
        defaults[node] = {f['name']: f['default_value'] for f in fields if f['default_value']}
    assert defaults[RCLPY]['bool_values_default'] == '(False, True, False)'
    assert defaults[RCLPY]['string_values_default'] == "('', 'max value', 'min value')"
    assert len(defaults[RCLPY]) == 14
    assert defaults[OURS] == defaults[RCLPY]


@pytest.mark.parametrize('request_kind', ['unknown', 'malformed'])
def test_unknown_or_malformed_hash_fails_like_rclpy(graph, request_kind):
    ours = graph['descriptions'][OURS][request_kind]
    theirs = graph['descriptions'][RCLPY][request_kind]
    assert theirs['successful'] is False and theirs['failure_reason']
    assert ours['successful'] is False
    assert ours['failure_reason'] == theirs['failure_reason']
    assert ours['type_description'] == theirs['type_description']


def test_no_service_when_start_type_description_service_is_false(graph):
    quiet = graph['descriptions'][QUIET]
    assert QUIET + '/get_parameters' in quiet['services'], quiet
    assert not quiet['available']
    assert QUIET + '/get_type_description' not in quiet['services']
