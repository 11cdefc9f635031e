"""What the app's panels show, read from the scene each refresh: plain lists and dicts for trame's
state, built only from the logic, its scene and its default ROS node (the app keeps no state of its
own about ROS objects). Rates are the difference of the scene's own counters between refreshes.
"""
from __future__ import annotations

import time

import vtk


def nodes_of_class(scene, class_name: str):
    nodes = vtk.vtkCollection()
    scene.GetNodesByClass(class_name, nodes)
    return [nodes.GetItemAsObject(i) for i in range(nodes.GetNumberOfItems())]


def clock_text(node) -> str:
    """The status line's word on time: nothing on the system clock (the usual case), the
    simulated time while the node's use_sim_time is on, or that it still waits for /clock."""
    if node is None or not node.GetUseSimTime():
        return ''
    if not node.GetSimTimeReceived():
        return 'sim time: waiting for /clock'
    return f'sim time {node.GetNodeTime():.3f} s'


def link_text(node) -> str:
    """The status line's word on the network: how many other ROS participants the node sees
    (its LinkStateChangedEvent fires when that changes), and how many it dropped after they fell
    silent beyond the DDS lease (a cut link)."""
    if node is None:
        return ''
    state = node.GetLinkState()
    if state == 'peers':
        count = node.GetNumberOfDiscoveredParticipants()
        text = f'link: {count} peer{"s" if count != 1 else ""}'
    else:
        text = f'link: {state}'
    dropped = node.GetNumberOfDroppedParticipants()
    return text + (f' ({dropped} dropped)' if dropped else '')


def robot_rows(scene):
    rows = []
    for robot in nodes_of_class(scene, 'vtkROS2RobotNode'):
        source = robot.GetDescriptionSource()
        where = {'parameter': f'{robot.GetParameterNodeName()} {robot.GetParameterName()}',
                 'topic': robot.GetDescriptionTopic(), 'file': robot.GetDescriptionFile()}.get(source, '')
        rows.append({'name': robot.GetRobotName(), 'source': f'{source}: {where}', 'state': robot.GetRobotState(),
                     'links': f'{robot.GetNumberOfLinksTracked()}/{robot.GetNumberOfLinks()}',
                     'visuals': robot.GetNumberOfModelNodes(), 'placeholders': robot.GetNumberOfPlaceholders(),
                     'fixed_frame': robot.GetFixedFrame(), 'tf_prefix': robot.GetTfPrefix(),
                     'error': robot.GetLastError() or ''})
    return rows


def robot_details(robot):
    """Per-link status (tracked by its tf lookup or not) and the load warnings of one robot."""
    links = []
    for link in [name for name in robot.GetLinkNames().split() if name]:
        transform = robot.GetLinkTransformNode(link)
        status = 'no transform node'
        if transform is not None:
            status = transform.GetLookupStatus() if hasattr(transform, 'GetLookupStatus') else 'placed'
        links.append({'link': link, 'status': status})
    return links, robot.GetWarnings()


class TopicRates:
    """Messages per second of each topic node, from its counter between two refreshes."""

    def __init__(self):
        self.last = {}

    def rate(self, node_id: str, count: int, now: float) -> float:
        previous = self.last.get(node_id)
        self.last[node_id] = (count, now)
        if previous is None or now <= previous[1]:
            return 0.0
        return max(0.0, (count - previous[0]) / (now - previous[1]))


def topic_rows(scene, rates: TopicRates, now: float | None = None):
    now = time.monotonic() if now is None else now
    rows = []
    for direction, class_name in (('publisher', 'vtkROS2PublisherNode'), ('subscriber', 'vtkROS2SubscriberNode')):
        for node in nodes_of_class(scene, class_name):
            if direction == 'publisher':
                count, matched = node.GetNumberOfMessagesSent(), node.GetNumberOfMatchedSubscriptions()
            else:
                count, matched = node.GetNumberOfMessages(), node.GetNumberOfMatchedPublications()
            rows.append({'id': node.GetID(), 'direction': direction, 'topic': node.GetTopic(),
                         'type': node.GetROSType(), 'vtk_type': node.GetSlicerType(),
                         'qos': node.GetQoSDescription(), 'matched': matched, 'count': count,
                         'rate': round(rates.rate(node.GetID(), count, now), 1),
                         'yaml_publish': hasattr(node, 'PublishYAML')})
    return rows


def tf_rows(scene):
    lookups = [{'id': n.GetID(), 'parent': n.GetParentID(), 'child': n.GetChildID(), 'status': n.GetLookupStatus(),
                'error': n.GetLastLookupError()} for n in nodes_of_class(scene, 'vtkROS2Tf2LookupNode')]
    broadcasters = [{'id': n.GetID(), 'parent': n.GetParentID(), 'child': n.GetChildID(),
                     'static': bool(n.GetStatic()), 'count': n.GetNumberOfBroadcasts()}
                    for n in nodes_of_class(scene, 'vtkROS2Tf2BroadcasterNode')]
    return lookups, broadcasters


