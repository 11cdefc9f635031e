"""Reads the locators a participant announces, from its SPDP DATA(p) datagrams (RTPS 2.x spec
9.4 / 9.6.2): an independent parser, so our participant's announcements are checked without our
code. Used by the loopback tests: the test binds the metatraffic port of one participant id on
127.0.0.1, where a LOCALHOST participant sends its announcements."""
from __future__ import annotations

import ipaddress
import socket
import struct
import time
from typing import Callable, Optional

SPDP_WRITER = b'\x00\x01\x00\xc2'
DATA = 0x15
LOCATOR_PIDS = {0x0031: 'default_unicast', 0x0032: 'metatraffic_unicast',
                0x0033: 'metatraffic_multicast', 0x0048: 'default_multicast'}
PID_SENTINEL = 0x0001
KIND_UDPV4 = 1


def _parameters(buffer: bytes, offset: int, little: bool):
    order = '<' if little else '>'
    while offset + 4 <= len(buffer):
        pid, length = struct.unpack_from(order + 'HH', buffer, offset)
        offset += 4
        if pid == PID_SENTINEL:
            return
        yield pid & 0x3fff, buffer[offset:offset + length], order
        offset += length


def locators(datagram: bytes) -> tuple[bytes, list[tuple[str, int, str, int]]]:
    """(GUID prefix, [(kind of list, locator kind, address, port)]) of the SPDP data in one
    datagram; an empty list when it carries none."""
    if len(datagram) < 20 or datagram[:4] != b'RTPS':
        return b'', []
    prefix = datagram[8:20]
    found = []
    offset = 20
    while offset + 4 <= len(datagram):
        sub_id, flags = datagram[offset], datagram[offset + 1]
        little = bool(flags & 0x01)
        (length,) = struct.unpack_from('<H' if little else '>H', datagram, offset + 2)
        body = offset + 4
        end = len(datagram) if length == 0 else body + length
        if sub_id == DATA and datagram[body + 8:body + 12] == SPDP_WRITER:
            (to_inline,) = struct.unpack_from('<H' if little else '>H', datagram, body + 2)
            cursor = body + 4 + to_inline
            if flags & 0x02:  # inline QoS: skip to its sentinel
                while cursor + 4 <= end:
                    pid, plen = struct.unpack_from('<HH' if little else '>HH', datagram, cursor)
                    cursor += 4 + (0 if pid == PID_SENTINEL else plen)
                    if pid == PID_SENTINEL:
                        break
            if flags & 0x04:
                encapsulation = datagram[cursor:cursor + 2]
                payload_little = encapsulation == b'\x00\x03'
                for pid, value, order in _parameters(datagram[:end], cursor + 4, payload_little):
                    if pid in LOCATOR_PIDS and len(value) >= 24:
                        kind, port = struct.unpack_from(order + 'iI', value, 0)
                        address = value[8:24]
                        text = (str(ipaddress.IPv4Address(address[12:])) if kind == KIND_UDPV4
                                else address.hex())
                        found.append((LOCATOR_PIDS[pid], kind, text, port))
        offset = end
    return prefix, found


def announcements(sock: socket.socket, seconds: float,
                  check_sender: Optional[Callable[[tuple], None]] = None) -> dict[bytes, list]:
    """The locators each participant announced on a bound socket within `seconds`, by GUID
    prefix, each locator once; `check_sender` sees every datagram's sender address first."""
    found: dict[bytes, list] = {}
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        sock.settimeout(max(0.05, deadline - time.monotonic()))
        try:
            datagram, sender = sock.recvfrom(65536)
        except socket.timeout:
            break
        if check_sender is not None:
            check_sender(sender)
        prefix, listed = locators(datagram)
        if listed:
            entries = found.setdefault(prefix, [])
            entries.extend(entry for entry in listed if entry not in entries)
    return found
