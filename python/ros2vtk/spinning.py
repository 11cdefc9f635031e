"""Spinning a ros2vtk logic from Python without a render window's timer.

`spin_until` spins until something happened (a message came, a robot loaded): the loop sleeps
in SpinOnWakeUp until data arrives (or `step` seconds pass, for conditions no message signals),
so it neither busy-waits nor adds a fixed delay to every message.

    from ros2vtk import spin_until
    assert spin_until(logic, lambda: robot.IsLoaded(), seconds=10)

(For a fixed time, vtkROS2Logic.SpinFor(seconds) spins at the logic's rate.)

`spin_at_prompt` is SlicerROS2's 50 Hz timer for the interactive interpreter: while the `>>>`
prompt (or `input()` on a terminal, or IPython's terminal prompt) waits for a line, the logic
spins at its SpinRate on the main thread, so observers fire and GetLastMessage() is current between typed commands, as in
Slicer's Python console. A running script is not interrupted (Slicer's timer does not fire
while a script runs either); it spins with Spin / SpinFor / spin_until. `getModuleLogic()`
turns it on for the process-wide logic it returns.
"""
from __future__ import annotations

import atexit
import ctypes
import select
import sys
import time
import warnings
from typing import Callable, Optional


def spin_until(logic, done: Callable[[], bool], seconds: float = 10.0, step: float = 0.05) -> bool:
    """Spins `logic` (a vtkROS2Logic) until `done()` is true or `seconds` have passed; returns
    `done()`. `seconds <= 0` checks once after one spin."""
    end = time.monotonic() + max(seconds, 0.0)
    while True:
        logic.SpinOnWakeUp(step)
        if done():
            return True
        if time.monotonic() >= end:
            return bool(done())


# --- the prompt hook ------------------------------------------------------------------------------
# PyOS_InputHook (int (*)(void)) is called by the interpreter's line reader (PyOS_Readline: the
# interactive prompt and input() on a terminal) while it waits for input, without the GIL; a
# ctypes CFUNCTYPE callback takes the GIL itself. This is how tkinter keeps Tk alive at the prompt
# (and, as tkinter's, it watches the stdin descriptor: the interpreter keeps no lines read ahead
# in C's stdin buffer in interactive mode, so a pasted block runs at once).
_HOOK_SIGNATURE = ctypes.CFUNCTYPE(ctypes.c_int)
_hook_state: dict = {'logic': None, 'callback': None}


def _input_hook_address() -> ctypes.c_void_p:
    return ctypes.c_void_p.in_dll(ctypes.pythonapi, 'PyOS_InputHook')


def _stdin_fd() -> Optional[int]:
    try:
        return sys.stdin.fileno() if sys.stdin is not None else None
    except (AttributeError, ValueError, OSError):
        return None


def _spin_while_waiting_for_input() -> int:
    logic = _hook_state['logic']
    fd = _stdin_fd()
    if logic is None or fd is None:
        return 0
    try:
        period = 1.0 / max(float(logic.GetSpinRate()), 1.0)
        while True:
            logic.Spin()
            readable, _, _ = select.select([fd], [], [], period)
            if readable:
                return 0
    except KeyboardInterrupt:
        return 0
    except Exception as error:  # never let an error escape into the interpreter's reader
        spin_at_prompt(None)
        print(f'ros2vtk: spinning at the prompt stopped: {error}', file=sys.stderr)
        return 0


# --- IPython's prompt -------------------------------------------------------------------------
# IPython's terminal reads lines with prompt_toolkit, which never calls PyOS_InputHook; it runs
# an event-loop integration instead (`%gui qt` and the like: IPython.terminal.pt_inputhooks).
# Ours is registered under the name 'ros2vtk' and turned on with the shell's enable_gui, as
# `%gui ros2vtk` would; `%gui` (no name) turns it off again.
IPYTHON_GUI_NAME = 'ros2vtk'


def _spin_until_ipython_input(context) -> None:
    """pt_inputhooks' contract: return once prompt_toolkit has input (context.input_is_ready)."""
    logic = _hook_state['logic']
    if logic is None:
        return
    try:
        period = 1.0 / max(float(logic.GetSpinRate()), 1.0)
        while not context.input_is_ready():
            logic.Spin()
            select.select([context.fileno()], [], [], period)
    except KeyboardInterrupt:
        return
    except Exception as error:  # never let an error escape into IPython's prompt
        _hook_state['logic'] = None
        print(f'ros2vtk: spinning at the IPython prompt stopped: {error}', file=sys.stderr)


