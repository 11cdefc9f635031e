"""An rclpy action server or client for test_msgs/action/Fibonacci in its own process: the real
ROS 2 peer of the action interop tests (test_scene_actions.py). Prints JSON lines: {"ready": true}
once serving (or once the server was found), then one result object.

    action_peer.py server /fibonacci --step 0.1 --max-order 20 --seconds 20
    action_peer.py client /fibonacci 5 --cancel-after 2

The server is rclpy's Fibonacci example: it starts from [0, 1], appends one number per step
(publishing the sequence so far as feedback after each), and succeeds with the sequence; it
rejects goals with order above --max-order and accepts every cancel request.
"""
from __future__ import annotations

import argparse
import json
import sys
import threading
import time

import rclpy
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from test_msgs.action import Fibonacci


def cmd_server(args) -> int:
    node = rclpy.create_node(args.node)
    counts = {'goals': 0, 'rejected': 0, 'canceled': 0, 'succeeded': 0, 'orders': []}

    def on_goal(goal_request):
        counts['orders'].append(goal_request.order)
        if goal_request.order > args.max_order:
            counts['rejected'] += 1
            return GoalResponse.REJECT
        counts['goals'] += 1
        return GoalResponse.ACCEPT

    def on_cancel(_goal_handle):
        return CancelResponse.ACCEPT

    def execute(goal_handle):
        sequence = [0, 1]
        feedback = Fibonacci.Feedback()
        for i in range(1, goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                counts['canceled'] += 1
                return Fibonacci.Result(sequence=sequence)
            sequence.append(sequence[i] + sequence[i - 1])
            feedback.sequence = sequence
            goal_handle.publish_feedback(feedback)
            time.sleep(args.step)
        goal_handle.succeed()
        counts['succeeded'] += 1
        return Fibonacci.Result(sequence=sequence)

    ActionServer(node, Fibonacci, args.name, execute_callback=execute, goal_callback=on_goal,
                 cancel_callback=on_cancel, callback_group=ReentrantCallbackGroup())
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        executor.spin_once(timeout_sec=0.05)
    print(json.dumps(counts), flush=True)
    executor.shutdown()
    node.destroy_node()
    return 0


def cmd_client(args) -> int:
    node = rclpy.create_node(args.node)
    client = ActionClient(node, Fibonacci, args.name)
    if not client.wait_for_server(timeout_sec=args.wait):
        print(json.dumps({'ready': False}), flush=True)
        return 1
    print(json.dumps({'ready': True}), flush=True)
    feedbacks = []
    future = client.send_goal_async(Fibonacci.Goal(order=args.order),
                                    feedback_callback=lambda m: feedbacks.append(list(m.feedback.sequence)))
    rclpy.spin_until_future_complete(node, future, timeout_sec=args.timeout)
    handle = future.result() if future.done() else None
    if handle is None or not handle.accepted:
        print(json.dumps({'accepted': False if handle is not None else None}), flush=True)
        return 0
    cancel = None
    if args.cancel_after:
        end = time.monotonic() + args.timeout
        while len(feedbacks) < args.cancel_after and time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.05)
        cancel_future = handle.cancel_goal_async()
        rclpy.spin_until_future_complete(node, cancel_future, timeout_sec=args.timeout)
        cancel = cancel_future.result().return_code if cancel_future.done() else None
    result_future = handle.get_result_async()
    rclpy.spin_until_future_complete(node, result_future, timeout_sec=args.timeout)
    result = result_future.result() if result_future.done() else None
    again = None
    if args.result_again_after:
        # Ask for the same goal's result once more, later (a server expires finished goals after
        # its result timeout: rcl then answers STATUS_UNKNOWN).
        end = time.monotonic() + args.result_again_after
        while time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.05)
        again_future = handle.get_result_async()
        rclpy.spin_until_future_complete(node, again_future, timeout_sec=args.timeout)
        again = again_future.result().status if again_future.done() else None
    print(json.dumps({'accepted': True, 'feedbacks': feedbacks, 'cancel_return_code': cancel,
                      'status': result.status if result else None,
                      'sequence': list(result.result.sequence) if result else None,
                      'status_asked_again': again}), flush=True)
    client.destroy()
    node.destroy_node()
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node', default='rclpy_action_peer')
    sub = parser.add_subparsers(dest='command', required=True)
    server = sub.add_parser('server')
    server.add_argument('name')
    server.add_argument('--seconds', type=float, default=20.0)
    server.add_argument('--step', type=float, default=0.05, help='seconds per Fibonacci step')
    server.add_argument('--max-order', type=int, default=40, help='goals above are rejected')
    client = sub.add_parser('client')
    client.add_argument('name')
    client.add_argument('order', type=int)
    client.add_argument('--cancel-after', type=int, default=0, help='cancel after this many feedbacks')
    client.add_argument('--timeout', type=float, default=10.0)
    client.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the server')
    client.add_argument('--result-again-after', type=float, default=0.0,
                        help='ask for the result again after this many seconds')
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'server': cmd_server, 'client': cmd_client}[args.command](args)
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
