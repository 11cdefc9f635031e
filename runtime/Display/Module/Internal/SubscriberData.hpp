// ros2vtk — the newest message of a subscriber node as a VTK object, whatever its class.
//
// Subscriber nodes are generated per message type, each with a typed GetLastMessage(); the base
// class has no virtual for it. This file is the one place that maps the generated subscriber
// classes to their VTK data (by the VTK type they produce: vtkImageData, vtkPoints, vtkPolyData,
// vtkTransformCollection), so the displayable managers pick nodes by the VTK type they draw and
// never name a message type. A generated virtual GetLastMessageObject() would replace it.
#ifndef ros2vtk_display_SubscriberData_hpp
#define ros2vtk_display_SubscriberData_hpp

class vtkObject;
class vtkROS2SceneNode;

namespace ros2vtk {
namespace display {

/// The VTK type a subscriber node converts its messages to (its GetSlicerType()), or "" when
/// `node` is not a subscriber.
const char* SubscriberVTKType(vtkROS2SceneNode* node);

/// Whether `node` is a subscriber whose messages convert to `vtkType`.
bool IsSubscriberOf(vtkROS2SceneNode* node, const char* vtkType);

/// The newest message converted (owned by the node, valid until its next spin), or nullptr
/// before the first message, when it cannot be converted, or for a class not in the table.
vtkObject* LastMessageObject(vtkROS2SceneNode* node);

}
}

#endif