def _ipython_terminal_shell():
    """The running IPython terminal shell (prompt_toolkit's), or None outside one."""
    ipython = sys.modules.get('IPython')
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is None or not hasattr(shell, 'active_eventloop') or getattr(shell, 'simple_prompt', True):
        return None  # a kernel, or --simple-prompt (reads with input(): PyOS_InputHook serves it)
    return shell


def _ipython_spin(shell, on: bool) -> bool:
    current = shell.active_eventloop
    if not on:
        if current == IPYTHON_GUI_NAME:
            shell.enable_gui(None)
        return True
    if current not in (None, IPYTHON_GUI_NAME):
        warnings.warn(f"ros2vtk: IPython's prompt already runs the '{current}' event loop (%gui); "
                      'spin with logic.Spin(), SpinFor() or spin_until() instead',
                      RuntimeWarning, stacklevel=3)
        return False
    from IPython.terminal.pt_inputhooks import register
    register(IPYTHON_GUI_NAME, _spin_until_ipython_input)
    if current is None:
        shell.enable_gui(IPYTHON_GUI_NAME)
    return True


def spin_at_prompt(logic) -> bool:
    """Spins `logic` (a vtkROS2Logic) at its SpinRate while the interpreter waits for a typed
    line (the `>>>` prompt, input(), and IPython's terminal prompt); `spin_at_prompt(None)`
    stops. Returns False (with a warning) when another library (tkinter, a GUI toolkit, another
    %gui) already owns the prompt's input hook."""
    shell = _ipython_terminal_shell()
    if shell is not None and not _ipython_spin(shell, logic is not None):
        return False
    hook = _input_hook_address()
    ours = _hook_state['callback']
    ours_address = ctypes.cast(ours, ctypes.c_void_p).value if ours is not None else None
    if logic is None:
        if ours_address is not None and hook.value == ours_address:
            hook.value = None
        _hook_state['logic'] = None
        return True
    if hook.value and hook.value != ours_address:
        warnings.warn('ros2vtk: another library already uses the interactive prompt\'s input hook '
                      '(PyOS_InputHook); spin with logic.Spin(), SpinFor() or spin_until() instead',
                      RuntimeWarning, stacklevel=2)
        return False
    if ours is None:
        ours = _hook_state['callback'] = _HOOK_SIGNATURE(_spin_while_waiting_for_input)
        # The interpreter must not call into a freed callback (or a deleted logic) at exit.
        atexit.register(spin_at_prompt, None)
    _hook_state['logic'] = logic
    hook.value = ctypes.cast(ours, ctypes.c_void_p).value
    return True


def spinning_at_prompt():
    """The logic spun by the prompt hook, or None."""
    shell = _ipython_terminal_shell()
    if shell is not None and shell.active_eventloop != IPYTHON_GUI_NAME:
        return None
    hook = _input_hook_address()
    ours = _hook_state['callback']
    if ours is None or hook.value != ctypes.cast(ours, ctypes.c_void_p).value:
        return None
    return _hook_state['logic']


# --- SlicerROS2's module logic ------------------------------------------------------------------
_module_logic: dict = {}


def getModuleLogic(name: str = 'ROS2'):  # noqa: N802 - slicer.util.getModuleLogic's spelling
    """The process-wide vtkROS2Logic, as `slicer.util.getModuleLogic('ROS2')` gives Slicer's:
    created on the first call, kept alive by this module (its nodes never outlive it), and spun
    at the interactive prompt (spin_at_prompt). Only 'ROS2' is known."""
    if name != 'ROS2':
        raise ValueError(f"ros2vtk.getModuleLogic: unknown module '{name}' (only 'ROS2')")
    logic = _module_logic.get(name)
    if logic is None:
        import ros2vtk  # late: this module is imported by the package itself
        logic = _module_logic[name] = ros2vtk.vtkROS2Logic()
        spin_at_prompt(logic)
    return logic
