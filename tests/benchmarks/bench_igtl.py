#!/usr/bin/env python3
"""Benchmark (reported, never asserted): ROS tf in -> OpenIGTLink TRANSFORM out through
`python -m ros2vtk igtl`, received by pyigtl (the Slicer stand-in), beside bare OpenIGTLink hops in
the same run. scripts/bench.sh runs it (section igtl of run_benchmarks.py).

    ROS_DOMAIN_ID=... ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST .venv/bin/python tests/benchmarks/bench_igtl.py \
        --build build [--rate 100] [--count 1000]

One process holds both ends (one clock): an rclpy node publishes world <- probe on /tf at --rate,
the translation x carrying the sequence number (1 mm each), and a pyigtl OpenIGTLinkClient
receives the TRANSFORMs; each is timestamped when pyigtl's receive thread stores it (a dict hook,
so pyigtl's 10 ms wait_for_message polling is not measured). Latency = stored - published.
The bare rows send the same TRANSFORM frames from a plain TCP socket (TCP_NODELAY) to (a) a raw
reader thread, the floor of the OpenIGTLink leg, and (b) a pyigtl client timestamped as above, the
same receiver as the ros2vtk row (ROS-IGTL-Bridge reports < 1.2 ms for transforms, Frank et al.
2017). Prints one JSON object.
"""
from __future__ import annotations

import argparse
import json
import os
import socket
import statistics
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / 'interop'))
from igtl_peer import HEADER, frame, free_port  # noqa: E402


def sysconfig_purelib() -> str:
    import sysconfig
    return sysconfig.get_paths()['purelib']


def summary(latencies_ms: list) -> dict:
    if not latencies_ms:
        return {'n': 0}
    ordered = sorted(latencies_ms)
    return {'n': len(ordered), 'median_ms': round(statistics.median(ordered), 3),
            'p99_ms': round(ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))], 3),
            'max_ms': round(ordered[-1], 3)}


def transform_body(x_mm: float) -> bytes:
    return struct.pack('>12f', 1, 0, 0, 0, 1, 0, 0, 0, 1, x_mm, 0, 0)


def bare(count: int, rate: float) -> dict:
    server = socket.socket()
    server.bind(('127.0.0.1', 0))
    server.listen(1)
    sender = socket.create_connection(server.getsockname())
    sender.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    receiver, _ = server.accept()
    sent = {}
    latencies = []

    def read():
        buffer = b''
        while len(latencies) < count:
            data = receiver.recv(65536)
            if not data:
                return
            now = time.perf_counter()
            buffer += data
            while len(buffer) >= HEADER.size:
                size = HEADER.unpack(buffer[:HEADER.size])[4]
                if len(buffer) < HEADER.size + size:
                    break
                seq = int(round(struct.unpack('>12f', buffer[HEADER.size:HEADER.size + 48])[9]))
                buffer = buffer[HEADER.size + size:]
                latencies.append(1000.0 * (now - sent[seq]))

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    for seq in range(count):
        sent[seq] = time.perf_counter()
        sender.sendall(frame('TRANSFORM', 'probe', transform_body(float(seq))))
        time.sleep(1.0 / rate)
    reader.join(timeout=5)
    for s in (sender, receiver, server):
        s.close()
    return summary(latencies)


class ArrivalLog(dict):
    """pyigtl's incoming-message store (device -> latest message) that also timestamps arrivals."""

    def __init__(self, arrived: list) -> None:
        super().__init__()
        self.arrived = arrived  # (perf_counter, message)

    def __setitem__(self, key, value) -> None:
        self.arrived.append((time.perf_counter(), value))
        super().__setitem__(key, value)


def pyigtl_client(port: int) -> tuple:
    """A pyigtl client whose every stored message is timestamped: (client, [(t, message)])."""
    import pyigtl
    arrived: list = []
    client = pyigtl.OpenIGTLinkClient('127.0.0.1', port, start_now=False)
    client.incoming_messages = ArrivalLog(arrived)
    client.start()
    return client, arrived


def sequence_of(message) -> int | None:
    if message.message_type != 'TRANSFORM' or message.device_name != 'probe':
        return None
    return int(round(float(message.matrix[0, 3])))


