#!/usr/bin/env python3
"""Fails when a hand-written C++ file differs from what clang-format makes of it (.clang-format at
the repository root). generated/ follows its templates and is left out, as .clang-format says."""
from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

SOURCE_FOLDERS = ("runtime", "tests", "examples")
SUFFIXES = {".cpp", ".hpp", ".h", ".cxx", ".cc", ".txx"}


def cpp_files(root: Path) -> list[Path]:
    files = []
    for folder in SOURCE_FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in SUFFIXES and path.is_file():
                files.append(path)
    return files


def unformatted(clang_format: str, files: list[Path]) -> list[str]:
    bad = []
    for path in files:
        formatted = subprocess.run([clang_format, "--style=file", str(path)], check=True,
                                   capture_output=True).stdout
        if formatted != path.read_bytes():
            bad.append(str(path))
    return bad


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("root", type=Path, help="repository root")
    parser.add_argument("--clang-format", default="clang-format")
    args = parser.parse_args()
    clang_format = shutil.which(args.clang_format)
    if clang_format is None:
        print(f"check_format: '{args.clang_format}' not found; scripts/setup.sh installs it "
              "(Debian package clang-format)")
        return 1
    files = cpp_files(args.root.resolve())
    bad = unformatted(clang_format, files)
    if bad:
        print(f"check_format: {len(bad)} of {len(files)} C++ files are not clang-formatted; "
              "run clang-format -i on:")
        for path in bad:
            print(f"  {path}")
        return 1
    print(f"check_format: {len(files)} C++ files match .clang-format")
    return 0


if __name__ == "__main__":
    sys.exit(main())
