"""Robot state without robot_state_publisher (issue 15), through the wrapped API: a robot from a
file shows its zero configuration, scripts and JointState messages move it, tf wins where it
arrives. Expected poses are worked out by hand in the comments (mm). The wire side (an rclpy node
publishing /joint_states, yourdfpy as the reference) is tests/interop/test_scene_robot_joint_states.py."""
from __future__ import annotations

import math

import pytest

from conftest import spin_until

# base --fixed (0, 0, 0.1)--> column --revolute z at (0.5, 0, 0), [-2, 2]--> arm
#   --prismatic along x, [0.05, 0.2]--> slider --revolute z at (0.1, 0, 0), mimic shoulder * -2 + 0.1--> jaw
URDF = """<robot name="state_test">
  <link name="base"/><link name="column"/><link name="arm"/><link name="slider"/><link name="jaw"/>
  <joint name="mount" type="fixed"><parent link="base"/><child link="column"/><origin xyz="0 0 0.1"/></joint>
  <joint name="shoulder" type="revolute"><parent link="column"/><child link="arm"/><origin xyz="0.5 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="insertion" type="prismatic"><parent link="arm"/><child link="slider"/>
    <axis xyz="1 0 0"/><limit lower="0.05" upper="0.2" effort="1" velocity="1"/></joint>
  <joint name="grip" type="revolute"><parent link="slider"/><child link="jaw"/><origin xyz="0.1 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
</robot>"""


@pytest.fixture
def vtk():
    import vtk as module
    return module


def load(logic, tmp_path, name='state'):
    urdf = tmp_path / f'{name}.urdf'
    urdf.write_text(URDF)
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromFile(name, str(urdf), '', '')
    assert robot is not None
    assert spin_until(logic, lambda: robot.IsLoaded() and robot.GetLinkPoseStatus('jaw') != '')
    return node, robot


def world(robot, link, vtk):
    matrix = vtk.vtkMatrix4x4()
    robot.GetLinkTransformNode(link).GetMatrixTransformToWorld(matrix)
    return [[matrix.GetElement(i, j) for j in range(4)] for i in range(4)]


def assert_pose(rows, position, yaw=0.0):
    for i in range(3):
        assert rows[i][3] == pytest.approx(position[i], abs=1e-9), rows
    assert rows[0][0] == pytest.approx(math.cos(yaw), abs=1e-12)
    assert rows[1][0] == pytest.approx(math.sin(yaw), abs=1e-12)
    assert rows[2][2] == pytest.approx(1.0, abs=1e-12)


def test_file_robot_without_tf_shows_its_zero_configuration(logic, tmp_path, vtk):
    node, robot = load(logic, tmp_path)
    assert robot.GetRobotState() == 'loaded'
    assert robot.GetNumberOfLinksTracked() == 1  # only the fixed frame's link: nothing from tf
    assert robot.GetLinkPoseStatus('base') == 'fixed frame'
    for link in ('column', 'arm', 'slider', 'jaw'):
        assert robot.GetLinkPoseStatus(link) == 'zero configuration (no tf)'
    assert robot.GetLinkPoseStatus('nope') == ''
    assert robot.GetLinkPoseSummary() == '5 links: 1 fixed frame, 4 zero configuration (no tf)'
    # insertion's range [0.05, 0.2] excludes 0: it starts at 0.05 (clamped zero).
    assert robot.GetJointPosition('insertion') == 0.05
    assert_pose(world(robot, 'column', vtk), (0, 0, 100))
    assert_pose(world(robot, 'arm', vtk), (500, 0, 100))
    assert_pose(world(robot, 'slider', vtk), (550, 0, 100))
    assert_pose(world(robot, 'jaw', vtk), (650, 0, 100), yaw=0.1)  # grip = -2 * 0 + 0.1


def test_set_joint_position_moves_links_with_limits_and_mimic(logic, tmp_path, vtk):
    node, robot = load(logic, tmp_path)
    assert robot.GetJointNames() == 'shoulder insertion'
    assert robot.SetJointPosition('shoulder', math.pi / 2)
    assert robot.SetJointPosition('insertion', 0.5)  # clamped to 0.2
    assert robot.GetJointPosition('insertion') == 0.2
    assert robot.GetJointPosition('grip') == pytest.approx(-math.pi + 0.1)
    logic.Spin()
    assert robot.GetLinkPoseStatus('slider') == 'joint positions (no tf)'
    # arm yawed 90°: its x is the world's y.
    assert_pose(world(robot, 'arm', vtk), (500, 0, 100), yaw=math.pi / 2)
    assert_pose(world(robot, 'slider', vtk), (500, 200, 100), yaw=math.pi / 2)
    assert_pose(world(robot, 'jaw', vtk), (500, 300, 100), yaw=math.pi / 2 - math.pi + 0.1)
    robot.ResetJointPositions()
    logic.Spin()
    assert robot.GetLinkPoseStatus('slider') == 'zero configuration (no tf)'
    assert_pose(world(robot, 'slider', vtk), (550, 0, 100))


def test_bad_joint_positions_are_errors_not_crashes(logic, tmp_path, ros2vtk):
    node, robot = load(logic, tmp_path)
    errors = []
    robot.AddObserver('ErrorEvent', lambda caller, event: errors.append(event))
    assert not robot.SetJointPosition('grip', 0.1)       # mimic
    assert not robot.SetJointPosition('mount', 0.1)      # fixed
    assert not robot.SetJointPosition('elbow', 0.1)      # unknown
    assert not robot.SetJointPosition('shoulder', float('nan'))
    assert not robot.SetJointPosition(None, 0.1)
    assert len(errors) == 5
    assert robot.GetJointPosition('shoulder') == 0.0
    assert math.isnan(robot.GetJointPosition('elbow'))


