"""The robot node through the wrapped API, with descriptions given directly (LoadRobotDescription)
and tf from a broadcaster node of this process: what it builds, units, reload, bad input and
removal. The wire side (robot_state_publisher as a real rclpy node) is tests/interop/test_scene_robot.py."""
from __future__ import annotations

from pathlib import Path

import pytest

from conftest import spin_until

ARM = Path(__file__).resolve().parents[2] / 'examples' / 'robots' / 'surgical_arm' / 'urdf' / 'surgical_arm.urdf'

TWO_LINKS = """<robot name="two">
  <material name="red"><color rgba="1 0 0 0.5"/></material>
  <link name="base"><visual><geometry><box size="0.1 0.2 0.3"/></geometry><material name="red"/></visual></link>
  <link name="tool">
    <visual><origin xyz="0 0 0.05"/><geometry><sphere radius="0.01"/></geometry></visual>
    <visual><geometry><mesh filename="missing/tool.stl"/></geometry></visual>
  </link>
  <joint name="j" type="prismatic"><parent link="base"/><child link="tool"/><origin xyz="0.1 0 0"/>
    <axis xyz="0 0 1"/><limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>
</robot>"""


def bounds(model, vtk):
    """World bounds of a model node's surface (mm)."""
    matrix = vtk.vtkMatrix4x4()
    model.GetMatrixModelToWorld(matrix)
    transform = vtk.vtkTransform()
    transform.SetMatrix(matrix)
    moved = vtk.vtkTransformPolyDataFilter()
    moved.SetTransform(transform)
    moved.SetInputData(model.GetPolyData())
    moved.Update()
    return moved.GetOutput().GetBounds()


@pytest.fixture
def vtk():
    import vtk as module
    return module


def make_robot(logic, name='two', fixed_frame=''):
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromTopic(name, f'/{name}/robot_description', fixed_frame, '')
    assert robot is not None
    return node, robot


def test_builds_links_models_and_placeholders_in_millimetres(logic, vtk):
    node, robot = make_robot(logic)
    assert robot.GetRobotState() == 'waiting for robot_description'
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    assert robot.IsLoaded() and robot.GetRobotState() == 'loaded'
    assert robot.GetLinkNames() == 'base tool'
    assert robot.GetNumberOfModelNodes() == 3
    assert robot.GetNumberOfPlaceholders() == 1
    assert "link 'tool'" in robot.GetWarnings() and 'missing/tool.stl' in robot.GetWarnings()
    box = robot.GetNthModelNode(0)
    assert box.GetColor() == (1.0, 0.0, 0.0) and box.GetOpacity() == 0.5
    b = bounds(box, vtk)  # the base link is the fixed frame: identity, box centred, in mm
    assert [round(v, 6) for v in b] == [-50.0, 50.0, -100.0, 100.0, -150.0, 150.0]
    # The tool link is a tf lookup base <- tool, waiting for tf.
    tool = robot.GetLinkTransformNode('tool')
    assert tool.GetClassName() == 'vtkROS2Tf2LookupNode'
    assert (tool.GetParentID(), tool.GetChildID()) == ('base', 'tool')
    assert robot.GetNumberOfLinksTracked() == 1


def test_links_follow_tf_and_the_base_transform_places_the_robot(logic, vtk, ros2vtk):
    node, robot = make_robot(logic)
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    broadcaster = node.CreateAndAddTf2BroadcasterNode('base', 'tool')
    matrix = vtk.vtkMatrix4x4()
    matrix.SetElement(0, 3, 100.0)  # mm: the joint origin
    matrix.SetElement(2, 3, 40.0)   # mm: prismatic joint at 0.04 m
    assert broadcaster.Broadcast(matrix)
    assert spin_until(logic, lambda: robot.GetNumberOfLinksTracked() == 2)
    sphere = robot.GetNthModelNode(1)
    b = bounds(sphere, vtk)
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    assert centre == pytest.approx([100.0, 0.0, 90.0], abs=1e-6)  # 40 mm + the 50 mm visual origin
    placement = vtk.vtkMatrix4x4()
    placement.SetElement(1, 3, 500.0)
    robot.GetBaseTransformNode().SetMatrixTransformToParent(placement)
    b = bounds(sphere, vtk)
    assert (b[2] + b[3]) / 2 == pytest.approx(500.0, abs=1e-6)