def bare_to_pyigtl(count: int, rate: float) -> dict:
    """Plain socket server sending TRANSFORM frames -> pyigtl client (the receiver of the ros2vtk row)."""
    server = socket.socket()
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(('127.0.0.1', 0))
    server.listen(1)
    client, arrived = pyigtl_client(server.getsockname()[1])
    sender, _ = server.accept()
    sender.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    sent = {}
    for seq in range(count):
        sent[seq] = time.perf_counter()
        sender.sendall(frame('TRANSFORM', 'probe', transform_body(float(seq))))
        time.sleep(1.0 / rate)
    time.sleep(0.5)
    client.stop()
    for s in (sender, server):
        s.close()
    latencies = {}
    for t, message in list(arrived):
        seq = sequence_of(message)
        if seq in sent and seq not in latencies:
            latencies[seq] = 1000.0 * (t - sent[seq])
    result = summary(list(latencies.values()))
    result['lost'] = count - len(latencies)
    return result


def through_ros2vtk(build: Path, count: int, rate: float) -> dict:
    import rclpy
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage

    port = free_port()
    env = dict(os.environ, PYTHONPATH=str(build / 'python'))
    ours = subprocess.Popen(['/usr/bin/python3', '-m', 'ros2vtk', 'igtl', '--port', str(port),
                             '--lookup', 'world:probe', '--seconds', str(count / rate + 20)],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    assert json.loads(ours.stdout.readline()).get('ready')
    rclpy.init()
    node = rclpy.create_node('bench_igtl_tf')
    publisher = node.create_publisher(TFMessage, '/tf', 100)
    client, stored = pyigtl_client(port)
    sent = {}
    arrived: dict = {}  # seq -> latency (ms), first arrival only

    def collect() -> None:
        while stored:
            t, message = stored.pop(0)
            seq = sequence_of(message)
            if seq is not None and seq in sent and seq not in arrived:
                arrived[seq] = 1000.0 * (t - sent[seq])

    def publish(seq: int) -> None:
        t = TransformStamped()
        t.header.stamp = node.get_clock().now().to_msg()
        t.header.frame_id = 'world'
        t.child_frame_id = 'probe'
        t.transform.translation.x = seq / 1000.0  # 1 mm per sequence number
        t.transform.rotation.w = 1.0
        sent[seq] = time.perf_counter()
        publisher.publish(TFMessage(transforms=[t]))

    # Warm-up: discovery and the first lookup (not measured).
    deadline = time.monotonic() + 15
    seq = 100_000
    while not arrived and time.monotonic() < deadline:
        publish(seq)
        seq += 1
        time.sleep(0.05)
        collect()
    sent.clear()
    time.sleep(0.2)
    collect()
    arrived.clear()
    for seq in range(count):
        publish(seq)
        time.sleep(1.0 / rate)
    time.sleep(0.5)
    collect()
    client.stop()
    latencies = list(arrived.values())
    ours.send_signal(2)
    ours.communicate(timeout=20)
    node.destroy_node()
    rclpy.shutdown()
    result = summary(latencies)
    result['lost'] = count - len(latencies)  # latest-only: a pose overtaken before sending is dropped
    return result


def robot_traffic(build: Path, urdf: Path, ament: Path | None, link_local: bool, configs: int = 21,
                  hold: float = 0.2) -> dict:
    """What a moving robot costs on the wire: an rclpy robot_state_publisher (tests/interop/rsp_peer.py)
    walks through `configs` joint configurations, `hold` s each; a raw reader (the protocol's own
    layout) counts what `ros2vtk igtl --robot` sends while it moves: world-baked meshes (default,
    resent as links move) or link-local ones (--link-local / --slicer-scene, sent once)."""
    from igtl_peer import RawClient
    port = free_port()
    env = dict(os.environ)
    if ament:
        env['AMENT_PREFIX_PATH'] = os.pathsep.join(filter(None, [str(ament), env.get('AMENT_PREFIX_PATH')]))
    rsp = subprocess.Popen([sys.executable, str(HERE.parent / 'interop' / 'rsp_peer.py'), str(urdf),
                            '--configs', str(configs), '--hold', str(hold), '--first-hold', '60', '--rate', '100'],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    assert json.loads(rsp.stdout.readline()).get('ready')
    ours = subprocess.Popen(['/usr/bin/python3', '-m', 'ros2vtk', 'igtl', '--port', str(port), '--robot',
                             *(['--link-local'] if link_local else []), '--seconds', '120'],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                            env=dict(env, PYTHONPATH=str(build / 'python')))
    assert json.loads(ours.stdout.readline()).get('ready')
    visuals = len(__import__('re').findall(r'<visual\b', urdf.read_text(errors='replace')))
    reader = RawClient(port)
    meshes: set = set()
    deadline = time.monotonic() + 60  # robot load, then the first (held) configuration settles
    while len(meshes) < visuals and time.monotonic() < deadline:
        meshes |= {d for t, d, _, _ in reader.read(0.5) if t == 'POLYDATA'}
    reader.read(2.0)
    # A first peer holds configuration 0 while the robot loads: 2 s of a robot standing still.
    # A second peer then walks through the configurations: the robot moving.
    still = reader.read(2.0)
    rsp.kill()
    rsp.communicate()
    mover = subprocess.Popen([sys.executable, str(HERE.parent / 'interop' / 'rsp_peer.py'), str(urdf),
                              '--configs', str(configs), '--hold', str(hold), '--rate', '100'],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    assert json.loads(mover.stdout.readline()).get('ready')
    mover.stdout.readline()  # configuration 0
    start = time.monotonic()
    moving = reader.read(configs * hold)
    seconds = time.monotonic() - start
    reader.close()
    mover.kill()
    mover.communicate()
    ours.send_signal(2)
    ours.communicate(timeout=30)

    def rates(messages, span):
        out = {}
        for kind in ('TRANSFORM', 'POLYDATA'):
            chosen = [body for t, _, _, body in messages if t == kind]
            out[kind] = {'messages_per_s': round(len(chosen) / span, 1),
                         'kbytes_per_s': round(sum(58 + len(b) for b in chosen) / span / 1000.0, 1)}
        return out
    return {'urdf': urdf.name, 'visuals': visuals, 'meshes_seen': len(meshes),
            'configuration_changes_per_s': round(1.0 / hold, 1),
            'still': rates(still, 2.0), 'moving': rates(moving, seconds)}


def main() -> int:
    try:
        import tf2_msgs.msg  # noqa: F401
    except ImportError:  # no wheel: built from its .msg (tests/fixtures/README.md); re-run with it
        from conftest import tf2_msgs_env
        env = dict(os.environ)
        for key, value in tf2_msgs_env().items():
            env[key] = os.pathsep.join(filter(None, [value, env.get(key)]))
        return subprocess.call([sys.executable, *sys.argv], env=env)
    parser = argparse.ArgumentParser()
    parser.add_argument('--build', type=Path, default=HERE.parents[1] / 'build')
    parser.add_argument('--rate', type=float, default=100.0)
    parser.add_argument('--count', type=int, default=1000)
    parser.add_argument('--robot-only', action='store_true', help='only the moving-robot traffic rows')
    args = parser.parse_args()
    robots = [(HERE.parents[1] / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf', None)]
    prefix = Path(sysconfig_purelib()) / 'cmeel.prefix'
    panda = prefix / 'share' / 'example-robot-data' / 'robots' / 'panda_description' / 'urdf' / 'panda.urdf'
    if panda.exists():  # example-robot-data (scripts/requirements): real meshes
        robots.append((panda, prefix))
    traffic = {f'{urdf.stem} {"link-local" if local else "baked"}': robot_traffic(args.build, urdf, ament, local)
               for urdf, ament in robots for local in (False, True)}
    if args.robot_only:
        print(json.dumps({'robot_traffic': traffic}))
        return 0
    result = {'rate_hz': args.rate, 'count': args.count,
              'bare_openigtlink_hop': bare(args.count, args.rate),
              'bare_openigtlink_to_pyigtl': bare_to_pyigtl(args.count, args.rate),
              'rclpy_tf_to_igtl_transform': through_ros2vtk(args.build, args.count, args.rate),
              'robot_traffic': traffic}
    print(json.dumps(result))
    return 0


if __name__ == '__main__':
    sys.exit(main())
