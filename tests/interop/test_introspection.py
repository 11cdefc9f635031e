"""Introspection parity (issue 19): what `ros2 node info` shows for an rclpy node —
publishers, subscribers, service servers and clients with their types, read through rclpy's
graph API (get_*_names_and_types_by_node), action servers and clients with their types, read
through rclpy.action's get_action_{server,client}_names_and_types_by_node (what `ros2 node info`
calls) — comes out the same for our node, and so do the hidden `<action>/_action/...` topics and
services behind the actions (with their QoS, as `ros2 topic info -v` shows it).

Our node (introspection_runner.py: the VTK-wrapped API's default node /slicer) and an rclpy node
(introspection_peer.py node) create the same endpoints; a third rclpy process queries the graph
for both and the lists are compared: first the endpoints we created, then the ones every rclpy
node has by default (/rosout, /parameter_events, the parameter services), with the node's own
name replaced by `~` so /slicer/get_parameters compares with /rclpy_introspect/get_parameters.

Then the REP 2011 type description service both serve (~/get_type_description): the same rclpy
process asks both nodes for every type they use, with the hash rosidl made for it, and our
answers must equal rclpy's and hash (rosidl's calculate_type_hash) to rosidl's hash; for types
rclpy's node does not serve (the services' _Event messages, an action's Goal/Result/Feedback...)
our answer must be rclpy's refusal.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import BUILD, HERE, REPO, VENV_PYTHON, Ros, _domains

OURS = '/slicer'
QUIET = '/slicer_quiet'  # ours, created with start_type_description_service false
RCLPY = '/rclpy_introspect'
KINDS = ('publishers', 'subscribers', 'services', 'clients', 'action_servers', 'action_clients')
# The hidden endpoints of an action (rcl_action), in the plain topic and service lists.
HIDDEN_ACTION = '/_action/'


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
                           '--types', *DESCRIBED, *NOT_SERVED])
        code, out, err = ros.finish(query, timeout=120)
        assert code == 0 and out.strip(), err
        result['descriptions'] = json.loads(out.strip().splitlines()[-1])
        yield result
    finally:
        ros.close()


def test_rclpy_reference_node_shows_what_it_created(graph):
    theirs, _ = split(graph[RCLPY], RCLPY)
    visible = {kind: {n: t for n, t in listed.items() if HIDDEN_ACTION not in n} for kind, listed in theirs.items()}
    assert visible == {
        'publishers': {'/introspect/chatter': ['std_msgs/msg/String']},
        'subscribers': {'/introspect/pose': ['geometry_msgs/msg/PoseStamped'],
                        '/introspect/image': ['sensor_msgs/msg/Image'],
                        '/introspect/arrays': ['test_msgs/msg/Arrays']},
        'services': {'/introspect/enable': ['std_srvs/srv/SetBool']},
        'clients': {'/introspect/trigger': ['std_srvs/srv/Trigger']},
        'action_servers': {'/introspect/compute': ['test_msgs/action/Fibonacci']},
        'action_clients': {'/introspect/request': ['test_msgs/action/Fibonacci']},
    }
    # rcl_action's hidden endpoints: the server's three services and two publishers, the
    # client's mirror set.
    hidden = {kind: {n: t for n, t in theirs[kind].items() if HIDDEN_ACTION in n} for kind in KINDS[:4]}
    assert hidden == {
        'publishers': {'/introspect/compute/_action/feedback': ['test_msgs/action/Fibonacci_FeedbackMessage'],
                       '/introspect/compute/_action/status': ['action_msgs/msg/GoalStatusArray']},
        'subscribers': {'/introspect/request/_action/feedback': ['test_msgs/action/Fibonacci_FeedbackMessage'],
                        '/introspect/request/_action/status': ['action_msgs/msg/GoalStatusArray']},
        'services': {'/introspect/compute/_action/cancel_goal': ['action_msgs/srv/CancelGoal'],
                     '/introspect/compute/_action/get_result': ['test_msgs/action/Fibonacci_GetResult'],
                     '/introspect/compute/_action/send_goal': ['test_msgs/action/Fibonacci_SendGoal']},
        'clients': {'/introspect/request/_action/cancel_goal': ['action_msgs/srv/CancelGoal'],
                    '/introspect/request/_action/get_result': ['test_msgs/action/Fibonacci_GetResult'],
                    '/introspect/request/_action/send_goal': ['test_msgs/action/Fibonacci_SendGoal']},
    }


@pytest.mark.parametrize('kind', KINDS)
def test_created_endpoints_match_rclpy(graph, kind):
    ours, _ = split(graph[OURS], OURS)
    theirs, _ = split(graph[RCLPY], RCLPY)
    assert ours[kind] == theirs[kind]


def test_ros2_node_info_actions_match_rclpy(graph):
    """What `ros2 node info` lists under Action Servers / Action Clients, and with
    --include-hidden the `_action/` topics and services behind them, for ours as for rclpy's."""
    ours, theirs = graph[OURS], graph[RCLPY]
    assert theirs['action_servers'] and theirs['action_clients']
    for kind in ('action_servers', 'action_clients'):
        assert ours[kind] == theirs[kind], kind
    for kind in KINDS[:4]:
        hidden_ours = {n: t for n, t in ours[kind].items() if HIDDEN_ACTION in n}
        hidden_theirs = {n: t for n, t in theirs[kind].items() if HIDDEN_ACTION in n}
        assert hidden_theirs, kind
        assert hidden_ours == hidden_theirs, kind