def test_a_broken_description_is_a_state_and_the_robot_shown_stays(logic):
    node, robot = make_robot(logic)
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    assert not robot.LoadRobotDescription('<robot name="x"><link name="a"/><joint name="j" type="fixed">'
                                          '<parent link="a"/><child link="nowhere"/></joint></robot>', '')
    assert robot.GetRobotState().startswith('failed: ')
    assert robot.GetLastError()
    assert robot.GetNumberOfModelNodes() == 3  # still the previous robot
    assert not robot.LoadRobotDescription('this is not XML', '')


def test_a_new_description_replaces_every_node(logic):
    node, robot = make_robot(logic)
    scene = logic.GetScene()
    before = scene.GetNumberOfNodes()
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    loaded = scene.GetNumberOfNodes()
    assert loaded == before + 1 + 2 + 3  # base transform, two link nodes, three models
    robot.AddMeshSearchPath(str(ARM.parents[1]))  # the package of package://ros2vtk_surgical_arm
    assert robot.LoadRobotDescription(ARM.read_text(), str(ARM.parent))
    assert robot.GetNumberOfLoads() == 2
    assert robot.GetNumberOfPlaceholders() == 0, robot.GetWarnings()
    assert robot.GetNumberOfLinks() == 8
    assert scene.GetNumberOfNodes() == before + 1 + robot.GetNumberOfLinks() + robot.GetNumberOfModelNodes()


def test_prefix_and_fixed_frame_rebuild_the_lookups(logic):
    node, robot = make_robot(logic, fixed_frame='world')
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    assert robot.GetLinkTransformNode('base').GetParentID() == 'world'
    robot.SetTfPrefix('r1/')
    logic.Spin()
    assert robot.GetLinkTransformNode('base').GetChildID() == 'r1/base'
    assert node.GetTf2LookupNodeByParentChild('world', 'base') is None  # the old lookup is gone


def test_remove_deletes_everything_it_created(logic):
    node, robot = make_robot(logic)
    scene = logic.GetScene()
    before = scene.GetNumberOfNodes()  # the ROS node, the robot, its description subscriber
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    assert node.GetSubscriberNodeByTopic('/two/robot_description') is not None
    assert node.RemoveAndDeleteRobotNode('two')
    assert scene.GetNumberOfNodes() == before - 2
    assert node.GetSubscriberNodeByTopic('/two/robot_description') is None
    assert node.GetRobotNodeByName('two') is None
    assert not node.RemoveAndDeleteRobotNode('two')


def test_names_are_unique_and_required(logic):
    node, robot = make_robot(logic)
    assert node.CreateAndAddRobotNodeFromTopic('two', '/other', '', '') is None
    assert node.CreateAndAddRobotNode('', '/robot_state_publisher') is None
    assert node.CreateAndAddRobotNode('p', '') is None


def test_a_reload_keeps_the_base_placement_and_the_link_nodes_of_links_still_there(logic, vtk):
    node, robot = make_robot(logic)
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    base = robot.GetBaseTransformNode()
    placement = vtk.vtkMatrix4x4()
    placement.SetElement(0, 3, 250.0)
    base.SetMatrixTransformToParent(placement)
    tool = robot.GetLinkTransformNode('tool')
    first_models = {robot.GetNthModelNode(i).GetID() for i in range(robot.GetNumberOfModelNodes())}
    # Another description with the same links (a bigger sphere): same base, same link nodes, new models.
    assert robot.LoadRobotDescription(TWO_LINKS.replace('radius="0.01"', 'radius="0.02"'), '')
    assert robot.GetBaseTransformNode() is base
    assert base.GetMatrixTransformToParent().GetElement(0, 3) == 250.0
    assert robot.GetLinkTransformNode('tool') is tool
    second_models = {robot.GetNthModelNode(i).GetID() for i in range(robot.GetNumberOfModelNodes())}
    assert second_models and not second_models & first_models
    assert all(logic.GetScene().GetNodeByID(i) is None for i in first_models)
    # A robot without a 'tool' link: its lookup goes, the base stays.
    robot.AddMeshSearchPath(str(ARM.parents[1]))
    assert robot.LoadRobotDescription(ARM.read_text(), str(ARM.parent))
    assert robot.GetBaseTransformNode() is base
    assert node.GetTf2LookupNodeByParentChild('base', 'tool') is None
    assert robot.GetLinkTransformNode('tool') is None


