"""SlicerROS2's blank messages for the mapped publishers whose type it generates a class for.

In SlicerROS2, ``pub = node.CreateAndAddPublisherNode('PoseArray', '/x')`` and
``msg = pub.GetBlankMessage()`` give its generated message object: ``msg.GetHeader()
.SetFrameId('world')``, ``msg.GetHeader().GetStamp().SetSec(12)``, ``msg.SetPoses((m1, m2))``
with ``vtkMatrix4x4`` poses, then ``pub.Publish(msg)``. A field whose type SlicerROS2 converts
(a Pose or Transform is a ``vtkMatrix4x4``, a Wrench or Twist a ``vtkDoubleArray``) is that VTK
object, filled in place (``msg.GetWrench().SetValue(0, 1.5)``).

Here the same: the publishers whose mapping rule says ``blank_message = "message"``
(msg_specs/mappings) hand out a :class:`VTKFieldMessage` of their ROS type, and their
``Publish`` takes it as well as their VTK value. Which fields are VTK objects needs no list of
types: a field is one when its ROS type is the type of exactly one VTK conversion among the
mapped publisher classes (geometry_msgs/Pose: the ``Pose`` rule's ``vtkMatrix4x4``), and it is
converted by that publisher class's own rule (``ConvertObjectToMessage``: millimetres to metres,
matrix to quaternion) when the message is published. Other fields are the typed message's
(:class:`ros2vtk.Message`): ``Get<Field>()`` / ``Set<Field>(v)``, nested messages as views.

The subscribers of those types give the same kind of object from ``GetLastMessage()``, as
SlicerROS2's do (``GetNewMessage(i)``, which SlicerROS2 lacks, still gives VTK values):
``sub.GetLastMessage().GetHeader().GetFrameId()``,
``.GetPoses()`` (a tuple of ``vtkMatrix4x4`` in mm), ``.GetWrench()`` (a ``vtkDoubleArray``). Its
VTK fields are converted from the received message by the subscriber class of the field's type
(``ConvertMessageToObject``, the subscriber's ``ScaleLengths``). The subscriber's own VTK value
stays reachable: ``sub.GetLastVTKMessage()``, the fill-in form ``sub.GetLastMessage(value)``, and
C++ ``GetLastMessage()``, which is unchanged.
"""
from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

from .messages import Message, _camel, _override_vtk_class


def _element_type(field_type: str) -> str:
    """'geometry_msgs/msg/Pose[]' / '…[<=3]' / '…[3]' -> 'geometry_msgs/msg/Pose'."""
    return field_type.split('[', 1)[0]


def _hands_out_messages(publisher) -> bool:
    """The generated GetBlankMessageIsMessageObject (only classes whose rule asks have it)."""
    method = getattr(publisher, 'GetBlankMessageIsMessageObject', None)
    return bool(method()) if method is not None else False


def _returns_messages(subscriber) -> bool:
    """The generated GetLastMessageIsMessageObject (only classes whose rule asks have it)."""
    method = getattr(subscriber, 'GetLastMessageIsMessageObject', None)
    return bool(method()) if method is not None else False


def _subscriber_class(publisher_class: type) -> Optional[type]:
    """The subscriber class of the same mapping rule as `publisher_class`."""
    import ros2vtk
    name = publisher_class.__name__.replace('vtkROS2Publisher', 'vtkROS2Subscriber', 1)
    return getattr(ros2vtk, name, None)


class _FieldConverters:
    """ROS type -> the mapped publisher class that converts its VTK value, found once among the
    wrapped classes (no per-type list)."""

    def __init__(self) -> None:
        self._by_type: Optional[Dict[str, type]] = None

    def _scan(self) -> Dict[str, type]:
        import ros2vtk
        found: Dict[str, Dict[str, type]] = {}
        for name in sorted(dir(ros2vtk)):
            if not (name.startswith('vtkROS2Publisher') and name.endswith('Node')):
                continue
            try:
                instance = getattr(ros2vtk, name)()
                ros_type, vtk_type = instance.GetROSType(), instance.GetSlicerType()
            except (TypeError, AttributeError):  # abstract or not a publisher
                continue
            # A type SlicerROS2 has a message class for stays a nested message.
            if ros_type and vtk_type.startswith('vtk') and not _hands_out_messages(instance) \
                    and hasattr(instance, 'ConvertObjectToMessage'):
                found.setdefault(ros_type, {}).setdefault(vtk_type, getattr(ros2vtk, name))
        # A ROS type mapped to two VTK types (Joy: axes or buttons) has no single VTK value.
        return {ros_type: next(iter(by_vtk.values()))
                for ros_type, by_vtk in found.items() if len(by_vtk) == 1}

    def for_type(self, ros_type: str) -> Optional[type]:
        if self._by_type is None:
            self._by_type = self._scan()
        return self._by_type.get(ros_type)


_converters = _FieldConverters()


