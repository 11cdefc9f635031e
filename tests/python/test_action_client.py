"""vtkROS2ActionClientNode without a server: creation through the ROS node, its key, bad input,
the no-server timeout, and the scene file round trip. Talking to a real action server is proven
in tests/interop/test_scene_actions.py (rclpy ActionServer in its own process)."""
from __future__ import annotations


def test_registered_action_types_are_the_shipped_action_specs(logic):
    from pathlib import Path
    specs = Path(__file__).resolve().parents[2] / 'msg_specs'
    expected = sorted(f'{p.parent.parent.name}/action/{p.stem}' for p in specs.glob('*/action/*.action'))
    assert expected and logic.GetDefaultROS2Node().GetRegisteredActionTypes().split() == expected


def test_client_is_a_child_found_by_its_resolved_action_name(logic, ros2vtk):
    node = logic.GetDefaultROS2Node()
    client = node.CreateAndAddActionClientNode('test_msgs/Fibonacci', 'py_fibonacci')
    assert client is not None and client.GetClassName() == 'vtkROS2ActionClientNode'
    assert client.GetActionName() == '/py_fibonacci'
    assert client.GetActionType() == 'test_msgs/action/Fibonacci'
    assert node.GetActionClientNodeByAction('/py_fibonacci') is client
    assert not client.IsServerReady() and client.GetStatusAsString() == 'idle'
    assert client.GetGoalYAML() == 'order: 0\n'
    # One client per action name and ROS node.
    assert node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', '/py_fibonacci') is None
    assert node.RemoveAndDeleteActionClientNode('/py_fibonacci')
    assert node.GetActionClientNodeByAction('/py_fibonacci') is None


def test_bad_types_and_goals_are_refused_with_the_reason(logic):
    node = logic.GetDefaultROS2Node()
    assert node.CreateAndAddActionClientNode('test_msgs/action/Nope', '/py_nope') is None
    assert node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', 'bad name!') is None
    client = node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', '/py_bad_goal')
    assert not client.SetGoalYAML('{order: many}')
    assert not client.SetGoalYAML('{no_such_field: 1}')
    assert not client.SetGoalField('order', '99999999999')
    assert client.GetGoalYAML() == 'order: 0\n'  # unchanged by the refused ones
    assert client.SetGoalField('order', '7') and client.GetGoalYAML() == 'order: 7\n'
    assert client.SendGoalYAML('{order: [1]}') == -1
    assert not client.CancelGoal()  # no goal running


def test_no_server_times_out_with_a_clear_error(logic, ros2vtk):
    client = logic.GetDefaultROS2Node().CreateAndAddActionClientNode('test_msgs/action/Fibonacci',
                                                                    '/py_nobody_serves_this')
    failures = []
    client.AddObserver(ros2vtk.vtkROS2ActionClientNode.GoalFailedEvent, lambda *_: failures.append(1))
    assert client.SendGoalAndWait('{order: 3}', 0.5) == ''
    assert client.GetStatusAsString() == 'timed out' and client.IsGoalDone()
    assert client.GetLastError() == ('timed out: no server for /py_nobody_serves_this '
                                     '(test_msgs/action/Fibonacci) appeared within 0.5 s')
    assert failures == [1] and client.GetNumberOfGoalsSent() == 1 and client.GetNumberOfResults() == 0
    assert len(client.GetGoalIdAsString()) == 32


def test_scene_file_round_trip(logic, ros2vtk, tmp_path):
    node = logic.GetDefaultROS2Node()
    client = node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', '/py_saved_action')
    client.SetTimeout(2.5)
    path = str(tmp_path / 'scene.xml')
    assert logic.GetScene().WriteToXMLFile(path)
    other = ros2vtk.vtkROS2Logic()
    try:
        assert other.GetScene().ReadFromXMLFile(path)
        restored = other.GetScene().GetNodeByID(client.GetID())
        assert restored.GetClassName() == 'vtkROS2ActionClientNode'
        assert restored.GetActionType() == 'test_msgs/action/Fibonacci'
        assert restored.GetActionName() == '/py_saved_action'
        assert restored.GetTimeout() == 2.5
        assert other.GetDefaultROS2Node().GetActionClientNodeByAction('/py_saved_action') is restored
    finally:
        other.GetScene().Clear()


def test_finished_goals_are_forgotten_on_request_and_beyond_the_bound(logic, ros2vtk):
    """Finished goals stay tracked by id until forgotten (ForgetGoalById, ForgetFinishedGoals) or
    pushed out by MaximumFinishedGoals on a later spin; a running goal is never dropped. Goals
    with no server time out, which finishes them without a peer."""
    node = logic.GetDefaultROS2Node()
    client = node.CreateAndAddActionClientNode('test_msgs/action/Fibonacci', '/py_forgetful')
    assert client.GetMaximumFinishedGoals() == 100
    client.SetTimeout(0.2)
    ids = []
    for order in (1, 2, 3, 4):
        client.SendGoalYAML(f'{{order: {order}}}')
        ids.append(client.GetGoalIdAsString())
    assert client.WaitForAllGoals(5.0)
    assert [client.GetNthGoalId(i) for i in range(client.GetNumberOfGoals())] == ids
    assert not client.ForgetGoalById('0' * 32)  # unknown id: refused with an error
    assert client.ForgetGoalById(ids[1]) and client.GetNumberOfGoals() == 3
    assert client.GetStatusAsStringById(ids[1]) == 'idle'  # forgotten: reads as unknown
    client.SetMaximumFinishedGoals(-1)  # refused
    assert client.GetMaximumFinishedGoals() == 100
    client.SetMaximumFinishedGoals(1)
    client.SetTimeout(30.0)
    client.SendGoalYAML('{order: 5}')  # waits for a server: running, not finished
    running = client.GetGoalIdAsString()
    node.Spin()  # the spin drops the oldest finished goals beyond the bound
    assert [client.GetNthGoalId(i) for i in range(client.GetNumberOfGoals())] == [ids[3], running]
    assert not client.ForgetGoalById(running)  # not finished
    assert client.ForgetFinishedGoals() == 1 and client.GetNumberOfGoals() == 1
    assert client.GetGoalIdAsString() == running and client.GetStatusAsString() == 'waiting for server'
    client.SetMaximumFinishedGoals(0)
    node.Spin()
    assert client.GetNumberOfGoals() == 1  # the running goal stays


def test_cancel_goals_before_refuses_a_time_that_is_not_one(logic):
    client = logic.GetDefaultROS2Node().CreateAndAddActionClientNode('test_msgs/action/Fibonacci',
                                                                    '/py_cancel_before')
    assert not client.CancelGoalsBefore(-1, 0)
    assert not client.CancelGoalsBefore(1, 1000000000)
    assert client.CancelGoalsBefore(1, 999999999)  # written: nobody has to be there
