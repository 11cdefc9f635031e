// ros2vtk — a typed message object for any registered ROS type: every field readable and
// writable by name ("header.stamp.sec", "poses[2].position.x"), sequences as VTK arrays, nested
// messages as vtkROS2Message, the whole message as YAML or as CDR bytes. It is the escape hatch
// for what a mapping rule does not carry (header stamps, child_frame_id, covariance, any type
// without a rule): publisher nodes publish one exactly as it is (PublishMessageObject) and
// subscriber nodes fill one with what arrived (GetLastMessageObject).
//
// One class serves every type, driven by the generated introspection tables (no per-type code
// to compile); Python adds attribute access and SlicerROS2-style Get<Field>() on top
// (ros2vtk.Message, python/ros2vtk/messages.py).
#ifndef vtkROS2Message_h
#define vtkROS2Message_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkObject.h"

#include <memory>
#include <string>

class vtkDataArray;
class vtkStringArray;
class vtkUnsignedCharArray;

namespace ros2vtk {
namespace wire {
struct MessageTypeSupport;
}
}

class ROS2VTKSCENE_EXPORT vtkROS2Message : public vtkObject
{
public:
  static vtkROS2Message* New();
  vtkTypeMacro(vtkROS2Message, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Makes this a default-valued message of `rosType` ("geometry_msgs/msg/PoseStamped" or
  /// "geometry_msgs/PoseStamped"). False (error listing the registered types) when unknown.
  bool SetROSType(const char* rosType);
  /// "" until a type is set.
  const char* GetROSType() const;
  /// Every field back to its default.
  void Reset();

  /// Introspection. `path` "" is the message itself; an index ("poses[0]") names one element.
  int GetNumberOfFields(const char* path = "");
  std::string GetFieldName(const char* path, int index);
  /// As a .msg file writes it: "float64", "string<=10", "geometry_msgs/msg/Point", "float64[]",
  /// "int32[3]", "uint8[<=16]". "" (and an error) for an unknown path.
  std::string GetFieldType(const char* path);
  bool IsMessageField(const char* path);
  bool IsArrayField(const char* path);

  /// The type's constants as its .msg file declares them (rcl_interfaces/msg/ParameterType:
  /// PARAMETER_NOT_SET = 0, PARAMETER_BOOL = 1, ...), in the file's order: how many, the name of
  /// one, and one's value as text (numbers as written, strings unquoted). An unknown name gives
  /// "" and an error. Types learnt at run time have none (type descriptions carry no constants).
  int GetNumberOfConstants();
  std::string GetConstantName(int index);
  std::string GetConstant(const char* name);

  /// One value as text (numbers exact, bools true/false, a nested message as YAML), or set from
  /// text. Errors name the path and the reason; a failed set changes nothing.
  std::string GetField(const char* path);
  bool SetField(const char* path, const char* value);
  /// Numbers and bools. Integers set from a double must be whole; out-of-range values are refused.
  double GetFieldAsDouble(const char* path);
  bool SetFieldFromDouble(const char* path, double value);
  vtkTypeInt64 GetFieldAsInteger(const char* path);
  bool SetFieldFromInteger(const char* path, vtkTypeInt64 value);
  bool GetFieldAsBool(const char* path);
  bool SetFieldFromBool(const char* path, bool value);

  /// Arrays and sequences: length (-1 on error), resize (fixed arrays keep their size,
  /// bounded sequences their bound), and the elements as one VTK array (numbers and bools; the
  /// output array's type is kept, values converted with a range check) or vtkStringArray.
  int GetFieldLength(const char* path);
  bool SetFieldLength(const char* path, int length);
  bool GetFieldAsArray(const char* path, vtkDataArray* values);
  bool SetFieldFromArray(const char* path, vtkDataArray* values);
  bool GetFieldAsStringArray(const char* path, vtkStringArray* values);
  bool SetFieldFromStringArray(const char* path, vtkStringArray* values);

  /// A nested message (or one element of a message sequence) copied out / in; the types must
  /// match.
  bool GetMessage(const char* path, vtkROS2Message* message);
  bool SetMessage(const char* path, vtkROS2Message* message);

  /// The whole message as YAML (`ros2 topic echo` style), or set from YAML (fields left out
  /// keep their values).
  std::string GetYAML();
  bool SetYAML(const char* yaml);

  /// The ROS 2 wire form (CDR with its encapsulation header), byte for byte what rclpy's
  /// serialize_message gives; Deserialize rejects malformed bytes with a reason.
  bool Serialize(vtkUnsignedCharArray* bytes);
  bool Deserialize(vtkUnsignedCharArray* bytes);

  /// Same type and same values.
  bool Equals(vtkROS2Message* other);
  void DeepCopy(vtkROS2Message* other);

  /// Why the last call failed ("" after a success).
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// C++ (not wrapped): the type and the message struct, for nodes that publish or fill one.
  const ros2vtk::wire::MessageTypeSupport* GetTypeSupport() const { return this->Type; }
  const void* GetRawMessage() const { return this->Message.get(); }
  void* GetRawMessage() { return this->Message.get(); }
  /// Becomes a copy of `message` of type `type`.
  void CopyFromRaw(const ros2vtk::wire::MessageTypeSupport& type, const void* message);

protected:
  vtkROS2Message();
  ~vtkROS2Message() override;

private:
  vtkROS2Message(const vtkROS2Message&) = delete;
  void operator=(const vtkROS2Message&) = delete;

  bool Fail(const std::string& error);
  bool Succeed();
  bool CheckType(const char* what);
  void Allocate(const ros2vtk::wire::MessageTypeSupport& type);

  const ros2vtk::wire::MessageTypeSupport* Type = nullptr;
  std::unique_ptr<void, void (*)(void*)> Message;
  std::string LastError;
};

#endif
