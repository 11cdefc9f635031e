"""Command line: `python3 -m ros2vtk_gen --args-file args.json [--list-outputs]`.

CMake passes one JSON file (like rosidl) so long spec lists never hit command-line limits:
  {"family": "messages", "target": "ros2vtkMessages", "output_dir": "...",
   "specs": ["..."], "dependencies": [{"target": "...", "specs": ["..."]}],
   "templates_dir": "..." (optional)}
Family "nodes" adds "mappings": [".toml"], "messages_target" and "library" (see nodes.py).
For use by hand, the same can be given as options (--target, --output-dir, specs...).
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import sys
from typing import List, Optional

from . import __version__
from .emit import FAMILIES, Config, expand_spec_paths, generate, list_outputs
from .errors import GeneratorError


def _config_from_json(path: str) -> Config:
    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
    except OSError as error:
        raise GeneratorError(f"{path}: cannot read args file: {error.strerror}", "R2V310") from None
    except json.JSONDecodeError as error:
        raise GeneratorError(f"{path}:{error.lineno}: args file is not JSON: {error.msg}",
                             "R2V310") from None
    if not isinstance(data, dict):
        raise GeneratorError(f"{path}: args file must hold a JSON object", "R2V310")
    missing = [key for key in ("target", "output_dir", "specs") if key not in data]
    if missing:
        raise GeneratorError(f"{path}: args file lacks {', '.join(missing)}", "R2V310")
    dependencies = tuple((str(d["target"]), tuple(expand_spec_paths(d.get("specs", []))))
                         for d in data.get("dependencies", []))
    return Config(family=str(data.get("family", "messages")), target=str(data["target"]),
                  output_dir=str(data["output_dir"]),
                  specs=tuple(expand_spec_paths(data["specs"])), dependencies=dependencies,
                  templates_dir=data.get("templates_dir"),
                  mappings=tuple(str(m) for m in data.get("mappings", [])),
                  messages_target=str(data.get("messages_target", "")),
                  library=str(data.get("library", "")))


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ros2vtk_gen", description=__doc__.splitlines()[0])
    parser.add_argument("--version", action="version", version=f"ros2vtk_gen {__version__}")
    parser.add_argument("--args-file", help="JSON file with every argument (what CMake uses)")
    parser.add_argument("--family", default=None, choices=FAMILIES,
                        help="artefact family to emit (default: messages)")
    parser.add_argument("--target", help="library target name (names the register function)")
    parser.add_argument("--output-dir", help="folder that receives include/ and src/")
    parser.add_argument("--dependency-spec", action="append", default=[],
                        help="spec (or folder) of another target, to resolve types; not emitted")
    parser.add_argument("--templates-dir", help="templates folder (default: the repository's)")
    parser.add_argument("--mapping", action="append", default=[],
                        help="family nodes: a mapping rule file (.toml); repeat for more")
    parser.add_argument("--messages-target", default="",
                        help="family nodes: the target holding the mapped message types")
    parser.add_argument("--list-outputs", action="store_true",
                        help="print the absolute output paths, one per line, and exit")
    parser.add_argument("specs", nargs="*", help=".msg/.srv files or folders")
    return parser


def _config(args: argparse.Namespace) -> Config:
    if args.args_file:
        config = _config_from_json(args.args_file)
        if args.family:
            config = dataclasses.replace(config, family=args.family)
        return config
    if not args.target or not args.output_dir or not args.specs:
        raise GeneratorError("give --args-file, or --target, --output-dir and spec files",
                             "R2V310")
    dependencies = (("", tuple(expand_spec_paths(args.dependency_spec))),) \
        if args.dependency_spec else ()
    return Config(args.family or "messages", args.target, args.output_dir,
                  tuple(expand_spec_paths(args.specs)), dependencies, args.templates_dir,
                  mappings=tuple(args.mapping), messages_target=args.messages_target)


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    try:
        config = _config(args)
        if args.list_outputs:
            import os
            for path in list_outputs(config):
                print(os.path.join(os.path.abspath(config.output_dir), path).replace(os.sep, "/"))
            return 0
        generate(config)
    except GeneratorError as error:
        print(str(error), file=sys.stderr)
        return 1
    return 0
