"""The ros2vtk web app: SlicerROS2's module panel in the browser, over a vtkROS2Logic.

    import ros2vtk, ros2vtk.app
    logic = ros2vtk.vtkROS2Logic()
    ros2vtk.app.serve(logic)            # blocks; http://127.0.0.1:8080/ ; the logic spins here

A trame server (Vuetify 3): one collapsible section per task (Robots, Topics, tf, Parameters,
Scene), the list of nodes on top and the details of the selected one below, a status line, and the
3D view streamed by trame-rca. Every panel is read from the scene on each refresh and every button
calls the same Python API a script uses (CreateAndAddRobotNode..., PublishYAML, WriteToXMLFile):
the app holds no ROS state the scene does not hold. The logic is spun from the server's asyncio
loop, so VTK and the scene are only touched on that one thread.
"""
from __future__ import annotations

import asyncio
import functools
import logging
import math
import os
import sys
import time

import vtk

from . import scene_state, volumes
from ..framing import ViewFraming
from .view import RenderWindowArea, SlicePanes, make_display, make_render_window

REFRESH_SECONDS = 0.5   # panels and status line
FRAME_SECONDS = 0.1     # 3D view (10 frames/s)
SLICE_SECONDS = 0.25    # slice panes (4 frames/s: three more renders and encodings per frame)
PARAMETER_SET_SECONDS = 15.0  # a set_parameters answer (and the node's discovery) may take this long
# Frames are asked for no sooner than RENDER_SHARE times what the last ones took to render: on a
# slow machine the views' frame rate drops, and the loop keeps most of its time for spinning, the
# panels and the browser's calls (a new size of the view among them).
RENDER_SHARE = 3.0
JPEG_QUALITY = 80       # every frame (trame-rca's second, 'still' frame would double the renders)


def _is_closed_connection(context: dict) -> bool:
    """An asyncio error context left by a browser tab that closed while a frame was being sent
    to it (aiohttp's ClientConnectionResetError is a ConnectionResetError)."""
    return isinstance(context.get('exception'), (ConnectionResetError, BrokenPipeError))


class _ClosedConnectionFilter(logging.Filter):
    """wslink logs an RPC whose answer went to a closed tab as three error records: 'Exception
    raised', the exception's repr and its traceback. The first says nothing the other two do not
    and is dropped; the other two are dropped when the exception is a reset connection."""

    def filter(self, record: logging.LogRecord) -> bool:
        # aiohttp's server logs "Error handling request" with the reset as exc_info.
        if record.exc_info and isinstance(record.exc_info[1], (ConnectionResetError, BrokenPipeError)):
            return False
        text = record.getMessage()
        return text != 'Exception raised' and 'ConnectionResetError' not in text \
            and 'Cannot write to closing transport' not in text


@functools.cache
def parameter_types() -> dict[str, tuple[int, str]]:
    """The form's parameter types ('bool', ..., 'integer[]', ...) with their type id and their
    rcl_interfaces/msg/ParameterValue field, from rcl_interfaces/msg/ParameterType's constants as
    the generated message tables hold them (PARAMETER_INTEGER_ARRAY = 7 -> 'integer[]': (7,
    'integer_array_value')): the app needs no ROS installation, only ros2vtk."""
    import ros2vtk
    constants, values = ros2vtk.vtkROS2Message(), ros2vtk.vtkROS2Message()
    if not (constants.SetROSType('rcl_interfaces/msg/ParameterType')
            and values.SetROSType('rcl_interfaces/msg/ParameterValue')):
        raise RuntimeError('this build of ros2vtk has no rcl_interfaces messages')
    types = {}
    for index in range(constants.GetNumberOfConstants()):
        name = constants.GetConstantName(index)  # PARAMETER_INTEGER_ARRAY
        if name == 'PARAMETER_NOT_SET':
            continue
        base = name.removeprefix('PARAMETER_').lower()  # integer_array
        field = base + '_value'
        if not values.GetFieldType(field):
            raise RuntimeError(f'rcl_interfaces/msg/ParameterValue has no field {field} for {name}')
        types[base.removesuffix('_array') + '[]' if base.endswith('_array') else base] = \
            (int(constants.GetConstant(name)), field)
    return types


def parse_parameter_value(kind: str, text: str):
    """The form's text as a value of `kind` (bool, integer, double, string or an array type such as
    integer[]: a YAML/JSON list, '[1, 2, 3]'); ValueError naming the element that does not fit."""
    if kind == 'bool':
        return text.strip().lower() in ('1', 'true', 'yes', 'on')
    if kind == 'integer':
        return int(text)
    if kind == 'double':
        return float(text)
    if kind == 'string':
        return text
    if kind not in parameter_types():
        raise ValueError(f'unknown parameter type {kind!r}')
    try:
        import yaml
        values = yaml.safe_load(text)
    except ImportError:
        import json
        values = json.loads(text)
    except Exception as error:  # noqa: BLE001 (yaml's own errors: the text is not YAML)
        raise ValueError(f'{kind}: not a list such as [1, 2, 3] ({str(error).splitlines()[0]})') from None
    if not isinstance(values, list):
        raise ValueError(f'{kind}: {text.strip()!r} is not a list such as [1, 2, 3]')
    element = kind[:-2]
    fits = {'bool': lambda v: isinstance(v, bool),
            'integer': lambda v: isinstance(v, int) and not isinstance(v, bool) and -2 ** 63 <= v < 2 ** 63,
            'double': lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
            'string': lambda v: isinstance(v, str),
            'byte': lambda v: isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 255}[element]
    for index, value in enumerate(values):
        if not fits(value):
            wanted = {'bool': 'true or false', 'integer': 'a whole number', 'double': 'a number',
                      'string': "a string (quote it: '1')", 'byte': 'a whole number 0..255'}[element]
            raise ValueError(f'{kind}: element {index} ({value!r}) is not {wanted}')
    return [float(v) for v in values] if element == 'double' else values


