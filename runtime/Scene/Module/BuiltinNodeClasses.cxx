// The runtime's own scene node classes, registered when the registry is first used.
#include "NodeClassRegistry.hpp"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2SubscriberGenericNode.h"

namespace ros2vtk {
namespace scene {

namespace {
template <typename T>
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
  };
  for (const auto& info : builtins)
  {
    registry.add(info, nullptr);
  }
}

} // namespace scene
} // namespace ros2vtk
