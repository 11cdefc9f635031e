// The runtime's own scene node classes, registered when the registry is first used.
#include "NodeClassRegistry.hpp"
#include "vtkROS2ModelNode.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2ParameterNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2ActionClientNode.h"
#include "vtkROS2ActionServerNode.h"
#include "vtkROS2ServiceClientNode.h"
#include "vtkROS2ServiceServerNode.h"
#include "vtkROS2SubscriberGenericNode.h"
#include "vtkROS2Tf2BroadcasterNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

namespace ros2vtk {
namespace scene {

namespace {
template<typename T>
vtkROS2SceneNode* create_node()
{
  return T::New();
}
} // namespace

void register_builtin_node_classes(NodeClassRegistry& registry)
{
  // Generic nodes are Other: they are not bound to one ROS type, so no short name resolves to
  // them; CreateAndAdd*Node picks them for ROS types without a mapped class.
  const NodeClassInfo builtins[] = {
    { "", "vtkROS2NodeNode", "", NodeDirection::Other, &create_node<vtkROS2NodeNode> },
    { "", "vtkROS2PublisherGenericNode", "", NodeDirection::Other,
      &create_node<vtkROS2PublisherGenericNode> },
    { "", "vtkROS2SubscriberGenericNode", "", NodeDirection::Other,
      &create_node<vtkROS2SubscriberGenericNode> },
    // Every other class a scene file may hold (vtkROS2Scene::ReadFromXML creates by class name).
    { "", "vtkROS2ParameterNode", "", NodeDirection::Other, &create_node<vtkROS2ParameterNode> },
    { "", "vtkROS2TransformNode", "", NodeDirection::Other, &create_node<vtkROS2TransformNode> },
    { "", "vtkROS2Tf2LookupNode", "", NodeDirection::Other, &create_node<vtkROS2Tf2LookupNode> },
    { "", "vtkROS2Tf2BroadcasterNode", "", NodeDirection::Other,
      &create_node<vtkROS2Tf2BroadcasterNode> },
    { "", "vtkROS2ModelNode", "", NodeDirection::Other, &create_node<vtkROS2ModelNode> },
    { "", "vtkROS2RobotNode", "", NodeDirection::Other, &create_node<vtkROS2RobotNode> },
    { "", "vtkROS2ServiceClientNode", "", NodeDirection::Other,
      &create_node<vtkROS2ServiceClientNode> },
    { "", "vtkROS2ServiceServerNode", "", NodeDirection::Other,
      &create_node<vtkROS2ServiceServerNode> },
    { "", "vtkROS2ActionClientNode", "", NodeDirection::Other,
      &create_node<vtkROS2ActionClientNode> },
    { "", "vtkROS2ActionServerNode", "", NodeDirection::Other,
      &create_node<vtkROS2ActionServerNode> },
  };
  for (const auto& info : builtins)
  {
    registry.add(info, nullptr);
  }
  // Slicer's core classes that Slicer scripts add next to ROS nodes, as our equivalents.
  registry.add_alias("vtkMRMLModelNode", "vtkROS2ModelNode", nullptr);
  registry.add_alias("vtkMRMLLinearTransformNode", "vtkROS2TransformNode", nullptr);
  registry.add_alias("vtkMRMLTransformNode", "vtkROS2TransformNode", nullptr);
}

} // namespace scene
} // namespace ros2vtk
