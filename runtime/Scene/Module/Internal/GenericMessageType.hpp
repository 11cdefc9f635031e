// ros2vtk — the ROS type a generic publisher/subscriber node carries, chosen at run time
// (private to the Scene module; generic nodes hold one).
#ifndef ros2vtk_scene_GenericMessageType_hpp
#define ros2vtk_scene_GenericMessageType_hpp

#include "ros2vtk/wire/TypeDescriptionClient.hpp"

#include <functional>
#include <memory>
#include <string>

class vtkObject;
class vtkXMLDataElement;

namespace ros2vtk {
namespace wire {
class Participant;
struct MessageTypeSupport;
}
namespace scene {

/// Finds a registered message type by "pkg/msg/Type" or "pkg/Type". On failure returns nullptr
/// and sets `error` to a message listing the registered types.
const wire::MessageTypeSupport* find_generic_type(const char* ros_type, std::string& error);

/// SetROSType of both generic nodes: the type cannot change while the node is added to a ROS
/// node (its endpoint exists); otherwise `ros_type` is looked up and stored in `type`. Returns ""
/// on success (`changed` says whether `type` changed), else the reason.
std::string assign_generic_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, bool& changed);

/// A type name a generic subscriber may learn at run time (issue 13): "pkg/msg/Type" or
/// "pkg/Type" (made "pkg/msg/Type" in place), every part an identifier. False otherwise.
bool runtime_type_name(std::string& ros_type);

/// The `rosType` attribute a generic node saved, or nullptr when absent or empty.
const char* saved_generic_type(vtkXMLDataElement* element);

class LearntMessageType;

/// SetROSTypeResolvedAtRuntime of both generic nodes, for a name no library registers: the type
/// cannot change while the node is added to a ROS node; otherwise `learnt` takes the name (to be
/// learnt from `peers`) and `type` is cleared. Returns "" on success (`changed` says whether
/// anything changed), else the reason.
std::string assign_learnt_type(const char* ros_type, bool added_to_ros_node,
  const wire::MessageTypeSupport*& type, LearntMessageType& learnt,
  wire::RuntimeTypeResolver::Peers peers, bool& changed);

/// The end of a generic node's SetROSType / SetROSTypeResolvedAtRuntime (`call`): the error
/// reported on `node` when there is one (false), else `node` Modified when `changed` (true).
bool finish_type_change(vtkObject* node, const char* call, const std::string& error, bool changed);

/// A type a generic subscriber or publisher learns at run time from the graph (issue 13): its
/// name, a stand-in table that only names it (GetROSType, scene files) while nothing can be sent
/// or received, the resolver that asks a peer's node, and what it waits for in words. Both
/// generic nodes hold one, so that learning a type is written once.
class LearntMessageType
{
public:
  using Peers = wire::RuntimeTypeResolver::Peers;

  LearntMessageType();
  ~LearntMessageType();
  LearntMessageType(const LearntMessageType&) = delete;
  LearntMessageType& operator=(const LearntMessageType&) = delete;

  /// Takes "pkg/msg/Type" or "pkg/Type" to be learnt from `peers`. False (nothing changed) for a
  /// text that is no type name.
  bool set(const char* ros_type, Peers peers);
  /// Forgets the type (a registered one replaces it).
  void clear();
  bool empty() const { return name_.empty(); }
  const std::string& name() const { return name_; }
  /// The stand-in table: names the type, describes nothing.
  const wire::MessageTypeSupport& named_only() const { return *named_only_; }

  ///@{
  /// What both generic nodes do with their type (`type`: the node's registered or learnt type,
  /// nullptr while it is to be learnt), so that each node's methods only delegate here.
  /// SetROSType: a registered type, which replaces one to be learnt. "" or the reason.
  std::string set_registered(const char* ros_type, bool added_to_ros_node,
    const wire::MessageTypeSupport*& type, bool& changed);
  /// SetROSTypeResolvedAtRuntime: a registered name as set_registered, another learnt from
  /// `peers`. "" or the reason.
  std::string set_resolved_at_runtime(const char* ros_type, bool added_to_ros_node,
    const wire::MessageTypeSupport*& type, Peers peers, bool& changed);
  /// CreateEndpoint: while the type is to be learnt, starts watching `topic` and returns true
  /// (the endpoint is created by spin_node once the type is known); false when `type` is known
  /// (the node creates its endpoint now).
  bool watch_unless_known(
    const wire::MessageTypeSupport* type, wire::Participant& participant, const std::string& topic);
  /// DestroyEndpoint: stops asking while the type is still to be learnt.
  void stop_unless_known(const wire::MessageTypeSupport* type);
  /// OnROS2NodeSpin while asking(): one step of spin(), `create` making the endpoint once the
  /// type is learnt; reports a failure on `node` and marks it Modified when something changed.
  void spin_node(vtkObject* node, const wire::MessageTypeSupport*& type,
    wire::Participant* participant, const char* verb,
    const std::function<bool(wire::Participant&, std::string&)>& create);
  ///@}

  /// Starts watching the graph for a peer of `topic` to ask (the node was added to a ROS node).
  void start(wire::Participant& participant, const std::string& topic);
  /// Stops asking (the node left its ROS node, or the type was learnt).
  void stop();
  bool asking() const { return resolver_ != nullptr; }
  /// One step of asking; the built type once learnt (asking then stops), else nullptr.
  /// `status_changed` says whether status() changed.
  const wire::MessageTypeSupport* poll(bool& status_changed);

  /// "" when nothing is to be learnt; what it waits for, or why it gave up.
  const std::string& status() const { return status_; }
  void set_status(std::string status) { status_ = std::move(status); }

  /// One spin of a generic node that waits for its type: asks, and once the type is learnt calls
  /// `open` (the node's endpoint creation; false with a reason when it fails). Returns whether
  /// the node changed (type learnt, or status). `type` receives the learnt type, or stays
  /// nullptr when `open` failed (the status then says why, `verb` naming what failed:
  /// "subscribe", "publish").
  template<typename Open>
  bool spin(const wire::MessageTypeSupport*& type, const char* verb, Open open)
  {
    bool status_changed = false;
    const wire::MessageTypeSupport* learnt = poll(status_changed);
    if (!learnt)
    {
      return status_changed;
    }
    type = learnt;
    std::string error;
    if (!open(error))
    {
      status_ = "learnt " + name_ + " but cannot " + verb + ": " + error;
      type = nullptr;
    }
    return true;
  }

private:
  std::string waiting_to_be_added() const;

  std::string name_;
  Peers peers_ = Peers::Publishers;
  std::unique_ptr<wire::MessageTypeSupport> named_only_;
  std::unique_ptr<wire::RuntimeTypeResolver> resolver_;
  std::string status_;
};

} // namespace scene
} // namespace ros2vtk

#endif
