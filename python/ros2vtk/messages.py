"""Typed message objects in Python: any registered ROS type, field by field.

    msg = ros2vtk.Message('geometry_msgs/msg/TransformStamped')
    msg.header.stamp.sec = 12                   # attribute access, as rclpy messages
    msg.child_frame_id = 'tool'
    msg.GetHeader().GetStamp().SetNanosec(5)    # SlicerROS2's Get<Field>() / Set<Field>() style
    publisher.PublishMessageObject(msg.vtk)     # exactly these values on the wire
    subscriber.GetLastMessageObject(msg.vtk)    # or ros2vtk.Message.last_of(subscriber)

A Message wraps a ``vtkROS2Message`` (``.vtk``); a nested field is a view into the same message,
so writing through it changes the message. Sequences of numbers, bools and strings read as
Python lists and are set from any iterable; a sequence of messages reads as a list of views.
Every type the registry knows works, with no per-type code (the C++ class reads the generated
introspection tables).
"""
from __future__ import annotations

import math
from typing import Any, List

_INTEGERS = ('byte', 'char', 'int8', 'uint8', 'int16', 'uint16', 'int32', 'uint32', 'int64',
             'uint64')
_FLOATS = ('float32', 'float64')


def _vtk_message_class():
    import ros2vtk  # late: this module is imported by the package itself
    return ros2vtk.vtkROS2Message


def _camel(name: str) -> str:
    """frame_id -> FrameId (SlicerROS2's accessor spelling)."""
    return ''.join(part[:1].upper() + part[1:] for part in name.split('_'))