def vtk_array(kind: str, values: list):
    """A checked list (parse_parameter_value) as the VTK array the parameter setters take."""
    if kind == 'string[]':
        array = vtk.vtkStringArray()
        for value in values:
            array.InsertNextValue(value)
        return array
    array = vtk.vtkDoubleArray() if kind == 'double[]' else vtk.vtkTypeInt64Array()
    for value in values:
        array.InsertNextValue(value)
    return array


class _BrowserCounter:
    """Counts the browser tabs connected to the app (wslink's onConnect/onClose per websocket):
    `connected` now, `seen` since the start."""

    def __init__(self):
        self.connected = 0
        self.seen = 0

    def link_protocol(self):
        from wslink.websocket import LinkProtocol
        counter = self

        class Counting(LinkProtocol):
            def onConnect(self, request, client_id):  # noqa: N802 (wslink's name)
                counter.connected += 1
                counter.seen += 1

            def onClose(self, client_id):  # noqa: N802
                counter.connected = max(0, counter.connected - 1)
        return Counting()


def _short_names(class_names: str, prefix: str):
    """'vtkROS2PublisherStringNode ...' -> ['String', ...] (the names CreateAndAdd... takes)."""
    return [name[len(prefix):-len('Node')] for name in class_names.split()
            if name.startswith(prefix) and name.endswith('Node')]


class VTKMessages:
    """Collects VTK's error and warning text (vtkErrorMacro of the scene's nodes) so that a failed
    action is shown in the app, not only in the server's terminal."""

    def __init__(self):
        self._install()

    def _install(self):
        self.window = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(self.window)
        self.consumed = 0

    def take(self) -> str:
        """The text written since the last call (echoed on stderr too)."""
        text = self.window.GetOutput()
        new, self.consumed = text[self.consumed:], len(text)
        if self.consumed > 1 << 20:  # the window cannot be cleared in VTK 9.1: start a new one
            self._install()
        if new:
            sys.stderr.write(new)
        return new.strip()


