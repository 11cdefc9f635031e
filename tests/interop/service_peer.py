"""An rclpy service server or client in its own process: the real ROS 2 peer of the service
interop tests (test_scene_services.py). Prints JSON lines: {"ready": true} once serving or once
the server was found, then one result object.

    service_peer.py server std_srvs/srv/SetBool /enable --seconds 20 [--delay 3]
    service_peer.py client std_srvs/srv/SetBool /enable '{"data": true}' --count 1000
"""
from __future__ import annotations

import argparse
import importlib
import json
import sys
import time

import rclpy

from ros_peer import from_plain, to_plain

# What the rclpy server answers per service type (the test checks these values on our side).
PARAMETER_VALUES = {  # name -> (ParameterType id, field, value) for GetParameters
    'flag': (1, 'bool_value', True),
    'count': (2, 'integer_value', -7),
    'gain': (3, 'double_value', 0.5),
    'frame': (4, 'string_value', 'ct_scanner'),
    'bytes': (5, 'byte_array_value', [b'\x01', b'\xff']),
    'flags': (6, 'bool_array_value', [True, False, True]),
    'counts': (7, 'integer_array_value', [1, -2, 3]),
    'gains': (8, 'double_array_value', [0.25, 1.5]),
    'frames': (9, 'string_array_value', ['base', 'tool']),
}


def service_class(type_name: str) -> type:
    package, kind, name = type_name.split('/') if type_name.count('/') == 2 else (*type_name.split('/'), None)
    return getattr(importlib.import_module(f'{package}.srv'), name or kind)


def answer(type_name: str, request, response, served: int):
    if type_name == 'std_srvs/srv/SetBool':
        response.success = request.data
        response.message = f'rclpy set {request.data}'
    elif type_name == 'std_srvs/srv/Trigger':
        response.success = True
        response.message = f'rclpy triggered {served}'
    elif type_name == 'rcl_interfaces/srv/GetParameters':
        from rcl_interfaces.msg import ParameterValue
        for name in request.names:
            value = ParameterValue()
            if name in PARAMETER_VALUES:
                value.type, field, content = PARAMETER_VALUES[name]
                setattr(value, field, content)
            response.values.append(value)
    elif type_name == 'rcl_interfaces/srv/SetParameters':
        from rcl_interfaces.msg import SetParametersResult
        for parameter in request.parameters:
            response.results.append(SetParametersResult(
                successful=parameter.value.type != 0, reason=f'{parameter.name}:{parameter.value.type}'))
    return response


def cmd_server(args) -> int:
    cls = service_class(args.type)
    node = rclpy.create_node(args.node)
    served = [0]

    def callback(request, response):
        served[0] += 1
        if args.delay:
            time.sleep(args.delay)
        return answer(args.type, request, response, served[0])

    node.create_service(cls, args.name, callback)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end and (not args.count or served[0] < args.count):
        rclpy.spin_once(node, timeout_sec=0.05)
    time.sleep(0.3)  # the last reply leaves before the process does
    print(json.dumps({'served': served[0]}), flush=True)
    node.destroy_node()
    return 0


def cmd_client(args) -> int:
    cls = service_class(args.type)
    node = rclpy.create_node(args.node)
    client = node.create_client(cls, args.name)
    if not client.wait_for_service(timeout_sec=args.wait):
        print(json.dumps({'ready': False}), flush=True)
        return 1
    print(json.dumps({'ready': True}), flush=True)
    request = from_plain(cls.Request(), json.loads(args.json))
    responses, failed, latencies = [], 0, []
    for _ in range(args.count):
        start = time.perf_counter()
        future = client.call_async(request)
        rclpy.spin_until_future_complete(node, future, timeout_sec=args.timeout)
        if future.done() and future.result() is not None:
            latencies.append((time.perf_counter() - start) * 1e3)
            responses.append(to_plain(future.result()))
        else:
            client.remove_pending_request(future)
            failed += 1
    print(json.dumps({'received': len(responses), 'failed': failed,
                      'first': responses[0] if responses else None,
                      'last': responses[-1] if responses else None,
                      'distinct': len({json.dumps(r, sort_keys=True) for r in responses}),
                      'latency_ms': latencies}), flush=True)
    node.destroy_node()
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node', default='rclpy_service_peer')
    sub = parser.add_subparsers(dest='command', required=True)
    server = sub.add_parser('server')
    server.add_argument('type')
    server.add_argument('name')
    server.add_argument('--seconds', type=float, default=20.0)
    server.add_argument('--delay', type=float, default=0.0, help='seconds each answer takes')
    server.add_argument('--count', type=int, default=0, help='stop after this many requests')
    client = sub.add_parser('client')
    client.add_argument('type')
    client.add_argument('name')
    client.add_argument('json')
    client.add_argument('--count', type=int, default=1)
    client.add_argument('--timeout', type=float, default=5.0)
    client.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the server')
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'server': cmd_server, 'client': cmd_client}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
