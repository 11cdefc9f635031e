"""The crowded ROS graph of the scale benchmark, in one rclpy process (Kilted wheels):

    scale_peer.py graph --nodes 50 --topics-per-node 10      # 50 nodes, 500 std_msgs/String topics at 1 Hz
    scale_peer.py stream --topics 100 --rate 100               # one node, 100 topics at 100 Hz each
    scale_peer.py observe --nodes 50 --topics 500              # the baseline: an rclpy node joining the graph

graph and stream print {"ready": true} once every publisher exists and run until killed.
observe prints {"discovery_ms": ...}: from its node's creation until rclpy's graph API lists every
/scale_ node and topic (what ours measures in bench_scale).
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import String


def cmd_graph(args) -> int:
    nodes = [rclpy.create_node(f'scale_node_{n}') for n in range(args.nodes)]
    publishers = [node.create_publisher(String, f'/scale_{n}_topic_{t}', 10)
                  for n, node in enumerate(nodes) for t in range(args.topics_per_node)]
    executor = SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    message = String(data='x')
    print(json.dumps({'ready': True, 'nodes': len(nodes), 'topics': len(publishers)}), flush=True)
    next_publish = time.monotonic()
    while True:
        executor.spin_once(timeout_sec=0.1)
        if time.monotonic() >= next_publish:
            next_publish += 1.0
            for publisher in publishers:
                publisher.publish(message)


def cmd_stream(args) -> int:
    node = rclpy.create_node('scale_stream')
    publishers = [node.create_publisher(String, f'/scale_stream_{t}', 10) for t in range(args.topics)]
    message = String(data='stream')
    period = 1.0 / args.rate
    print(json.dumps({'ready': True, 'topics': len(publishers)}), flush=True)
    sent = 0
    next_tick = time.monotonic()
    while True:
        for publisher in publishers:
            publisher.publish(message)
        sent += len(publishers)
        next_tick += period
        delay = next_tick - time.monotonic()
        if delay > 0:
            time.sleep(delay)


def cmd_observe(args) -> int:
    start = time.perf_counter()
    node = rclpy.create_node('scale_observer')
    deadline = time.monotonic() + args.wait
    nodes = topics = 0
    while time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.01)
        topics = sum(1 for name, _ in node.get_topic_names_and_types() if name.startswith('/scale_'))
        nodes = sum(1 for name in node.get_node_names() if name.startswith('scale_node_'))
        if topics >= args.topics and nodes >= args.nodes:
            break
    elapsed = (time.perf_counter() - start) * 1e3
    print(json.dumps({'discovery_ms': elapsed, 'nodes_seen': nodes, 'topics_seen': topics}), flush=True)
    node.destroy_node()
    return 0 if topics >= args.topics and nodes >= args.nodes else 1


def main() -> int:
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest='command', required=True)
    graph = sub.add_parser('graph')
    graph.add_argument('--nodes', type=int, default=50)
    graph.add_argument('--topics-per-node', type=int, default=10)
    stream = sub.add_parser('stream')
    stream.add_argument('--topics', type=int, default=100)
    stream.add_argument('--rate', type=float, default=100.0)
    observe = sub.add_parser('observe')
    observe.add_argument('--nodes', type=int, default=50)
    observe.add_argument('--topics', type=int, default=500)
    observe.add_argument('--wait', type=float, default=60.0)
    args = parser.parse_args()
    rclpy.init()
    try:
        return {'graph': cmd_graph, 'stream': cmd_stream, 'observe': cmd_observe}[args.command](args)
    except KeyboardInterrupt:
        return 0


if __name__ == '__main__':
    sys.exit(main())
