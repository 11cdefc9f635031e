"""The wrapped scene API under Python: import, SlicerROS2-style calls, observers on Spin."""

from __future__ import annotations

import threading
import time

import pytest
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_INT

from conftest import spin_until


def test_package_reexports_the_scene_classes(ros2vtk):
    for name in ('vtkROS2Logic', 'vtkROS2Scene', 'vtkROS2NodeNode', 'vtkROS2PublisherNode',
                 'vtkROS2SubscriberNode', 'vtkROS2PublisherGenericNode',
                 'vtkROS2SubscriberGenericNode'):
        assert name in ros2vtk.__all__
        assert getattr(ros2vtk, name).__name__ == name
    assert 'ros2vtkScene' in ros2vtk.extension_modules


def test_default_node_is_slicer_and_created_once(logic):
    node = logic.GetDefaultROS2Node()
    assert node.GetROS2NodeName() == 'slicer'
    assert node.GetROS2NodeNamespace() == '/'
    assert node.IsCreated()
    assert logic.GetDefaultROS2Node() is node
    assert logic.GetScene().GetNumberOfNodes() == 1
    assert node.GetWakeUpFileDescriptor() >= 0


def test_generic_nodes_come_back_as_their_python_class(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('geometry_msgs/msg/Point', '/py_point')
    sub = node.CreateAndAddSubscriberNode('geometry_msgs/Point', '/py_point')
    assert pub.GetClassName() == 'vtkROS2PublisherGenericNode'
    assert type(pub).__name__ == 'vtkROS2PublisherGenericNode'
    assert sub.GetROSType() == 'geometry_msgs/msg/Point'
    assert node.GetPublisherNodeByTopic('/py_point') is pub
    assert node.GetSubscriberNodeByTopic('/py_point') is sub
    assert pub.GetSlicerType() == 'YAML'


def test_unknown_type_returns_none(logic):
    node = logic.GetDefaultROS2Node()
    node.GlobalWarningDisplayOff()
    try:
        assert node.CreateAndAddPublisherNode('NoSuchType', '/nowhere') is None
    finally:
        node.GlobalWarningDisplayOn()
    assert node.GetPublisherNodeByTopic('/nowhere') is None


def test_observer_fires_once_per_spin_on_the_spinning_thread_with_the_count(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('geometry_msgs/msg/Point', '/py_observed')
    sub = node.CreateAndAddSubscriberNode('geometry_msgs/msg/Point', '/py_observed')
    assert spin_until(logic, lambda: pub.GetNumberOfMatchedSubscriptions() > 0
                      and sub.GetNumberOfMatchedPublications() > 0)

    calls = []

    # `count` defaults: other changes of the node (e.g. removal) fire ModifiedEvent without data.
    @calldata_type(VTK_INT)
    def on_modified(caller, event, count=None):
        calls.append((caller.GetTopic(), event, count, threading.get_ident()))

    sub.AddObserver('ModifiedEvent', on_modified)
    for x in (1.0, 2.0, 3.0):
        assert pub.PublishYAML(f'{{x: {x}, y: 0.0, z: 0.0}}')
    handled = []
    end = time.monotonic() + 10.0
    while sub.GetNumberOfMessages() < 3 and time.monotonic() < end:
        handled.append(logic.Spin())
        time.sleep(0.005)
    assert sum(handled) == 3
    assert [c[2] for c in calls] == [h for h in handled if h > 0]
    assert all(c[0] == '/py_observed' and c[1] == 'ModifiedEvent' for c in calls)
    assert {c[3] for c in calls} == {threading.get_ident()}
    assert sub.GetLastMessage() == 'x: 3.0\ny: 0.0\nz: 0.0\n'
    assert sub.GetLastMessageYAML() == sub.GetLastMessage()
    assert pub.GetNumberOfMessagesSent() == 3


def test_invalid_yaml_is_refused_and_counted(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('geometry_msgs/msg/Point', '/py_bad_yaml')
    pub.GlobalWarningDisplayOff()
    try:
        assert not pub.PublishYAML('{x: [1, 2}')
        assert not pub.PublishYAML('{no_such_field: 1}')
    finally:
        pub.GlobalWarningDisplayOn()
    assert pub.GetNumberOfCalls() == 2
    assert pub.GetNumberOfMessagesSent() == 0


def test_qos_setters_validate_and_report(logic):
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode('geometry_msgs/msg/Point', '/py_qos')
    assert sub.SetQoSProfile('sensor_data')
    assert (sub.GetReliability(), sub.GetDurability(), sub.GetHistoryDepth()) == \
        ('best_effort', 'volatile', 5)
    assert sub.IsAddedToROS2Node()
    sub.GlobalWarningDisplayOff()
    try:
        assert not sub.SetReliability('maybe')
        assert not sub.SetHistoryDepth(0)
    finally:
        sub.GlobalWarningDisplayOn()
    assert sub.GetQoSDescription().startswith('best_effort')


def test_remove_and_delete(logic):
    node = logic.GetDefaultROS2Node()
    node.CreateAndAddSubscriberNode('geometry_msgs/msg/Point', '/py_gone')
    assert node.RemoveAndDeleteSubscriberNode('/py_gone')
    assert node.GetSubscriberNodeByTopic('/py_gone') is None
    assert logic.GetScene().GetNumberOfNodes() == 1


def test_scene_file_round_trip(logic, ros2vtk, tmp_path):
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode('geometry_msgs/msg/Point', '/py_saved')
    sub.SetDurability('transient_local')
    sub.SetAttribute('purpose', 'test')
    path = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(path)

    other = ros2vtk.vtkROS2Logic()
    assert other.GetScene().ReadFromXMLFile(path)
    restored = other.GetScene().GetNodeByID(sub.GetID())
    assert restored.GetClassName() == 'vtkROS2SubscriberGenericNode'
    assert restored.IsAddedToROS2Node()
    assert restored.GetDurability() == 'transient_local'
    assert restored.GetAttribute('purpose') == 'test'
    assert other.GetDefaultROS2Node().GetID() == node.GetID()
    other.GetScene().Clear()


def test_spin_on_wake_up_times_out_without_data(logic):
    logic.GetDefaultROS2Node()
    assert logic.SpinOnWakeUp(0.05) == 0
    assert logic.GetWakeUpFileDescriptor() >= 0


def test_interactor_timer_spins_at_the_rate_and_detaches(logic):
    from vtkmodules.vtkRenderingUI import vtkGenericRenderWindowInteractor

    interactor = vtkGenericRenderWindowInteractor()
    created, destroyed = [], []
    interactor.AddObserver('CreateTimerEvent', lambda o, e: created.append(
        (o.GetTimerEventId(), o.GetTimerEventDuration())))
    interactor.AddObserver('DestroyTimerEvent', lambda o, e: destroyed.append(o.GetTimerEventId()))
    interactor.Enable()
    logic.SetSpinRate(25.0)
    assert logic.AttachToInteractor(interactor)
    assert len(created) == 1 and created[0][1] == 40  # ms between spins at 25 Hz
    timer_id = created[0][0]

    spins = logic.GetNumberOfSpins()
    interactor.SetTimerEventId(timer_id)
    interactor.TimerEvent()
    assert logic.GetNumberOfSpins() == spins + 1

    logic.DetachFromInteractor()
    assert set(destroyed) == {timer_id}  # VTK 9.1 reports a destroyed timer once per interactor layer
    interactor.SetTimerEventId(timer_id)
    interactor.TimerEvent()
    assert logic.GetNumberOfSpins() == spins + 1


def test_scene_file_restores_tf2_parameter_transform_and_model_nodes(logic, ros2vtk, tmp_path):
    node = logic.GetDefaultROS2Node()
    node.CreateAndAddTf2LookupNode('world', 'tool')
    broadcaster = node.CreateAndAddTf2BroadcasterNode('world', 'marker')
    broadcaster.StaticOn()
    parameters = node.CreateAndAddParameterNode('/robot_state_publisher')
    assert parameters.AddParameter('robot_description')
    model = ros2vtk.vtkROS2ModelNode()
    model.SetColor(0.1, 0.2, 0.3)
    model.ScalarVisibilityOn()
    logic.GetScene().AddNode(model)
    path = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(path)

    assert logic.GetScene().ReadFromXMLFile(path)
    node = logic.GetDefaultROS2Node()
    lookup = node.GetTf2LookupNodeByParentChild('world', 'tool')
    assert lookup is not None and lookup.GetLookupStatus() != 'ok'
    restored = node.GetTf2BroadcasterNodeByParentChild('world', 'marker')
    assert restored is not None and restored.GetROS2Node() is node and restored.GetStatic()
    parameters = node.GetParameterNodeByNode('/robot_state_publisher')
    assert parameters is not None and parameters.GetParameterNames() == 'robot_description'
    model = logic.GetScene().GetNodeByID(model.GetID())
    assert model.GetColor() == (0.1, 0.2, 0.3) and model.GetScalarVisibility()
    # The restored lookup listens to tf again (the wire side: tests/interop/test_scene_robot.py).
    import vtk
    tool = node.CreateAndAddTf2BroadcasterNode('world', 'tool')
    assert tool.Broadcast(vtk.vtkMatrix4x4())
    assert spin_until(logic, lambda: lookup.GetLookupStatus() == 'ok')


def test_a_ros_node_added_after_spins_is_spun(logic, ros2vtk):
    # The logic keeps its list of ROS nodes between spins; adding a node refreshes it. (Removing
    # one while another lives is left out: Fast DDS 2.9 may crash deleting one of several
    # participants of a process, eProsima/Fast-DDS#5034.)
    logic.GetDefaultROS2Node()
    logic.Spin()
    second = ros2vtk.vtkROS2NodeNode()
    logic.GetScene().AddNode(second)
    assert second.Create('second_node', '')
    sub = second.CreateAndAddSubscriberNode('std_msgs/msg/String', '/py_second')
    pub = logic.GetDefaultROS2Node().CreateAndAddPublisherNode('String', '/py_second')
    assert spin_until(logic, lambda: pub.Publish('hello') and sub.GetNumberOfMessages() > 0)


def test_spin_until_stops_at_the_condition_or_the_timeout(logic, ros2vtk):
    logic.GetDefaultROS2Node()
    before = logic.GetNumberOfSpins()
    assert ros2vtk.spin_until(logic, lambda: True, seconds=30.0) is True
    assert logic.GetNumberOfSpins() == before + 1  # the condition held: one spin, no waiting
    calls = []
    assert ros2vtk.spin_until(logic, lambda: calls.append(1) and False, seconds=0.2, step=0.02) is False
    assert len(calls) >= 2  # spun until the timeout, checking each time
    sub = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('String', '/py_spin_until')
    pub = logic.GetDefaultROS2Node().CreateAndAddPublisherNode('String', '/py_spin_until')
    assert ros2vtk.spin_until(logic, lambda: pub.Publish('x') and sub.GetNumberOfMessages() > 0, seconds=10.0)


def test_scene_file_of_the_previous_version_loads(logic, ros2vtk, tmp_path):
    """tests/scene/data/previous_version_scene.xml was written by the version before issue 10
    (write_previous_version_scene.py beside it): its topic nodes reference their ROS node as
    'ROS2Node', the other children as 'ros2Node'. Both read into the one role, and the file
    written again uses only that role."""
    from pathlib import Path
    fixture = Path(__file__).resolve().parents[1] / 'scene' / 'data' / 'previous_version_scene.xml'
    scene = logic.GetScene()
    assert scene.ReadFromXMLFile(str(fixture))
    node = logic.GetDefaultROS2Node()
    assert node.GetID() == 'vtkROS2NodeNode1' and node.IsCreated()
    role = 'ros2Node'  # vtkROS2SceneNode::ROS2NodeReferenceRole
    publisher = node.GetPublisherNodeByTopic('/legacy_pub')
    subscriber = node.GetSubscriberNodeByTopic('/legacy_sub')
    assert publisher is not None and publisher.GetClassName() == 'vtkROS2PublisherStringNode'
    assert subscriber is not None and subscriber.GetAttribute('purpose') == 'legacy'
    lookup = node.GetTf2LookupNodeByParentChild('world', 'tool')
    broadcaster = node.GetTf2BroadcasterNodeByParentChild('world', 'marker')
    parameters = node.GetParameterNodeByNode('/robot_state_publisher')
    for child in (publisher, subscriber, lookup, broadcaster, parameters):
        assert child is not None
        assert child.GetNodeReferenceID(role) == node.GetID(), child.GetClassName()
        assert child.GetNodeReferenceID('ROS2Node') is None
        assert child.GetROS2Node() is node
    assert broadcaster.GetStatic()
    assert parameters.GetParameterNames() == 'robot_description'
    written = scene.WriteToXMLString()
    assert 'role="ROS2Node"' not in written and written.count('role="ros2Node"') == 5


def test_endpoint_nodes_of_the_version_before_their_base_class_load(logic, ros2vtk):
    """tests/scene/data/endpoint_nodes_before_base_class.xml was written by the version before
    vtkROS2EndpointNode (main at f7f938e: a service client and server, an action client and
    server, with non-default timeouts). Every property comes back, each node re-attaches to its
    ROS node and is found by name, and writing the scene again gives the same attributes."""
    import xml.etree.ElementTree as ET
    from pathlib import Path
    fixture = Path(__file__).resolve().parents[1] / 'scene' / 'data' / 'endpoint_nodes_before_base_class.xml'
    scene = logic.GetScene()
    assert scene.ReadFromXMLFile(str(fixture))
    node = logic.GetDefaultROS2Node()
    assert node.GetID() == 'vtkROS2NodeNode1' and node.IsCreated()
    client = node.GetServiceClientNodeByService('/enable')
    server = node.GetServiceServerNodeByService('/enable')
    action_client = node.GetActionClientNodeByAction('/fibonacci')
    action_server = node.GetActionServerNodeByAction('/fibonacci')
    for child in (client, server, action_client, action_server):
        assert child is not None
        assert isinstance(child, ros2vtk.vtkROS2EndpointNode)
        assert child.GetROS2Node() is node
        assert child.GetROS2NodeChildKey() == ('/enable' if 'Service' in child.GetClassName() else '/fibonacci')
    assert (client.GetServiceName(), client.GetServiceType(), client.GetTimeout()) == \
        ('/enable', 'std_srvs/srv/SetBool', 3.0)
    assert (server.GetServiceName(), server.GetServiceType(), server.GetResponseTimeout()) == \
        ('/enable', 'std_srvs/srv/SetBool', 2.5)
    assert not server.GetAnswerUnansweredWithDefault()
    assert (action_client.GetActionName(), action_client.GetActionType(), action_client.GetTimeout()) == \
        ('/fibonacci', 'test_msgs/action/Fibonacci', 4.0)
    assert (action_server.GetActionName(), action_server.GetActionType()) == ('/fibonacci', 'test_msgs/action/Fibonacci')
    # Re-attached: the wire endpoints exist again (a client and a server of one process match).
    assert ros2vtk.spin_until(logic, client.IsServiceReady, seconds=10)
    assert ros2vtk.spin_until(logic, action_client.IsServerReady, seconds=10)

    def endpoints(text):
        return {element.tag: element.attrib for element in ET.fromstring(text)
                if element.tag.startswith(('vtkROS2Service', 'vtkROS2Action'))}
    assert endpoints(scene.WriteToXMLString()) == endpoints(fixture.read_text())


def test_type_description_service_switch_is_read_only_and_saved(logic, ros2vtk):
    # rclpy's start_type_description_service: default true, read-only once the node exists.
    import vtk
    node = ros2vtk.vtkROS2NodeNode()
    assert node.GetStartTypeDescriptionService()
    default = vtk.vtkXMLDataElement()
    node.WriteXML(default)
    assert default.GetAttribute('startTypeDescriptionService') is None  # old files unchanged
    assert node.SetStartTypeDescriptionService(False)
    off = vtk.vtkXMLDataElement()
    node.WriteXML(off)
    assert off.GetAttribute('startTypeDescriptionService') == '0'
    restored = ros2vtk.vtkROS2NodeNode()
    assert restored.ReadXML(off) and not restored.GetStartTypeDescriptionService()

    logic.GetScene().AddNode(node)
    assert node.Create('no_type_descriptions_py')
    assert not node.GetStartTypeDescriptionService()
    assert node.PrintOwnParameter('start_type_description_service') == \
        'start_type_description_service (bool): false'
    assert not node.SetStartTypeDescriptionService(True)  # read-only after Create
    assert not node.SetParameterAsBool('start_type_description_service', True)
    served = logic.GetDefaultROS2Node()
    assert served.GetStartTypeDescriptionService()
    assert served.PrintOwnParameter('start_type_description_service') == \
        'start_type_description_service (bool): true'


def test_a_subscriber_of_an_unregistered_type_waits_for_its_publisher_and_survives_a_scene_file(logic):
    """Issue 13: a full type name nothing registers makes a YAML subscriber that learns the type
    from a publisher (tests/interop/test_runtime_types.py has the rclpy side); with no publisher it
    says what it waits for, keeps the name, and a scene file brings it back waiting."""
    node = logic.GetDefaultROS2Node()
    sub = node.CreateAndAddSubscriberNode('nobody_ships_msgs/Thing', '/py_unknown_type')
    assert sub is not None and sub.GetClassName() == 'vtkROS2SubscriberGenericNode'
    assert sub.GetROSType() == 'nobody_ships_msgs/msg/Thing'
    assert sub.IsWaitingForType()
    spin_until(logic, lambda: False, seconds=0.3)
    assert sub.GetTypeStatus() == ('waiting for a publisher of nobody_ships_msgs/msg/Thing on '
                                   '/py_unknown_type to learn the type from')
    assert sub.GetNumberOfMessages() == 0 and sub.GetLastMessage() == ''
    scene = logic.GetScene()
    xml = scene.WriteToXMLString()
    assert 'rosType="nobody_ships_msgs/msg/Thing"' in xml
    assert scene.ReadFromXMLString(xml)
    node = logic.GetDefaultROS2Node()
    restored = node.GetSubscriberNodeByTopic('/py_unknown_type')
    assert restored is not None and restored.GetROSType() == 'nobody_ships_msgs/msg/Thing'
    spin_until(logic, lambda: False, seconds=0.3)
    assert restored.GetTypeStatus().startswith('waiting for a publisher of nobody_ships_msgs/msg/Thing')


def test_texts_that_are_no_type_names_are_still_refused(logic):
    node = logic.GetDefaultROS2Node()
    assert node.CreateAndAddSubscriberNode('not a/type', '/py_bad_type') is None
    assert node.CreateAndAddSubscriberNode('NoSuchShortName', '/py_bad_type') is None
    assert node.CreateAndAddPublisherNode('not a/type', '/py_bad_type') is None
    assert node.CreateAndAddPublisherNode('NoSuchShortName', '/py_bad_type') is None
    sub = ros2vtk_generic_subscriber(logic)
    assert not sub.SetROSType('nobody_ships_msgs/msg/Thing')  # SetROSType stays strict
    assert not sub.SetROSTypeResolvedAtRuntime('pkg/srv/Thing')
    assert sub.SetROSTypeResolvedAtRuntime('pkg/msg/Thing') and sub.IsWaitingForType()
    assert sub.SetROSType('std_msgs/msg/String') and not sub.IsWaitingForType()
    assert sub.GetROSType() == 'std_msgs/msg/String' and sub.GetTypeStatus() == ''


def test_a_publisher_of_an_unregistered_type_waits_to_learn_it_and_refuses_to_publish(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('nobody_ships_msgs/Thing', '/py_unknown_pub')
    assert pub is not None and pub.GetClassName() == 'vtkROS2PublisherGenericNode'
    assert pub.GetROSType() == 'nobody_ships_msgs/msg/Thing' and pub.IsWaitingForType()
    spin_until(logic, lambda: False, seconds=0.3)
    assert pub.GetTypeStatus() == ('waiting for a subscriber or publisher of nobody_ships_msgs/msg/Thing on '
                                   '/py_unknown_pub to learn the type from')
    assert not pub.PublishYAML('{}')
    assert pub.GetLastPublishError().startswith('the message type is not known yet: waiting for a subscriber')
    xml = logic.GetScene().WriteToXMLString()
    assert 'rosType="nobody_ships_msgs/msg/Thing"' in xml


def ros2vtk_generic_subscriber(logic):
    import ros2vtk
    sub = ros2vtk.vtkROS2SubscriberGenericNode()
    logic.GetScene().AddNode(sub)
    return sub


def test_the_scenes_fixed_frame_is_saved_only_when_set_and_used_by_marker_subscribers(logic):
    """vtkROS2Scene::SetFixedFrame (RViz's global Fixed Frame): written as the root's fixedFrame
    only when set (files of earlier versions stay byte-identical), read back from a file, and the
    frame a marker subscriber without its own fixed frame places its markers in."""
    import ros2vtk
    scene = logic.GetScene()
    sub = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('MarkerArray', '/py_fixed_frame_markers')
    assert scene.GetFixedFrame() == '' and 'fixedFrame' not in scene.WriteToXMLString()
    assert sub.GetEffectiveFixedFrame() == ''
    scene.SetFixedFrame('map')
    assert sub.GetFixedFrame() == '' and sub.GetEffectiveFixedFrame() == 'map'
    xml = scene.WriteToXMLString()
    assert xml.count('fixedFrame="map"') == 1, xml  # the scene's; the subscriber has none of its own
    sub.SetFixedFrame('odom')  # its own wins
    assert sub.GetEffectiveFixedFrame() == 'odom'
    xml = scene.WriteToXMLString()
    restored = ros2vtk.vtkROS2Scene()
    assert restored.ReadFromXMLString(xml)
    assert restored.GetFixedFrame() == 'map'
    scene.SetFixedFrame('')
    assert 'fixedFrame="map"' not in scene.WriteToXMLString()