class Message:
    """A typed ROS message (see the module doc). ``Message(ros_type)`` makes a default one."""

    __slots__ = ('vtk', '_path')

    def __init__(self, ros_type: str | None = None, *, _vtk=None, _path: str = '') -> None:
        object.__setattr__(self, 'vtk', _vtk if _vtk is not None else _vtk_message_class()())
        object.__setattr__(self, '_path', _path)
        if ros_type is not None and not self.vtk.SetROSType(ros_type):
            raise ValueError(self.vtk.GetLastError())

    # ------------------------------------------------------------------ construction helpers
    @classmethod
    def of(cls, vtk_message) -> 'Message':
        """Wraps a vtkROS2Message a node handed out (a service client's CreateBlankRequest or
        GetLastResponse) for attribute and Get<Field>/Set<Field> access; writes go to it."""
        if vtk_message is None:
            raise ValueError('no message object (None)')
        return cls(_vtk=vtk_message)

    @classmethod
    def last_of(cls, subscriber) -> 'Message':
        """The newest message of a subscriber node; raises LookupError before the first."""
        message = cls()
        if not subscriber.GetLastMessageObject(message.vtk):
            raise LookupError('no message received yet on ' + str(subscriber.GetTopic()))
        return message

    @classmethod
    def from_yaml(cls, ros_type: str, yaml: str) -> 'Message':
        message = cls(ros_type)
        message.set_yaml(yaml)
        return message

    # ------------------------------------------------------------------ introspection
    @property
    def ros_type(self) -> str:
        return self.vtk.GetFieldType(self._path) if self._path else self.vtk.GetROSType()

    def field_names(self) -> List[str]:
        count = self.vtk.GetNumberOfFields(self._path)
        return [self.vtk.GetFieldName(self._path, i) for i in range(max(count, 0))]

    def field_type(self, name: str) -> str:
        return self.vtk.GetFieldType(self._child(name))

    # ------------------------------------------------------------------ whole-message forms
    def yaml(self) -> str:
        return self.vtk.GetYAML() if not self._path else self.vtk.GetField(self._path)

    def set_yaml(self, yaml: str) -> None:
        if self._path:
            whole = Message(self.ros_type)
            whole.set_yaml(yaml)
            if not self.vtk.SetMessage(self._path, whole.vtk):
                raise ValueError(self.vtk.GetLastError())
        elif not self.vtk.SetYAML(yaml):
            raise ValueError(self.vtk.GetLastError())

    def serialize(self) -> bytes:
        import vtkmodules.vtkCommonCore as core  # Debian's VTK Python
        data = core.vtkUnsignedCharArray()
        if not self._whole().vtk.Serialize(data):
            raise ValueError(self.vtk.GetLastError())
        return bytes(data.GetValue(i) for i in range(data.GetNumberOfValues()))

    def deserialize(self, payload: bytes) -> None:
        import vtkmodules.vtkCommonCore as core
        data = core.vtkUnsignedCharArray()
        data.SetNumberOfValues(len(payload))
        for i, byte in enumerate(payload):
            data.SetValue(i, byte)
        if not self._whole().vtk.Deserialize(data):
            raise ValueError(self.vtk.GetLastError())

    def copy(self) -> 'Message':
        """An independent message holding this one (or this nested field's) values."""
        duplicate = Message()
        if not self.vtk.GetMessage(self._path, duplicate.vtk):
            raise ValueError(self.vtk.GetLastError())
        return duplicate

    # ------------------------------------------------------------------ field access
    def get(self, name: str) -> Any:
        return self._read(self._child(name))

    def set(self, name: str, value: Any) -> None:
        self._write(self._child(name), value)

    def __getattr__(self, name: str) -> Any:
        if name.startswith('_'):
            raise AttributeError(name)
        if name in self.field_names():
            return self.get(name)
        accessor = self._accessor(name)
        if accessor is not None:
            return accessor
        raise AttributeError(f"{self.ros_type} has no field '{name}' "
                             f"(fields: {', '.join(self.field_names())})")

    def __setattr__(self, name: str, value: Any) -> None:
        if name not in self.field_names():
            raise AttributeError(f"{self.ros_type} has no field '{name}' "
                                 f"(fields: {', '.join(self.field_names())})")
        self.set(name, value)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Message):
            return NotImplemented
        return self.copy().vtk.Equals(other.copy().vtk)

    def __repr__(self) -> str:
        return f'<ros2vtk.Message {self.ros_type}>\n{self.yaml()}'

    def __dir__(self) -> List[str]:
        names = self.field_names()
        return sorted(set(super().__dir__()) | set(names) |
                      {prefix + _camel(n) for n in names for prefix in ('Get', 'Set')})

    # ------------------------------------------------------------------ internals
    def _child(self, name: str) -> str:
        return f'{self._path}.{name}' if self._path else name

    def _whole(self) -> 'Message':
        return self if not self._path else self.copy()

    def _accessor(self, name: str):
        """GetFrameId() / SetFrameId(v) for field frame_id (SlicerROS2's typed-object style)."""
        if len(name) <= 3 or name[:3] not in ('Get', 'Set'):
            return None
        wanted = name[3:]
        field = next((n for n in self.field_names() if _camel(n) == wanted), None)
        if field is None:
            return None
        if name.startswith('Get'):
            return lambda: self.get(field)
        return lambda value: self.set(field, value)

    def _fail(self) -> None:
        raise ValueError(self.vtk.GetLastError())

    def _read(self, path: str) -> Any:
        kind = self.vtk.GetFieldType(path)
        if not kind:
            self._fail()
        if self.vtk.IsArrayField(path):
            length = self.vtk.GetFieldLength(path)
            return [self._read_element(f'{path}[{i}]') for i in range(length)]
        return self._read_element(path)

    def _read_element(self, path: str) -> Any:
        kind = self.vtk.GetFieldType(path)
        if self.vtk.IsMessageField(path):
            return Message(_vtk=self.vtk, _path=path)
        text = self.vtk.GetField(path)
        if self.vtk.GetLastError():
            self._fail()
        base = kind.split('<=')[0]
        if base == 'bool':
            return text == 'true'
        if base in _INTEGERS:
            return int(text)
        if base in _FLOATS:
            return {'.nan': math.nan, '.inf': math.inf, '-.inf': -math.inf}.get(text) \
                if text in ('.nan', '.inf', '-.inf') else float(text)
        return text

    def _write(self, path: str, value: Any) -> None:
        if self.vtk.IsArrayField(path):
            items = list(value) if not isinstance(value, (str, bytes)) else list(value)
            if self.vtk.GetFieldLength(path) != len(items) and \
                    not self.vtk.SetFieldLength(path, len(items)):
                self._fail()
            for i, item in enumerate(items):
                self._write_element(f'{path}[{i}]', item)
            return
        self._write_element(path, value)

    def _write_element(self, path: str, value: Any) -> None:
        if self.vtk.IsMessageField(path):
            if isinstance(value, Message):
                source = value.copy()
                if not self.vtk.SetMessage(path, source.vtk):
                    self._fail()
                return
            if isinstance(value, dict):
                view = Message(_vtk=self.vtk, _path=path)
                for key, item in value.items():
                    view.set(key, item)
                return
            raise TypeError(f"field '{path}' is a {self.vtk.GetFieldType(path)}: give a Message "
                            'or a dict of its fields')
        kind = self.vtk.GetFieldType(path).split('<=')[0]
        if kind == 'bool':
            text = 'true' if value else 'false'
        elif kind in _FLOATS:
            number = float(value)
            text = repr(number) if math.isfinite(number) else str(number)
        elif kind in _INTEGERS:
            if isinstance(value, float) and not value.is_integer():
                raise ValueError(f"field '{path}' is {kind}: {value} is not a whole number")
            text = str(int(value))
        else:
            text = str(value)
        if not self.vtk.SetField(path, text):
            self._fail()