def test_a_saved_scene_restores_the_robot_its_base_and_links_and_it_loads_again(logic, vtk, ros2vtk, tmp_path):
    node, robot = make_robot(logic)
    robot.SetTfPrefix('r1/')
    robot.SetFixedFrame('world')
    folder = tmp_path / 'mesh folder with spaces'
    robot.AddMeshSearchPath(str(folder))
    robot.SetMeshBaseFolder(str(tmp_path))
    assert robot.LoadRobotDescription(TWO_LINKS, '')
    placement = vtk.vtkMatrix4x4()
    placement.SetElement(2, 3, -75.0)
    robot.GetBaseTransformNode().SetMatrixTransformToParent(placement)
    # A node of the user's hung under a link keeps its parent through save, restore and reload.
    needle = ros2vtk.vtkROS2TransformNode()
    logic.GetScene().AddNode(needle)
    needle.SetParentTransformNodeID(robot.GetLinkTransformNode('tool').GetID())
    ids = {link: robot.GetLinkTransformNode(link).GetID() for link in ('base', 'tool')}
    base_id = robot.GetBaseTransformNode().GetID()

    path = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(path)
    text = open(path, encoding='utf-8').read()
    assert 'vtkROS2ModelNode' not in text  # geometry comes back with the description
    assert 'mesh folder with spaces' in text

    scene = logic.GetScene()
    assert scene.ReadFromXMLFile(path)
    node = logic.GetDefaultROS2Node()
    restored = node.GetRobotNodeByName('two')
    assert restored is not None and restored is not robot
    assert (restored.GetDescriptionSource(), restored.GetDescriptionTopic()) == ('topic', '/two/robot_description')
    assert (restored.GetTfPrefix(), restored.GetFixedFrame()) == ('r1/', 'world')
    assert restored.GetMeshBaseFolder() == str(tmp_path)
    assert not restored.IsLoaded() and restored.GetNumberOfModelNodes() == 0
    assert restored.GetBaseTransformNode().GetID() == base_id
    assert restored.GetBaseTransformNode().GetMatrixTransformToParent().GetElement(2, 3) == -75.0
    assert restored.GetLinkNames() == 'base tool'
    assert node.GetSubscriberNodeByTopic('/two/robot_description') is not None
    nodes = scene.GetNumberOfNodes()

    assert restored.LoadRobotDescription(TWO_LINKS, '')
    assert {link: restored.GetLinkTransformNode(link).GetID() for link in ('base', 'tool')} == ids
    assert restored.GetNumberOfModelNodes() == 3
    assert scene.GetNumberOfNodes() == nodes + 3  # only the models are new
    assert scene.GetNodeByID(needle.GetID()).GetParentTransformNodeID() == ids['tool']
    assert restored.GetLinkTransformNode('tool').GetChildID() == 'r1/tool'
    assert node.RemoveAndDeleteRobotNode('two')
    assert scene.GetNodeByID(base_id) is None and scene.GetNodeByID(ids['tool']) is None


def test_a_scene_file_with_a_robot_missing_its_source_is_refused(logic, ros2vtk):
    broken = ('<ROS2Scene version="1"><vtkROS2RobotNode id="vtkROS2RobotNode1" name="r" robotName="r"/>'
              '</ROS2Scene>')
    scene = logic.GetScene()
    scene.GlobalWarningDisplayOff()
    try:
        assert not scene.ReadFromXMLString(broken)
    finally:
        scene.GlobalWarningDisplayOn()


COLOURED_PLY = """ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 1
property list uchar int vertex_indices
end_header
0 0 0 255 0 0
0.1 0 0 0 255 0
0 0.1 0 0 0 255
3 0 1 2
"""


