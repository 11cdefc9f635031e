#!/usr/bin/env python3
"""Listens on one host for the SPDP announcements of a ROS domain (the multicast group 239.255.0.1
on the domain's discovery port) and prints, as one JSON object, the locators each participant
announced ({GUID prefix hex: [[list kind, locator kind, address, port], ...]}). Parsed by the
independent RTPS reader tests/interop/spdp_capture.py, not by our code.

    spdp_listen.py DOMAIN INTERFACE_ADDRESS SECONDS
"""
from __future__ import annotations

import json
import socket
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'interop'))
from spdp_capture import announcements  # noqa: E402

GROUP = '239.255.0.1'


def main() -> int:
    domain, interface, seconds = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(('', 7400 + 250 * domain))
    sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                    socket.inet_aton(GROUP) + socket.inet_aton(interface))
    print(json.dumps({'ready': True}), flush=True)
    found = {prefix.hex(): [list(entry) for entry in listed]
             for prefix, listed in announcements(sock, seconds).items()}
    print(json.dumps(found), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