def parameter_rows(scene):
    rows = []
    for node in nodes_of_class(scene, 'vtkROS2ParameterNode'):
        for name in [n for n in node.GetParameterNames().split() if n]:
            ready = node.IsParameterSet(name, True)
            value = node.PrintParameter(name) if ready else '(not set yet)'
            rows.append({'node': node.GetMonitoredNodeName(), 'name': name,
                         'type': node.GetParameterType(name) if ready else '',
                         'value': value if len(value) < 400 else value[:400] + f'... ({len(value)} characters)'})
        if not node.GetParameterNames().split():
            rows.append({'node': node.GetMonitoredNodeName(), 'name': '', 'type': '',
                         'value': 'ready' if node.IsMonitoredNodeReady() else 'waiting for the node'})
    return rows


def graph(ros_node, text_filter: str):
    """The ROS graph as our node sees it: node names and (topic, types) rows, filtered."""
    wanted = (text_filter or '').strip().lower()
    nodes = [line for line in ros_node.GetNodeNamesAndNamespaces().splitlines() if line.strip()]
    topics = []
    for line in ros_node.GetTopicNamesAndTypes().splitlines():
        parts = line.split(None, 1)
        if parts:
            topics.append({'topic': parts[0], 'types': parts[1].strip('[] ') if len(parts) > 1 else ''})
    if wanted:
        nodes = [n for n in nodes if wanted in n.lower()]
        topics = [t for t in topics if wanted in t['topic'].lower() or wanted in t['types'].lower()]
    return nodes, topics


def parse_frames_yaml(text: str) -> dict[str, dict[str, str]]:
    """tf2's allFramesAsYAML (vtkROS2NodeNode.GetTf2FramesAsYAML) -> {frame: {key: value}}:
    one unindented 'frame:' line per frame, then indented 'key: value' lines (quotes dropped)."""
    frames: dict[str, dict[str, str]] = {}
    current = None
    for line in (text or '').splitlines():
        if not line.strip() or line.strip() == '[]':
            continue
        if not line.startswith(' ') and line.endswith(':'):
            current = frames.setdefault(line[:-1], {})
        elif current is not None and ':' in line:
            key, value = line.strip().split(':', 1)
            current[key] = value.strip().strip("'")
    return frames


def tf_publishers(ros_node) -> list[dict]:
    """The nodes publishing /tf and /tf_static, from the ROS graph (as `ros2 topic info -v`)."""
    if ros_node is None or not hasattr(ros_node, 'GetPublisherNodeNames'):
        return []
    return [{'topic': topic, 'nodes': ', '.join(ros_node.GetPublisherNodeNames(topic).split()) or '(none)'}
            for topic in ('/tf', '/tf_static')]


def tf_frame_rows(ros_node) -> list[dict]:
    """Every frame the node's tf buffer knows, as a depth-first tree (parent before its children,
    siblings by name): depth, parent, the age of its newest transform ('static' for /tf_static
    frames), its rate, and the node that published its newest transform (tf2's 'broadcaster':
    our listener records the node of the DDS writer each message came from, as the ROS graph
    names it; '?' while no node announcement lists that writer). Roots (frames that are only
    parents) head their trees."""
    if ros_node is None or not hasattr(ros_node, 'GetTf2FramesAsYAML'):
        return []
    frames = parse_frames_yaml(ros_node.GetTf2FramesAsYAML())
    children: dict[str, list[str]] = {}
    for frame, info in frames.items():
        children.setdefault(info.get('parent', ''), []).append(frame)
    roots = sorted({info.get('parent', '') for info in frames.values()} - set(frames) - {''})
    rows: list[dict] = []

    def add(frame: str, depth: int, seen: set) -> None:
        info = frames.get(frame, {})
        static = info.get('most_recent_transform', '') in ('0.000000', '0')
        if not info:
            age, rate = '(root)', ''
        elif static:
            age, rate = 'static', ''
        else:
            delay = float(info.get('transform_delay', 'nan'))
            try:
                rate = f"{float(info.get('rate', '')):.1f}"
            except ValueError:
                rate = info.get('rate', '')
            age = f'{max(delay, 0.0):.3f} s'
        authority = info.get('broadcaster', '')
        if not info:
            publisher = ''
        elif authority in ('ros2vtk_tf_listener', 'no recorded authority', ''):
            publisher = '?'
        else:
            publisher = authority
        rows.append({'frame': frame, 'depth': depth, 'parent': info.get('parent', ''), 'age': age,
                     'rate': rate, 'static': static, 'topic': ('/tf_static' if static else '/tf') if info else '',
                     'publisher': publisher})
        for child in sorted(children.get(frame, [])):
            if child not in seen:  # a loop in a broken tree must not recurse forever
                seen.add(child)
                add(child, depth + 1, seen)
    seen: set = set(roots)
    for root in roots:
        add(root, 0, seen)
    for frame in sorted(frames):  # frames of a loop (no root above them)
        if frame not in seen:
            seen.add(frame)
            add(frame, 0, seen)
    return rows
