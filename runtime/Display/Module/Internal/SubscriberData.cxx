// ros2vtk — the newest message of a subscriber node as a VTK object (see the header): a table of
// the generated subscriber classes that produce VTK data objects, by class.
#include "Internal/SubscriberData.hpp"

#include "vtkROS2SubscriberImageNode.h"
#include "vtkROS2SubscriberMarkerArrayNode.h"
#include "vtkROS2SubscriberMarkerNode.h"
#include "vtkROS2SubscriberNode.h"
#include "vtkROS2SubscriberPathPolylineNode.h"
#include "vtkROS2SubscriberPointCloud2Node.h"
#include "vtkROS2SubscriberPointCloudNode.h"
#include "vtkROS2SubscriberPoseArrayNode.h"

#include "vtkImageData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTransformCollection.h"

#include <cstring>

namespace ros2vtk {
namespace display {
namespace {

struct Getter
{
  vtkObject* (*last)(vtkROS2SceneNode*);
};

template<class Node>
vtkObject* LastOf(vtkROS2SceneNode* node)
{
  Node* subscriber = Node::SafeDownCast(node);
  return subscriber ? subscriber->GetLastMessage() : nullptr;
}

// One line per generated subscriber class whose message converts to a VTK data object.
const Getter kGetters[] = {
  { &LastOf<vtkROS2SubscriberImageNode> },
  { &LastOf<vtkROS2SubscriberPointCloudNode> },
  { &LastOf<vtkROS2SubscriberPointCloud2Node> },
  { &LastOf<vtkROS2SubscriberPoseArrayNode> },
  { &LastOf<vtkROS2SubscriberMarkerNode> },
  { &LastOf<vtkROS2SubscriberMarkerArrayNode> },
  { &LastOf<vtkROS2SubscriberPathPolylineNode> },
};

}

const char* SubscriberVTKType(vtkROS2SceneNode* node)
{
  auto* subscriber = vtkROS2SubscriberNode::SafeDownCast(node);
  const char* type = subscriber ? subscriber->GetSlicerType() : nullptr;
  return type ? type : "";
}

bool IsSubscriberOf(vtkROS2SceneNode* node, const char* vtkType)
{
  return std::strcmp(SubscriberVTKType(node), vtkType) == 0;
}

vtkObject* LastMessageObject(vtkROS2SceneNode* node)
{
  if (!vtkROS2SubscriberNode::SafeDownCast(node))
  {
    return nullptr;
  }
  for (const Getter& getter : kGetters)
  {
    if (vtkObject* object = getter.last(node))
    {
      return object;
    }
  }
  return nullptr;
}

}
}