# --- SlicerROS2's accessors on the VTK message objects themselves -------------------------------
# SlicerROS2 scripts call Get<Field>() / Set<Field>() straight on the objects a node hands out
# (`req = client.CreateBlankRequest(); req.SetX(4.0)`, `client.GetLastResponse().GetName()`).
# vtkROS2Message is one generic C++ class, so those names cannot be wrapped methods; a Python
# subclass answers them through a Message view, and is made the class of every vtkROS2Message
# that reaches Python, also those created in C++. That is VTK's `override` (VTK >= 9.2); on
# Debian's VTK 9.1, which lacks it, the same one-pointer change is made by hand below.
def _wrapping_core_library():
    import ctypes
    with open('/proc/self/maps') as maps:
        paths = {line.split()[-1] for line in maps if 'libvtkWrappingPythonCore' in line}
    if len(paths) != 1:
        return None
    return ctypes.CDLL(paths.pop())


def _override_vtk_class(base, subclass) -> str:
    """Makes `subclass` the Python class of every `base` object (VTK's vtkObject.override).
    Returns '' or why it was not possible."""
    if hasattr(base, 'override'):
        base.override(subclass)
        return ''
    import ctypes
    library = _wrapping_core_library()
    if library is None:
        return 'the VTK Python wrapping library is not loaded exactly once'
    try:
        find_class = library._ZN13vtkPythonUtil9FindClassEPKc  # vtkPythonUtil::FindClass(const char*)
    except AttributeError:
        return 'vtkPythonUtil::FindClass is not exported'
    find_class.restype = ctypes.POINTER(ctypes.c_void_p)  # PyVTKClass*: py_type comes first
    find_class.argtypes = [ctypes.c_char_p]
    entry = find_class(base.__vtkname__.encode() if hasattr(base, '__vtkname__') else base.__name__.encode())
    if not entry or entry[0] != id(base):
        return 'the class table entry does not hold the expected Python type'
    entry[0] = id(subclass)
    return ''


def _method_or_field_accessor(method, name: str):
    def call(self, *args):
        try:
            return method(self, *args)
        except TypeError:
            if len(args) != (0 if name.startswith('Get') else 1):
                raise
            accessor = Message.of(self)._accessor(name)
            if accessor is None:
                raise
            return accessor(*args)
    call.__name__ = name
    call.__doc__ = method.__doc__
    return call


def install_accessors_on_vtk_messages() -> str:
    """Called once by the package; returns '' or why the accessors are missing (then scripts
    wrap objects with Message.of)."""
    import ros2vtk
    base = ros2vtk.vtkROS2Message

    class vtkROS2Message(base):  # noqa: N801 - keeps the VTK class name in reprs and errors
        __doc__ = base.__doc__

        def __getattr__(self, name: str) -> Any:
            if name.startswith(('Get', 'Set')) and not name.startswith('__'):
                return getattr(Message.of(self), name)
            raise AttributeError(f"'vtkROS2Message' object has no attribute '{name}'")

        def __dir__(self) -> List[str]:
            return sorted(set(super().__dir__()) | set(Message.of(self).__dir__()))

    # A field whose accessor is also a C++ method (`message` and GetMessage(path, out) of
    # Trigger's response, `field`, `yaml`, ...): the C++ method when the arguments fit it, the
    # field's accessor when they fit only that (Get: none, Set: one value).
    for name in dir(base):
        if name.startswith(('Get', 'Set')) and callable(getattr(base, name)):
            setattr(vtkROS2Message, name, _method_or_field_accessor(getattr(base, name), name))
    vtkROS2Message.__module__ = base.__module__
    vtkROS2Message.__qualname__ = base.__qualname__
    why = _override_vtk_class(base, vtkROS2Message)
    if not why:
        _overrides.append(vtkROS2Message)  # the table points at it: keep it alive
    return why


_overrides: list = []
