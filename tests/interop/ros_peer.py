#!/usr/bin/env python3
"""A real ROS 2 node (rclpy from the Kilted wheels) for interop tests, one process per role.

    ros_peer.py pub TOPIC TYPE JSON [--count N] [--rate HZ] [--qos PROFILE] [--wait-matched N]
    ros_peer.py echo TOPIC TYPE [--count N] [--timeout S] [--qos PROFILE]
    ros_peer.py graph [--wait S] [--expect-node NAME]
    ros_peer.py serialize TYPE JSON          (hex of rclpy's CDR bytes)

Messages go in and out as JSON objects (fields by name, nested objects, lists), so tests can
compare them with what our side printed. `echo` prints one JSON object per line, then exits.
"""
from __future__ import annotations

import argparse
import array
import importlib
import json
import sys
import time
from pathlib import Path
from typing import Any

import rclpy
import rclpy.parameter_client
from rclpy.qos import (DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy,
                       qos_profile_sensor_data)


def message_class(type_name: str) -> type:
    parts = type_name.split('/')
    if len(parts) == 2:
        parts = [parts[0], 'msg', parts[1]]
    package, kind, name = parts
    return getattr(importlib.import_module(f'{package}.{kind}'), name)


def to_plain(value: Any) -> Any:
    """rclpy message -> JSON-able value (what rosidl_runtime_py.message_to_ordereddict does)."""
    if hasattr(value, 'get_fields_and_field_types'):
        return {name: to_plain(getattr(value, name)) for name in value.get_fields_and_field_types()}
    if isinstance(value, (list, tuple, array.array)):
        return [to_plain(item) for item in value]
    if hasattr(value, 'tolist'):  # numpy arrays of fixed-size fields
        return value.tolist()
    if isinstance(value, bytes):
        return list(value)
    return value


def from_plain(message: Any, values: dict) -> Any:
    """Sets fields of an rclpy message from a JSON object (recursively)."""
    types = message.get_fields_and_field_types()
    for name, value in values.items():
        if name not in types:
            raise KeyError(f'{type(message).__name__} has no field {name!r}')
        current = getattr(message, name)
        if hasattr(current, 'get_fields_and_field_types'):
            from_plain(current, value)
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            element_type = types[name].split('<')[1].rstrip('>') if '<' in types[name] else types[name]
            element_type = element_type.split('[')[0]
            cls = message_class(element_type)
            setattr(message, name, [from_plain(cls(), item) for item in value])
        elif types[name] in ('byte', 'sequence<byte>') or types[name].startswith('byte['):
            setattr(message, name, [bytes([v]) for v in value] if isinstance(value, list) else bytes([value]))
        else:
            setattr(message, name, value)
    return message


def make_qos(name: str) -> QoSProfile:
    if name == 'sensor_data':
        return qos_profile_sensor_data
    if name in ('transient_local', 'latched'):
        return QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST,
                          reliability=ReliabilityPolicy.RELIABLE,
                          durability=DurabilityPolicy.TRANSIENT_LOCAL)
    if name == 'keep_all':
        return QoSProfile(depth=1000, history=HistoryPolicy.KEEP_ALL,
                          reliability=ReliabilityPolicy.RELIABLE)
    return QoSProfile(depth=10)


def cmd_pub(args: argparse.Namespace) -> int:
    cls = message_class(args.type)
    text = Path(args.json[1:]).read_text() if args.json.startswith('@') else args.json  # @FILE: large messages
    values = json.loads(text)
    # --list: the JSON is a list of messages, sent in order one per period (all of them by default).
    messages = [from_plain(cls(), v) for v in values] if args.list else [from_plain(cls(), values)]
    if args.list and args.count == 1:
        args.count = len(messages)
    node = rclpy.create_node(args.node)
    publisher = node.create_publisher(cls, args.topic, make_qos(args.qos))
    deadline = time.monotonic() + args.wait
    while publisher.get_subscription_count() < args.wait_matched and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.02)
    period = 1.0 / args.rate if args.rate > 0 else 0.0
    next_time = time.monotonic()
    sent = 0
    while args.count < 0 or sent < args.count:
        message = messages[sent % len(messages)]
        if args.sequence_field:
            setattr(message, args.sequence_field, type(getattr(message, args.sequence_field))(sent))
        publisher.publish(message)
        sent += 1
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    print(json.dumps({'sent': sent}), flush=True)
    end = time.monotonic() + args.linger
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    node.destroy_node()
    return 0


