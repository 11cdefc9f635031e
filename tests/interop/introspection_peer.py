"""The rclpy side of the introspection parity test (tests/interop/test_introspection.py).

    introspection_peer.py node --node rclpy_introspect [--seconds S]
        an rclpy node with the endpoints of introspection_runner.py (same kinds, names, types);
        prints {"ready": true} once created, then spins for S seconds.
    introspection_peer.py query NODE [NODE ...] [--wait S] [--settle S]
        a third rclpy node that asks rclpy's graph API what `ros2 node info` asks for each NODE
        (a fully qualified name such as /slicer): publishers, subscribers, service servers and
        clients with their types. Waits until every NODE shows its /introspect endpoints (or S
        seconds), then for the lists to stay unchanged for --settle seconds, and prints one JSON
        object {node: {"publishers": {name: [types]}, "subscribers": ..., "services": ...,
        "clients": ...}}.
    introspection_peer.py describe NODE [NODE ...] --types TYPE [TYPE ...] [--wait S]
        calls each NODE's ~/get_type_description (REP 2011) for each TYPE with the hash rosidl
        made for it (share/<pkg>/<msg|srv>/<Type>.json of the venv's wheels), then with a
        well-formed hash of no type and with a malformed one. Prints one JSON object
        {node: {"available": bool, "services": [names], "types": {TYPE: response},
        "unknown": response, "malformed": response}}; a response is the message as plain JSON
        plus "asked_hash" (the hash sent) and "rclpy_hash": rosidl's calculate_type_hash of the
        description it carries.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time

import rclpy
from geometry_msgs.msg import PoseStamped
from rosidl_generator_type_description import calculate_type_hash
from sensor_msgs.msg import Image
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger
from test_msgs.msg import Arrays
from type_description_interfaces.srv import GetTypeDescription

KINDS = {
    'publishers': 'get_publisher_names_and_types_by_node',
    'subscribers': 'get_subscriber_names_and_types_by_node',
    'services': 'get_service_names_and_types_by_node',
    'clients': 'get_client_names_and_types_by_node',
}
# One endpoint per kind, as both nodes create them.
EXPECTED = {
    'publishers': '/introspect/chatter',
    'subscribers': '/introspect/pose',
    'services': '/introspect/enable',
    'clients': '/introspect/trigger',
}


def cmd_node(args: argparse.Namespace) -> int:
    node = rclpy.create_node(args.node)
    node.create_publisher(String, '/introspect/chatter', 10)
    node.create_subscription(PoseStamped, '/introspect/pose', lambda _: None, 10)
    node.create_subscription(Image, '/introspect/image', lambda _: None, 10)
    node.create_subscription(Arrays, '/introspect/arrays', lambda _: None, 10)  # array default values
    node.create_service(SetBool, '/introspect/enable', lambda _, response: response)
    node.create_client(Trigger, '/introspect/trigger')
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    node.destroy_node()
    return 0


def node_info(node, full_name: str) -> dict:
    namespace, _, name = full_name.rpartition('/')
    namespace = namespace or '/'
    info = {}
    for kind, method in KINDS.items():
        try:
            pairs = getattr(node, method)(name, namespace)
        except Exception as error:  # NodeNameNonExistentError while not discovered yet
            return {'error': f'{type(error).__name__}: {error}'}
        info[kind] = {topic: sorted(types) for topic, types in sorted(pairs)}
    return info


def complete(info: dict) -> bool:
    return 'error' not in info and all(EXPECTED[kind] in info[kind] for kind in KINDS)


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
    print(json.dumps(result, sort_keys=True), flush=True)
    node.destroy_node()
    return 0


def rosidl_hash(ros_type: str) -> str:
    """The RIHS01 hash rosidl generated for `ros_type` (pkg/msg/Type or pkg/srv/Type)."""
    package, kind, name = ros_type.split('/')
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


def call(node, client, type_name: str, type_hash: str, wait: float) -> dict:
    request = GetTypeDescription.Request(type_name=type_name, type_hash=type_hash,
                                         include_type_sources=False)
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=wait)
    if not future.done():
        return {'error': 'no response'}
    response = plain(future.result())
    response['asked_hash'] = type_hash
    if response['successful']:
        response['rclpy_hash'] = calculate_type_hash(response['type_description'])
    return response


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