def test_action_topic_qos_matches_rclpy(graph):
    """The QoS discovery announces for the action's feedback and status publishers and
    subscriptions (what `ros2 topic info -v` prints), ours as rclpy's."""
    ours, theirs = graph['qos'][OURS], graph['qos'][RCLPY]
    assert sorted(theirs) == [f'{side} {name}' for side, name in (
        ('publisher', '/introspect/compute/_action/feedback'), ('publisher', '/introspect/compute/_action/status'),
        ('subscription', '/introspect/request/_action/feedback'),
        ('subscription', '/introspect/request/_action/status'))]
    assert ours == theirs


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
    # an action server and client: the action type itself (rcl_action registers it), its
    # services' and topics' types.
    'test_msgs/action/Fibonacci', 'test_msgs/action/Fibonacci_SendGoal', 'test_msgs/action/Fibonacci_GetResult',
    'test_msgs/action/Fibonacci_FeedbackMessage', 'action_msgs/srv/CancelGoal', 'action_msgs/msg/GoalStatusArray',
    'test_msgs/msg/Arrays',
)
# Types the same rclpy node answers "not in use" for (checked below: the expectation is rclpy's
# answer): messages a service or action type only nests or synthesizes, such as the _Event
# messages of service introspection (off by default, so no publisher) and an action's
# Goal/Result/Feedback.
NOT_SERVED = (
    'std_srvs/srv/SetBool_Event', 'std_srvs/srv/SetBool_Request', 'action_msgs/srv/CancelGoal_Event',
    'test_msgs/action/Fibonacci_SendGoal_Event', 'test_msgs/action/Fibonacci_GetResult_Event',
    'test_msgs/action/Fibonacci_SendGoal_Request', 'test_msgs/action/Fibonacci_Goal',
    'test_msgs/action/Fibonacci_Result', 'test_msgs/action/Fibonacci_Feedback',
    'action_msgs/msg/GoalStatus', 'action_msgs/msg/GoalInfo', 'unique_identifier_msgs/msg/UUID',
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


@pytest.mark.parametrize('ros_type', DESCRIBED)
def test_our_type_sources_equal_rclpys(graph, ros_type):
    """Asked with include_type_sources, rclpy's node answers the interface file of the type and
    of each type it references, in the description's order (TypeSource: encoding "msg", "srv"
    or "action" with the file's text, "implicit" and no text for what a .srv or .action
    synthesizes); ours answers the same, from the files our generator read."""
    descriptions = graph['descriptions']
    theirs = descriptions[RCLPY]['types'][ros_type]
    ours = descriptions[OURS]['types'][ros_type]
    names = [theirs['type_description']['type_description']['type_name']] + [
        t['type_name'] for t in theirs['type_description']['referenced_type_descriptions']]
    assert [s['type_name'] for s in theirs['sources_asked']] == names
    own = theirs['sources_asked'][0]
    assert own['encoding'] == 'implicit' or own['raw_file_contents'], own  # rclpy serves text
    # Where the peer's distribution installs another text of an interface file than the one we
    # ship (Jazzy's builtin_interfaces Time.msg and Duration.msg comments; none on Kilted), only
    # that entry's text may differ.
    other_text = {name for name in names if peer_file_differs(name)}
    assert other_text <= {'builtin_interfaces/msg/Time', 'builtin_interfaces/msg/Duration'}, other_text
    assert [{**s, 'raw_file_contents': None} if s['type_name'] in other_text else s for s in ours['sources_asked']] \
        == [{**s, 'raw_file_contents': None} if s['type_name'] in other_text else s for s in theirs['sources_asked']]


def peer_file_differs(ros_type: str) -> bool:
    """True when the peer's venv installs `ros_type`'s interface file with another text than
    the one our generator read (msg_specs/, or the generator's fixed_specs/)."""
    package, kind, name = ros_type.split('/')
    relative = Path(package) / kind / f'{name}.{kind}'
    theirs = VENV_PYTHON.parents[1] / 'share' / relative
    ours = next((p for p in (REPO / 'msg_specs' / relative,
                             REPO / 'generator' / 'ros2vtk_gen' / 'fixed_specs' / relative) if p.exists()), None)
    return theirs.exists() and ours is not None and theirs.read_text() != ours.read_text()


# Types in use whose sources carry constants: their own (Log's levels) or a referenced type's
# (GoalStatus's STATUS_* in GoalStatusArray, ParameterType's in ParameterEvent's values).
WITH_CONSTANTS = {
    'rcl_interfaces/msg/Log': 'rcl_interfaces/msg/Log',
    'action_msgs/msg/GoalStatusArray': 'action_msgs/msg/GoalStatus',
    'test_msgs/action/Fibonacci': 'service_msgs/msg/ServiceEventInfo',
}


@pytest.mark.parametrize('ros_type', sorted(WITH_CONSTANTS))
def test_constants_read_from_our_type_sources_are_rclpys(graph, ros_type):
    """A tool lacking the types reads their constants from the sources we serve: rosidl's .msg
    parser (run by the rclpy process on our answer) finds every constant of rclpy's class of
    each type, with its value."""
    constants = graph['descriptions'][OURS]['types'][ros_type]['source_constants']
    assert constants[WITH_CONSTANTS[ros_type]]['rclpy'], constants  # the type has some
    for type_name, found in constants.items():
        assert found['parsed'] == found['rclpy'], type_name


@pytest.mark.parametrize('ros_type', NOT_SERVED)
def test_types_rclpy_does_not_serve_we_do_not_either(graph, ros_type):
    """A type only nested in (or synthesized beside) the types in use is refused by rclpy's
    node (rcl's node type cache holds the endpoints' own types); ours refuses it the same way."""
    descriptions = graph['descriptions']
    theirs = descriptions[RCLPY]['types'][ros_type]
    ours = descriptions[OURS]['types'][ros_type]
    assert theirs['successful'] is False, theirs['type_description']['type_description']['type_name']
    assert ours['successful'] is False, ours['type_description']['type_description']['type_name']
    assert ours['failure_reason'] == theirs['failure_reason']
    assert ours['type_description'] == theirs['type_description']
    assert ours['sources_asked'] == theirs['sources_asked'] == []


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
