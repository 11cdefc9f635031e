"""Action goal -> result latency, one goal at a time (test_msgs/action/Fibonacci, order 1: the
server succeeds at once, so the time is the protocol's: SendGoal request and response, the
GetResult request and response, the status update). Two clients in one file, run by different
Pythons: `rclpy` (the venv's rclpy ActionClient, the baseline) and `ours` (vtkROS2ActionClientNode
through the VTK wrapping, Debian's python3 with <build>/python on PYTHONPATH). The servers are the
interop peers (tests/interop/action_peer.py, action_runner.py). Prints {"ready": ...}, then one
object with the per-goal times in ms.

    action_bench.py rclpy /bench_fibonacci --count 500
    action_bench.py ours /bench_fibonacci --count 500
"""
from __future__ import annotations

import argparse
import json
import sys
import time


def rclpy_client(args) -> int:
    import rclpy
    from rclpy.action import ActionClient
    from test_msgs.action import Fibonacci

    rclpy.init()
    node = rclpy.create_node('rclpy_action_bench')
    client = ActionClient(node, Fibonacci, args.name)
    ready = client.wait_for_server(timeout_sec=args.wait)
    print(json.dumps({'ready': ready}), flush=True)
    latencies: list[float] = []
    failed = 0
    for _ in range(args.count if ready else 0):
        start = time.perf_counter()
        goal = client.send_goal_async(Fibonacci.Goal(order=args.order))
        rclpy.spin_until_future_complete(node, goal, timeout_sec=args.timeout)
        handle = goal.result() if goal.done() else None
        if handle is None or not handle.accepted:
            failed += 1
            continue
        result = handle.get_result_async()
        rclpy.spin_until_future_complete(node, result, timeout_sec=args.timeout)
        if result.done() and result.result().status == 4:  # GoalStatus.STATUS_SUCCEEDED
            latencies.append((time.perf_counter() - start) * 1e3)
        else:
            failed += 1
    print(json.dumps({'succeeded': len(latencies), 'failed': failed, 'latency_ms': latencies}), flush=True)
    client.destroy()
    node.destroy_node()
    rclpy.shutdown()
    return 0


def ours_client(args) -> int:
    import ros2vtk

    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    client = node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', args.name)
    ready = ros2vtk.spin_until(logic, client.IsServerReady, seconds=args.wait)
    print(json.dumps({'ready': bool(ready)}), flush=True)
    latencies: list[float] = []
    failed = 0
    goal = f'order: {args.order}'
    for _ in range(args.count if ready else 0):
        start = time.perf_counter()
        client.SendGoalAndWait(goal, args.timeout)
        if client.GetStatusAsString() == 'succeeded':
            latencies.append((time.perf_counter() - start) * 1e3)
        else:
            failed += 1
    print(json.dumps({'succeeded': len(latencies), 'failed': failed, 'latency_ms': latencies,
                      'last_status': client.GetStatusAsString()}), flush=True)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('client', choices=['rclpy', 'ours'])
    parser.add_argument('name')
    parser.add_argument('--count', type=int, default=100)
    parser.add_argument('--order', type=int, default=1)
    parser.add_argument('--timeout', type=float, default=5.0)
    parser.add_argument('--wait', type=float, default=20.0, help='seconds to wait for the server')
    args = parser.parse_args()
    return rclpy_client(args) if args.client == 'rclpy' else ours_client(args)


if __name__ == '__main__':
    sys.exit(main())
