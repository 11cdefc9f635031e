"""The rclpy side of the introspection parity test (tests/interop/test_introspection.py).

    introspection_peer.py node --node rclpy_introspect [--seconds S]
        an rclpy node with the endpoints of introspection_runner.py (same kinds, names, types),
        action server and client included; prints {"ready": true} once created, then spins for
        S seconds.
    introspection_peer.py query NODE [NODE ...] [--wait S] [--settle S]
        a third rclpy node that asks rclpy's graph API what `ros2 node info` asks for each NODE
        (a fully qualified name such as /slicer): publishers, subscribers, service servers and
        clients with their types (rclpy.Node.get_*_names_and_types_by_node), action servers and
        clients with their types (rclpy.action.get_action_*_names_and_types_by_node, what
        `ros2 node info` calls). Waits until every NODE shows its /introspect endpoints (or S
        seconds), then for the lists to stay unchanged for --settle seconds, and prints one JSON
        object {node: {"publishers": {name: [types]}, "subscribers": ..., "services": ...,
        "clients": ..., "action_servers": ..., "action_clients": ...}, "qos": {node: {"publisher
        <topic>": [qos]...}}} (the QoS of the node's endpoints on hidden `_action/` topics).
    introspection_peer.py describe NODE [NODE ...] --types TYPE [TYPE ...] [--wait S]
        calls each NODE's ~/get_type_description (REP 2011) for each TYPE with the hash rosidl
        made for it (share/<pkg>/<msg|srv|action>/<Type>.json of the venv's wheels; the types
        rosidl synthesizes, such as pkg/srv/X_Event or pkg/action/X_SendGoal, are in X.json), then with a
        well-formed hash of no type and with a malformed one. Prints one JSON object
        {node: {"available": bool, "services": [names], "types": {TYPE: response},
        "unknown": response, "malformed": response}}; a response is the message as plain JSON
        plus "asked_hash" (the hash sent), "rclpy_hash": rosidl's calculate_type_hash of the
        description it carries, and "sources_asked": the type_sources of the same request with
        include_type_sources true and "source_constants" (see source_constants()).
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import sys
import time

import rclpy
from rclpy.action import (ActionClient, ActionServer, get_action_client_names_and_types_by_node,
                          get_action_server_names_and_types_by_node)
from geometry_msgs.msg import PoseStamped
from rosidl_adapter.parser import parse_message_string
from rosidl_generator_type_description import calculate_type_hash
from sensor_msgs.msg import Image
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger
from test_msgs.action import Fibonacci
from test_msgs.msg import Arrays
from type_description_interfaces.srv import GetTypeDescription

KINDS = {
    'publishers': 'get_publisher_names_and_types_by_node',
    'subscribers': 'get_subscriber_names_and_types_by_node',
    'services': 'get_service_names_and_types_by_node',
    'clients': 'get_client_names_and_types_by_node',
}
# What `ros2 node info` (ros2node.api) asks rclpy.action for.
ACTION_KINDS = {
    'action_servers': get_action_server_names_and_types_by_node,
    'action_clients': get_action_client_names_and_types_by_node,
}
# One endpoint per kind, as both nodes create them.
EXPECTED = {
    'publishers': '/introspect/chatter',
    'subscribers': '/introspect/pose',
    'services': '/introspect/enable',
    'clients': '/introspect/trigger',
    'action_servers': '/introspect/compute',
    'action_clients': '/introspect/request',
}


def cmd_node(args: argparse.Namespace) -> int:
    node = rclpy.create_node(args.node)
    node.create_publisher(String, '/introspect/chatter', 10)
    node.create_subscription(PoseStamped, '/introspect/pose', lambda _: None, 10)
    node.create_subscription(Image, '/introspect/image', lambda _: None, 10)
    node.create_subscription(Arrays, '/introspect/arrays', lambda _: None, 10)  # array default values
    node.create_service(SetBool, '/introspect/enable', lambda _, response: response)
    node.create_client(Trigger, '/introspect/trigger')
    # Never asked for a goal: the server only needs to exist (the execute callback is unused).
    server = ActionServer(node, Fibonacci, '/introspect/compute', lambda handle: Fibonacci.Result())
    client = ActionClient(node, Fibonacci, '/introspect/request')
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    client.destroy()
    server.destroy()
    node.destroy_node()
    return 0


def node_info(node, full_name: str) -> dict:
    namespace, _, name = full_name.rpartition('/')
    namespace = namespace or '/'
    info = {}
    queries = {kind: (lambda method=method: getattr(node, method)(name, namespace)) for kind, method in KINDS.items()}
    queries.update({kind: (lambda function=function: function(node, name, namespace))
                    for kind, function in ACTION_KINDS.items()})
    for kind, query in queries.items():
        try:
            pairs = query()
        except Exception as error:  # NodeNameNonExistentError while not discovered yet
            return {'error': f'{type(error).__name__}: {error}'}
        info[kind] = {topic: sorted(types) for topic, types in sorted(pairs)}
    return info


def action_topic_qos(node, full_name: str, info: dict) -> dict:
    """The QoS `ros2 topic info -v` prints for the node's endpoints on its actions' hidden
    topics (<action>/_action/feedback, status): {"publisher <topic>": [qos], ...}, as discovery
    announced them (history and depth are not announced: UNKNOWN and 0 for remote endpoints)."""
    namespace, _, name = full_name.rpartition('/')
    namespace = namespace or '/'
    result = {}
    for side, kind, method in (('publisher', 'publishers', node.get_publishers_info_by_topic),
                               ('subscription', 'subscribers', node.get_subscriptions_info_by_topic)):
        for topic in info[kind]:
            if '/_action/' not in topic:
                continue
            profiles = []
            for endpoint in method(topic):
                if endpoint.node_name != name or endpoint.node_namespace != namespace:
                    continue
                qos = endpoint.qos_profile
                profiles.append({
                    'type': endpoint.topic_type,
                    # the USER_DATA typehash (`ros2 topic info -v`: "Topic type hash"); Jazzy
                    # rclpy reports it too.
                    'type_hash': str(endpoint.topic_type_hash),
                    'reliability': qos.reliability.name, 'durability': qos.durability.name,
                    'history': qos.history.name, 'depth': qos.depth,
                    'liveliness': qos.liveliness.name,
                    'deadline_ns': qos.deadline.nanoseconds, 'lifespan_ns': qos.lifespan.nanoseconds,
                    'liveliness_lease_duration_ns': qos.liveliness_lease_duration.nanoseconds,
                })
            result[f'{side} {topic}'] = sorted(profiles, key=json.dumps)
    return result


def complete(info: dict) -> bool:
    return 'error' not in info and all(name in info[kind] for kind, name in EXPECTED.items())


def cmd_query(args: argparse.Namespace) -> int:
    node = rclpy.create_node(args.node)
    deadline = time.monotonic() + args.wait
    result: dict = {}
    stable_since = None
    while time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.1)
        now = {target: node_info(node, target) for target in args.targets}
        if now != result:
            result, stable_since = now, time.monotonic()
        if (all(complete(info) for info in result.values())
                and time.monotonic() - stable_since >= args.settle):
            break
    result['qos'] = {target: action_topic_qos(node, target, info) for target, info in result.items()
                     if 'error' not in info}
    print(json.dumps(result, sort_keys=True), flush=True)
    node.destroy_node()
    return 0


def rosidl_hash(ros_type: str) -> str:
    """The RIHS01 hash rosidl generated for `ros_type` (pkg/msg/Type, pkg/srv/Type,
    pkg/action/Type, or a type rosidl synthesizes: pkg/srv/X_Event, pkg/action/X_SendGoal...,
    found in X.json beside X's own)."""
    package, kind, name = ros_type.split('/')
    # rosidl type names are PascalCase, without underscores: X_SendGoal_Request is in X.json.
    name = name.split('_')[0]
    # The wheels install share/ into the venv; a sourced ROS install lists its prefixes.
    prefixes = [sys.prefix] + os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep)
    path = next(p for p in (os.path.join(prefix, 'share', package, kind, name + '.json') for prefix in prefixes)
                if os.path.exists(p))
    with open(path) as stream:
        hashes = json.load(stream)['type_hashes']
    return next(h['hash_string'] for h in hashes if h['type_name'] == ros_type)