class _View:
    """One message level of a VTKFieldMessage (the message itself or a nested message field)."""

    __slots__ = ('_root', '_path')

    def __init__(self, root: 'VTKFieldMessage', path: str) -> None:
        object.__setattr__(self, '_root', root)
        object.__setattr__(self, '_path', path)

    def _typed(self) -> Message:
        return Message(_vtk=self._root.message.vtk, _path=self._path)

    def _child(self, name: str) -> str:
        return f'{self._path}.{name}' if self._path else name

    def _field_for(self, accessor: str) -> Optional[str]:
        wanted = accessor[3:]
        return next((n for n in self._typed().field_names() if _camel(n) == wanted), None)

    def __getattr__(self, name: str) -> Any:
        if name.startswith(('Get', 'Set')) and len(name) > 3:
            field = self._field_for(name)
            if field is not None:
                path = self._child(field)
                if name.startswith('Get'):
                    return lambda: self._root._get(path)
                return lambda value: self._root._set(path, value)
        typed = self._typed()
        raise AttributeError(f"{typed.ros_type} has no accessor '{name}' (fields: "
                             f"{', '.join(typed.field_names())}; call Get<Field>() / "
                             'Set<Field>(value))')

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"set fields with Set<Field>(value), not '{name} = …'")

    def __dir__(self) -> List[str]:
        names = self._typed().field_names()
        return sorted({prefix + _camel(n) for n in names for prefix in ('Get', 'Set')})

    def __repr__(self) -> str:
        return f'<ros2vtk.VTKFieldMessage view {self._typed().ros_type} at {self._path or "(root)"}>'


class VTKFieldMessage(_View):
    """A message of ``ros_type`` whose fields of mapped types are VTK objects (module doc).
    ``message`` is the typed message holding every other field."""

    __slots__ = ('message', '_values', '_received_scale')

    def __init__(self, ros_type: str) -> None:
        object.__setattr__(self, 'message', Message(ros_type))
        object.__setattr__(self, '_values', {})
        object.__setattr__(self, '_received_scale', None)
        super().__init__(self, '')

    @classmethod
    def received(cls, message: Message, scale_lengths: bool = True) -> 'VTKFieldMessage':
        """A received message (a subscriber's GetLastMessage): its VTK fields are converted
        from `message` on first read, lengths in mm unless `scale_lengths` is off."""
        result = cls(message.ros_type)
        object.__setattr__(result, 'message', message)
        object.__setattr__(result, '_received_scale', bool(scale_lengths))
        return result

    @property
    def ros_type(self) -> str:
        return self.message.ros_type

    # ------------------------------------------------------------------ fields
    def _converter(self, path: str) -> Optional[type]:
        return _converters.for_type(_element_type(self.message.vtk.GetFieldType(path)))

    def _get(self, path: str) -> Any:
        converter = self._converter(path)
        if converter is not None:
            if path not in self._values and self._received_scale is not None:
                self._values[path] = self._converted(converter, path)
            if self.message.vtk.IsArrayField(path):
                return tuple(self._values.get(path, ()))
            if path not in self._values:
                self._values[path] = converter().GetBlankMessage()
            return self._values[path]
        if self.message.vtk.IsMessageField(path) and not self.message.vtk.IsArrayField(path):
            return _View(self, path)
        return self.message._read(path)

    def _set(self, path: str, value: Any) -> None:
        converter = self._converter(path)
        if converter is not None:
            vtk_type = converter().GetSlicerType()
            is_sequence = self.message.vtk.IsArrayField(path)
            if is_sequence and (isinstance(value, (str, bytes)) or not hasattr(value, '__iter__')):
                raise TypeError(f"field '{path}' of {self.ros_type} takes a sequence of "
                                f"{vtk_type}, not {type(value).__name__}")
            items = list(value) if is_sequence else [value]
            for item in items:
                if not (hasattr(item, 'IsA') and item.IsA(vtk_type)):
                    raise TypeError(f"field '{path}' of {self.ros_type} takes "
                                    f"{'a sequence of ' if is_sequence else 'a '}{vtk_type}, "
                                    f"not {type(item).__name__}")
            self._values[path] = items if is_sequence else items[0]
            return
        if isinstance(value, _View):  # a nested message given whole: its fields, converted
            value = value._root.to_message().copy() if not value._path else \
                Message(_vtk=value._root.to_message().vtk, _path=value._path)
        self.message._write(path, value)

    def _converted(self, converter: type, path: str) -> Any:
        """The received field `path` as VTK value(s), converted by the subscriber class of the
        same rule as `converter` (a list for a sequence field)."""
        subscriber_class = _subscriber_class(converter)
        if subscriber_class is None:
            raise AttributeError(f"field '{path}' of {self.ros_type}: no subscriber class "
                                 f"for {converter.__name__}")
        subscriber = subscriber_class()
        subscriber.SetScaleLengths(self._received_scale)
        is_sequence = self.message.vtk.IsArrayField(path)
        paths = [f'{path}[{i}]' for i in range(self.message.vtk.GetFieldLength(path))] \
            if is_sequence else [path]
        values = []
        for item_path in paths:
            nested, value = Message(), converter().GetBlankMessage()
            if not self.message.vtk.GetMessage(item_path, nested.vtk):
                raise ValueError(f"field '{item_path}': {self.message.vtk.GetLastError()}")
            if not subscriber.ConvertMessageToObject(nested.vtk, value):
                raise ValueError(f"field '{item_path}': {subscriber.GetLastConversionError()}")
            values.append(value)
        return values if is_sequence else values[0]

    # ------------------------------------------------------------------ publishing
    def to_message(self, scale_lengths: bool = True) -> Message:
        """The typed message with every VTK field converted by its publisher class's rule."""
        result = self.message.copy()
        for path, value in sorted(self._values.items()):
            converter = self._converter(path)()
            converter.SetScaleLengths(scale_lengths)
            items: List[Tuple[str, Any]]
            if isinstance(value, list):
                if not result.vtk.SetFieldLength(path, len(value)):
                    raise ValueError(result.vtk.GetLastError())
                items = [(f'{path}[{i}]', item) for i, item in enumerate(value)]
            else:
                items = [(path, value)]
            for item_path, item in items:
                converted = Message()
                if not converter.ConvertObjectToMessage(item, converted.vtk):
                    raise ValueError(f"field '{item_path}': {converter.GetLastConversionError()}")
                if not result.vtk.SetMessage(item_path, converted.vtk):
                    raise ValueError(result.vtk.GetLastError())
        return result

    def __repr__(self) -> str:
        return f'<ros2vtk.VTKFieldMessage {self.ros_type}>'


