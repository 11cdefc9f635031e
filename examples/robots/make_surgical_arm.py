#!/usr/bin/env python3
"""Writes the shipped demo robot: a 7-joint surgical arm holding a needle-guide instrument.

Output (committed; rerun to regenerate, the output is deterministic):
  surgical_arm/package.xml           so `package://ros2vtk_surgical_arm/...` resolves
  surgical_arm/urdf/surgical_arm.urdf
  surgical_arm/meshes/*.stl          binary STL made here (cylinders, boxes, a cone)

Some meshes are written in millimetres and scaled by 0.001 in the URDF, others in metres, so
per-visual mesh scale is exercised; links mix meshes, primitives and several visuals.
Standard library only.
"""
from __future__ import annotations

import math
import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent
PACKAGE = 'ros2vtk_surgical_arm'
OUT = HERE / 'surgical_arm'

Triangle = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]


def cylinder(radius: float, length: float, segments: int = 32, z0: float = 0.0) -> list[Triangle]:
    """A closed cylinder along +z from z0 to z0 + length."""
    tris: list[Triangle] = []
    z1 = z0 + length
    for i in range(segments):
        a0 = 2 * math.pi * i / segments
        a1 = 2 * math.pi * (i + 1) / segments
        p0 = (radius * math.cos(a0), radius * math.sin(a0))
        p1 = (radius * math.cos(a1), radius * math.sin(a1))
        tris.append(((p0[0], p0[1], z0), (p1[0], p1[1], z0), (p1[0], p1[1], z1)))
        tris.append(((p0[0], p0[1], z0), (p1[0], p1[1], z1), (p0[0], p0[1], z1)))
        tris.append(((0.0, 0.0, z0), (p1[0], p1[1], z0), (p0[0], p0[1], z0)))
        tris.append(((0.0, 0.0, z1), (p0[0], p0[1], z1), (p1[0], p1[1], z1)))
    return tris


def cone(radius: float, length: float, segments: int = 32) -> list[Triangle]:
    """A cone along +z, base at z=0, apex at z=length."""
    tris: list[Triangle] = []
    for i in range(segments):
        a0 = 2 * math.pi * i / segments
        a1 = 2 * math.pi * (i + 1) / segments
        p0 = (radius * math.cos(a0), radius * math.sin(a0), 0.0)
        p1 = (radius * math.cos(a1), radius * math.sin(a1), 0.0)
        tris.append((p0, p1, (0.0, 0.0, length)))
        tris.append(((0.0, 0.0, 0.0), p1, p0))
    return tris


