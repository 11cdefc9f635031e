"""SlicerROS2 spellings the wrapped API accepts (issue 14's compatibility surface): the
Registered… names without Get, children by scene node ID, MRML's AddNewNodeByClass with
vtkMRMLROS2… class names, and GetParameterType's "" for a parameter never seen."""
from __future__ import annotations

import ros2vtk


def test_registered_node_classes_in_both_spellings():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    assert node.RegisteredROS2PublisherNodes() == node.GetRegisteredROS2PublisherNodes()
    assert node.RegisteredROS2SubscriberNodes() == node.GetRegisteredROS2SubscriberNodes()
    assert 'vtkROS2PublisherPoseNode' in node.RegisteredROS2PublisherNodes().split()
    assert 'vtkROS2SubscriberWrenchNode' in node.RegisteredROS2SubscriberNodes().split()


def test_children_by_scene_node_id_only_from_their_own_ros_node():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    lookup = node.CreateAndAddTf2LookupNode('world', 'tool')
    broadcaster = node.CreateAndAddTf2BroadcasterNode('world', 'probe')
    parameters = node.CreateAndAddParameterNode('/robot_state_publisher')
    assert node.GetTf2LookupNodeByID(lookup.GetID()) is lookup
    assert node.GetTf2BroadcasterNodeByID(broadcaster.GetID()) is broadcaster
    assert node.GetParameterNodeByNodeID(parameters.GetID()) is parameters
    # The wrong kind or an unknown ID gives None, not another node.
    assert node.GetTf2LookupNodeByID(broadcaster.GetID()) is None
    assert node.GetParameterNodeByNodeID('vtkROS2NoSuchNode7') is None


def test_add_new_node_by_class_takes_the_mrml_spelling():
    logic = ros2vtk.vtkROS2Logic()
    scene = logic.GetScene()
    created = scene.AddNewNodeByClass('vtkMRMLROS2NodeNode', 'planner')
    assert created.GetClassName() == 'vtkROS2NodeNode' and created.GetName() == 'planner'
    assert scene.GetNodeByID(created.GetID()) is created
    transform = scene.AddNewNodeByClass('vtkROS2TransformNode')
    assert transform.GetClassName() == 'vtkROS2TransformNode'
    assert scene.AddNewNodeByClass('vtkMRMLROS2NoSuchNode') is None


def test_parameter_type_of_a_parameter_never_seen_is_empty():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    parameters = node.CreateAndAddParameterNode('/nobody_here')
    parameters.AddParameter('robot_description')
    assert parameters.GetParameterType('robot_description') == ''
    assert parameters.GetParameterType('never_added') == ''


def test_empty_publisher_takes_slicerros2s_publish_with_text():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    publisher = node.CreateAndAddPublisherNode('Empty', '/slicerros2_names_empty')
    assert publisher.Publish('') == 1
    assert publisher.Publish() == 1
    assert publisher.GetNumberOfMessagesSent() == 2


def test_spinning_state_and_its_warning():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    import vtkmodules.vtkCommonCore as core
    assert node.GetSpinning() is False
    window = core.vtkStringOutputWindow()
    previous = core.vtkOutputWindow.GetInstance()
    core.vtkOutputWindow.SetInstance(window)
    try:
        node.WarnIfNotSpinning('adding a subscriber')  # a VTK warning, as SlicerROS2 gives
        logic.Spin()
        node.WarnIfNotSpinning('adding a lookup')      # spinning now: silent
    finally:
        core.vtkOutputWindow.SetInstance(previous)
    assert 'Node slicer is not spinning (yet) when adding a subscriber' in window.GetOutput()
    assert 'adding a lookup' not in window.GetOutput()
    assert node.GetSpinning() is True


def test_tf2_nodes_removed_by_scene_node_id():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    lookup = node.CreateAndAddTf2LookupNode('world', 'pointer')
    broadcaster = node.CreateAndAddTf2BroadcasterNode('world', 'target')
    lookup_id, broadcaster_id = lookup.GetID(), broadcaster.GetID()
    assert not node.RemoveAndDeleteTf2LookupNode(broadcaster_id)  # not a lookup: refused
    assert node.RemoveAndDeleteTf2LookupNode(lookup_id)
    assert node.RemoveAndDeleteTf2BroadcasterNode(broadcaster_id)
    assert logic.GetScene().GetNodeByID(lookup_id) is None
    assert node.GetTf2BroadcasterNodeByParentChild('world', 'target') is None


def test_broadcast_a_transform_node_and_look_it_up_in_the_fill_in_form():
    import vtkmodules.vtkCommonMath as math_
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    other = logic.GetScene().AddNewNodeByClass('vtkMRMLROS2NodeNode')
    assert other.Create('names_broadcaster')
    lookup = node.CreateAndAddTf2LookupNode('names_world', 'names_tool')
    lookup.SetModifiedOnLookup(True)
    assert lookup.GetModifiedOnLookup()
    broadcaster = other.CreateAndAddTf2BroadcasterNode('names_world', 'names_tool')
    source = logic.GetScene().AddNewNodeByClass('vtkROS2TransformNode')
    matrix = math_.vtkMatrix4x4()
    matrix.SetElement(0, 3, 12.5)  # mm
    source.SetMatrixTransformToParent(matrix)
    modified = []
    lookup.AddObserver('ModifiedEvent', lambda caller, event: modified.append(1))
    # /tf is not latched: broadcast until the lookup's subscription has matched and seen one.
    assert ros2vtk.spin_until(
        logic, lambda: broadcaster.Broadcast(source) and lookup.GetLookupStatus() == 'ok', 10)
    out = math_.vtkMatrix4x4()
    lookup.GetMatrixTransformToParent(out)
    assert abs(out.GetElement(0, 3) - 12.5) < 1e-9
    before = len(modified)
    # Later stamps, the same matrix.
    assert ros2vtk.spin_until(
        logic, lambda: broadcaster.Broadcast(source) and len(modified) > before, 10), \
        'ModifiedOnLookup: a new stamp with the same matrix still fires ModifiedEvent'


def test_int_array_publisher_takes_narrower_vtk_arrays_with_a_range_check():
    import vtkmodules.vtkCommonCore as core
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    publisher = node.CreateAndAddPublisherNode('IntArray', '/slicerros2_names_ints')
    subscriber = node.CreateAndAddSubscriberNode('IntArray', '/slicerros2_names_ints')
    assert ros2vtk.spin_until(logic, lambda: publisher.GetNumberOfMatchedSubscriptions() > 0, 10)
    ints = core.vtkIntArray()      # SlicerROS2 scripts publish vtkIntArray
    for value in (7, -2, 2**31 - 1):
        ints.InsertNextValue(value)
    assert publisher.Publish(ints) == 1
    assert ros2vtk.spin_until(logic, lambda: subscriber.GetNumberOfMessages() == 1, 10)
    received = subscriber.GetLastMessage()
    assert [received.GetValue(i) for i in range(received.GetNumberOfValues())] == [7, -2, 2**31 - 1]
    fractions = core.vtkDoubleArray()
    fractions.InsertNextValue(1.5)
    assert publisher.Publish(fractions) == 0
    assert 'value 1.5 at row 0 is not a whole number that fits int64' in publisher.GetLastConversionError()
