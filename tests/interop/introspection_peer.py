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
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger

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
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'node': cmd_node, 'query': cmd_query}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