def plain(value):
    """A message as plain JSON (fields in declaration order)."""
    if hasattr(value, 'get_fields_and_field_types'):
        return {name: plain(getattr(value, name)) for name in value.get_fields_and_field_types()}
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    return value


def ask(node, client, type_name: str, type_hash: str, wait: float, sources: bool):
    request = GetTypeDescription.Request(type_name=type_name, type_hash=type_hash,
                                         include_type_sources=sources)
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=wait)
    return future.result() if future.done() else None


def call(node, client, type_name: str, type_hash: str, wait: float) -> dict:
    """The response without type sources, plus under "sources_asked" the type_sources of a
    second request with include_type_sources true."""
    result = ask(node, client, type_name, type_hash, wait, sources=False)
    if result is None:
        return {'error': 'no response'}
    response = plain(result)
    response['asked_hash'] = type_hash
    if response['successful']:
        response['rclpy_hash'] = calculate_type_hash(response['type_description'])
    with_sources = ask(node, client, type_name, type_hash, wait, sources=True)
    response['sources_asked'] = plain(with_sources.type_sources) if with_sources else 'no response'
    if with_sources:
        response['source_constants'] = source_constants(with_sources.type_sources)
    return response


def source_constants(sources) -> dict:
    """What a ROS 2 tool that lacks the types learns of their constants from the sources:
    {type_name: {"parsed": {NAME: value}, "rclpy": {NAME: value}}} for every "msg" source,
    "parsed" by rosidl_adapter's .msg parser (what rosidl reads .msg files with), "rclpy" the
    constants of rclpy's own class of the type (its metaclass's table), for comparison."""
    result = {}
    for source in sources:
        if source.encoding != 'msg':
            continue
        package, _, name = source.type_name.split('/')
        spec = parse_message_string(package, name, source.raw_file_contents)
        metaclass = type(getattr(importlib.import_module(f'{package}.msg'), name))
        result[source.type_name] = {
            'parsed': {c.name: plain_constant(c.value) for c in spec.constants},
            'rclpy': {name: plain_constant(value) for name, value in
                      getattr(metaclass, f'_{metaclass.__name__}__constants').items()},
        }
    return result


