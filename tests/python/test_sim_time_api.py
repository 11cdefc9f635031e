"""Simulated time from Python: use_sim_time on the default ROS node, a second node of this process
as the simulator on /clock, the header stamp a generated (mapped) publisher writes, and the app's
status-line text. The wire side against rclpy is tests/interop/test_sim_time.py."""

from __future__ import annotations

import time

import yaml
from vtkmodules.vtkCommonMath import vtkMatrix4x4

from conftest import spin_until
from ros2vtk.app import scene_state


def test_use_sim_time_stamps_a_mapped_publisher_and_shows_in_the_status_line(ros2vtk, logic):
    node = logic.GetDefaultROS2Node()
    assert scene_state.clock_text(node) == ''  # system clock: nothing to say
    assert abs(node.GetNodeTime() - time.time()) < 60
    assert node.SetUseSimTime(True)
    assert node.GetUseSimTime() and node.GetNodeTime() == 0.0
    assert scene_state.clock_text(node) == 'sim time: waiting for /clock'

    simulator = ros2vtk.vtkROS2NodeNode()
    logic.GetScene().AddNode(simulator)
    assert simulator.Create('simulator_py')
    clock = simulator.CreateAndAddPublisherNode('rosgraph_msgs/msg/Clock', '/clock')
    listener = simulator.CreateAndAddSubscriberNode('PoseStamped', '/sim_pose')
    pose = node.CreateAndAddPublisherNode('PoseStamped', '/sim_pose')
    assert spin_until(logic, lambda: (clock.PublishYAML('{clock: {sec: 1000, nanosec: 250000000}}')
                                      and node.GetSimTimeReceived()))
    assert node.GetNodeTime() == 1000.25
    assert scene_state.clock_text(node) == 'sim time 1000.250 s'

    matrix = vtkMatrix4x4()
    assert spin_until(logic, lambda: pose.Publish(matrix) and listener.GetNumberOfMessages() > 0)
    stamp = yaml.safe_load(listener.GetLastMessageYAML())['header']['stamp']
    assert stamp == {'sec': 1000, 'nanosec': 250000000}

    # Off again through the parameter (as `ros2 param set` would): back to the system clock.
    assert node.SetParameterAsBool('use_sim_time', False)
    assert not node.GetUseSimTime()
    assert abs(node.GetNodeTime() - time.time()) < 60
    assert scene_state.clock_text(node) == ''
