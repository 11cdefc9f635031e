"""The OpenIGTLink connector node in scene files (issue 16): every setting a user made (type,
host, port, mirrored nodes, device mappings, WorldToSlicer, ModelsInWorld) comes back from the
XML, and a connector that was serving serves again on its port after the restore. The wire side
of a restored connector (pyigtl and rclpy peers) is tests/interop/test_igtl.py."""

from __future__ import annotations

import socket

# No skip when the connector is missing: scripts/setup.sh installs libopenigtlink-dev, so a build
# without vtkROS2IGTLConnectorNode is a broken set-up and these tests fail on it.


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def test_connector_settings_mirrored_nodes_and_maps_survive_save_and_restore(ros2vtk, logic):
    import vtk
    scene = logic.GetScene()
    node = logic.GetDefaultROS2Node()
    needle = node.CreateAndAddTf2LookupNode('world', 'needle')
    other = node.CreateAndAddTf2LookupNode('world', 'camera')
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    connector.SetName('Slicer link')
    port = free_port()
    connector.SetPort(port)
    connector.SetHostname('127.0.0.1')
    connector.MirrorAllNodesOff()
    connector.AddMirroredNodeID(needle.GetID())
    connector.ModelsInWorldOff()
    lps = vtk.vtkMatrix4x4()
    lps.SetElement(0, 0, -1.0)
    lps.SetElement(1, 1, -1.0)
    lps.SetElement(2, 3, 12.5)
    connector.SetWorldToSlicer(lps)
    assert connector.MapDeviceToTf('Target', 'world', 'target')
    assert connector.MapDeviceToTopic('F', '/slicer/points', 'PointCloud')
    assert connector.Start(node), connector.GetLastError()
    xml = scene.WriteToXMLString()
    ids = (needle.GetID(), other.GetID(), node.GetID())

    scene.Clear()  # stops the connector: its port is free again
    assert scene.GetNumberOfNodes() == 0
    assert scene.ReadFromXMLString(xml)
    restored = scene.GetNthNodeByClass(0, 'vtkROS2IGTLConnectorNode')
    assert restored is not None and restored is not connector
    assert restored.GetName() == 'Slicer link'
    assert (restored.GetPort(), restored.GetHostname(), restored.GetClient()) == (port, '127.0.0.1', False)
    assert not restored.GetMirrorAllNodes() and not restored.GetModelsInWorld()
    assert restored.IsMirrored(scene.GetNodeByID(ids[0]))
    assert not restored.IsMirrored(scene.GetNodeByID(ids[1]))
    m = restored.GetWorldToSlicer()
    assert [m.GetElement(0, 0), m.GetElement(1, 1), m.GetElement(2, 2), m.GetElement(2, 3)] == [-1.0, -1.0, 1.0, 12.5]
    assert restored.GetDeviceMap('Target') == 'tf:world:target'
    assert restored.GetDeviceMap('F') == 'topic:/slicer/points:PointCloud'
    assert restored.GetDeviceMap('nothing') == ''
    # It was serving when saved: it serves again, spun by the restored ROS node.
    assert restored.GetState() == 'listening', restored.GetLastError()
    assert restored.GetStartedROS2Node() is scene.GetNodeByID(ids[2])
    with socket.create_connection(('127.0.0.1', port), timeout=5):
        pass
    restored.Stop()


def test_a_stopped_connector_is_restored_stopped_and_a_client_stays_a_client(ros2vtk, logic):
    scene = logic.GetScene()
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    connector.SetTypeToClient()
    connector.SetHostname('198.18.0.2')
    connector.SetPort(18999)
    xml = scene.WriteToXMLString()
    scene.Clear()
    assert scene.ReadFromXMLString(xml)
    restored = scene.GetNthNodeByClass(0, 'vtkROS2IGTLConnectorNode')
    assert (restored.GetClient(), restored.GetHostname(), restored.GetPort()) == (True, '198.18.0.2', 18999)
    assert restored.GetMirrorAllNodes() and restored.GetModelsInWorld()
    assert restored.GetState() == 'off'


def test_invalid_connector_settings_leave_the_scene_unchanged(ros2vtk, logic):
    scene = logic.GetScene()
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    good = scene.WriteToXMLString()
    for bad in (good.replace('port="18944"', 'port="70000"'),
                good.replace('type="server"', 'type="bridge"'),
                good.replace('worldToSlicer="', 'worldToSlicer="1 2 3" x="')):
        assert bad != good
        before = scene.GetNumberOfNodes()
        assert not scene.ReadFromXMLString(bad)
        assert scene.GetNumberOfNodes() == before and scene.GetNthNode(0) is connector