def plain_constant(value):
    """A constant as JSON holds it: rclpy keeps a byte constant as bytes (b'\\n'), its integer."""
    return value[0] if isinstance(value, bytes) else value


def cmd_describe(args: argparse.Namespace) -> int:
    node = rclpy.create_node(args.node)
    result = {}
    for target in args.targets:
        namespace, _, name = target.rpartition('/')
        # Discovered once its parameter services show (every node of ours and rclpy's has them).
        deadline = time.monotonic() + args.wait
        services: list = []
        while time.monotonic() < deadline:
            rclpy.spin_once(node, timeout_sec=0.1)
            try:
                services = sorted(n for n, _ in node.get_service_names_and_types_by_node(name, namespace or '/'))
            except Exception:  # NodeNameNonExistentError while not discovered yet
                continue
            if target + '/get_parameters' in services:
                break
        time.sleep(1.0)  # the rest of its services (announced together) settle
        rclpy.spin_once(node, timeout_sec=0.1)
        try:
            services = sorted(n for n, _ in node.get_service_names_and_types_by_node(name, namespace or '/'))
        except Exception:  # never discovered
            services = []
        client = node.create_client(GetTypeDescription, target + '/get_type_description')
        available = target + '/get_type_description' in services and client.wait_for_service(timeout_sec=10)
        entry = {'available': available, 'services': services}
        if available:
            entry['types'] = {t: call(node, client, t, rosidl_hash(t), args.wait) for t in args.types}
            entry['unknown'] = call(node, client, 'std_msgs/msg/String', 'RIHS01_' + '0' * 64, args.wait)
            entry['malformed'] = call(node, client, 'std_msgs/msg/String', 'not a hash', args.wait)
        node.destroy_client(client)
        result[target] = entry
    print(json.dumps(result, sort_keys=True), flush=True)
    node.destroy_node()
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node', default='introspect_query')
    sub = parser.add_subparsers(dest='command', required=True)
    serve = sub.add_parser('node')
    serve.add_argument('--seconds', type=float, default=40.0)
    query = sub.add_parser('query')
    query.add_argument('targets', nargs='+')
    query.add_argument('--wait', type=float, default=30.0)
    query.add_argument('--settle', type=float, default=2.0)
    describe = sub.add_parser('describe')
    describe.add_argument('targets', nargs='+')
    describe.add_argument('--types', nargs='+', required=True)
    describe.add_argument('--wait', type=float, default=20.0)
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'node': cmd_node, 'query': cmd_query, 'describe': cmd_describe}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
