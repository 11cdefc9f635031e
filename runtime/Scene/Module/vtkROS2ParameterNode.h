// ros2vtk — watches parameters of one remote ROS node (SlicerROS2's parameter node): values
// come from the node's parameter services and /parameter_events and are refreshed on the spin
// of the ROS node this node is attached to. A remote node that is absent is a state
// (IsMonitoredNodeReady), never an error per spin; values are fetched again when it returns.
#ifndef vtkROS2ParameterNode_h
#define vtkROS2ParameterNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2SceneNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string
#include <vector> // for std::vector

class vtkDoubleArray;
class vtkIntArray;
class vtkROS2NodeNode;
class vtkStringArray;
class vtkTypeInt64Array;
class vtkUnsignedCharArray;

class ROS2VTKSCENE_EXPORT vtkROS2ParameterNode : public vtkROS2SceneNode
{
public:
  static vtkROS2ParameterNode* New();
  vtkTypeMacro(vtkROS2ParameterNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Fired (with ModifiedEvent) on the spin that brings new values; SlicerROS2's id.
  enum
  {
    ParameterModifiedEvent = vtkCommand::UserEvent + 54
  };

  /// The remote node, fully qualified ("/robot_state_publisher", "/PSM1/robot_state_publisher").
  const char* GetMonitoredNodeName() const;
  /// True while the remote node's parameter services are reachable.
  bool IsMonitoredNodeReady() const;

  /// Starts / stops following a parameter (the value arrives on a later spin).
  bool AddParameter(const char* name);
  bool RemoveParameter(const char* name);
  /// Space-separated names of the followed parameters.
  std::string GetParameterNames() const;

  /// Whether the parameter has a value (the remote node declared and set it).
  bool IsParameterSet(const char* name, bool noWarning = false) const;
  /// "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
  /// "double_array", "string_array", "not set" (reported without a value), or "" for a
  /// parameter never seen (SlicerROS2's answer).
  std::string GetParameterType(const char* name) const;

  /// Typed values; a wrong type or unset parameter gives vtkErrorMacro and a default value.
  bool GetParameterAsBool(const char* name) const;
  vtkTypeInt64 GetParameterAsInteger(const char* name) const;
  double GetParameterAsDouble(const char* name) const;
  std::string GetParameterAsString(const char* name) const;
  /// Arrays fill a caller-owned VTK array (resized; false with vtkErrorMacro on a wrong type).
  bool GetParameterAsVectorOfBools(const char* name, vtkIntArray* values) const;
  bool GetParameterAsVectorOfIntegers(const char* name, vtkTypeInt64Array* values) const;
  bool GetParameterAsVectorOfDoubles(const char* name, vtkDoubleArray* values) const;
  bool GetParameterAsVectorOfStrings(const char* name, vtkStringArray* values) const;
  bool GetParameterAsByteArray(const char* name, vtkUnsignedCharArray* values) const;
  /// SlicerROS2's one-argument forms: the values themselves (a tuple in Python), empty with
  /// vtkErrorMacro on a wrong type or unset parameter. Bools come as 0/1 (SlicerROS2 returns
  /// std::vector<char>; VTK's wrapping cannot return std::vector<bool>).
  std::vector<int> GetParameterAsVectorOfBools(const char* name) const;
  std::vector<vtkTypeInt64> GetParameterAsVectorOfIntegers(const char* name) const;
  std::vector<double> GetParameterAsVectorOfDoubles(const char* name) const;
  std::vector<std::string> GetParameterAsVectorOfStrings(const char* name) const;
  /// "name (type): value" as `ros2 param get` would show it, for any type.
  std::string PrintParameter(const char* name) const;

  vtkROS2NodeNode* GetROS2Node() const;

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  void OnSceneRestored() override;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: watch `remoteNode` through this ROS node.
  bool Attach(vtkROS2NodeNode* rosNode, const std::string& remoteNode);
  /// Used by vtkROS2NodeNode::Spin: takes responses and events; fires the events when values
  /// changed. Returns the number of parameters that changed.
  int ProcessParameterUpdates();
#endif

  /// Destroy hook: the parameter client's endpoints live in the ROS node's participant, so they
  /// go with it (otherwise they would be released after the participant, at scene teardown).
  void OnROS2NodeDestroyed(vtkROS2NodeNode*) override;
  /// Spin hook (vtkROS2SceneNode::OnROS2NodeSpin): applies parameter updates.
  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    return this->ProcessParameterUpdates();
  }
  /// Index key among the ROS node's parameter nodes.
  std::string GetROS2NodeChildKey() const override
  {
    return this->GetMonitoredNodeName();
  }

protected:
  vtkROS2ParameterNode();
  ~vtkROS2ParameterNode() override;
  void OnRemovedFromScene() override;

private:
  vtkROS2ParameterNode(const vtkROS2ParameterNode&) = delete;
  void operator=(const vtkROS2ParameterNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
