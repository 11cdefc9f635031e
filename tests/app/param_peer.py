"""An rclpy node for the app's remote-parameter tests, in its own process: declares `gain`
(double, 0.5), refusing negative values with a reason, and two arrays, `ids` (integer[], [1, 2])
and `names` (string[], ['a']); prints one JSON line per accepted
change ({"gain": value}) and {"ready": true} once up; `--slow-first S` answers its first set
request S seconds late (the callback blocks its executor). Runs until terminated."""
from __future__ import annotations

import argparse
import json
import sys
import time

import rclpy
from rcl_interfaces.msg import SetParametersResult


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node', default='tuner')
    parser.add_argument('--slow-first', type=float, default=0.0)
    args = parser.parse_args()
    rclpy.init()
    node = rclpy.create_node(args.node)
    node.declare_parameter('gain', 0.5)
    node.declare_parameter('ids', [1, 2])
    node.declare_parameter('names', ['a'])

    slow = [args.slow_first]

    def check(parameters) -> SetParametersResult:
        if slow[0] > 0:
            time.sleep(slow.pop())
            slow.append(0.0)
        for parameter in parameters:
            if parameter.name == 'gain' and parameter.value < 0:
                return SetParametersResult(successful=False, reason='gain must be >= 0')
        return SetParametersResult(successful=True)

    def report(parameters) -> None:
        for parameter in parameters:
            value = parameter.value
            print(json.dumps({parameter.name: list(value) if not isinstance(value, (str, float, int, bool)) else value}),
                  flush=True)
    node.add_on_set_parameters_callback(check)
    node.add_post_set_parameters_callback(report)
    print(json.dumps({'ready': True}), flush=True)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, rclpy.executors.ExternalShutdownException):
        pass
    return 0


if __name__ == '__main__':
    sys.exit(main())
