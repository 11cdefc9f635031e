"""vtkROS2Message / ros2vtk.Message through the wrapped API: paths, errors that name the path,
failed writes that change nothing, containers, nested messages, YAML and the node hooks. What the
bytes look like on the wire is proven against rclpy in tests/interop/test_message_objects.py."""
from __future__ import annotations

import math

import pytest

import ros2vtk


def test_unknown_type_lists_the_registered_ones():
    message = ros2vtk.vtkROS2Message()
    assert not message.SetROSType('no_pkg/msg/Nothing')
    assert "unknown ROS message type 'no_pkg/msg/Nothing'" in message.GetLastError()
    assert 'geometry_msgs/msg/Pose' in message.GetLastError()
    assert message.GetROSType() == ''
    with pytest.raises(ValueError, match='unknown ROS message type'):
        ros2vtk.Message('no_pkg/Nothing')


def test_introspection_spells_types_as_msg_files_do():
    message = ros2vtk.vtkROS2Message()
    assert message.SetROSType('rcl_interfaces/ParameterDescriptor')
    assert message.GetROSType() == 'rcl_interfaces/msg/ParameterDescriptor'
    assert message.GetFieldType('floating_point_range') == \
        'rcl_interfaces/msg/FloatingPointRange[<=1]'
    assert message.IsArrayField('floating_point_range')
    assert not message.IsMessageField('floating_point_range')
    gid = ros2vtk.vtkROS2Message()
    assert gid.SetROSType('rmw_dds_common/msg/Gid')
    assert gid.GetFieldType('data') == 'char[16]'  # as Gid.msg spells it (uint8 on the wire)
    assert gid.GetFieldLength('data') == 16
    names = [message.GetFieldName('', i) for i in range(message.GetNumberOfFields(''))]
    assert names[:3] == ['name', 'type', 'description']


def test_paths_and_their_errors():
    m = ros2vtk.vtkROS2Message()
    assert m.SetROSType('geometry_msgs/msg/PoseArray')
    assert not m.SetField('poses[0].position.x', '1.0')
    assert 'index 0 of' in m.GetLastError() and 'out of range (it holds 0)' in m.GetLastError()
    assert m.SetFieldLength('poses', 2)
    assert m.SetFieldFromDouble('poses[1].position.x', 0.1)
    assert m.GetFieldAsDouble('poses[1].position.x') == 0.1
    assert not m.SetField('poses.position.x', '1')
    assert 'sequence of messages: pick one, poses[i]' in m.GetLastError()
    assert not m.SetField('header.nothing', '1')
    assert "std_msgs/msg/Header has no field 'nothing'" in m.GetLastError()
    assert not m.SetField('poses[x]', '1')
    assert 'malformed path' in m.GetLastError()


def test_failed_writes_change_nothing():
    m = ros2vtk.Message('sensor_msgs/msg/JointState')
    m.position = [1.0, 2.0]
    before = m.vtk.GetYAML()
    assert not m.vtk.SetField('position[0]', 'not a number')
    assert "'not a number' does not fit field 'position[0]' (float64)" in m.vtk.GetLastError()
    assert not m.vtk.SetYAML('{position: [1.0, }')
    assert m.vtk.GetYAML() == before
    gid = ros2vtk.vtkROS2Message()
    gid.SetROSType('rmw_dds_common/msg/Gid')
    assert not gid.SetFieldLength('data', 3)
    assert 'holds exactly 16 elements, not 3' in gid.GetLastError()
    assert not gid.SetFieldFromInteger('data[0]', 256)
    assert gid.GetFieldAsInteger('data[0]') == 0
    descriptor = ros2vtk.vtkROS2Message()
    descriptor.SetROSType('rcl_interfaces/msg/ParameterDescriptor')
    assert not descriptor.SetFieldLength('floating_point_range', 2)
    assert 'holds at most 1 elements, not 2' in descriptor.GetLastError()


def test_integers_exact_at_the_extremes_and_floats_exact():
    m = ros2vtk.Message('rcl_interfaces/msg/ParameterValue')
    m.integer_value = -2**63
    assert m.integer_value == -2**63
    m.integer_array_value = [2**63 - 1, -1]
    assert m.integer_array_value == [2**63 - 1, -1]
    m.double_value = 0.1 + 0.2
    assert m.double_value == 0.1 + 0.2
    m.double_value = math.inf
    assert m.double_value == math.inf
    with pytest.raises(ValueError, match='not a whole number'):
        m.integer_value = 1.5
    assert not m.vtk.SetFieldFromDouble('integer_value', 2.5)
    assert 'takes whole numbers only' in m.vtk.GetLastError()


def test_nested_messages_views_copies_and_slicer_style_accessors():
    m = ros2vtk.Message('geometry_msgs/msg/TransformStamped')
    header = m.header  # a view: writing through it changes m
    header.frame_id = 'world'
    assert m.header.frame_id == 'world'
    m.GetHeader().GetStamp().SetSec(7)
    assert m.header.stamp.sec == 7 and m.GetHeader().GetStamp().GetSec() == 7
    copy = m.header.copy()  # a copy: independent
    copy.frame_id = 'other'
    assert m.header.frame_id == 'world'
    point = ros2vtk.Message('geometry_msgs/msg/Point')
    assert not m.vtk.SetMessage('header', point.vtk)
    assert 'is a std_msgs/msg/Header, not a geometry_msgs/msg/Point' in m.vtk.GetLastError()
    with pytest.raises(AttributeError, match="has no field 'frameid'"):
        m.header.frameid = 'x'


def test_arrays_through_vtk_arrays():
    import vtkmodules.vtkCommonCore as core
    m = ros2vtk.vtkROS2Message()
    m.SetROSType('std_msgs/msg/Float64MultiArray')
    values = core.vtkDoubleArray()
    for v in (0.5, -1.25, 3.0):
        values.InsertNextValue(v)
    assert m.SetFieldFromArray('data', values)
    out = core.vtkDoubleArray()
    assert m.GetFieldAsArray('data', out)
    assert [out.GetValue(i) for i in range(out.GetNumberOfTuples())] == [0.5, -1.25, 3.0]
    ints = ros2vtk.vtkROS2Message()
    ints.SetROSType('std_msgs/msg/Int64MultiArray')
    big = core.vtkTypeInt64Array()
    big.InsertNextValue(2**62 + 1)  # beyond a double's 53 bits: kept exact
    assert ints.SetFieldFromArray('data', big)
    assert ints.GetField('data[0]') == str(2**62 + 1)
    names = core.vtkStringArray()
    joint = ros2vtk.vtkROS2Message()
    joint.SetROSType('sensor_msgs/msg/JointState')
    names.InsertNextValue('shoulder')
    names.InsertNextValue('elbow')
    assert joint.SetFieldFromStringArray('name', names)
    assert joint.GetField('name[1]') == 'elbow'


def test_publisher_hands_out_its_type_and_refuses_another():
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    publisher = node.CreateAndAddPublisherNode('PoseStamped', '/message_objects_pose')
    blank = publisher.CreateMessageObject()
    assert blank.GetROSType() == 'geometry_msgs/msg/PoseStamped'
    assert publisher.PublishMessageObject(blank)
    wrong = ros2vtk.Message('std_msgs/msg/String')
    assert not publisher.PublishMessageObject(wrong.vtk)
    assert publisher.GetNumberOfMessagesSent() == 1 and publisher.GetNumberOfCalls() == 2
    subscriber = node.CreateAndAddSubscriberNode('PoseStamped', '/message_objects_pose')
    with pytest.raises(LookupError, match='no message received yet'):
        ros2vtk.Message.last_of(subscriber)
