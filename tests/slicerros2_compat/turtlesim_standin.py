#!/usr/bin/env python3
"""A stand-in for turtlesim (which SlicerROS2's Python tests start with `ros2 run turtlesim
turtlesim_node`): an rclpy node named /turtlesim with turtlesim's three integer parameters
(background_r/g/b = 69, 86, 255) and a /spawn service that answers "turtle2".

turtlesim has no wheel on PyPI, so /spawn is a std_srvs/srv/Trigger here: the reply's `message`
carries the name turtlesim's Spawn would return. Prints {"ready": true} once serving, then runs
until it is killed (as turtlesim does)."""
from __future__ import annotations

import json
import sys

import rclpy
from std_srvs.srv import Trigger


def main() -> int:
    rclpy.init()
    node = rclpy.create_node('turtlesim')
    node.declare_parameter('background_r', 69)
    node.declare_parameter('background_g', 86)
    node.declare_parameter('background_b', 255)
    spawned = [1]

    def spawn(_request, response):
        spawned[0] += 1
        response.success = True
        response.message = f'turtle{spawned[0]}'
        return response

    node.create_service(Trigger, '/spawn', spawn)
    print(json.dumps({'ready': True}), flush=True)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