class App:
    """One app over one logic: state, controllers, layout, the spin task."""

    def __init__(self, logic, server=None, title='ros2vtk', slices: bool | str = 'auto'):
        from trame.app import get_server
        self.logic = logic
        self.scene = logic.GetScene()
        self.node = logic.GetDefaultROS2Node()
        self.server = server or get_server('ros2vtk', client_type='vue3')
        self.state, self.ctrl = self.server.state, self.server.controller
        self.messages = VTKMessages()
        self.rates = scene_state.TopicRates()
        self.window, self.renderer = make_render_window()
        self.display = make_display(logic, self.renderer)
        self.area = RenderWindowArea(self.window, frame_rate=1.0 / FRAME_SECONDS)
        self.view_handler = None
        # 2D panes of a volume (vtkROS2SliceView: needs the Display module): shown always
        # (slices=True), never (False), or while there is a volume to show ('auto').
        import ros2vtk
        self.slices = SlicePanes(self.scene) if slices and hasattr(ros2vtk, 'vtkROS2SliceView') else None
        self.slices_always = slices is True
        self.slice_widgets, self.slice_handlers = {}, {}
        # The camera frames the robots' workspaces and what is drawn; again only when that changes.
        self.framing = ViewFraming(self.scene, self.renderer)
        self.next_frame = self.next_refresh = self.next_slices = 0.0
        self.errors = []
        self.spin_callbacks = []
        self.parameter_sets = []  # (client node, description) of set_parameters requests in flight
        self.parameter_queue = []  # (service, name, type, value, description) waiting for their service
        self.last_status = (time.monotonic(), logic.GetNumberOfSpins(), 0)
        self.browsers = _BrowserCounter()
        self.server.add_protocol_to_configure(lambda protocol: protocol.registerLinkProtocol(
            self.browsers.link_protocol()))
        self.stopped_for = ''  # why serve() stopped by itself: 'duration', 'no browser'
        self._init_state(title)
        self._bind_controllers()
        self._build_layout(title)
        self.ctrl.on_server_ready.add(self._on_ready)

    # ------------------------------------------------------------------ state
    def _init_state(self, title):
        s = self.state
        s.trame__title = title
        s.update({
            'robots': [], 'robot_selected': '', 'robot_links': [], 'robot_warnings': '',
            'robot_name': 'robot', 'robot_source': 'parameter', 'robot_param_node': '/robot_state_publisher',
            'robot_param_name': 'robot_description', 'robot_topic': '/robot_description', 'robot_file': '',
            'robot_fixed_frame': '', 'robot_tf_prefix': '', 'robot_mesh_paths': '', 'robot_mesh_base': '',
            'topics': [], 'topic_selected': '', 'topic_yaml': '', 'topic_direction': 'subscriber',
            'topic_type': 'String', 'topic_name': '/chatter', 'publish_yaml': "{data: 'hello'}",
            'graph_filter': '', 'graph_nodes': [], 'graph_topics': [],
            'tf_frames': [], 'tf_publishers': [], 'tf_lookups': [], 'tf_broadcasters': [], 'tf_parent': 'world', 'tf_child': 'base_link',
            'tf_static': False,
            'parameters': [], 'param_node': '/robot_state_publisher', 'param_names': 'robot_description',
            'remote_param_node': '/robot_state_publisher', 'remote_param_name': 'publish_frequency',
            'remote_param_type': 'double', 'remote_param_value': '20.0', 'remote_param_result': '',
            'own_param_name': 'rate', 'own_param_type': 'double', 'own_param_value': '1.0',
            'parameter_types': list(parameter_types()),
            'scene_file': os.path.abspath('ros2vtk-scene.xml'),
            'volume_file': '', 'slice_sources': [], 'slice_source': '', 'volume_window': '', 'volume_level': '',
            'slices_shown': self.slices is not None and self.slices_always,
            'message': '', 'message_kind': 'info', 'errors': [], 'status': '', 'panels': [0, 1, 2, 3, 4, 5],
            'types_publishers': _short_names(self.node.GetRegisteredROS2PublisherNodes(), 'vtkROS2Publisher'),
            'types_subscribers': _short_names(self.node.GetRegisteredROS2SubscriberNodes(), 'vtkROS2Subscriber'),
        })

    def _apply(self, form):
        """The form's fields as the browser had them at the click."""
        if isinstance(form, dict):
            self.state.update(form)

    def _report(self, ok: bool, success: str, failure: str) -> bool:
        """Shows the outcome of an action: its VTK error text when it failed."""
        text = self.messages.take()
        if ok:
            self.state.message, self.state.message_kind = success, 'success'
        else:
            detail = text.splitlines()[-1] if text else ''
            message = f'{failure}: {detail}' if detail else failure
            self.state.message, self.state.message_kind = message, 'error'
            self.errors = (self.errors + [message])[-20:]
            self.state.errors = list(self.errors)
        self.refresh()
        return ok

    # ------------------------------------------------------------------ controllers
    def _bind_controllers(self):
        c = self.ctrl
        c.add_robot = self.add_robot
        c.remove_robot = self.remove_robot
        c.add_topic = self.add_topic
        c.remove_topic = self.remove_topic
        c.publish = self.publish
        c.add_lookup = self.add_lookup
        c.add_broadcaster = self.add_broadcaster
        c.watch_parameters = self.watch_parameters
        c.set_own_parameter = self.set_own_parameter
        c.set_remote_parameter = self.set_remote_parameter
        c.open_volume = self.open_volume
        c.remove_volume = self.remove_volume
        c.set_window_level = self.set_window_level
        c.set_window_preset = self.set_window_preset
        c.save_scene = self.save_scene
        c.load_scene = self.load_scene
        c.reset_camera = self.reset_camera
        c.on_error.add(self._browser_error)
        self.state.change('robot_selected', 'topic_selected')(lambda **_: self.refresh())
        self.state.change('topic_selected')(self._prefill_publish_yaml)
        self.state.change('slice_source')(self._show_slice_source)

    def _browser_error(self, message):
        """A JavaScript error reported by the page: shown in the terminal as one line. Chromium's
        'ResizeObserver loop' notice (a layout pass deferred while the panels resize) is not an
        error and is dropped."""
        text = str(message)
        if 'ResizeObserver loop' not in text:
            print(f'[app] browser error: {text}', file=sys.stderr, flush=True)

    def _prefill_publish_yaml(self, topic_selected='', **_):
        """Selecting a publisher of a mapped type fills the YAML box with its message's fields
        (blank values), so the form shows what there is to publish."""
        node = self.scene.GetNodeByID(topic_selected) if topic_selected else None
        if node is None or not node.IsA('vtkROS2PublisherNode') or hasattr(node, 'PublishYAML'):
            return
        message = node.CreateMessageObject()
        if message is not None:
            self.state.publish_yaml = message.GetYAML()

    def add_robot(self, form=None):
        self._apply(form)
        s = self.state
        name = s.robot_name.strip()
        if not name:
            return self._report(False, '', 'Add robot: a name is required')
        if s.robot_source == 'parameter':
            robot = self.node.CreateAndAddRobotNode(name, s.robot_param_node, s.robot_param_name,
                                                    s.robot_fixed_frame, s.robot_tf_prefix)
        elif s.robot_source == 'topic':
            robot = self.node.CreateAndAddRobotNodeFromTopic(name, s.robot_topic, s.robot_fixed_frame,
                                                             s.robot_tf_prefix)
        else:
            robot = self.node.CreateAndAddRobotNodeFromFile(name, s.robot_file, s.robot_fixed_frame,
                                                            s.robot_tf_prefix)
        if robot is not None:
            if (s.robot_mesh_base or '').strip():
                robot.SetMeshBaseFolder(s.robot_mesh_base.strip())  # relative mesh paths start here
            for folder in (s.robot_mesh_paths or '').split(os.pathsep):
                if folder.strip():
                    robot.AddMeshSearchPath(folder.strip())
            s.robot_selected = name  # (the view is framed again once it has loaded: ViewFraming)
        return self._report(robot is not None, f'Robot {name} added ({s.robot_source})', f'Add robot {name} failed')

    def remove_robot(self, name=None):
        name = name or self.state.robot_selected
        ok = bool(name) and self.node.RemoveAndDeleteRobotNode(name)
        if ok:
            self.state.robot_selected = ''
        return self._report(ok, f'Robot {name} removed', f'Remove robot {name} failed')

    def add_topic(self, form=None):
        self._apply(form)
        s = self.state
        topic, kind = s.topic_name.strip(), s.topic_type.strip()
        if s.topic_direction == 'publisher':
            node = self._add_yaml_publisher(kind, topic)
        else:
            node = self.node.CreateAndAddSubscriberNode(kind, topic)
        if node is not None:
            s.topic_selected = node.GetID()
        return self._report(node is not None, f'{s.topic_direction} {topic} ({kind}) added',
                            f'Add {s.topic_direction} {topic} failed')

    def _add_yaml_publisher(self, kind, topic):
        """A publisher the form can publish YAML with: a mapped type's node takes VTK values, so a
        ROS type given in full gets the generic (YAML) node; a short name gets the mapped node."""
        if '/' not in kind:
            return self.node.CreateAndAddPublisherNode(kind, topic)
        if self.node.GetPublisherNodeByTopic(topic) is not None:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'a publisher on {topic} exists; remove it first\n')
            return None
        import ros2vtk
        node = ros2vtk.vtkROS2PublisherGenericNode()
        if not node.SetROSType(kind):
            return None
        node.SetName(topic)
        self.scene.AddNode(node)
        if not node.AddToROS2Node(self.node.GetID(), topic):
            self.scene.RemoveNode(node)
            return None
        return node

    def remove_topic(self, node_id=None):
        node = self.scene.GetNodeByID(node_id or self.state.topic_selected)
        ok = False
        if node is not None:
            topic = node.GetTopic()
            if node.IsA('vtkROS2PublisherNode'):
                ok = self.node.RemoveAndDeletePublisherNode(topic)
            else:
                ok = self.node.RemoveAndDeleteSubscriberNode(topic)
            self.state.topic_selected = ''
        return self._report(ok, 'Topic node removed', 'Remove failed')

    def publish(self, form=None):
        self._apply(form)
        node = self.scene.GetNodeByID(self.state.topic_selected)
        if node is None or not node.IsA('vtkROS2PublisherNode'):
            return self._report(False, '', 'Publish: select a publisher')
        if hasattr(node, 'PublishYAML'):
            ok = node.PublishYAML(self.state.publish_yaml)
        else:
            # A mapped publisher (PoseStamped, ...): the YAML fills a typed message object of its
            # type, published as it is (SI units, no stamping: docs/messages.md).
            message = node.CreateMessageObject()
            ok = message is not None and message.SetYAML(self.state.publish_yaml) and node.PublishMessageObject(message)
        return self._report(ok, f'Published on {node.GetTopic()} ({node.GetNumberOfMessagesSent()} sent)',
                            f'Publish on {node.GetTopic()} failed')

    def add_lookup(self, form=None):
        self._apply(form)
        s = self.state
        node = self.node.CreateAndAddTf2LookupNode(s.tf_parent, s.tf_child)
        return self._report(node is not None, f'Lookup {s.tf_parent} -> {s.tf_child} added', 'Add lookup failed')

    def add_broadcaster(self, form=None):
        self._apply(form)
        s = self.state
        node = self.node.CreateAndAddTf2BroadcasterNode(s.tf_parent, s.tf_child)
        if node is not None:
            node.SetStatic(bool(s.tf_static))
            node.Broadcast(vtk.vtkMatrix4x4())  # identity until a script or transform drives it
        return self._report(node is not None, f'Broadcaster {s.tf_parent} -> {s.tf_child} added (identity)',
                            'Add broadcaster failed')

    def watch_parameters(self, form=None):
        self._apply(form)
        s = self.state
        node = self.node.GetParameterNodeByNode(s.param_node) or self.node.CreateAndAddParameterNode(s.param_node)
        ok = node is not None
        for name in (s.param_names or '').replace(',', ' ').split() if ok else []:
            ok = node.AddParameter(name) and ok
        return self._report(ok, f'Watching {s.param_node}', f'Watch {s.param_node} failed')

    def set_own_parameter(self, form=None):
        self._apply(form)
        s = self.state
        name, kind, text = s.own_param_name.strip(), s.own_param_type, s.own_param_value
        try:
            value = parse_parameter_value(kind, text)
            if kind == 'bool':
                ok = self.node.SetParameterAsBool(name, value)
            elif kind == 'integer':
                ok = self.node.SetParameterAsInteger(name, value)
            elif kind == 'double':
                ok = self.node.SetParameterAsDouble(name, value)
            elif kind == 'string':
                ok = self.node.SetParameterAsString(name, value)
            else:  # bool[] -> SetParameterAsBoolArray, ...
                setter = getattr(self.node, f'SetParameterAs{kind[:-2].capitalize()}Array')
                ok = setter(name, vtk_array(kind, value))
        except ValueError as error:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'{error}\n')
            ok = False
        return self._report(ok, f'{self.node.GetROS2NodeName()}: {name} = {text}', f'Set parameter {name} failed')

    def set_remote_parameter(self, form=None):
        """Sends one SetParameters request to another node's `<node>/set_parameters` service (a
        service client node, removed once answered); the node's answer (successful, reason)
        is shown when it arrives."""
        self._apply(form)
        s = self.state
        target, name, kind, text = s.remote_param_node.strip(), s.remote_param_name.strip(), s.remote_param_type, \
            s.remote_param_value
        try:
            if not target or not name or kind not in parameter_types():
                raise ValueError('a node, a name and a type are required')
            value = parse_parameter_value(kind, text)
        except ValueError as error:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'{error}\n')
            return self._report(False, '', f'Set {target} {name} failed')
        service = target.rstrip('/') + '/set_parameters'
        description = f'{target}: {name} = {text}'
        if any(c.GetServiceName() == service for c, _ in self.parameter_sets):
            # One request per service client node at a time: this one waits for the answer to the
            # one in flight, then goes (in the order they were asked for).
            self.parameter_queue.append((service, name, kind, value, description))
            print(f'[app] parameter set queued behind the one in flight: {description}', flush=True)
            s.remote_param_result = f'{description}: queued behind the set in flight'
            return self._report(True, f'Set request queued for {service}', '')
        ok = self._send_parameter_set(service, name, kind, value, description)
        return self._report(ok, f'Set request sent to {service}', f'Set {target} {name} failed')

    def _send_parameter_set(self, service: str, name: str, kind: str, value, description: str) -> bool:
        """Sends one SetParameters request for `name` (checked value of type `kind`)."""
        type_id, field = parameter_types()[kind]
        client = self.node.GetServiceClientNodeByService(service) or \
            self.node.CreateAndAddServiceClientNode('rcl_interfaces/srv/SetParameters', service)
        ok = client is not None
        if ok:
            client.SetTimeout(PARAMETER_SET_SECONDS)
            request = client.CreateBlankRequest()
            path = f'parameters[0].value.{field}'
            ok = request.SetFieldLength('parameters', 1) and request.SetField('parameters[0].name', name) \
                and request.SetField('parameters[0].value.type', str(type_id))
            if ok and kind == 'string[]':
                ok = request.SetFieldFromStringArray(path, vtk_array(kind, value))
            elif ok and kind.endswith('[]'):
                ok = request.SetFieldFromArray(path, vtk_array(kind, value))
            elif ok:
                ok = request.SetField(path, {True: 'true', False: 'false'}.get(value, str(value))
                                      if kind != 'double' else repr(value))
            ok = ok and client.SendAsyncRequest(request) > 0
        if ok:
            self.parameter_sets.append((client, description))
            self.state.remote_param_result = f'{description}: sent, waiting for the answer'
        return ok

    def _take_parameter_answers(self):
        """Shows the answers of set_parameters requests that arrived; drops their clients."""
        pending = []
        for client, description in self.parameter_sets:
            status = client.GetStatusAsString()
            if status in ('waiting for server', 'waiting for response'):
                pending.append((client, description))
                continue
            if status == 'succeeded':
                ok = client.GetResponseField('results[0].successful') == 'true'
                reason = client.GetResponseField('results[0].reason')
                text = f'{description}: ' + ('set' if ok else 'refused') + (f' ({reason})' if reason else '')
            else:
                ok, text = False, f'{description}: {status} ({client.GetLastError()})'
            self.node.RemoveAndDeleteServiceClientNode(client.GetServiceName())
            self.state.remote_param_result = text
            self.state.message, self.state.message_kind = text, 'success' if ok else 'error'
            if not ok:
                self.errors = (self.errors + [text])[-20:]
                self.state.errors = list(self.errors)
        self.parameter_sets = pending
        for queued in list(self.parameter_queue):  # the next queued set of each free service
            service = queued[0]
            if any(c.GetServiceName() == service for c, _ in self.parameter_sets):
                continue
            self.parameter_queue.remove(queued)
            if not self._send_parameter_set(*queued):
                text = f'{queued[-1]}: not sent ({self.messages.take().strip() or "no client"})'
                self.state.remote_param_result = text
                self.state.message, self.state.message_kind = text, 'error'
                self.errors = (self.errors + [text])[-20:]
                self.state.errors = list(self.errors)

    def open_volume(self, form=None, path: str | None = None):
        """Reads a volume file (NRRD, MetaImage, NIfTI) on the server into a vtkROS2VolumeNode:
        drawn in the 3D view by the display layer, and shown in the slice panes."""
        self._apply(form)
        path = self.state.volume_file if path is None else path
        try:
            image, file_to_world = volumes.read_volume(path)
        except ValueError as error:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'{error}\n')
            return self._report(False, '', 'Open volume failed')
        name = volumes.volume_name(path.strip())
        node = volumes.add_volume_node(self.scene, image, file_to_world, name)
        self.display.Update()
        self._frame_view()  # the volume in view beside the robots (again once the panes have taken
        self.render()  # their share of the page: the view's new shape), unless the user moved the camera
        dims, spacing = image.GetDimensions(), image.GetSpacing()
        self.state.slice_source = node.GetID()
        self._show_slice_source(node.GetID())
        return self._report(True, f'Volume {name} opened: {dims[0]} x {dims[1]} x {dims[2]} voxels of '
                                  f'{spacing[0]:g} x {spacing[1]:g} x {spacing[2]:g} mm', '')

    def remove_volume(self):
        """Removes the volume node the slice panes show (a subscriber stays: remove it in Topics)."""
        node = self._chosen_volume()
        if node is None:
            return self._report(False, '', 'Remove volume: choose a volume in the list')
        name = node.GetName()
        volumes.remove_volume_node(self.scene, node)
        self.state.slice_source = ''
        self._show_slice_source('')
        return self._report(True, f'Volume {name} removed', '')

    def _chosen_volume(self):
        """The volume node chosen in the Volumes section's list, or None."""
        node = self.scene.GetNodeByID(self.state.slice_source) if self.state.slice_source else None
        return node if node is not None and node.IsA('vtkROS2VolumeNode') else None

    def set_window_level(self, form=None):
        """The chosen volume's window and level (vtkROS2VolumeNode.SetWindow/SetLevel), used by the
        3D view's rendering and the slice panes; a window of 0 or left empty: its scalar range."""
        self._apply(form)
        s = self.state
        node = self._chosen_volume()
        if node is None:
            return self._report(False, '', 'Window/level: choose a volume in the list')
        text_window, text_level = str(s.volume_window or '').strip(), str(s.volume_level or '').strip()
        try:
            window = float(text_window) if text_window else 0.0
            level = float(text_level) if text_level else 0.0
        except ValueError:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(
                f'window and level are numbers (got {text_window!r}, {text_level!r})\n')
            return self._report(False, '', 'Window/level not set')
        if not (math.isfinite(window) and math.isfinite(level)):
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText('window and level are finite numbers\n')
            return self._report(False, '', 'Window/level not set')
        return self._window_level(node, window, level)

    def set_window_preset(self, name: str, form=None):
        """One of Slicer's window/level presets (volumes.WINDOW_LEVEL_PRESETS) on the chosen
        volume, or 'auto': its scalar range. The window and level fields show the numbers."""
        self._apply(form)
        s = self.state
        node = self._chosen_volume()
        if node is None:
            return self._report(False, '', 'Window/level: choose a volume in the list')
        if name != 'auto' and name not in volumes.WINDOW_LEVEL_PRESETS:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'no window/level preset {name!r}\n')
            return self._report(False, '', 'Window/level not set')
        window, level = volumes.WINDOW_LEVEL_PRESETS.get(name, (0.0, 0.0))
        s.volume_window, s.volume_level = (f'{window:g}', f'{level:g}') if window > 0 else ('', '')
        return self._window_level(node, window, level, name)

    def _window_level(self, node, window: float, level: float, preset: str = ''):
        """Sets a volume node's window and level (window <= 0: its scalar range) and shows it."""
        node.SetWindow(max(window, 0.0))
        node.SetLevel(level)
        node.Modified()
        self.display.Update()
        self.render()
        self.next_slices = 0.0  # the panes at the next spin
        named = f' ({preset})' if preset and preset != 'auto' else ''
        if window > 0:
            return self._report(True, f'{node.GetName()}: window {window:g}, level {level:g}{named}', '')
        return self._report(True, f'{node.GetName()}: window/level from its scalar range', '')

    def _show_slice_source(self, slice_source='', **_):
        if self.slices is not None:
            self.slices.set_source(slice_source)
            self.next_slices = 0.0  # at the next spin

    def save_scene(self, form=None):
        self._apply(form)
        path = self.state.scene_file
        ok = bool(path) and self.scene.WriteToXMLFile(path)
        return self._report(ok, f'Scene saved to {path}', f'Save to {path} failed')

    def load_scene(self, form=None):
        self._apply(form)
        path = self.state.scene_file
        ok = bool(path) and os.path.isfile(path)
        if not ok:
            vtk.vtkOutputWindow.GetInstance().DisplayErrorText(f'no such file: {path}\n')
        else:
            ok = self.scene.ReadFromXMLFile(path)
            self.node = self.logic.GetDefaultROS2Node()
        return self._report(ok, f'Scene loaded from {path}', f'Load {path} failed')

    def reset_camera(self):
        self._frame_view(now=True)
        self.render()

    # ------------------------------------------------------------------ refresh and spin
    def refresh(self):
        s = self.state
        now = time.monotonic()
        s.robots = scene_state.robot_rows(self.scene)
        robot = self.node.GetRobotNodeByName(s.robot_selected) if s.robot_selected else None
        s.robot_links, s.robot_warnings = scene_state.robot_details(robot) if robot is not None else ([], '')
        s.topics = scene_state.topic_rows(self.scene, self.rates, now)
        selected = self.scene.GetNodeByID(s.topic_selected) if s.topic_selected else None
        s.topic_yaml = selected.GetLastMessageYAML() if selected is not None and hasattr(
            selected, 'GetLastMessageYAML') else ''
        s.graph_nodes, s.graph_topics = scene_state.graph(self.node, s.graph_filter)
        s.tf_lookups, s.tf_broadcasters = scene_state.tf_rows(self.scene)
        s.tf_frames = scene_state.tf_frame_rows(self.node)
        s.tf_publishers = scene_state.tf_publishers(self.node)
        if self.parameter_sets or self.parameter_queue:
            self._take_parameter_answers()
        s.parameters = scene_state.parameter_rows(self.scene)
        if self.slices is not None:
            s.slice_sources = volumes.slice_sources(self.scene)
            shown = self.slices_always or self.slices.volume is not None
            if shown and self.view_handler is not None:
                self._stream_slice_panes()
            s.slices_shown = shown
        then, spins, received = self.last_status
        total = sum(t['count'] for t in s.topics if t['direction'] == 'subscriber')
        elapsed = max(now - then, 1e-6)
        s.status = (f'spin {(self.logic.GetNumberOfSpins() - spins) / elapsed:.0f}/s, '
                    f'{self.logic.GetMeanSpinDuration():.3f} ms mean, '
                    f'{max(total - received, 0) / elapsed:.0f} msgs/s to subscribers, '
                    f'{len(s.topics)} topic nodes, {len(s.robots)} robots, {len(self.errors)} errors')
        link = scene_state.link_text(self.node)
        if link:
            s.status += f', {link}'
        clock = scene_state.clock_text(self.node)
        if clock:
            s.status += f', {clock}'
        self.last_status = (now, self.logic.GetNumberOfSpins(), total)

    def render(self):
        if self.view_handler is not None:
            self.view_handler.schedule_render()

    def _frame_view(self, now: bool = False) -> None:
        """Frames the 3D view now, or when what it shows asks for it and the user has not moved
        the camera (ViewFraming.update); one terminal line each time, so a camera that moves by
        itself can be told from a user's, and one when the user takes the camera."""
        held = self.framing.user_camera
        if self.framing.frame() if now else self.framing.update():
            print(f'[app] 3D view framed: {self.framing.describe()}', flush=True)
        elif self.framing.user_camera and not held:
            print('[app] 3D view: camera moved by the user, kept until "Reset view"', flush=True)

    async def _spin_loop(self):
        period = 1.0 / max(self.logic.GetSpinRate(), 1.0)
        while True:
            try:
                self._spin_once_and_show()
            except Exception as error:  # noqa: BLE001 (the app keeps running; the error is shown)
                self.errors = (self.errors + [f'spin: {error!r}'])[-20:]
                with self.state:
                    self.state.errors = list(self.errors)
            await asyncio.sleep(period)

    def add_spin_callback(self, callback) -> None:
        """`callback()` runs after each spin of the app's loop (a script's per-spin work)."""
        self.spin_callbacks.append(callback)

    def _spin_once_and_show(self):
        """One spin, the display layer updated, a frame every FRAME_SECONDS, the slice panes (when
        shown) every SLICE_SECONDS (both less often when rendering is slow: RENDER_SHARE), the
        panels every REFRESH_SECONDS."""
        self.logic.Spin()
        for callback in self.spin_callbacks:
            callback()
        self.display.Update()
        now = time.monotonic()
        if now >= self.next_frame:
            self._frame_view()
            self.render()
            self.next_frame = now + max(FRAME_SECONDS, RENDER_SHARE * self.area.render_seconds)
        if self.slices is not None and now >= self.next_slices:
            self.next_slices = now + max(SLICE_SECONDS, RENDER_SHARE * sum(
                area.render_seconds for area in self.slices.areas.values()))
            if self.slices.update():
                for handler in self.slice_handlers.values():
                    handler.schedule_render()
        if now >= self.next_refresh:
            stray = self.messages.take()  # errors from spinning (e.g. a failed reload)
            with self.state:
                if stray:
                    self.errors = (self.errors + stray.splitlines()[-3:])[-20:]
                    self.state.errors = list(self.errors)
                self.refresh()
            self.next_refresh = now + REFRESH_SECONDS

    def _on_wake_up(self):
        """Data queued on a ROS node: spin now rather than at the next tick (the loop's frames and
        panel refreshes would otherwise delay messages by up to a tick)."""
        try:
            self.logic.Spin()
        except Exception as error:  # noqa: BLE001
            self.errors = (self.errors + [f'spin: {error!r}'])[-20:]

    def _on_ready(self, **_):
        self.view_handler = self.view_widget.create_view_handler(
            self.area, encoder='jpeg', target_fps=20, interactive_quality=JPEG_QUALITY, still_quality=JPEG_QUALITY)
        if self.slices_always:
            self._stream_slice_panes()
        loop = asyncio.get_event_loop()

        def quiet_closed_connections(loop, context):
            if not _is_closed_connection(context):  # a closed tab is not a traceback in the terminal
                loop.default_exception_handler(context)
        loop.set_exception_handler(quiet_closed_connections)
        wake_up = self.logic.GetWakeUpFileDescriptor()
        if wake_up >= 0:
            loop.add_reader(wake_up, self._on_wake_up)
        loop.create_task(self._spin_loop())

    def _stream_slice_panes(self) -> None:
        """Streams the slice panes (once, when first shown: hidden panes' streams stalled the app's
        loop once a robot was drawn)."""
        if self.slice_handlers:
            return
        for orientation, widget in self.slice_widgets.items():
            self.slice_handlers[orientation] = widget.create_view_handler(
                self.slices.areas[orientation], encoder='jpeg', target_fps=10, interactive_quality=JPEG_QUALITY,
                still_quality=JPEG_QUALITY)

    def release_windows(self):
        """Frees the render windows' X resources while their X server is still there (the app's
        Xvfb ends right after; a window finalized later, at the interpreter's exit, crashed it)."""
        windows = [self.window] + (list(self.slices.windows.values()) if self.slices is not None else [])
        for window in windows:
            window.Finalize()

    # ------------------------------------------------------------------ layout
    def _build_layout(self, title):
        from .layout import build
        self.view_widget, self.slice_widgets = build(self, title)


