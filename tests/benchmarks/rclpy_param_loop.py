#!/usr/bin/env python3
"""rclpy's side of the robot load-time benchmark (run_benchmarks.py robot_load_traffic):

    rclpy_param_loop.py serve URDF        a /robot_state_publisher node holding robot_description
    rclpy_param_loop.py load [--loads N] [--new-context]
                                          the baseline: what ours does per load (robot_load_loop.py),
                                          in rclpy: a client of /robot_state_publisher/get_parameters,
                                          wait_for_service, get robot_description; one JSON line per load
    rclpy_param_loop.py churn             other traffic: a node joins and leaves the graph every 0.5 s

serve and churn print {"ready": true} and run until killed.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from rcl_interfaces.srv import GetParameters


def cmd_serve(args) -> int:
    rclpy.init()
    node = rclpy.create_node('robot_state_publisher')
    node.declare_parameter('robot_description', open(args.urdf, encoding='utf-8').read())
    print(json.dumps({'ready': True}), flush=True)
    rclpy.spin(node)
    return 0


def load_once(node, timeout: float) -> dict:
    start = time.monotonic()
    client = node.create_client(GetParameters, '/robot_state_publisher/get_parameters')
    marks: dict = {}
    if client.wait_for_service(timeout_sec=timeout):
        marks['available'] = time.monotonic() - start
        future = client.call_async(GetParameters.Request(names=['robot_description']))
        rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
        if future.done() and future.result().values:
            marks['loaded'] = time.monotonic() - start
    node.destroy_client(client)
    return marks


def cmd_load(args) -> int:
    rclpy.init()
    node = rclpy.create_node('rclpy_param_loop')
    print(json.dumps({'ready': True}), flush=True)
    for index in range(args.loads):
        if args.new_context and index:
            node.destroy_node()
            rclpy.shutdown()
            rclpy.init()
        start = time.monotonic()
        if args.new_context and index:
            node = rclpy.create_node('rclpy_param_loop')  # the participant is created here
        created = time.monotonic() - start
        # Counted from before the node's creation, as robot_load_loop.py counts from its new participant.
        marks = {k: v + created for k, v in load_once(node, args.timeout).items()}
        print(json.dumps({'load': index, 'available': marks.get('available'), 'loaded': marks.get('loaded')}),
              flush=True)
        time.sleep(args.pause)
    node.destroy_node()
    rclpy.try_shutdown()
    return 0


def cmd_churn(args) -> int:
    print(json.dumps({'ready': True}), flush=True)
    index = 0
    while True:
        context = rclpy.Context()
        rclpy.init(context=context)
        node = rclpy.create_node(f'churn_{index}', context=context)
        publisher = node.create_publisher(GetParameters.Request, f'/churn_{index}', 10)
        end = time.monotonic() + 0.5
        while time.monotonic() < end:
            publisher.publish(GetParameters.Request(names=['x']))
            time.sleep(0.05)
        node.destroy_node()
        rclpy.shutdown(context=context)
        index += 1


def main() -> int:
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest='command', required=True)
    serve = sub.add_parser('serve')
    serve.add_argument('urdf')
    load = sub.add_parser('load')
    load.add_argument('--loads', type=int, default=50)
    load.add_argument('--new-context', action='store_true', help='each load in a new context (participant)')
    load.add_argument('--timeout', type=float, default=60.0)
    load.add_argument('--pause', type=float, default=0.05)
    sub.add_parser('churn')
    args = parser.parse_args()
    return {'serve': cmd_serve, 'load': cmd_load, 'churn': cmd_churn}[args.command](args)


if __name__ == '__main__':
    sys.exit(main())