def test_joint_states_from_a_topic_move_the_robot_and_bad_messages_are_refused(logic, tmp_path, vtk, ros2vtk):
    node, robot = load(logic, tmp_path)
    assert robot.GetJointStatesTopic() == ''
    assert robot.SetJointStatesTopic('/state_test/joint_states')
    assert robot.GetJointStatesTopic() == '/state_test/joint_states'
    publisher = node.CreateAndAddPublisherNode('JointState', '/state_test/joint_states')
    warnings = []
    robot.AddObserver('WarningEvent', lambda caller, event: warnings.append(event))

    def joint_state(names, positions):
        message = ros2vtk.vtkROS2Message()
        assert message.SetROSType('sensor_msgs/msg/JointState')
        import vtk as v
        n, p = v.vtkStringArray(), v.vtkDoubleArray()
        for name in names:
            n.InsertNextValue(name)
        for position in positions:
            p.InsertNextValue(position)
        assert message.SetFieldFromStringArray('name', n)
        assert message.SetFieldFromArray('position', p)
        return message

    assert spin_until(logic, lambda: publisher.GetNumberOfMatchedSubscriptions() > 0)
    assert publisher.PublishMessageObject(joint_state(['shoulder', 'gripper', 'insertion'], [math.pi / 2, 1.0, 0.1]))
    assert spin_until(logic, lambda: robot.GetNumberOfJointStatesApplied() == 1)
    assert robot.GetJointPosition('shoulder') == math.pi / 2
    assert robot.GetLinkPoseStatus('slider') == 'joint positions (no tf)'
    assert_pose(world(robot, 'slider', vtk), (500, 100, 100), yaw=math.pi / 2)
    assert len(warnings) == 1  # 'gripper' is no joint of this robot: reported once
    # Names and positions of different lengths: the whole message is refused.
    assert publisher.PublishMessageObject(joint_state(['shoulder', 'insertion'], [0.3]))
    assert spin_until(logic, lambda: robot.GetNumberOfJointStatesRefused() == 1)
    assert '2 names but 1 positions' in robot.GetLastJointStateError()
    assert robot.GetJointPosition('shoulder') == math.pi / 2
    # NaN: that joint is ignored, the others taken.
    assert publisher.PublishMessageObject(joint_state(['shoulder', 'insertion'], [float('nan'), 0.15]))
    assert spin_until(logic, lambda: robot.GetNumberOfJointStatesApplied() == 2)
    reported = len(warnings)  # + the refusal and the NaN, each reported at once
    assert reported == 3
    assert publisher.PublishMessageObject(joint_state(['gripper'], [0.0]))
    assert spin_until(logic, lambda: robot.GetNumberOfJointStatesApplied() == 3)
    assert len(warnings) == reported  # 'gripper' was said once already
    assert robot.GetJointPosition('shoulder') == math.pi / 2 and robot.GetJointPosition('insertion') == 0.15
    assert robot.SetJointStatesTopic('')
    assert node.GetSubscriberNodeByTopic('/state_test/joint_states') is None  # ours, removed


def test_tf_wins_where_it_arrives(logic, tmp_path, vtk):
    node, robot = load(logic, tmp_path)
    broadcaster = node.CreateAndAddTf2BroadcasterNode('base', 'arm')
    matrix = vtk.vtkMatrix4x4()
    matrix.SetElement(1, 3, -70.0)
    assert broadcaster.Broadcast(matrix)
    assert spin_until(logic, lambda: robot.GetLinkPoseStatus('arm') == 'tf')
    assert_pose(world(robot, 'arm', vtk), (0, -70, 0))
    assert robot.GetLinkPoseStatus('slider') == 'zero configuration (no tf)'
    assert_pose(world(robot, 'slider', vtk), (550, 0, 100))
    assert robot.GetLinkPoseSummary() == '5 links: 1 tf, 1 fixed frame, 3 zero configuration (no tf)'


def test_joint_states_topic_and_publish_tf_are_saved_with_the_scene(logic, tmp_path):
    node, robot = load(logic, tmp_path)
    assert not robot.GetPublishTf()
    robot.SetPublishTf(True)
    assert robot.SetJointStatesTopic('/saved/joint_states')
    xml = logic.GetScene().WriteToXMLString()
    assert 'jointStatesTopic="/saved/joint_states"' in xml and 'publishTf="1"' in xml
    assert logic.GetScene().ReadFromXMLString(xml)
    node = logic.GetDefaultROS2Node()
    robot = node.GetRobotNodeByName('state')
    assert spin_until(logic, lambda: robot.IsLoaded() and robot.GetLinkPoseStatus('jaw') != '')
    assert robot.GetJointStatesTopic() == '/saved/joint_states' and robot.GetPublishTf()
    assert node.GetSubscriberNodeByTopic('/saved/joint_states') is not None
    # The restored subscriber is still the robot's: it goes when the robot stops following.
    assert robot.SetJointStatesTopic('')
    assert node.GetSubscriberNodeByTopic('/saved/joint_states') is None


def test_joint_states_topic_of_another_type_or_a_bad_name_is_refused(logic, tmp_path):
    node, robot = load(logic, tmp_path)
    errors = []
    robot.AddObserver('ErrorEvent', lambda caller, event: errors.append(event))
    assert node.CreateAndAddSubscriberNode('String', '/busy') is not None
    assert not robot.SetJointStatesTopic('/busy')
    assert not robot.SetJointStatesTopic('not a topic name')
    assert len(errors) == 2
    assert robot.GetJointStatesTopic() == ''
    assert node.GetSubscriberNodeByTopic('/busy') is not None  # a script's subscriber stays
