"""ros2vtk: ROS 2 publishers, subscribers and nodes as VTK objects, without a ROS install.

    import ros2vtk
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('String', '/pub')
    pub.Publish('Hello world.')
    logic.Spin()                      # or: ros2vtk.spin_until(logic, lambda: ..., seconds=5)

SlicerROS2 scripts: `rosLogic = ros2vtk.getModuleLogic('ROS2')` gives one process-wide logic
that also spins while the interactive prompt waits (ros2vtk.spin_at_prompt).

Every VTK-wrapped extension module in this package (the runtime's ``ros2vtkScene`` and any
generated node module built next to it, or in a downstream build's ``python/ros2vtk/`` found on
``sys.path``) is imported here and its ``vtk*`` classes are re-exported, so
``ros2vtk.vtkROS2Logic`` and the generated ``ros2vtk.vtkROS2PublisherStringNode`` are reached
the same way. Importing a generated module also registers its node classes, which is
what makes ``CreateAndAddPublisherNode('String', ...)`` find them.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import os
import pkgutil
from types import ModuleType
from typing import Dict, List

# A downstream project's wrapped node module lands in <its build>/python/ros2vtk/ (no
# __init__.py there): with that folder's parent on sys.path, it joins this package.
__path__ = pkgutil.extend_path(__path__, __name__)

# The runtime's module first: generated modules depend on it.
_CORE_MODULE = 'ros2vtkScene'


def _extension_module_names() -> List[str]:
    """Names of the compiled modules of this package, core first, the rest sorted."""
    names = set()
    for folder in __path__:
        for entry in (os.listdir(folder) if os.path.isdir(folder) else []):
            # Longest suffix first (.cpython-311-x86_64-linux-gnu.so before .so).
            suffix = next((s for s in importlib.machinery.EXTENSION_SUFFIXES
                           if entry.endswith(s)), None)
            if suffix and '.' not in entry[:-len(suffix)]:
                names.add(entry[:-len(suffix)])
    names = sorted(names)
    if _CORE_MODULE in names:
        names.remove(_CORE_MODULE)
        names.insert(0, _CORE_MODULE)
    return names


def _import_extension_modules() -> Dict[str, ModuleType]:
    modules: Dict[str, ModuleType] = {}
    for name in _extension_module_names():
        modules[name] = importlib.import_module(f'{__name__}.{name}')
    if _CORE_MODULE not in modules:
        raise ImportError(f'ros2vtk: the wrapped module {_CORE_MODULE} is missing from {__path__}; '
                          'build the project with ROS2VTK_WRAP_PYTHON=ON')
    return modules


def _point_at_this_environments_xacro() -> None:
    """Robot nodes expand .xacro files with the xacro program (runtime/Robot XacroProcessor):
    the one installed next to this Python (a venv's bin/, active or not) unless the user named one
    in ROS2VTK_XACRO."""
    import sys
    candidate = os.path.join(os.path.dirname(sys.executable), 'xacro')
    if 'ROS2VTK_XACRO' not in os.environ and os.access(candidate, os.X_OK):
        os.environ['ROS2VTK_XACRO'] = candidate


_point_at_this_environments_xacro()
extension_modules: Dict[str, ModuleType] = _import_extension_modules()

__all__: List[str] = []
for _module in extension_modules.values():
    for _name in dir(_module):
        if _name.startswith('vtk'):
            globals()[_name] = getattr(_module, _name)
            __all__.append(_name)
del _module, _name

from .spinning import spin_until, spin_at_prompt, spinning_at_prompt, getModuleLogic  # noqa: E402 (after the classes it spins)
from .messages import Message, install_accessors_on_vtk_messages  # noqa: E402 (wraps vtkROS2Message)

# SlicerROS2's req.SetX(4.0) / res.GetName() on the message objects nodes hand out.
vtk_message_accessors_missing: str = install_accessors_on_vtk_messages()

from .blank_messages import VTKFieldMessage, install_message_blanks  # noqa: E402

# SlicerROS2's msg = pub.GetBlankMessage(); msg.GetHeader().SetFrameId('world') on the
# publishers of the types it generates a message class for (PoseArray, WrenchStamped, …).
message_blanks_missing: str = install_message_blanks(globals())

__all__ += ['VTKFieldMessage', 'spin_until', 'spin_at_prompt', 'spinning_at_prompt', 'getModuleLogic', 'Message']
