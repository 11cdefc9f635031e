"""Helpers for the OpenIGTLink interop tests (tests/interop/test_igtl.py): our `ros2vtk igtl`
process, a free loopback port, and a raw OpenIGTLink reader written from the protocol spec
(header.md, polydata.md) with struct, for what pyigtl cannot decode (POLYDATA) and for bad input.
Independent of our C++ framing: nothing here is produced by the code under test.
"""
from __future__ import annotations

import socket
import struct
import time

from conftest import BUILD

HEADER = struct.Struct('>H12s20sQQQ')  # version, type, device, timestamp, body size, CRC


def free_port() -> int:
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def start_ours(ros, port: int, *args: str):
    """`python -m ros2vtk igtl` (Debian's python3 with <build>/python), its own process."""
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', '-m', 'ros2vtk', 'igtl', '--port', str(port), *args], env)


def _crc64_table():
    poly = 0x42F0E1EBA9EA3693
    table = []
    for i in range(256):
        crc = i << 56
        for _ in range(8):
            crc = ((crc << 1) ^ poly) if crc & (1 << 63) else (crc << 1)
            crc &= 0xFFFFFFFFFFFFFFFF
        table.append(crc)
    return table


_TABLE = _crc64_table()


def crc64(data: bytes) -> int:
    crc = 0
    for byte in data:
        crc = _TABLE[((crc >> 56) ^ byte) & 0xFF] ^ ((crc << 8) & 0xFFFFFFFFFFFFFFFF)
    return crc


def frame(type_: str, device: str, body: bytes, *, version: int = 1, crc: int | None = None,
          size: int | None = None) -> bytes:
    return HEADER.pack(version, type_.encode(), device.encode(), 0,
                       len(body) if size is None else size, crc64(body) if crc is None else crc) + body


class RawClient:
    """Reads whole messages off a socket: (type, device, body) with the CRC checked."""

    def __init__(self, port: int, timeout: float = 10.0) -> None:
        deadline = time.monotonic() + timeout
        while True:
            try:
                self.sock = socket.create_connection(('127.0.0.1', port), timeout=1.0)
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.1)
        self.sock.settimeout(0.2)
        self.buffer = b''

    def read(self, seconds: float):
        end = time.monotonic() + seconds
        out = []
        while time.monotonic() < end:
            try:
                data = self.sock.recv(1 << 20)
                if not data:
                    break
                self.buffer += data
            except socket.timeout:
                pass
            while len(self.buffer) >= HEADER.size:
                version, t, d, _, size, crc = HEADER.unpack(self.buffer[:HEADER.size])
                if len(self.buffer) < HEADER.size + size:
                    break
                body = self.buffer[HEADER.size:HEADER.size + size]
                self.buffer = self.buffer[HEADER.size + size:]
                assert crc64(body) == crc, 'CRC mismatch in a message we received'
                out.append((t.rstrip(b'\0').decode(), d.rstrip(b'\0').decode(), version, body))
        return out

    def close(self) -> None:
        self.sock.close()


def polydata_points(body: bytes, version: int = 1):
    """Points (x, y, z) of a POLYDATA body (polydata.md: 10 uint32 counts, then float32 points)."""
    if version == 2:
        ext = struct.unpack('>H', body[:2])[0]
        meta_header, meta = struct.unpack('>HI', body[2:8])
        body = body[ext:len(body) - meta_header - meta]
    npoints = struct.unpack('>I', body[:4])[0]
    values = struct.unpack(f'>{3 * npoints}f', body[40:40 + 12 * npoints])
    return [values[i:i + 3] for i in range(0, len(values), 3)]


def v2_metadata(body: bytes) -> dict:
    ext = struct.unpack('>H', body[:2])[0]
    meta_header, meta = struct.unpack('>HI', body[2:8])
    start = len(body) - meta_header - meta
    count = struct.unpack('>H', body[start:start + 2])[0]
    entries = [struct.unpack('>HHI', body[start + 2 + 8 * i:start + 10 + 8 * i]) for i in range(count)]
    data = body[start + meta_header:]
    out, at = {}, 0
    for key_size, _, value_size in entries:
        key = data[at:at + key_size].decode()
        at += key_size
        out[key] = data[at:at + value_size].decode()
        at += value_size
    assert ext == 12
    return out


TDATA_ELEMENT = struct.Struct('>20sBx12f')  # tdata.md: name, type, reserved, R11 R21 R31 R12 … TX TY TZ


def tdata_body(elements) -> bytes:
    """A TDATA body from (name, 4x4 matrix) pairs, 6D instruments, written from the spec."""
    out = b''
    for name, m in elements:
        rotation = [m[r][c] for c in range(3) for r in range(3)]  # column by column
        out += TDATA_ELEMENT.pack(name.encode(), 2, *rotation, m[0][3], m[1][3], m[2][3])
    return out


def tdata_elements(body: bytes):
    """(name, type, 4x4 matrix as nested lists) of every element of a TDATA body."""
    assert len(body) % TDATA_ELEMENT.size == 0, len(body)
    out = []
    for offset in range(0, len(body), TDATA_ELEMENT.size):
        name, kind, *v = TDATA_ELEMENT.unpack_from(body, offset)
        m = [[v[0], v[3], v[6], v[9]], [v[1], v[4], v[7], v[10]], [v[2], v[5], v[8], v[11]], [0, 0, 0, 1]]
        out.append((name.rstrip(b'\0').decode(), kind, m))
    return out
