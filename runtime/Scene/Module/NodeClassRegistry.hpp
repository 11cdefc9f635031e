// ros2vtk — the registry of scene node classes (plain C++, not wrapped).
//
// Every class a scene can create by name registers here: the runtime's own classes (ROS node,
// generic publisher/subscriber) when the Scene library loads, and the generated publisher and
// subscriber classes (vtkROS2PublisherStringNode, …) when the generated library loads. The
// registry is what lets CreateAndAddPublisherNode accept 'String', 'vtkROS2PublisherStringNode',
// 'vtkMRMLROS2PublisherStringNode' or 'std_msgs/msg/String', and lets a saved scene be restored.
// It lives in the shared Scene library, so there is one per process.
#ifndef ros2vtk_scene_NodeClassRegistry_hpp
#define ros2vtk_scene_NodeClassRegistry_hpp

#include "ros2vtkSceneModule.h" // for export macro

#include <map>
#include <mutex>
#include <string>
#include <vector>

class vtkROS2SceneNode;

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}

namespace scene {

/// Which side of a topic a class sits on; Other for nodes that are not topic endpoints.
enum class NodeDirection
{
  Publisher,
  Subscriber,
  Other
};

/// One registered class.
struct NodeClassInfo
{
  std::string short_name; ///< "String", "PoseStamped" (mapping rule's short name); "" for Other
  std::string class_name; ///< "vtkROS2PublisherStringNode"
  std::string ros_type;   ///< "std_msgs/msg/String"; "" when not bound to one type
  NodeDirection direction = NodeDirection::Other;
  /// Returns a new instance with a reference count of one (as T::New()).
  vtkROS2SceneNode* (*create)() = nullptr;
};

/// What a user's type string names, for CreateAndAdd{Publisher,Subscriber}Node.
struct NodeTypeResolution
{
  /// The mapped class to create, or nullptr.
  const NodeClassInfo* mapped_class = nullptr;
  /// Set instead when the string names a registered ROS type with no (unique) mapped class:
  /// create the generic node for this type.
  const wire::MessageTypeSupport* generic_type = nullptr;
  /// Set when neither: a message naming the string and listing the known names.
  std::string error;
};

class ROS2VTKSCENE_EXPORT NodeClassRegistry
{
public:
  /// The process-wide registry (holds the runtime's own classes from the first call on).
  static NodeClassRegistry& instance();

  /// False (and `error`) when the info is incomplete or the class name is already registered
  /// with a different factory; registering the same class twice is harmless.
  bool add(const NodeClassInfo& info, std::string* error);

  /// Lets `alias` name a registered class: Slicer's core classes that Slicer scripts add next to
  /// ROS nodes (vtkMRMLModelNode) map to our equivalents. False (and `error`) when the alias is a
  /// class name itself or already names another class.
  bool add_alias(const std::string& alias, const std::string& class_name, std::string* error);

  /// Accepts a class name, an alias, or SlicerROS2's spelling of a class name ("vtkMRMLROS2…" for
  /// "vtkROS2…"). nullptr when unknown. Pointers stay valid for the life of the process.
  const NodeClassInfo* find_class(const std::string& class_name) const;
  const NodeClassInfo* find_short_name(
    NodeDirection direction, const std::string& short_name) const;
  std::vector<const NodeClassInfo*> find_ros_type(
    NodeDirection direction, const std::string& ros_type) const;

  /// Registered classes of one direction, sorted by class name.
  std::vector<const NodeClassInfo*> classes(NodeDirection direction) const;

  /// Interprets a user's type string for one direction:
  /// - "Short", "vtkROS2<Publisher|Subscriber>ShortNode", "vtkMRMLROS2<…>ShortNode" → that class
  ///   (a class of the other direction is an error naming the right call);
  /// - "pkg/msg/Type" or "pkg/Type" of a registered message type → its mapped class when exactly
  ///   one is registered for this direction, else the generic node for that type;
  /// - anything else → error listing the short names, class names and ROS types known.
  NodeTypeResolution resolve(NodeDirection direction, const std::string& type) const;

private:
  NodeClassRegistry() = default;
  mutable std::mutex mutex_;
  std::map<std::string, NodeClassInfo>
    classes_;                                  // by class name; node-based, so pointers are stable
  std::map<std::string, std::string> aliases_; // alias -> class name
};

/// "Publisher" / "Subscriber" / "Other".
ROS2VTKSCENE_EXPORT const char* to_string(NodeDirection direction);

} // namespace scene
} // namespace ros2vtk

#endif
