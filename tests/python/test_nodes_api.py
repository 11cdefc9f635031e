"""The generated node classes (ros2vtk.ros2vtkNodes) under Python, the SlicerROS2 way:
String publisher, PoseStamped/vtkMatrix4x4 subscriber with an observer, units, aliases."""

from __future__ import annotations

import time

import pytest
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkImageData, vtkPolyData
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.util.vtkConstants import VTK_UNSIGNED_CHAR

from conftest import spin_until


def connect(logic, pub, sub) -> None:
    assert spin_until(logic, lambda: pub.GetNumberOfMatchedSubscriptions() > 0
                      and sub.GetNumberOfMatchedPublications() > 0), 'never matched'


def test_generated_module_is_imported_and_reexported(ros2vtk):
    assert 'ros2vtkNodes' in ros2vtk.extension_modules
    for name in ('vtkROS2PublisherStringNode', 'vtkROS2SubscriberPoseStampedNode',
                 'vtkROS2PublisherImageNode', 'vtkROS2SubscriberJointStateNode'):
        assert getattr(ros2vtk, name).__name__ == name


def test_paper_hello_world(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('String', '/pub')
    assert type(pub).__name__ == 'vtkROS2PublisherStringNode'
    sub = node.CreateAndAddSubscriberNode('vtkMRMLROS2SubscriberStringNode', '/pub')
    connect(logic, pub, sub)
    assert pub.Publish('Hello world.') == 1
    assert spin_until(logic, lambda: sub.GetNumberOfMessages() >= 1)
    assert sub.GetLastMessage() == 'Hello world.'
    assert 'Hello world.' in sub.GetLastMessageYAML()
    assert pub.GetNumberOfMessagesSent() == 1


def test_pose_stamped_subscriber_observer_gets_millimetres(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('vtkMRMLROS2PublisherPoseStampedNode', '/py_pose')
    sub = node.CreateAndAddSubscriberNode('PoseStamped', '/py_pose')
    connect(logic, pub, sub)
    seen = []

    def on_modified(caller, _event):
        matrix = caller.GetLastMessage().GetPose()  # SlicerROS2's PoseStamped object
        seen.append((matrix.GetElement(0, 3), matrix.GetElement(2, 3), caller.GetLastMessageFrameID()))

    sub.AddObserver(vtkCommand.ModifiedEvent, on_modified)
    pub.SetFrameID('base')
    # Its blank message is SlicerROS2's PoseStamped object (GetHeader(), GetPose()); the VTK
    # value it publishes is a vtkMatrix4x4.
    assert pub.GetBlankMessage().GetPose().IsA('vtkMatrix4x4')
    matrix = vtkMatrix4x4()
    matrix.SetElement(0, 3, 100.0)  # mm
    matrix.SetElement(2, 3, -5.0)
    assert pub.Publish(matrix) == 1
    assert spin_until(logic, lambda: bool(seen))
    assert seen[0][0] == pytest.approx(100.0)
    assert seen[0][1] == pytest.approx(-5.0)
    assert seen[0][2] == 'base'
    # The same message in metres when the subscriber does not scale.
    sub.ScaleLengthsOff()
    metres = vtkMatrix4x4()
    assert sub.GetLastMessage(metres)
    assert metres.GetElement(0, 3) == pytest.approx(0.1)
    assert sub.GetLastMessageTime() > time.time() - 60


def test_alias_and_image_round_trip(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('UInt8Image', '/py_image')
    sub = node.CreateAndAddSubscriberNode('sensor_msgs/msg/Image', '/py_image')
    assert type(pub).__name__ == 'vtkROS2PublisherImageNode'
    assert type(sub).__name__ == 'vtkROS2SubscriberImageNode'
    connect(logic, pub, sub)
    image = vtkImageData()
    image.SetDimensions(3, 2, 1)
    image.AllocateScalars(VTK_UNSIGNED_CHAR, 3)
    image.SetScalarComponentFromDouble(2, 1, 0, 1, 200)
    pub.SetEncoding('bgr8')
    assert pub.Publish(image) == 1
    assert spin_until(logic, lambda: sub.GetNumberOfMessages() >= 1)
    assert 'encoding: bgr8' in sub.GetLastMessageYAML()
    received = sub.GetLastMessage()
    assert received.GetDimensions() == (3, 2, 1)
    assert received.GetScalarComponentAsDouble(2, 1, 0, 1) == 200


def test_wrench_values_are_not_scaled(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('WrenchStamped', '/py_wrench')
    sub = node.CreateAndAddSubscriberNode('WrenchStamped', '/py_wrench')
    connect(logic, pub, sub)
    values = vtkDoubleArray()
    for value in (1.0, 2.0, 3.0, 0.1, 0.2, 0.3):
        values.InsertNextValue(value)
    assert pub.Publish(values) == 1
    assert spin_until(logic, lambda: sub.GetNumberOfMessages() >= 1)
    # SlicerROS2's WrenchStamped object; its wrench is the Wrench rule's vtkDoubleArray ...
    received = sub.GetLastMessage().GetWrench()
    assert [received.GetValue(i) for i in range(6)] == [1.0, 2.0, 3.0, 0.1, 0.2, 0.3]
    # ... and this subscriber's own VTK value is GetLastVTKMessage() (C++ GetLastMessage()).
    received = sub.GetLastVTKMessage()
    assert [received.GetValue(i) for i in range(6)] == [1.0, 2.0, 3.0, 0.1, 0.2, 0.3]


def test_message_object_subscriber_before_any_message_and_bad_conversions(ros2vtk, logic):
    """GetLastMessage() of a subscriber that returns SlicerROS2's message objects is None before
    the first message; the per-field conversion refuses a wrong message or VTK type with why."""
    sub = logic.GetDefaultROS2Node().CreateAndAddSubscriberNode('PoseArray', '/py_no_pose_array')
    sub.GlobalWarningDisplayOff()  # the never-spun warning
    try:
        assert sub.GetLastMessage() is None and sub.GetLastVTKMessage() is None
    finally:
        sub.GlobalWarningDisplayOn()
    pose = ros2vtk.vtkROS2SubscriberPoseNode()
    assert not pose.ConvertMessageToObject(ros2vtk.Message('geometry_msgs/msg/Point').vtk, vtkMatrix4x4())
    assert 'the message is a geometry_msgs/msg/Point, not a geometry_msgs/msg/Pose' in pose.GetLastConversionError()
    assert not pose.ConvertMessageToObject(ros2vtk.Message('geometry_msgs/msg/Pose').vtk, vtkPoints())
    assert 'is a vtkMatrix4x4, not vtkPoints' in pose.GetLastConversionError()
    matrix = vtkMatrix4x4()
    message = ros2vtk.Message('geometry_msgs/msg/Pose')
    message.position.x = 0.5
    assert pose.ConvertMessageToObject(message.vtk, matrix) and matrix.GetElement(0, 3) == 500.0


def test_bad_publish_returns_zero_with_a_reason(logic):
    node = logic.GetDefaultROS2Node()
    pub = node.CreateAndAddPublisherNode('PoseStamped', '/py_bad_pose')
    sheared = vtkMatrix4x4()
    sheared.SetElement(0, 1, 0.5)
    pub.GlobalWarningDisplayOff()
    try:
        assert pub.Publish(sheared) == 0
        assert pub.Publish(None) == 0
    finally:
        pub.GlobalWarningDisplayOn()
    assert pub.GetLastConversionError() != ''
    assert pub.GetNumberOfMessagesSent() == 0


def test_generic_publish_object_and_value_reach_the_typed_publish_or_say_why_not(logic):
    """PublishObject / PublishValue (the path of callers that hold a publisher of any class, as
    the OpenIGTLink connector's device mappings): the node's own VTK type is published, anything
    else is refused with a reason naming both types, and nothing is sent for it."""
    from vtkmodules.vtkCommonCore import vtkPoints, vtkVariant
    node = logic.GetDefaultROS2Node()
    pose_pub = node.CreateAndAddPublisherNode('PoseStamped', '/py_generic_pose')
    pose_sub = node.CreateAndAddSubscriberNode('PoseStamped', '/py_generic_pose')
    text_pub = node.CreateAndAddPublisherNode('String', '/py_generic_text')
    text_sub = node.CreateAndAddSubscriberNode('String', '/py_generic_text')
    int_pub = node.CreateAndAddPublisherNode('Int', '/py_generic_int')
    int_sub = node.CreateAndAddSubscriberNode('Int', '/py_generic_int')
    connect(logic, pose_pub, pose_sub)
    connect(logic, text_pub, text_sub)
    connect(logic, int_pub, int_sub)
    matrix = vtkMatrix4x4()
    matrix.SetElement(1, 3, 42.0)
    assert pose_pub.PublishObject(matrix) == 1
    assert text_pub.PublishValue(vtkVariant('from Slicer')) == 1
    assert int_pub.PublishValue(vtkVariant(-7)) == 1
    pose_pub.GlobalWarningDisplayOff()
    try:
        assert pose_pub.PublishObject(vtkPoints()) == 0
        assert 'vtkROS2PublisherPoseStampedNode publishes vtkMatrix4x4, not vtkPoints' in pose_pub.GetLastPublishError()
        assert pose_pub.PublishObject(None) == 0
        assert pose_pub.PublishValue(vtkVariant(1.0)) == 0
        assert text_pub.PublishValue(vtkVariant(3.5)) == 0
        assert 'vtkROS2PublisherStringNode publishes' in text_pub.GetLastPublishError()
        assert int_pub.PublishValue(vtkVariant('12')) == 0  # a string is not a number here
        assert text_pub.PublishObject(matrix) == 0
    finally:
        pose_pub.GlobalWarningDisplayOn()
    assert spin_until(logic, lambda: pose_sub.GetNumberOfMessages() >= 1 and text_sub.GetNumberOfMessages() >= 1
                      and int_sub.GetNumberOfMessages() >= 1)
    assert pose_sub.GetLastMessage().GetPose().GetElement(1, 3) == 42.0
    assert text_sub.GetLastMessage() == 'from Slicer'
    assert int_sub.GetLastMessage() == -7
    assert (pose_pub.GetNumberOfMessagesSent(), text_pub.GetNumberOfMessagesSent(), int_pub.GetNumberOfMessagesSent()) \
        == (1, 1, 1)


def test_marker_array_subscriber_keeps_markers_and_names_what_it_cannot_draw(logic):
    """The MarkerArray subscriber (kind marker_array) folds every message into the markers it
    keeps: a marker of a type Marker does not define (42, not drawn) is left out and named, the cube and a TEXT label
    stay; metres when not scaling; our
    MarkerArray publisher's ADD (ns '', id 0) is one more kept marker."""
    import yaml
    import ros2vtk
    node = logic.GetDefaultROS2Node()
    pub = ros2vtk.vtkROS2PublisherGenericNode()
    logic.GetScene().AddNode(pub)
    pub.SetROSType('visualization_msgs/msg/MarkerArray')
    pub.AddToROS2Node(node.GetID(), '/py_markers')
    sub = node.CreateAndAddSubscriberNode('MarkerArray', '/py_markers')
    connect(logic, pub, sub)
    cube = {'ns': 'a', 'id': 1, 'type': 1, 'action': 0, 'pose': {'position': {'x': 1.0}, 'orientation': {'w': 1.0}},
            'scale': {'x': 0.1, 'y': 0.1, 'z': 0.1}, 'color': {'r': 1.0, 'a': 1.0}}
    arrows = {'ns': 'a', 'id': 2, 'type': 42, 'action': 0, 'pose': {'orientation': {'w': 1.0}},  # no such type
              'scale': {'x': 0.1, 'y': 0.1, 'z': 0.1}, 'points': [{'x': 0.0}, {'x': 1.0}, {'y': 1.0}]}
    text = {'ns': 'b', 'id': 1, 'type': 9, 'action': 0, 'pose': {'orientation': {'w': 1.0}},
            'scale': {'z': 0.1}, 'text': 'label'}
    assert pub.PublishYAML(yaml.safe_dump({'markers': [cube, arrows, text]}))
    assert spin_until(logic, lambda: sub.GetNumberOfMessages() == 1)
    drawn = sub.GetLastMessage()
    assert drawn is not None and drawn.GetBounds()[:2] == pytest.approx((950.0, 1050.0))
    assert "ns 'a', id 2" in sub.GetLastConversionError() and 'not supported' in sub.GetLastConversionError()
    assert drawn.GetFieldData().GetAbstractArray('LabelText').GetValue(0) == 'label'
    sub.ScaleLengthsOff()
    assert sub.GetLastMessage().GetBounds()[:2] == pytest.approx((0.95, 1.05))
    sub.ScaleLengthsOn()
    # Our own MarkerArray publisher: a two-point line, ADD under ('', 0); the cube is still kept.
    assert node.RemoveAndDeletePublisherNode('/py_markers')  # one publisher per topic and node
    typed = node.CreateAndAddPublisherNode('MarkerArray', '/py_markers')
    assert spin_until(logic, lambda: typed.GetNumberOfMatchedSubscriptions() > 0)
    line = vtkPolyData()
    points = vtkPoints()
    points.InsertNextPoint(0.0, 0.0, 0.0)
    points.InsertNextPoint(0.0, 500.0, 0.0)
    line.SetPoints(points)
    cells = vtkCellArray()
    cells.InsertNextCell(2)
    cells.InsertCellPoint(0)
    cells.InsertCellPoint(1)
    line.SetLines(cells)
    assert typed.Publish(line) == 1
    assert spin_until(logic, lambda: sub.GetNumberOfMessages() == 2)
    drawn = sub.GetLastMessage()
    index = drawn.GetCellData().GetArray('MarkerIndex')
    assert {int(index.GetValue(c)) for c in range(drawn.GetNumberOfCells())} == {0, 1}  # ('', 0) and ('a', 1)
    assert drawn.GetBounds()[3] == pytest.approx(500.0)
    assert sub.GetLastConversionError() == ''  # the latest message applied entirely
    # GetNewMessage(i) draws message i alone: the line only.
    assert sub.GetNumberOfNewMessages() == 1
    alone = sub.GetNewMessage(0)
    assert alone.GetNumberOfPoints() == 2