def test_per_vertex_mesh_colours_are_shown_unless_the_urdf_gives_a_material(logic, tmp_path):
    (tmp_path / 'tri.ply').write_text(COLOURED_PLY)
    urdf = """<robot name="c">
      <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
      <link name="base">
        <visual><geometry><mesh filename="tri.ply"/></geometry></visual>
        <visual><geometry><mesh filename="tri.ply"/></geometry><material name="grey"/></visual>
      </link></robot>"""
    node, robot = make_robot(logic, name='c')
    assert robot.LoadRobotDescription(urdf, str(tmp_path)), robot.GetLastError()
    plain, painted = robot.GetNthModelNode(0), robot.GetNthModelNode(1)
    assert plain.GetScalarVisibility() and not painted.GetScalarVisibility()
    scalars = plain.GetPolyData().GetPointData().GetScalars()
    assert scalars is not None and scalars.GetNumberOfComponents() == 4
    assert [tuple(scalars.GetTuple(i))[:3] for i in range(3)] == [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    assert painted.GetColor() == (0.5, 0.5, 0.5)


def test_a_robot_from_a_urdf_file_resolves_its_own_package_and_reloads_on_request(logic, tmp_path):
    node = logic.GetDefaultROS2Node()
    # The shipped arm names its meshes package://ros2vtk_surgical_arm/...: the package.xml above
    # the file makes them resolve with no search path and no AMENT_PREFIX_PATH.
    arm = node.CreateAndAddRobotNodeFromFile('arm', str(ARM))
    assert arm is not None and arm.GetDescriptionSource() == 'file'
    assert arm.GetDescriptionFile() == str(ARM)
    assert spin_until(logic, arm.IsLoaded)
    assert arm.GetNumberOfLinks() == 8 and arm.GetNumberOfPlaceholders() == 0, arm.GetWarnings()

    path = tmp_path / 'two.urdf'
    path.write_text(TWO_LINKS.replace('missing/tool.stl', 'tool.stl'))
    two = node.CreateAndAddRobotNodeFromFile('two', str(path))
    assert spin_until(logic, two.IsLoaded)
    assert two.GetNumberOfPlaceholders() == 1  # tool.stl, relative to the file, is not there yet
    (tmp_path / 'tool.stl').write_bytes((ARM.parents[1] / 'meshes' / 'base.stl').read_bytes())
    logic.Spin()
    assert two.GetNumberOfLoads() == 1  # the file did not change: no reload by itself
    two.Reload()
    assert spin_until(logic, lambda: two.GetNumberOfLoads() == 2)
    assert two.GetNumberOfPlaceholders() == 0, two.GetWarnings()


def test_a_missing_or_unreadable_urdf_file_is_refused_or_reported(logic, tmp_path):
    node = logic.GetDefaultROS2Node()
    node.GlobalWarningDisplayOff()
    try:
        assert node.CreateAndAddRobotNodeFromFile('none', str(tmp_path / 'absent.urdf')) is None
        assert node.GetRobotNodeByName('none') is None
        path = tmp_path / 'gone.urdf'
        path.write_text(TWO_LINKS)
        robot = node.CreateAndAddRobotNodeFromFile('gone', str(path))
        path.unlink()  # removed before the spin that reads it
        robot.GlobalWarningDisplayOff()
        logic.Spin()
        assert robot.GetRobotState().startswith('failed: cannot read the URDF file')
        assert not robot.IsLoaded()
    finally:
        node.GlobalWarningDisplayOn()


def test_a_file_robot_comes_back_with_the_scene_file(logic, tmp_path):
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromFile('arm', str(ARM), '', 'left/')
    assert spin_until(logic, robot.IsLoaded)
    scene_file = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(scene_file)
    assert logic.GetScene().ReadFromXMLFile(scene_file)
    restored = logic.GetDefaultROS2Node().GetRobotNodeByName('arm')
    assert restored.GetDescriptionSource() == 'file' and restored.GetTfPrefix() == 'left/'
    assert spin_until(logic, restored.IsLoaded)
    assert restored.GetNumberOfPlaceholders() == 0 and restored.GetNumberOfModelNodes() == robot_models(ARM)
    assert restored.GetLinkTransformNode('upper_arm_link').GetChildID() == 'left/upper_arm_link'


def robot_models(urdf: Path) -> int:
    import xml.etree.ElementTree as ElementTree
    return len(ElementTree.parse(urdf).getroot().findall('link/visual'))


def test_a_urdf_file_over_the_size_limit_is_refused_without_reading_it(logic, tmp_path):
    node = logic.GetDefaultROS2Node()
    huge = tmp_path / 'huge.urdf'
    with open(huge, 'wb') as f:
        f.truncate(300 * 1024 * 1024)  # sparse: 300 MB on paper, nothing on disk
    robot = node.CreateAndAddRobotNodeFromFile('huge', str(huge))
    robot.GlobalWarningDisplayOff()
    try:
        logic.Spin()
    finally:
        robot.GlobalWarningDisplayOn()
    assert 'over the limit' in robot.GetRobotState(), robot.GetRobotState()
    assert not robot.IsLoaded()


def test_relative_meshes_of_a_topic_description_use_the_mesh_search_path_and_one_line_is_logged(logic, vtk, tmp_path):
    # Issue 15: a description from a parameter or topic has no folder of its own; its relative
    # meshes are looked for in the mesh search paths, and a load logs one summary line, not one
    # line per missing visual.
    meshes = tmp_path / 'robot_files' / 'meshes'
    meshes.mkdir(parents=True)
    (meshes / 'arm.STL').write_bytes((ARM.parents[1] / 'meshes' / 'base.stl').read_bytes())
    links = ''.join(f'<link name="l{i}"><visual><geometry><mesh filename="{uri}"/></geometry></visual></link>'
                    for i, uri in enumerate(['meshes/arm.STL', '../meshes/arm.STL', 'package://ghost/a.stl',
                                             'package://ghost/b.stl']))
    joints = ''.join(f'<joint name="j{i}" type="fixed"><parent link="l{i - 1}"/><child link="l{i}"/></joint>'
                     for i in range(1, 4))
    description = f'<robot name="rel">{links}{joints}</robot>'
    node, robot = make_robot(logic, 'rel')
    logged = []

    @vtk.calldata_type(vtk.VTK_STRING)
    def on_warning(caller, event, text):
        logged.append(text)

    robot.AddObserver('WarningEvent', on_warning)
    assert robot.LoadRobotDescription(description, '')
    assert robot.GetNumberOfPlaceholders() == 4
    assert 'SetMeshBaseFolder' in robot.GetLinkStatus('l0') and 'AddMeshSearchPath' in robot.GetLinkStatus('l0')
    assert len(logged) == 1, logged
    assert '4 visuals, 4 of 4 meshes missing (4 warnings, ' in logged[0], logged[0]
    assert robot.GetLoadSummary() in logged[0]

    robot.AddMeshSearchPath(str(tmp_path / 'robot_files'))
    logged.clear()
    assert robot.LoadRobotDescription(description, '')
    assert robot.GetNumberOfPlaceholders() == 2, robot.GetWarnings()
    assert robot.GetLinkStatus('l0') == 'ok' and robot.GetLinkStatus('l1') == 'ok'
    assert robot.GetLinkStatus('l2').startswith("1 of 1 visuals are placeholders: link 'l2': could not load mesh "
                                                "'package://ghost/a.stl': package 'ghost' not found")
    assert robot.GetLinkStatus('no_such_link') == ''
    assert len(logged) == 1 and robot.GetLoadSummary().startswith('4 visuals, 2 of 4 meshes missing (2 warnings, 1 cause)')


XACRO_ARM = """<?xml version="1.0"?>
<robot name="xarm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="edge" value="0.1"/>
  <xacro:macro name="boxed" params="name size">
    <link name="${name}"><visual><geometry><box size="${size} ${size} ${size}"/></geometry></visual></link>
  </xacro:macro>
  <xacro:boxed name="$(arg prefix)base" size="${edge}"/>
  <xacro:boxed name="$(arg prefix)tool" size="${edge / 2}"/>
  <joint name="$(arg prefix)j" type="fixed"><parent link="$(arg prefix)base"/><child link="$(arg prefix)tool"/></joint>
</robot>"""


def test_a_xacro_file_is_expanded_with_its_arguments_and_they_come_back_with_the_scene(logic, ros2vtk, tmp_path):
    # Importing ros2vtk from the venv points ROS2VTK_XACRO at the venv's xacro (pip install xacro).
    path = tmp_path / 'xarm.urdf.xacro'
    path.write_text(XACRO_ARM)
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromFile('xarm', str(path))
    assert robot.SetXacroArguments('prefix:=left_')
    assert spin_until(logic, robot.IsLoaded), robot.GetRobotState()
    assert robot.GetLinkNames() == 'left_base left_tool'
    # New arguments reload the file.
    assert robot.SetXacroArguments('prefix:=right_')
    assert spin_until(logic, lambda: robot.GetLinkNames() == 'right_base right_tool'), robot.GetRobotState()
    node.GlobalWarningDisplayOff()
    robot.GlobalWarningDisplayOff()
    try:
        assert not robot.SetXacroArguments('prefix=right_')  # not name:=value: refused, kept
    finally:
        node.GlobalWarningDisplayOn()
        robot.GlobalWarningDisplayOn()
    assert robot.GetXacroArguments() == 'prefix:=right_'

    scene_file = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(scene_file)
    assert logic.GetScene().ReadFromXMLFile(scene_file)
    restored = logic.GetDefaultROS2Node().GetRobotNodeByName('xarm')
    assert restored.GetXacroArguments() == 'prefix:=right_'
    assert spin_until(logic, restored.IsLoaded), restored.GetRobotState()
    assert restored.GetLinkNames() == 'right_base right_tool'


def test_a_xacro_file_that_xacro_rejects_is_a_failed_state_with_xacros_words(logic, tmp_path):
    path = tmp_path / 'bad.xacro'
    path.write_text('<robot name="b" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:nosuch/></robot>')
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromFile('bad', str(path))
    robot.GlobalWarningDisplayOff()  # process-wide: back on below
    try:
        assert spin_until(logic, lambda: robot.GetRobotState().startswith('failed'))
    finally:
        robot.GlobalWarningDisplayOn()
    state = robot.GetRobotState()
    assert 'xacro failed' in state and 'unknown macro name: xacro:nosuch' in state, state


def test_removing_a_robot_after_its_own_subscriber_left_the_scene_reports_nothing(logic):
    # What clearing a scene does (the demo's exit printed "RemoveAndDeleteSubscriberNode: no
    # subscriber on '/robot_description'"): the robot's own source leaves first.
    node = logic.GetDefaultROS2Node()
    robot = node.CreateAndAddRobotNodeFromTopic('solo', '/solo/robot_description', '', '')
    assert robot is not None
    subscriber = node.GetSubscriberNodeByTopic('/solo/robot_description')
    assert subscriber is not None
    errors = []
    node.AddObserver('ErrorEvent', lambda caller, event: errors.append(event))
    logic.GetScene().RemoveNode(subscriber)
    assert node.RemoveAndDeleteRobotNode('solo')
    assert errors == []
    assert node.GetRobotNodeByName('solo') is None


def test_the_workspace_sphere_holds_the_robot_in_every_pose(logic, vtk):
    """GetWorkspaceSphere (what the app's 3D view frames): the surgical arm, placed by its joint
    positions (no tf), has every model inside the sphere at every corner and middle of its joints'
    ranges; the sphere is centred on its shoulder (the column turns about the axis the shoulder
    is on) and moves with the base placement."""
    import itertools
    node, robot = make_robot(logic, 'arm')
    sphere = [0.0] * 4
    assert not robot.GetWorkspaceSphere(sphere)  # not loaded yet
    assert robot.LoadRobotDescription(ARM.read_text(), str(ARM.parent))
    assert robot.GetWorkspaceSphere(sphere)
    # The shoulder: 0.1 + 0.4 m above the base; the arm below it: 0.35 + 0.3 + 0.12 + 0.2 + 0.08
    # (insertion travel) + 0.05 m, plus the needle tip's marker.
    assert sphere[:3] == pytest.approx([0.0, 0.0, 500.0], abs=1e-6)
    assert 1100.0 < sphere[3] < 1150.0, sphere
    limits = {'shoulder_pitch': (-1.6, 1.6), 'elbow_pitch': (-2.2, 2.2), 'wrist_pitch': (-1.5, 1.5),
              'instrument_insertion': (0.0, 0.08), 'base_to_column': (-2.8, 0.0)}
    furthest = 0.0
    for values in itertools.product(*[(low, (low + high) / 2, high) for low, high in limits.values()]):
        for joint, value in zip(limits, values):
            assert robot.SetJointPosition(joint, value)
        logic.Spin()
        for n in range(robot.GetNumberOfModelNodes()):
            b = bounds(robot.GetNthModelNode(n), vtk)
            for corner in itertools.product(b[0:2], b[2:4], b[4:6]):
                furthest = max(furthest, sum((c - s) ** 2 for c, s in zip(corner, sphere[:3])) ** 0.5)
    print(f"furthest model box corner {furthest:.0f} mm from the centre; sphere {sphere}")
    # (Box corners of a model can lie a little outside a sphere its surface never leaves.)
    assert furthest <= sphere[3] * 1.01, (furthest, sphere)
    assert furthest > sphere[3] * 0.95, (furthest, sphere)  # and not much too large
    placement = vtk.vtkMatrix4x4()
    placement.SetElement(1, 3, 300.0)
    robot.GetBaseTransformNode().SetMatrixTransformToParent(placement)
    assert robot.GetWorkspaceSphere(sphere)
    assert sphere[:3] == pytest.approx([0.0, 300.0, 500.0], abs=1e-6)