def cmd_echo(args: argparse.Namespace) -> int:
    cls = message_class(args.type)
    node = rclpy.create_node(args.node)
    received: list = []
    node.create_subscription(cls, args.topic, received.append, make_qos(args.qos))
    print(json.dumps({'ready': True}), flush=True)
    deadline = time.monotonic() + args.timeout
    printed = 0
    while (args.count < 0 or printed < args.count) and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
        while received and (args.count < 0 or printed < args.count):
            print(json.dumps(to_plain(received.pop(0))), flush=True)
            printed += 1
    node.destroy_node()
    return 0 if args.count < 0 or printed >= args.count else 3


def cmd_graph(args: argparse.Namespace) -> int:
    node = rclpy.create_node(args.node)
    deadline = time.monotonic() + args.wait
    while time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
        names = [name for name, _ in node.get_node_names_and_namespaces()]
        if args.expect_node and args.expect_node in names:
            break
    topics = node.get_topic_names_and_types()
    result = {
        'nodes': [[name, ns] for name, ns in node.get_node_names_and_namespaces()],
        'topics': {name: types for name, types in topics},
        'publishers': {name: [[i.node_name, i.node_namespace, i.topic_type]
                              for i in node.get_publishers_info_by_topic(name)]
                       for name, _ in topics},
        'subscribers': {name: [[i.node_name, i.node_namespace, i.topic_type]
                               for i in node.get_subscriptions_info_by_topic(name)]
                        for name, _ in topics},
    }
    print(json.dumps(result), flush=True)
    node.destroy_node()
    return 0


def cmd_params(args: argparse.Namespace) -> int:
    """Drives a remote node's parameter services with rclpy's AsyncParameterClient and prints one
    JSON object: {list, get, types, describe, set, events}."""
    from rclpy.parameter import Parameter, parameter_value_to_python
    from rcl_interfaces.msg import ParameterEvent
    node = rclpy.create_node(args.node)
    events: list = []
    node.create_subscription(ParameterEvent, '/parameter_events', events.append, QoSProfile(depth=1000))
    client = rclpy.parameter_client.AsyncParameterClient(node, args.target)
    result: dict = {}
    if not client.wait_for_services(timeout_sec=args.wait):
        print(json.dumps({'error': 'services not ready'}), flush=True)
        return 4

    def call(future):
        rclpy.spin_until_future_complete(node, future, timeout_sec=10.0)
        return future.result()

    def plain(value):  # rclpy gives a byte[] as a list of one-byte bytes: JSON takes their numbers
        value = parameter_value_to_python(value)
        return [v[0] if isinstance(v, bytes) else v for v in value] if isinstance(value, list) else value

    result['list'] = sorted(call(client.list_parameters()).result.names)
    if args.get:
        values = call(client.get_parameters(args.get)).values
        result['get'] = {name: plain(value) for name, value in zip(args.get, values)}
        result['types'] = list(call(client.get_parameter_types(args.get)).types)
        result['describe'] = [{'name': d.name, 'type': d.type, 'read_only': d.read_only}
                              for d in call(client.describe_parameters(args.get)).descriptors]
    if args.set or args.set_sized:
        parameters = []
        for item in args.set:
            name, _, text = item.partition('=')
            parameters.append(Parameter(name, value=json.loads(text)))
        for item in args.set_sized:
            name, _, spec = item.partition('=')
            kind, _, count = spec.partition(':')
            made = {'string': lambda n: 'x' * n, 'integer_array': lambda n: list(range(n)),
                    'string_array': lambda n: ['ab'] * n}[kind](int(count))
            parameters.append(Parameter(name, value=made))
        results = call(client.set_parameters(parameters)).results
        result['set'] = [{'successful': r.successful, 'reason': r.reason} for r in results]
        end = time.monotonic() + 2.0
        while time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.05)
        result['events'] = [{'node': e.node, 'changed': [p.name for p in e.changed_parameters]}
                            for e in events if e.node == args.target]
        if args.get:
            values = call(client.get_parameters(args.get)).values
            result['get_after'] = {name: plain(value) for name, value in zip(args.get, values)}
    print(json.dumps(result), flush=True)
    node.destroy_node()
    return 0