def test_slicer_scene_file_puts_models_under_their_transforms_and_a_bad_path_is_an_error(ros2vtk, logic, tmp_path):
    """WriteSlicerScene (the --slicer-scene file): link-local models under a LinearTransform named as
    their parent's device; with ModelsInWorld on (baked meshes) at the root; an unwritable path is
    -1 with a reason, and the connector keeps working."""
    import xml.etree.ElementTree as ET
    import vtk
    scene = logic.GetScene()
    link = ros2vtk.vtkROS2TransformNode()
    link.SetName('arm:a_link_name_far_beyond_twenty_bytes')
    scene.AddNode(link)
    model = ros2vtk.vtkROS2ModelNode()
    model.SetName('arm:tool')
    model.SetColor(0.25, 0.5, 1.0)
    model.SetPolyData(vtk.vtkPolyData())
    scene.AddNode(model)
    model.SetParentTransformNodeID(link.GetID())
    loose = ros2vtk.vtkROS2ModelNode()  # no parent: not in the file
    loose.SetName('loose')
    scene.AddNode(loose)
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    connector.SetPort(18999)
    connector.ModelsInWorldOff()

    path = tmp_path / 'robot.mrml'
    assert connector.WriteSlicerScene(str(path)) == 1
    root = ET.parse(path).getroot()
    transform, = root.iter('LinearTransform')
    # The device name rule of OpenIGTLink's 20 bytes (tested in test_igtl.py against the wire).
    assert transform.get('name') == ros2vtk.vtkROS2IGTLConnectorNode.MakeDeviceName(link.GetName())
    assert len(transform.get('name')) <= 20
    m, = root.iter('Model')
    assert m.get('name') == 'arm:tool'  # the model's device name
    assert m.get('references') == f"display:{root.find('ModelDisplay').get('id')};transform:{transform.get('id')};"
    assert [float(v) for v in root.find('ModelDisplay').get('color').split()] == [0.25, 0.5, 1.0]
    connector_element, = root.iter('IGTLConnector')
    assert connector_element.get('serverPort') == '18999' and connector_element.get('connectorType') == 'CLIENT'

    connector.ModelsInWorldOn()
    assert connector.WriteSlicerScene(str(path)) == 1
    root = ET.parse(path).getroot()
    assert not list(root.iter('LinearTransform'))
    assert 'transform:' not in root.find('Model').get('references')

    connector.SetTypeToClient()  # Slicer is then the server
    assert connector.WriteSlicerScene(str(path)) == 1
    assert ET.parse(path).getroot().find('IGTLConnector').get('connectorType') == 'SERVER'

    assert connector.WriteSlicerScene(str(tmp_path / 'missing' / 'robot.mrml')) == -1
    assert 'cannot write' in connector.GetLastError()
    assert connector.WriteSlicerScene(str(path)) == 1


def test_a_model_at_the_scene_root_is_sent_in_slicer_coordinates_even_with_link_local_meshes(ros2vtk, logic):
    """--link-local sends meshes in their link's coordinates; a model under no link has only the
    world: its mesh goes through WorldToSlicer (here LPS: x, y negated). Read from the wire with
    polydata.md's layout (58-byte header; body: 10 uint32 counts, then float32 x y z per point)."""
    import struct
    import time
    import vtk
    scene = logic.GetScene()
    cube = vtk.vtkCubeSource()
    cube.SetCenter(10.0, 20.0, 30.0)
    cube.SetXLength(2.0)
    cube.SetYLength(2.0)
    cube.SetZLength(2.0)
    cube.Update()
    model = ros2vtk.vtkROS2ModelNode()
    model.SetName('marker')
    model.SetPolyData(cube.GetOutput())
    scene.AddNode(model)
    connector = ros2vtk.vtkROS2IGTLConnectorNode()
    scene.AddNode(connector)
    connector.SetPort(free_port())
    connector.ModelsInWorldOff()
    lps = vtk.vtkMatrix4x4()
    lps.SetElement(0, 0, -1.0)
    lps.SetElement(1, 1, -1.0)
    connector.SetWorldToSlicer(lps)
    assert connector.Start(None), connector.GetLastError()
    reader = socket.create_connection(('127.0.0.1', connector.GetPort()), timeout=0.05)
    data = b''
    end = time.monotonic() + 10
    while time.monotonic() < end and b'POLYDATA' not in data[:12]:
        connector.Update()
        try:
            data += reader.recv(1 << 20)
        except socket.timeout:
            pass
        while len(data) >= 58 and b'POLYDATA' not in data[:12] and len(data) >= 58 + struct.unpack('>Q', data[42:50])[0]:
            data = data[58 + struct.unpack('>Q', data[42:50])[0]:]  # a message of another type
    while len(data) < 58 + struct.unpack('>Q', data[42:50])[0] and time.monotonic() < end:
        connector.Update()
        data += reader.recv(1 << 20)
    reader.close()
    connector.Stop()
    assert data[2:10] == b'POLYDATA' and data[14:20] == b'marker', data[:34]
    version = struct.unpack('>H', data[:2])[0]
    assert version == 1  # no ros.parent metadata: it has no link
    body = data[58:]
    count = struct.unpack('>I', body[:4])[0]
    points = [struct.unpack('>3f', body[40 + 12 * i:52 + 12 * i]) for i in range(count)]
    xs, ys, zs = zip(*points)
    assert (min(xs), max(xs), min(ys), max(ys), min(zs), max(zs)) == (-11.0, -9.0, -21.0, -19.0, 29.0, 31.0)
