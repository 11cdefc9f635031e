"""Every user-facing method of SlicerROS2's public headers (rosmed/slicer_ros2_module: Logic/ and
MRML/vtkMRMLROS2*.h, listed here by hand) exists on our class of the same role, so a script's
calls resolve. MRML plumbing that scripts never call (CreateNodeInstance, GetNodeTagName,
ReadXMLAttributes, UpdateScene, the robot node's Initialize…/Setup… steps, PreRequestCheck) is
left out, and so are AddToROS2Node / RemoveFromROS2Node on the kinds other than publishers and
subscribers: SlicerROS2's CreateAndAdd… and RemoveAndDelete… call them internally, and scripts
(every SlicerROS2 example and test) use those; here the same CreateAndAdd… / RemoveAndDelete…
calls do it. docs/porting-from-slicerros2.md covers the behaviour behind each name."""
from __future__ import annotations

import pytest

import ros2vtk

SLICERROS2_METHODS = {
    'vtkROS2Logic': 'AddRobot GetDefaultROS2Node RemoveRobot Spin',
    'vtkROS2NodeNode': (
        'Create CreateAndAddParameterNode CreateAndAddPublisherNode CreateAndAddRobotNode '
        'CreateAndAddServiceClientNode CreateAndAddSubscriberNode CreateAndAddTf2BroadcasterNode '
        'CreateAndAddTf2LookupNode Destroy GetParameterNodeByNode GetParameterNodeByNodeID '
        'GetPublisherNodeByTopic GetROS2NodeName GetRobotNodeByName GetServiceClientNodeByService '
        'GetSpinning GetSubscriberNodeByTopic GetTf2BroadcasterNodeByID '
        'GetTf2BroadcasterNodeByParentChild GetTf2LookupNodeByID GetTf2LookupNodeByParentChild '
        'RegisteredROS2PublisherNodes RegisteredROS2ServiceClientNodes RegisteredROS2SubscriberNodes '
        'RemoveAndDeleteParameterNode RemoveAndDeleteParameterNodeByNodeID RemoveAndDeletePublisherNode '
        'RemoveAndDeleteRobotNode RemoveAndDeleteServiceClientNode RemoveAndDeleteSubscriberNode '
        'RemoveAndDeleteTf2BroadcasterNode RemoveAndDeleteTf2LookupNode Spin WarnIfNotSpinning'),
    'vtkROS2PublisherStringNode': (
        'AddToROS2Node GetNumberOfCalls GetNumberOfMessagesSent GetROSType GetSlicerType GetTopic '
        'IsAddedToROS2Node RemoveFromROS2Node GetBlankMessage Publish'),
    'vtkROS2SubscriberStringNode': (
        'AddToROS2Node GetLastMessageYAML GetNumberOfMessages GetROSType GetSlicerType GetTopic '
        'IsAddedToROS2Node RemoveFromROS2Node GetLastMessage'),
    'vtkROS2ParameterNode': (
        'AddParameter GetMonitoredNodeName GetParameterAsBool GetParameterAsDouble '
        'GetParameterAsInteger GetParameterAsString GetParameterAsVectorOfBools '
        'GetParameterAsVectorOfDoubles GetParameterAsVectorOfIntegers GetParameterAsVectorOfStrings '
        'GetParameterType IsAddedToROS2Node IsMonitoredNodeReady IsParameterSet PrintParameter '
        'RemoveParameter'),
    'vtkROS2Tf2LookupNode': (
        'GetChildID GetModifiedOnLookup GetParentID IsAddedToROS2Node '
        'IsParentAndChildSet SetChildID SetModifiedOnLookup SetParentID'),
    'vtkROS2Tf2BroadcasterNode': (
        'Broadcast GetChildID GetParentID IsAddedToROS2Node IsParentAndChildSet '
        'ObserveTransformNode SetChildID SetParentID'),
    'vtkROS2RobotNode': 'GetRobotName IsAddedToROS2Node SetRobotName',
    'vtkROS2ServiceClientNode': (
        'GetNumberOfCalls GetNumberOfRequestsSent GetROSType GetService '
        'IsAddedToROS2Node SendAsyncRequest GetLastResponse '
        'GetLastResponseStatus CreateBlankRequest'),
}


@pytest.mark.parametrize('class_name', sorted(SLICERROS2_METHODS))
def test_every_slicerros2_method_exists(class_name: str) -> None:
    cls = getattr(ros2vtk, class_name)
    missing = [name for name in SLICERROS2_METHODS[class_name].split() if not hasattr(cls, name)]
    assert missing == [], f'{class_name} lacks SlicerROS2 methods: {missing}'
