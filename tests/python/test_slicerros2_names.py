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


def test_a_node_whose_logic_was_garbage_collected_says_why():
    """`node = ros2vtk.vtkROS2Logic().GetDefaultROS2Node()` loses the logic at once (SlicerROS2's
    logic lives as long as Slicer); the node's next error names that cause, not 'add this ROS
    node to a scene first'."""
    import gc
    import vtk

    node = ros2vtk.vtkROS2Logic().GetDefaultROS2Node()
    gc.collect()
    errors = []

    @vtk.calldata_type(vtk.VTK_STRING)
    def on_error(_caller, _event, text):
        errors.append(text)

    node.AddObserver('ErrorEvent', on_error)
    assert node.CreateAndAddPublisherNode('String', '/orphan') is None
    assert len(errors) == 1
    assert 'the vtkROS2Logic that owned its scene was deleted' in errors[0]
    assert 'keep a reference to the logic' in errors[0]

    never_in_a_scene = ros2vtk.vtkROS2NodeNode()
    never_in_a_scene.AddObserver('ErrorEvent', on_error)
    assert never_in_a_scene.CreateAndAddPublisherNode('String', '/orphan') is None
    assert 'add this ROS node to a scene first' in errors[-1]


def test_logic_add_robot_and_remove_robot_act_on_the_default_node():
    logic = ros2vtk.vtkROS2Logic()
    robot = logic.AddRobot('arm', '/robot_state_publisher', 'robot_description', 'world', '')
    assert robot is not None and robot.GetClassName() == 'vtkROS2RobotNode'
    assert logic.GetDefaultROS2Node().GetRobotNodeByName('arm') is robot
    assert logic.RemoveRobot('arm') is True
    assert logic.GetDefaultROS2Node().GetRobotNodeByName('arm') is None
    assert logic.RemoveRobot('arm') is False


def test_reading_a_subscriber_whose_node_never_spun_warns_once_with_the_fix():
    """SlicerROS2 scripts have no spin of their own (Slicer spins on a timer): reading a
    subscriber before anything spun says why nothing arrives, once."""
    import vtk

    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    subscriber = node.CreateAndAddSubscriberNode('String', '/never_spun')
    warnings = []

    @vtk.calldata_type(vtk.VTK_STRING)
    def on_warning(_caller, _event, text):
        warnings.append(text)

    subscriber.AddObserver('WarningEvent', on_warning)
    assert subscriber.GetLastMessage() == ''
    subscriber.GetLastMessageYAML()
    assert len(warnings) == 1
    assert 'has never spun' in warnings[0] and 'logic.Spin()' in warnings[0]

    logic.Spin()
    spun = node.CreateAndAddSubscriberNode('String', '/spun')
    spun.AddObserver('WarningEvent', on_warning)
    spun.GetLastMessage()
    assert len(warnings) == 1
