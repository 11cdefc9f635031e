"""Adding a package under msg_specs/ and removing it again, in a copy of the tree (issue 20,
"How it is proven"; the steps of docs/extending.md, "Inside the repository").

The copy is minimal: the folders the message family needs (cmake/, generator/, templates/,
msg_specs/, generated/, runtime/Message, tests/golden) and a top-level CMakeLists.txt holding the
message part of the real one, so that configure takes seconds and only lab_msgs' own objects are
compiled (through the build's compiler launcher). Adding lab_msgs needs no list edit; after
`ros2vtk_regenerate` the golden check passes; after removing the folder, generated/messages/ is
byte-identical to the repository's again, and neither the build's output folder nor a fresh
install holds a lab_msgs file."""
from __future__ import annotations

import filecmp
import os
import shutil
import subprocess
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
BUILD = Path(os.environ.get("ROS2VTK_BUILD_DIR", REPO / "build"))
WORK = BUILD / "extending-tree"
LAUNCHER = os.environ.get("ROS2VTK_COMPILER_LAUNCHER", "")

COPIED = ["cmake", "generator", "templates", "msg_specs", "generated/messages", "runtime/Message",
          "tests/golden"]
TOP_LEVEL = """\
# The message part of the repository's CMakeLists.txt (tests/extending/test_add_remove_package.py).
cmake_minimum_required(VERSION 3.21)
project(ros2vtk_copy VERSION 0.1.0 LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
list(APPEND CMAKE_MODULE_PATH "${CMAKE_CURRENT_SOURCE_DIR}/cmake")
include(GNUInstallDirs)
include(ros2vtk_internal)
find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter)
add_subdirectory(runtime/Message)
add_subdirectory(msg_specs)
"""


def run(*args: str, cwd: Path | None = None) -> str:
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    assert result.returncode == 0, f"{' '.join(args)}\n{result.stdout}\n{result.stderr}"
    return result.stdout


def lab_files(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if "lab_msgs" in str(p))


def same_tree(left: Path, right: Path) -> list[str]:
    """Relative paths that differ, or exist on one side only."""
    problems = []
    compare = filecmp.dircmp(left, right)
    stack = [("", compare)]
    while stack:
        prefix, node = stack.pop()
        problems += [f"{prefix}{name}" for name in node.left_only + node.right_only]
        _, mismatch, errors = filecmp.cmpfiles(left / prefix, right / prefix, node.common_files,
                                               shallow=False)
        problems += [f"{prefix}{name}" for name in mismatch + errors]
        stack += [(f"{prefix}{name}/", sub) for name, sub in node.subdirs.items()]
    return problems


def test_add_then_remove_a_package_in_a_copy_of_the_tree():
    source, build, install = WORK / "src", WORK / "build", WORK / "install"
    shutil.rmtree(source, ignore_errors=True)
    shutil.rmtree(install, ignore_errors=True)
    for folder in COPIED:
        shutil.copytree(REPO / folder, source / folder,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    (source / "CMakeLists.txt").write_text(TOP_LEVEL)

    # Add: the folder is all it takes.
    shutil.copytree(HERE / "lab_msgs", source / "msg_specs" / "lab_msgs")
    configure = ["cmake", "-S", str(source), "-B", str(build), "-G", "Ninja",
                 "-DPython3_EXECUTABLE=/usr/bin/python3", "-DCMAKE_BUILD_TYPE=RelWithDebInfo"]
    if LAUNCHER:
        configure.append(f"-DCMAKE_CXX_COMPILER_LAUNCHER={LAUNCHER}")
    out = run(*configure)
    assert "lab_msgs" in next(line for line in out.splitlines() if "message packages" in line)
    run("cmake", "--build", str(build), "--target", "ros2vtk_regenerate")
    golden = source / "generated" / "messages"
    assert (golden / "include/ros2vtk/lab_msgs/msg/needle_target.hpp").exists()
    args_file = build / "msg_specs" / "ros2vtkMessages_args.json"
    golden_check = ["cmake", "-DPYTHON=/usr/bin/python3", f"-DGENERATOR_DIR={source / 'generator'}",
                    f"-DARGS_FILE={args_file}", f"-DGOLDEN_DIR={golden}",
                    f"-DOUTPUT_DIR={WORK / 'regenerated'}", f"-DBUILD_DIR={build}",
                    "-P", str(source / "tests/golden/check_golden.cmake")]
    run(*golden_check)
    # It builds: lab_msgs' generated sources compile against ros2vtk::Message.
    # The generated files compile in unity batches (cmake/ros2vtk_generate.cmake): build the
    # batches that include lab_msgs' two files (needle_target__cdr.cpp, __type_support.cpp).
    unity = build / "msg_specs" / "CMakeFiles" / "ros2vtkMessages.dir" / "Unity"
    batches = sorted(p for p in unity.glob("unity_*_cxx.cxx") if "lab_msgs" in p.read_text())
    included = [line for p in batches for line in p.read_text().splitlines() if "lab_msgs" in line]
    assert len(included) == 2, included
    objects = [str(p.relative_to(build)) + ".o" for p in batches]
    run("ninja", "-C", str(build), *objects)
    out_dir = build / "msg_specs" / "ros2vtkMessages"
    assert lab_files(out_dir), "the build generated no lab_msgs file"

    # Remove: the same command gives back the repository's generated/ and a clean build/install.
    shutil.rmtree(source / "msg_specs" / "lab_msgs")
    run("cmake", "--build", str(build), "--target", "ros2vtk_regenerate")
    assert same_tree(golden, REPO / "generated" / "messages") == []
    run(*golden_check)
    register = out_dir / "src" / "register_types.cpp"
    run("ninja", "-C", str(build), str(register.relative_to(build)))  # the generate step
    assert lab_files(out_dir) == []
    assert "lab_msgs" not in register.read_text()
    run("cmake", "--install", str(build), "--prefix", str(install))
    assert (install / "include/ros2vtk/std_msgs/msg/header.hpp").exists()
    assert lab_files(install) == []