def _finish_pending_tasks() -> None:
    """Cancels the tasks the stopped server left in its loop (the spin loop, trame-rca's frame
    streams) and lets them end now: left pending, their coroutines were finalized at the
    interpreter's exit, which crashed it (a segmentation fault after '[demo] stopped', 2 runs in 3)."""
    try:
        loop = asyncio.get_event_loop()
    except RuntimeError:
        return
    if loop.is_running() or loop.is_closed():
        return
    pending = [task for task in asyncio.all_tasks(loop) if not task.done()]
    for task in pending:
        task.cancel()
    if pending:
        loop.run_until_complete(asyncio.gather(*pending, return_exceptions=True))


def serve(logic, host: str = '127.0.0.1', port: int = 8080, allow_remote: bool = False,
          open_browser: bool = False, title: str = 'ros2vtk', on_app=None, duration: float | None = None,
          slices: bool | str = 'auto', browser_wait: float | None = None) -> App:
    """Serves the app on `logic` until interrupted, or for `duration` seconds (blocking). Binds
    the loopback unless `allow_remote` is set; another host is then reachable by anyone on the
    network. `on_app(app)` runs once the App exists (add actors to app.renderer, spin callbacks).
    `slices`: axial, sagittal and coronal panes of a volume below the 3D view (the one chosen in
    the Volumes section, else the scene's first vtkROS2VolumeNode; app.slices.set_point(x, y, z)
    moves their planes): True always, 'auto' (default) while there is a volume, False never.
    `browser_wait`: stop after that many seconds if no browser has connected by then (a headless
    run nobody watches); once one has, serve on (until `duration` or Ctrl-C). Returns the App
    (`app.stopped_for`: 'duration', 'no browser' or '' for Ctrl-C)."""
    from .view import ensure_x_display
    if host not in ('127.0.0.1', 'localhost', '::1') and not allow_remote:
        raise ValueError(f'serve: host {host} is not the loopback; pass allow_remote=True (--allow-remote) to serve it')
    if host not in ('127.0.0.1', 'localhost', '::1'):
        print(f'[app] WARNING: serving on {host}: anyone who reaches this port controls the ROS node', flush=True)
    xvfb = ensure_x_display()
    for logger in ('wslink.protocol', 'aiohttp.server', 'aiohttp.web'):
        logging.getLogger(logger).addFilter(_ClosedConnectionFilter())
    app = App(logic, title=title, slices=slices)
    if on_app is not None:
        on_app(app)
    def stop(reason: str) -> None:
        app.stopped_for = reason
        asyncio.ensure_future(app.server.stop())
    if duration:
        app.ctrl.on_server_ready.add(lambda **_: asyncio.get_event_loop().call_later(duration, stop, 'duration'))
    if browser_wait:
        app.ctrl.on_server_ready.add(lambda **_: asyncio.get_event_loop().call_later(
            browser_wait, lambda: None if app.browsers.seen else stop('no browser')))
    app.ctrl.on_server_ready.add(lambda **_: print(f'[app] ros2vtk app at http://{host}:{app.server.port}/',
                                                   flush=True))
    saved_argv = sys.argv
    sys.argv = saved_argv[:1]  # trame parses sys.argv itself; our options are not its options
    try:
        app.server.start(host=host, port=port, timeout=0, open_browser=open_browser, show_connection_info=False)
    finally:
        sys.argv = saved_argv
        _finish_pending_tasks()
        app.release_windows()
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    return app
