#!/usr/bin/env python3
"""No include cycles between the classes of a runtime folder (issue: the ROS-node hub and its
child kinds included each other). A class is a .h/.hpp with its .cxx/.cpp; class A depends on B
when A's header or source includes B's header. Prints every cycle found and exits 1 if any.

    check_include_cycles.py [--allow A,B ...] FOLDER [FOLDER ...]

--allow names a group of classes that may depend on each other (exactly that group), for a
pair that is one design by nature: the scene and its node base (vtkROS2Scene <-> vtkROS2SceneNode,
as vtkMRMLScene <-> vtkMRMLNode: the document holds nodes, a node resolves its references
through its document).
"""
from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Dict, List, Set

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def classes_of(folders: List[Path]) -> Dict[str, List[Path]]:
    files: Dict[str, List[Path]] = {}
    for folder in folders:
        for path in sorted(folder.iterdir()):
            if path.suffix in ('.h', '.hpp', '.cxx', '.cpp'):
                files.setdefault(path.stem, []).append(path)
    return files


def dependencies(files: Dict[str, List[Path]]) -> Dict[str, Set[str]]:
    graph: Dict[str, Set[str]] = {name: set() for name in files}
    for name, paths in files.items():
        for path in paths:
            for included in INCLUDE.findall(path.read_text(errors='replace')):
                stem = Path(included).stem
                if stem != name and stem in files:
                    graph[name].add(stem)
    return graph


def cycles(graph: Dict[str, Set[str]]) -> List[List[str]]:
    """Strongly connected components with more than one class (Tarjan)."""
    index: Dict[str, int] = {}
    low: Dict[str, int] = {}
    stack: List[str] = []
    on_stack: Set[str] = set()
    found: List[List[str]] = []
    counter = [0]

    def visit(node: str) -> None:
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for other in sorted(graph[node]):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                item = stack.pop()
                on_stack.discard(item)
                component.append(item)
                if item == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def main(argv: List[str]) -> int:
    args = argv[1:]
    allowed = []
    while len(args) >= 2 and args[0] == '--allow':
        allowed.append(sorted(args[1].split(',')))
        args = args[2:]
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    graph = dependencies(classes_of([Path(a) for a in args]))
    found = [component for component in cycles(graph) if component not in allowed]
    for component in found:
        print('include cycle: ' + ' <-> '.join(component))
        for name in component:
            print(f'  {name} includes: ' + ', '.join(sorted(graph[name] & set(component))))
    if not found:
        print(f'no include cycles among {len(graph)} classes')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
