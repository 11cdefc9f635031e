// ros2vtk — the seam between generated message code and the hand-written runtime.
//
// The generator emits, for every message type, one constant MessageTypeSupport table (names,
// type hash, function pointers, field descriptions). The runtime only ever consumes these
// tables, so it never names a message type (the rosidl_typesupport_fastrtps / rmw_fastrtps
// split). Field descriptions (introspection) drive YAML output, generic nodes and Python field
// access without per-type code.
#ifndef ros2vtk_wire_MessageTypeSupport_hpp
#define ros2vtk_wire_MessageTypeSupport_hpp

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {

class CdrReader;
class CdrWriter;
struct MessageTypeSupport;

/// The element type of a field, as in the .msg grammar (`char` is uint8, `byte` an octet).
enum class FieldType : uint8_t
{
  Bool,
  Byte,
  Char,
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Int64,
  UInt64,
  Float32,
  Float64,
  String,
  WString,
  Message
};

/// The ROS IDL spelling of a field type ("float64", "string"; "message" for nested ones), for
/// error messages and field descriptions.
const char* field_type_name(FieldType type);

/// How many elements a field holds: one, a fixed array T[N], T[<=N] or T[].
enum class Container : uint8_t
{
  None,
  Array,
  BoundedSequence,
  Sequence
};

/// One member of a message struct. Container access goes through functions because the
/// element storage differs (std::array, std::vector, std::vector<bool>).
struct FieldInfo
{
  const char* name;
  FieldType type;
  Container container;
  uint32_t array_size;                   ///< N of T[N] or T[<=N]; 0 otherwise
  uint32_t string_bound;                 ///< N of string<=N; 0 when unbounded
  size_t offset;                         ///< offsetof(struct, member)
  const MessageTypeSupport* (*nested)(); ///< element type when type == Message, else nullptr

  // Container access, all nullptr when container == None. `field` points at the member.
  size_t (*size)(const void* field);
  void* (*element)(void* field, size_t index); ///< nullptr for bool sequences (see get_bool)
  bool (*resize)(void* field, size_t count);   ///< false for fixed arrays of another size
  bool (*get_bool)(const void* field, size_t index);
  void (*set_bool)(void* field, size_t index, bool value);
};

/// rosidl gives a message without fields one placeholder member (a uint8 named
/// structure_needs_at_least_one_member); it is on the wire, but rclpy's classes and
/// rosidl_runtime_py hide it (`ros2 topic echo` prints such a message as `{}`), and so do we
/// wherever fields are shown or set by name.
bool is_placeholder_field(const FieldInfo& field);

/// A named constant of a message (`uint8 BOOL=1`), kept for YAML/Python display.
struct ConstantInfo
{
  const char* name;
  FieldType type;
  const char* value; ///< as written in the spec, normalised (strings unquoted)
};

/// One field of a REP 2011 type description (type_description_interfaces/msg/Field): what a
/// node's ~/get_type_description serves, generated next to the type hash computed from it.
struct TypeDescriptionField
{
  const char* name;
  uint8_t type_id;          ///< type_description_interfaces/msg/FieldType id (container included)
  uint64_t capacity;        ///< N of T[N] or T[<=N]
  uint64_t string_capacity; ///< N of string<=N
  const char* nested_type_name; ///< "std_msgs/msg/Header" for nested types, else ""
  const char* default_value;    ///< as rosidl writes it ("1.0", "True"), "" when none
};

/// Where a type was defined (type_description_interfaces/msg/TypeSource, without its name):
/// what ~/get_type_description serves with include_type_sources, as rosidl_generator_c embeds
/// it, so that a tool lacking the type reads its constants and comments from our node too.
struct TypeSourceTable
{
  const char* encoding;          ///< "msg", "srv", "action"; "implicit" for synthesized types
  const char* raw_file_contents; ///< the file's lines joined by '\n' ("" when implicit)
  /// Set instead of raw_file_contents in a referenced type's entry when that type is generated:
  /// its own table's source is the text (each interface file is in the generated code once).
  const MessageTypeSupport* (*defined_by)();
};

/// One type of a description (type_description_interfaces/msg/IndividualTypeDescription),
/// with its source.
struct IndividualTypeDescriptionTable
{
  const char* type_name;
  uint32_t field_count;
  const TypeDescriptionField* fields;
  TypeSourceTable source;
};

/// A type's full description (type_description_interfaces/msg/TypeDescription): the type and
/// every type it references, sorted by name. Its RIHS01 hash is the type's type_hash.
struct TypeDescriptionTable
{
  IndividualTypeDescriptionTable type;
  uint32_t referenced_count;
  const IndividualTypeDescriptionTable* referenced;
};

/// Everything the runtime knows about one message type.
struct MessageTypeSupport
{
  const char* ros_type;      ///< "std_msgs/msg/String"
  const char* dds_type_name; ///< "std_msgs::msg::dds_::String_"
  const char* type_hash;     ///< "RIHS01_<64 hex>" (USER_DATA typehash), as rosidl computes it
  size_t struct_size;
  uint32_t field_count;
  const FieldInfo* fields;
  uint32_t constant_count;
  const ConstantInfo* constants;

  void* (*create)();                        ///< new default-initialised message
  void (*destroy)(void* message);           ///< deletes what create() returned
  void (*copy)(const void* from, void* to); ///< assignment
  bool (*equal)(const void* a, const void* b);
  size_t (*serialized_size)(const void* message); ///< payload size, header included
  void (*serialize)(const void* message, CdrWriter& writer);
  bool (*deserialize)(void* message, CdrReader& reader); ///< false on hostile bytes
  /// The REP 2011 description; nullptr for hand-written tables (tests), which no node serves.
  const TypeDescriptionTable* description;
};

/// A service: its request and response messages (`<Srv>_Request` / `<Srv>_Response`).
struct ServiceTypeSupport
{
  const char* ros_type; ///< "rcl_interfaces/srv/GetParameters"
  const MessageTypeSupport* (*request)();
  const MessageTypeSupport* (*response)();
  /// The service type's RIHS01 hash and description (request_message, response_message,
  /// event_message, as rosidl synthesizes them); empty / nullptr for hand-written tables.
  const char* type_hash;
  const TypeDescriptionTable* description;
};

/// An action `pkg/action/X`: the types rosidl synthesizes from X.action (all registered as
/// messages and services too) and the fixed action_msgs types its endpoints use, so the runtime
/// runs the action protocol (docs/actions.md) without naming any per-action type.
struct ActionTypeSupport
{
  const char* ros_type;                            ///< "test_msgs/action/Fibonacci"
  const MessageTypeSupport* (*goal)();             ///< X_Goal
  const MessageTypeSupport* (*result)();           ///< X_Result
  const MessageTypeSupport* (*feedback)();         ///< X_Feedback
  const ServiceTypeSupport* (*send_goal)();        ///< X_SendGoal (goal_id, goal / accepted, stamp)
  const ServiceTypeSupport* (*get_result)();       ///< X_GetResult (goal_id / status, result)
  const MessageTypeSupport* (*feedback_message)(); ///< X_FeedbackMessage (goal_id, feedback)
  const ServiceTypeSupport* (*cancel_goal)();      ///< action_msgs/srv/CancelGoal
  const MessageTypeSupport* (*status)();           ///< action_msgs/msg/GoalStatusArray
  /// The action type's RIHS01 hash and description (goal, result, feedback, send_goal_service,
  /// get_result_service, feedback_message, as rosidl synthesizes them).
  const char* type_hash;
  const TypeDescriptionTable* description;
};

/// Process-wide registry filled by the generated libraries when they load, so the runtime
/// and the Python layer can find any generated type by its ROS name.
void register_message_type(const MessageTypeSupport* type);
void register_service_type(const ServiceTypeSupport* type);
void register_action_type(const ActionTypeSupport* type);

/// Accepts "pkg/msg/Type" and "pkg/Type". nullptr when unknown.
const MessageTypeSupport* find_message_type(const std::string& ros_type);
const ServiceTypeSupport* find_service_type(const std::string& ros_type);
/// As above; when unknown, `error` says so and lists the registered service types.
const ServiceTypeSupport* find_service_type(const std::string& ros_type, std::string* error);

/// Accepts "pkg/action/X" and "pkg/X"; when unknown (nullptr), `error` (if given) says so and
/// lists the registered action types.
const ActionTypeSupport* find_action_type(
  const std::string& ros_type, std::string* error = nullptr);

/// Sorted ROS names of every registered message / service / action type.
std::vector<std::string> registered_message_types();
std::vector<std::string> registered_service_types();
std::vector<std::string> registered_action_types();

/// Serializes into `buffer` (cleared first); the result is a complete payload.
void serialize_message(
  const MessageTypeSupport& type, const void* message, std::vector<uint8_t>& buffer);

/// Deserializes a complete payload; on failure returns false and sets `error`.
bool deserialize_message(const MessageTypeSupport& type, const uint8_t* data, size_t size,
  void* message, std::string* error);

} // namespace wire
} // namespace ros2vtk

#endif