def cmd_tf_pub(args: argparse.Namespace) -> int:
    """Publishes parent -> child transforms like tf2_ros's broadcasters (TFMessage on /tf or
    /tf_static with their QoS), stamped now, from a JSON {"t": [x, y, z], "q": [x, y, z, w]}."""
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage
    node = rclpy.create_node(args.node)
    if args.static:
        qos = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
    else:
        qos = QoSProfile(depth=100)
    publisher = node.create_publisher(TFMessage, '/tf_static' if args.static else '/tf', qos)
    pose = json.loads(args.json)
    end = time.monotonic() + args.seconds
    sent = 0
    while time.monotonic() < end:
        if not args.static or sent == 0:
            t = TransformStamped()
            t.header.stamp = node.get_clock().now().to_msg()
            t.header.frame_id = args.parent
            t.child_frame_id = args.child
            # float(): these wheels serialize an int assigned to a float64 field as integer bits.
            t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = map(float, pose['t'])
            (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
             t.transform.rotation.w) = map(float, pose['q'])
            publisher.publish(TFMessage(transforms=[t]))
            sent += 1
        rclpy.spin_once(node, timeout_sec=1.0 / args.rate)
    print(json.dumps({'sent': sent}), flush=True)
    node.destroy_node()
    return 0


def cmd_tf_echo(args: argparse.Namespace) -> int:
    """Prints the transforms received on /tf or /tf_static as JSON lines."""
    from tf2_msgs.msg import TFMessage
    node = rclpy.create_node(args.node)
    if args.static:
        qos = QoSProfile(depth=100, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
    else:
        qos = QoSProfile(depth=100)
    received: list = []
    node.create_subscription(TFMessage, '/tf_static' if args.static else '/tf', received.append, qos)
    print(json.dumps({'ready': True}), flush=True)
    deadline = time.monotonic() + args.timeout
    printed = 0
    while printed < args.count and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
        while received and printed < args.count:
            message = received.pop(0)
            if args.child and all(t.child_frame_id != args.child for t in message.transforms):
                continue  # another frame's transform (--child filters)
            print(json.dumps(to_plain(message)), flush=True)
            printed += 1
    node.destroy_node()
    return 0 if printed >= args.count else 3


def cmd_param_node(args: argparse.Namespace) -> int:
    """A node with a parameter of every type; after --change-after seconds it sets
    `gain` to 2.5 (a remote change our parameter node must follow)."""
    node = rclpy.create_node(args.node)
    node.declare_parameter('flag', True)
    node.declare_parameter('count', -7)
    node.declare_parameter('gain', args.gain)
    node.declare_parameter('frame', 'ct_scanner')
    node.declare_parameter('bytes', [b'\x01', b'\xff'])
    node.declare_parameter('flags', [True, False, True])
    node.declare_parameter('counts', [1, -2, 3])
    node.declare_parameter('gains', [0.25, 1.5])
    node.declare_parameter('frames', ['base', 'tool'])
    print(json.dumps({'ready': True}), flush=True)
    start = time.monotonic()
    changed = False
    while time.monotonic() - start < args.seconds:
        rclpy.spin_once(node, timeout_sec=0.05)
        if not changed and time.monotonic() - start > args.change_after:
            from rclpy.parameter import Parameter
            node.set_parameters([Parameter('gain', value=2.5)])
            changed = True
    node.destroy_node()
    return 0


def cmd_round_trip(args: argparse.Namespace) -> int:
    """The paper's client: publishes Float64 send times on /round_trip/out at --rate, takes them
    back from /round_trip/back, prints {sent, received, lost, latency_ms: [...]}."""
    from std_msgs.msg import Float64
    node = rclpy.create_node(args.node)
    back: list = []
    node.create_subscription(Float64, '/round_trip/back', lambda m: back.append((time.monotonic(), m.data)),
                             QoSProfile(depth=1000))
    publisher = node.create_publisher(Float64, '/round_trip/out', QoSProfile(depth=1000))
    deadline = time.monotonic() + 20
    while (publisher.get_subscription_count() == 0 or node.count_publishers('/round_trip/back') == 0) \
            and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
    time.sleep(0.5)
    period = 1.0 / args.rate
    next_time = time.monotonic()
    for _ in range(args.count):
        publisher.publish(Float64(data=time.monotonic()))
        next_time += period
        while time.monotonic() < next_time:
            rclpy.spin_once(node, timeout_sec=max(0.0, next_time - time.monotonic()))
    end = time.monotonic() + 2.0
    while len(back) < args.count and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    latencies = sorted(1000 * (received - sent) for received, sent in back)
    print(json.dumps({'sent': args.count, 'received': len(back), 'lost': args.count - len(back),
                      'latency_ms': latencies}), flush=True)
    node.destroy_node()
    return 0


def cmd_pub_raw(args: argparse.Namespace) -> int:
    """Publishes raw bytes (hex) as a message of TYPE: how a peer sends malformed samples."""
    cls = message_class(args.type)
    node = rclpy.create_node(args.node)
    publisher = node.create_publisher(cls, args.topic, QoSProfile(depth=10))
    deadline = time.monotonic() + 10
    while publisher.get_subscription_count() == 0 and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
    for item in args.hex:
        for _ in range(args.count):
            publisher.publish(bytes.fromhex(item))
            time.sleep(0.02)
    time.sleep(0.5)
    print(json.dumps({'sent': args.count * len(args.hex)}), flush=True)
    node.destroy_node()
    return 0


def cmd_serialize(args: argparse.Namespace) -> int:
    from rclpy.serialization import serialize_message
    message = from_plain(message_class(args.type)(), json.loads(args.json))
    print(serialize_message(message).hex())
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node', default='rclpy_peer')
    sub = parser.add_subparsers(dest='command', required=True)
    pub = sub.add_parser('pub')
    pub.add_argument('topic')
    pub.add_argument('type')
    pub.add_argument('json', help='the message as JSON, or @FILE holding it')
    pub.add_argument('--count', type=int, default=1)
    pub.add_argument('--rate', type=float, default=10.0)
    pub.add_argument('--qos', default='default')
    pub.add_argument('--wait', type=float, default=10.0)
    pub.add_argument('--wait-matched', type=int, default=1)
    pub.add_argument('--linger', type=float, default=0.5)
    pub.add_argument('--sequence-field', default='')
    pub.add_argument('--list', action='store_true', help='JSON is a list of messages sent in turn')
    echo = sub.add_parser('echo')
    echo.add_argument('topic')
    echo.add_argument('type')
    echo.add_argument('--count', type=int, default=1)
    echo.add_argument('--timeout', type=float, default=20.0)
    echo.add_argument('--qos', default='default')
    graph = sub.add_parser('graph')
    graph.add_argument('--wait', type=float, default=3.0)
    graph.add_argument('--expect-node', default='')
    ser = sub.add_parser('serialize')
    ser.add_argument('type')
    ser.add_argument('json')
    tf_pub = sub.add_parser('tf_pub')
    tf_pub.add_argument('parent')
    tf_pub.add_argument('child')
    tf_pub.add_argument('json')
    tf_pub.add_argument('--static', action='store_true')
    tf_pub.add_argument('--rate', type=float, default=20.0)
    tf_pub.add_argument('--seconds', type=float, default=10.0)
    tf_echo = sub.add_parser('tf_echo')
    tf_echo.add_argument('--static', action='store_true')
    tf_echo.add_argument('--count', type=int, default=1)
    tf_echo.add_argument('--timeout', type=float, default=20.0)
    tf_echo.add_argument('--child', default='', help='only messages with a transform of this child frame')
    param_node = sub.add_parser('param_node')
    param_node.add_argument('--seconds', type=float, default=20.0)
    param_node.add_argument('--change-after', type=float, default=4.0)
    param_node.add_argument('--gain', type=float, default=0.5)
    round_trip = sub.add_parser('round_trip')
    round_trip.add_argument('--count', type=int, default=100)
    round_trip.add_argument('--rate', type=float, default=50.0)
    pub_raw = sub.add_parser('pub_raw')
    pub_raw.add_argument('topic')
    pub_raw.add_argument('type')
    pub_raw.add_argument('hex', nargs='+')
    pub_raw.add_argument('--count', type=int, default=3)
    params = sub.add_parser('params')
    params.add_argument('target')
    params.add_argument('--get', nargs='*', default=[])
    params.add_argument('--set', nargs='*', default=[])
    params.add_argument('--set-sized', nargs='*', default=[],
                        help='NAME=KIND:COUNT, a value made here (too big for a command line): '
                             'KIND string (COUNT chars), integer_array, string_array (COUNT items)')
    params.add_argument('--wait', type=float, default=15.0)
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'pub': cmd_pub, 'echo': cmd_echo, 'graph': cmd_graph,
                'serialize': cmd_serialize, 'params': cmd_params, 'tf_pub': cmd_tf_pub,
                'tf_echo': cmd_tf_echo, 'param_node': cmd_param_node, 'round_trip': cmd_round_trip,
                'pub_raw': cmd_pub_raw}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
