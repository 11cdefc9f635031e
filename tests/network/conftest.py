"""Two lab hosts on one machine: the robot's computer and the imaging workstation.

Each test gets two network namespaces made by the test itself, joined by a veth pair with
addresses from the benchmarking range 198.18.0.0/15 (never a private or public network), the
loopback up in each, and a multicast route on the veth (ROS 2's default SUBNET discovery). The
namespaces have no other interface and no route anywhere else, so nothing a test sends can leave
the pair; they are deleted at the end, also on failure. Processes run inside with
`ip netns exec`; rclpy peers and our processes are the same programs the interop tests use.
"""
from __future__ import annotations

import importlib.util
import itertools
import os
import subprocess
import sys
from pathlib import Path
from typing import Iterator

import pytest

INTEROP = Path(__file__).resolve().parents[1] / 'interop'
sys.path.insert(0, str(INTEROP))
# The interop fixtures' Ros session (loaded under another name: both files are "conftest").
_spec = importlib.util.spec_from_file_location('interop_conftest', INTEROP / 'conftest.py')
interop = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(interop)
Ros, VENV_PYTHON = interop.Ros, interop.VENV_PYTHON
# What the interop test modules reused here import from "their" conftest.
BUILD, HERE, REPO, tf2_msgs_env = interop.BUILD, interop.HERE, interop.REPO, interop.tf2_msgs_env

# Domains 0..99 cycle here; the interop tests use 100..179 (both suites hold the ros_graph lock).
_domains = (int(os.environ.get('ROS2VTK_NETWORK_DOMAIN_BASE', '20')) + n % 60 for n in itertools.count())
ROBOT_ADDRESS = '198.18.0.1'
IMAGING_ADDRESS = '198.18.0.2'


def ip(*args: str, check: bool = True) -> subprocess.CompletedProcess:
    return subprocess.run(['ip', *args], check=check, capture_output=True, text=True)


class Host(Ros):
    """A ROS session whose processes all run inside one network namespace."""

    def __init__(self, domain: int, namespace: str, address: str, range_: str) -> None:
        super().__init__(domain)
        self.namespace = namespace
        self.address = address
        self.env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = range_

    def start(self, args: list[str], env: dict | None = None) -> subprocess.Popen:
        return super().start(['ip', 'netns', 'exec', self.namespace, *args], env)


class Lab:
    """The two hosts and the link between them (cut and heal it, drop packets on it)."""

    def __init__(self, tag: str, domain: int, range_: str = 'SUBNET') -> None:
        self.robot_ns, self.imaging_ns = f'r2v{tag}_robot', f'r2v{tag}_imaging'
        self.robot_if, self.imaging_if = f'r2v{tag}r', f'r2v{tag}i'
        for ns in (self.robot_ns, self.imaging_ns):
            ip('netns', 'add', ns)
        ip('link', 'add', self.robot_if, 'netns', self.robot_ns, 'type', 'veth',
           'peer', 'name', self.imaging_if, 'netns', self.imaging_ns)
        for ns, dev, address in ((self.robot_ns, self.robot_if, ROBOT_ADDRESS),
                                 (self.imaging_ns, self.imaging_if, IMAGING_ADDRESS)):
            ip('-n', ns, 'addr', 'add', f'{address}/24', 'dev', dev)
            ip('-n', ns, 'link', 'set', 'lo', 'up')
            ip('-n', ns, 'link', 'set', dev, 'up', 'multicast', 'on')
            ip('-n', ns, 'route', 'add', '224.0.0.0/4', 'dev', dev)
        self.robot = Host(domain, self.robot_ns, ROBOT_ADDRESS, range_)
        self.imaging = Host(domain, self.imaging_ns, IMAGING_ADDRESS, range_)

    def cut(self) -> None:
        """The cable pulled: the robot side's interface goes down (its address stays)."""
        ip('-n', self.robot_ns, 'link', 'set', self.robot_if, 'down')

    def heal(self) -> None:
        ip('-n', self.robot_ns, 'link', 'set', self.robot_if, 'up')
        ip('-n', self.robot_ns, 'route', 'replace', '224.0.0.0/4', 'dev', self.robot_if)

    def drop(self, percent: int) -> None:
        """Random packet loss on both ends of the link, sent and received (nftables `numgen`; this
        kernel has no netem, so delay cannot be emulated)."""
        for ns, dev in ((self.robot_ns, self.robot_if), (self.imaging_ns, self.imaging_if)):
            rules = (f'table inet r2v_loss {{\n'
                     f'  chain out {{ type filter hook output priority 0; policy accept;\n'
                     f'    oifname "{dev}" numgen random mod 100 < {percent} drop\n  }}\n'
                     f'  chain in {{ type filter hook input priority 0; policy accept;\n'
                     f'    iifname "{dev}" numgen random mod 100 < {percent} drop\n  }}\n}}\n')
            subprocess.run(['ip', 'netns', 'exec', ns, 'nft', '-f', '-'], input=rules, text=True,
                           check=True, capture_output=True)

    def block_multicast(self) -> None:
        """A network that drops multicast (hospital and Wi-Fi networks): nothing to 224.0.0.0/4
        leaves or enters either end of the link."""
        for ns, dev in ((self.robot_ns, self.robot_if), (self.imaging_ns, self.imaging_if)):
            rules = (f'table ip r2v_nomulticast {{\n'
                     f'  chain out {{ type filter hook output priority 0; policy accept;\n'
                     f'    oifname "{dev}" ip daddr 224.0.0.0/4 drop\n  }}\n'
                     f'  chain in {{ type filter hook input priority 0; policy accept;\n'
                     f'    iifname "{dev}" ip daddr 224.0.0.0/4 drop\n  }}\n}}\n')
            subprocess.run(['ip', 'netns', 'exec', ns, 'nft', '-f', '-'], input=rules, text=True,
                           check=True, capture_output=True)

    def close(self) -> None:
        self.robot.close()
        self.imaging.close()
        for ns in (self.robot_ns, self.imaging_ns):
            ip('netns', 'del', ns, check=False)  # takes the veth with it


def namespaces_unavailable() -> str:
    """Why this process cannot make namespaces ('' when it can)."""
    if os.geteuid() != 0:
        return 'network namespaces need root (CAP_NET_ADMIN); run the network tests as root'
    probe = f'r2vprobe{os.getpid()}'
    result = ip('netns', 'add', probe, check=False)
    if result.returncode != 0:
        return f'`ip netns add` failed: {result.stderr.strip()}'
    ip('netns', 'del', probe, check=False)
    return ''


@pytest.fixture
def lab() -> Iterator[Lab]:
    reason = namespaces_unavailable()
    if reason:
        print(f'network tests skipped: {reason}')
        pytest.skip(reason)
    if not VENV_PYTHON.exists():
        pytest.fail(f'no ROS 2 venv at {VENV_PYTHON}: run scripts/setup.sh')
    made = Lab(f'{os.getpid() % 100000}', next(_domains))
    try:
        yield made
    finally:
        made.close()
