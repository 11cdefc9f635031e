"""Our side of the name table through the VTK-wrapped Python API: one ROS node per namespace,
named like rclpy_names_table.py's node, and a String publisher node per name; prints one JSON line
per row with the topic the publisher node resolved (GetTopic) or null when it was refused;
the publisher is removed again so a later row resolving to the same topic is not a duplicate.

Reads `namespace<TAB>name` lines on stdin. Run with Debian's python3 and PYTHONPATH=<build>/python.
"""
import json
import sys

import ros2vtk


def main() -> int:
    logic = ros2vtk.vtkROS2Logic()
    nodes = {}
    for line in sys.stdin.read().splitlines():
        namespace, name = line.split('\t')
        if namespace not in nodes:
            node = ros2vtk.vtkROS2NodeNode()
            logic.GetScene().AddNode(node)
            if not node.Create('talker', namespace):
                print(json.dumps({'error': f'node not created in {namespace}'}), flush=True)
                return 1
            nodes[namespace] = node
        publisher = nodes[namespace].CreateAndAddPublisherNode('String', name)
        topic = publisher.GetTopic() if publisher else None
        print(json.dumps({'namespace': namespace, 'name': name, 'topic': topic}), flush=True)
        # One publisher per topic and node: free the topic for the next row naming it too.
        if publisher and not nodes[namespace].RemoveAndDeletePublisherNode(topic):
            print(json.dumps({'error': f'publisher on {topic} not removed'}), flush=True)
            return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
