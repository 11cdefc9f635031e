"""Writes previous_version_scene.xml: a scene saved by ros2vtk BEFORE issue 10's restructuring
(main at 2b84ff8, whose topic nodes spell their reference role "ROS2Node" and every other child
"ros2Node"). Kept for the record of how the fixture was made; re-running it with a newer build
would no longer produce the old file, so test_scene_previous_version reads the committed copy.

  PYTHONPATH=<old build>/python python write_previous_version_scene.py previous_version_scene.xml
"""
import sys

import ros2vtk

logic = ros2vtk.vtkROS2Logic()
node = logic.GetDefaultROS2Node()
publisher = node.CreateAndAddPublisherNode('String', '/legacy_pub')
subscriber = node.CreateAndAddSubscriberNode('geometry_msgs/msg/Point', '/legacy_sub')
subscriber.SetAttribute('purpose', 'legacy')
node.CreateAndAddTf2LookupNode('world', 'tool')
broadcaster = node.CreateAndAddTf2BroadcasterNode('world', 'marker')
broadcaster.StaticOn()
parameters = node.CreateAndAddParameterNode('/robot_state_publisher')
parameters.AddParameter('robot_description')
assert logic.GetScene().WriteToXMLFile(sys.argv[1])
logic.GetScene().Clear()
