#!/usr/bin/env python3
"""One benchmark message serialized by rclpy, for tests/benchmarks/bare_publish.cpp's --payload.

    rclpy_payload.py --type Image [--width W --height H --encoding rgb8|bgr8|mono8|mono16] --out FILE
    rclpy_payload.py --type PoseStamped --out FILE
    rclpy_payload.py --type PointCloud2 [--points N] --out FILE
    rclpy_payload.py --type PoseArray [--poses N] --out FILE

The message is the one tests/benchmarks/ros_publisher.py sends (its build() is reused), with a
zero header.stamp (bare_publish writes the stamp per publish). FILE gets the bytes of
rclpy.serialization.serialize_message: CDR encapsulation header included. The driver can call
write_payload() directly.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from rclpy.serialization import serialize_message

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ros_publisher import build  # noqa: E402  (beside this file; builds the message from args)

TYPES = ('PoseStamped', 'Image', 'PointCloud2', 'PoseArray')


def payload_bytes(kind: str, *, width: int = 640, height: int = 480, encoding: str = 'rgb8',
                  points: int = 100000, poses: int = 1000) -> bytes:
    """The rclpy-serialized bytes of one `kind` message, as ros_publisher.py builds it."""
    if kind not in TYPES:
        raise ValueError(f'unknown type {kind!r} (one of {", ".join(TYPES)})')
    args = argparse.Namespace(type=kind, width=width, height=height, encoding=encoding,
                              points=points, poses=poses)
    return serialize_message(build(args))


def write_payload(kind: str, out: Path | str, *, width: int = 640, height: int = 480,
                  encoding: str = 'rgb8', points: int = 100000, poses: int = 1000) -> int:
    """Writes payload_bytes(kind, ...) to `out`; returns the number of bytes written."""
    data = payload_bytes(kind, width=width, height=height, encoding=encoding, points=points,
                         poses=poses)
    Path(out).write_bytes(data)
    return len(data)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--type', required=True, choices=TYPES)
    parser.add_argument('--out', required=True, type=Path)
    parser.add_argument('--width', type=int, default=640)
    parser.add_argument('--height', type=int, default=480)
    parser.add_argument('--encoding', default='rgb8', choices=('rgb8', 'bgr8', 'mono8', 'mono16'))
    parser.add_argument('--points', type=int, default=100000)
    parser.add_argument('--poses', type=int, default=1000)
    args = parser.parse_args()
    size = write_payload(args.type, args.out, width=args.width, height=args.height,
                         encoding=args.encoding, points=args.points, poses=args.poses)
    print(f'{args.out}: {size} bytes ({args.type})')
    return 0


if __name__ == '__main__':
    sys.exit(main())
