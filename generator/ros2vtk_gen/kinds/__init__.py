"""The mapping kinds, collected from the modules of this folder (one per kind, each defining
`KIND` or `KINDS`): adding a kind is a module here plus its template in templates/convert/kinds/.
"""
from __future__ import annotations

import importlib
import pkgutil
from typing import Dict

from .base import Kind


def _collect() -> Dict[str, Kind]:
    kinds: Dict[str, Kind] = {}
    for module_info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        if module_info.name == "base":
            continue
        module = importlib.import_module(f"{__name__}.{module_info.name}")
        found = getattr(module, "KINDS", None) or (getattr(module, "KIND"),)
        for kind in found:
            if kind.name in kinds:
                raise RuntimeError(f"kind {kind.name} is defined twice ({module_info.name})")
            kinds[kind.name] = kind
    return kinds


KINDS: Dict[str, Kind] = _collect()