def _publisher_handing_out_messages(base: type) -> type:
    """`base` (a mapped publisher class) whose GetBlankMessage is a VTKFieldMessage and whose
    Publish also takes one."""

    class Publisher(base):  # type: ignore[misc,valid-type]
        __doc__ = base.__doc__

        def GetBlankMessage(self):  # noqa: N802 - SlicerROS2's name
            """A VTKFieldMessage of this publisher's ROS type, as SlicerROS2's blank message
            (its VTK value: ``vtk.<GetSlicerType()>()``)."""
            return VTKFieldMessage(self.GetROSType())

        def Publish(self, *args):  # noqa: N802
            if len(args) == 1 and isinstance(args[0], VTKFieldMessage):
                message = args[0]
                if message.ros_type != self.GetROSType():  # refused with the reason, counted
                    return 1 if base.PublishMessageObject(self, message.message.vtk) else 0
                try:
                    converted = message.to_message(self.GetScaleLengths())
                except ValueError as error:
                    print(f'{base.__name__}.Publish: {error}')
                    return 0
                return 1 if base.PublishMessageObject(self, converted.vtk) else 0
            return base.Publish(self, *args)

    Publisher.__name__ = base.__name__
    Publisher.__qualname__ = base.__qualname__
    Publisher.__module__ = base.__module__
    return Publisher


def _subscriber_returning_messages(base: type) -> type:
    """`base` (a mapped subscriber class) whose GetLastMessage() is a VTKFieldMessage, as
    SlicerROS2's; GetLastVTKMessage() is the VTK value (GetNewMessage(i) still gives VTK values:
    SlicerROS2 has no GetNewMessage)."""

    class Subscriber(base):  # type: ignore[misc,valid-type]
        __doc__ = base.__doc__

        def GetLastMessage(self, *args):  # noqa: N802 - SlicerROS2's name
            """The newest message as SlicerROS2's message object (a VTKFieldMessage; None before
            the first). GetLastMessage(value) fills a VTK value as before."""
            if args:
                return base.GetLastMessage(self, *args)
            base.GetLastMessage(self)  # the never-spun warning and conversion errors, as before
            message = Message()
            if not base.GetLastMessageObject(self, message.vtk):
                return None
            return VTKFieldMessage.received(message, self.GetScaleLengths())

        def GetLastVTKMessage(self):  # noqa: N802
            """The newest message as this subscriber's VTK value (C++ GetLastMessage())."""
            return base.GetLastMessage(self)

    Subscriber.__name__ = base.__name__
    Subscriber.__qualname__ = base.__qualname__
    Subscriber.__module__ = base.__module__
    return Subscriber


_overrides: list = []


def install_message_blanks(namespace: dict) -> str:
    """Makes the publisher classes whose rule asks for it hand out VTKFieldMessages, and their
    subscriber classes return them (their Python class, also for nodes created in C++, and
    `namespace`'s name for it). Returns '' or why not."""
    reasons = []
    kinds = (('vtkROS2Publisher', _hands_out_messages, _publisher_handing_out_messages),
             ('vtkROS2Subscriber', _returns_messages, _subscriber_returning_messages))
    for name in sorted(namespace):
        kind = next((k for k in kinds if name.startswith(k[0]) and name.endswith('Node')), None)
        if kind is None:
            continue
        base = namespace[name]
        try:
            if not kind[1](base()):
                continue
        except TypeError:  # abstract
            continue
        subclass = kind[2](base)
        why = _override_vtk_class(base, subclass)
        if why:
            reasons.append(f'{name}: {why}')
            continue
        _overrides.append(subclass)
        namespace[name] = subclass
    return '; '.join(reasons)
