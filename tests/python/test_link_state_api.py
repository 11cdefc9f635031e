"""The link state from Python: the node's LinkStateChangedEvent (call data: the state word) fires
on the spinning thread when another participant appears and when it leaves, and the app's status
line says it. Across a real cut link: tests/network/test_two_hosts.py."""

from __future__ import annotations

import threading

import vtk

from conftest import spin_until
from ros2vtk.app import scene_state


def test_link_state_changes_fire_an_event_and_show_in_the_status_line(ros2vtk, logic):
    node = logic.GetDefaultROS2Node()
    assert scene_state.link_text(ros2vtk.vtkROS2NodeNode()) == 'link: not created'
    events = []

    @vtk.calldata_type(vtk.VTK_STRING)
    def on_change(caller, event, state):
        events.append((state, caller.GetNumberOfDiscoveredParticipants(), threading.get_ident()))
    node.AddObserver(ros2vtk.vtkROS2NodeNode.LinkStateChangedEvent, on_change)
    assert spin_until(logic, lambda: True, 0.5)
    assert node.GetNumberOfDiscoveredParticipants() == 0, 'another process on this test domain'
    assert scene_state.link_text(node) == 'link: no peers'

    visitor = ros2vtk.vtkROS2NodeNode()
    logic.GetScene().AddNode(visitor)
    assert visitor.Create('visitor_py')
    assert spin_until(logic, lambda: any(state == 'peers' for state, _, _ in events))
    assert events[0][:2] == ('peers', 1), events
    assert scene_state.link_text(node) == 'link: 1 peer'

    assert visitor.Destroy()  # leaves cleanly: removed, not dropped
    assert spin_until(logic, lambda: events[-1][0] == 'no peers')
    assert events[-1][:2] == ('no peers', 0), events
    assert scene_state.link_text(node) == 'link: no peers'
    assert all(thread == threading.get_ident() for _, _, thread in events)