def box(sx: float, sy: float, sz: float, z0: float = 0.0) -> list[Triangle]:
    """A box centred on the z axis, from z0 to z0 + sz."""
    x, y = sx / 2, sy / 2
    v = [(-x, -y, z0), (x, -y, z0), (x, y, z0), (-x, y, z0),
         (-x, -y, z0 + sz), (x, -y, z0 + sz), (x, y, z0 + sz), (-x, y, z0 + sz)]
    faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
             (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return [(v[a], v[b], v[c]) for a, b, c in faces]


def scaled(tris: list[Triangle], factor: float) -> list[Triangle]:
    return [tuple(tuple(c * factor for c in p) for p in t) for t in tris]  # type: ignore[misc]


def write_stl(path: Path, tris: list[Triangle], name: str) -> None:
    header = f'ros2vtk {name}'.encode().ljust(80, b' ')
    with path.open('wb') as f:
        f.write(header)
        f.write(struct.pack('<I', len(tris)))
        for a, b, c in tris:
            u = [b[i] - a[i] for i in range(3)]
            w = [c[i] - a[i] for i in range(3)]
            n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            norm = math.sqrt(sum(k * k for k in n)) or 1.0
            f.write(struct.pack('<3f', *(k / norm for k in n)))
            for p in (a, b, c):
                f.write(struct.pack('<3f', *p))
            f.write(b'\0\0')


MESHES = {
    # name: (triangles, unit) — 'mm' meshes get <mesh scale="0.001 0.001 0.001">
    'base.stl': (box(0.30, 0.30, 0.10), 'm'),
    'column.stl': (scaled(cylinder(0.06, 0.40), 1000.0), 'mm'),
    'upper_arm.stl': (cylinder(0.045, 0.35), 'm'),
    'forearm.stl': (scaled(cylinder(0.04, 0.30), 1000.0), 'mm'),
    'wrist.stl': (box(0.07, 0.07, 0.12), 'm'),
    'instrument.STL': (cylinder(0.012, 0.20), 'm'),  # upper-case extension on purpose
    'needle_guide.stl': (scaled(cone(0.015, 0.05), 1000.0), 'mm'),
}

# (joint, type, parent, child, xyz, rpy, axis, limits)
JOINTS = [
    ('base_to_column', 'revolute', 'base_link', 'column_link', (0, 0, 0.10), (0, 0, 0), (0, 0, 1), (-2.8, 2.8)),
    ('shoulder_pitch', 'revolute', 'column_link', 'upper_arm_link', (0, 0, 0.40), (0, 0, 0), (0, 1, 0), (-1.6, 1.6)),
    ('elbow_pitch', 'revolute', 'upper_arm_link', 'forearm_link', (0, 0, 0.35), (0, 0, 0), (0, 1, 0), (-2.2, 2.2)),
    ('forearm_roll', 'revolute', 'forearm_link', 'wrist_link', (0, 0, 0.30), (0, 0, 0), (0, 0, 1), (-3.0, 3.0)),
    ('wrist_pitch', 'revolute', 'wrist_link', 'instrument_link', (0, 0, 0.12), (0, 0, 0), (0, 1, 0), (-1.5, 1.5)),
    ('instrument_insertion', 'prismatic', 'instrument_link', 'needle_guide_link', (0, 0, 0.20), (0, 0, 0), (0, 0, 1), (0.0, 0.08)),
    ('needle_tip_mount', 'fixed', 'needle_guide_link', 'needle_tip', (0, 0, 0.05), (0, 0, 0), None, None),
]

# link: list of visuals (geometry xml, origin xyz, material)
VISUALS = {
    'base_link': [('<mesh filename="package://{p}/meshes/base.stl"/>', (0, 0, 0), 'slate'),
                  ('<cylinder radius="0.02" length="0.05"/>', (0.12, 0.12, 0.125), 'signal')],
    'column_link': [('<mesh filename="package://{p}/meshes/column.stl" scale="0.001 0.001 0.001"/>', (0, 0, 0), 'white')],
    'upper_arm_link': [('<sphere radius="0.06"/>', (0, 0, 0), 'blue'),
                       ('<mesh filename="package://{p}/meshes/upper_arm.stl"/>', (0, 0, 0), 'white')],
    'forearm_link': [('<sphere radius="0.05"/>', (0, 0, 0), 'blue'),
                     ('<mesh filename="../meshes/forearm.stl" scale="0.001 0.001 0.001"/>', (0, 0, 0), 'white')],
    'wrist_link': [('<mesh filename="package://{p}/meshes/wrist.stl"/>', (0, 0, 0), 'slate')],
    'instrument_link': [('<mesh filename="package://{p}/meshes/instrument.STL"/>', (0, 0, 0), 'steel')],
    'needle_guide_link': [('<mesh filename="package://{p}/meshes/needle_guide.stl" scale="0.001 0.001 0.001"/>', (0, 0, 0), 'signal')],
    'needle_tip': [('<box size="0.004 0.004 0.004"/>', (0, 0, 0), 'signal')],
}

MATERIALS = {'slate': (0.25, 0.28, 0.32, 1.0), 'white': (0.92, 0.92, 0.90, 1.0),
             'blue': (0.15, 0.35, 0.75, 1.0), 'steel': (0.7, 0.72, 0.75, 1.0),
             'signal': (0.95, 0.45, 0.1, 1.0)}


def urdf() -> str:
    lines = ['<?xml version="1.0"?>',
             '<!-- Generated by examples/robots/make_surgical_arm.py; edit the script, not this file. -->',
             '<robot name="surgical_arm">']
    for name, (r, g, b, a) in MATERIALS.items():
        lines.append(f'  <material name="{name}"><color rgba="{r} {g} {b} {a}"/></material>')
    for link, visuals in VISUALS.items():
        lines.append(f'  <link name="{link}">')
        for geometry, (x, y, z), material in visuals:
            lines.append('    <visual>')
            lines.append(f'      <origin xyz="{x} {y} {z}" rpy="0 0 0"/>')
            lines.append(f'      <geometry>{geometry.format(p=PACKAGE)}</geometry>')
            lines.append(f'      <material name="{material}"/>')
            lines.append('    </visual>')
        lines.append('  </link>')
    for name, kind, parent, child, xyz, rpy, axis, limits in JOINTS:
        lines.append(f'  <joint name="{name}" type="{kind}">')
        lines.append(f'    <parent link="{parent}"/><child link="{child}"/>')
        lines.append(f'    <origin xyz="{xyz[0]} {xyz[1]} {xyz[2]}" rpy="{rpy[0]} {rpy[1]} {rpy[2]}"/>')
        if axis:
            lines.append(f'    <axis xyz="{axis[0]} {axis[1]} {axis[2]}"/>')
        if limits:
            lines.append(f'    <limit lower="{limits[0]}" upper="{limits[1]}" effort="50" velocity="1.0"/>')
        lines.append('  </joint>')
    lines.append('</robot>')
    return '\n'.join(lines) + '\n'


def main() -> None:
    (OUT / 'urdf').mkdir(parents=True, exist_ok=True)
    (OUT / 'meshes').mkdir(parents=True, exist_ok=True)
    for name, (tris, _unit) in MESHES.items():
        write_stl(OUT / 'meshes' / name, tris, name)
    (OUT / 'urdf' / 'surgical_arm.urdf').write_text(urdf())
    (OUT / 'package.xml').write_text(
        '<?xml version="1.0"?>\n<package format="3">\n'
        f'  <name>{PACKAGE}</name>\n  <version>0.1.0</version>\n'
        '  <description>Demo surgical arm of ros2vtk (generated by make_surgical_arm.py)</description>\n'
        '  <maintainer email="ros2vtk@example.org">ros2vtk</maintainer>\n'
        '  <license>Apache-2.0</license>\n</package>\n')
    print(f'wrote {OUT}')


if __name__ == '__main__':
    main()
