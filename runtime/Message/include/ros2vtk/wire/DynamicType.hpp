// ros2vtk — message types built at run time from a REP 2011 type description (issue 13).
//
// A node that publishes a type we ship no spec for still tells us what the type is: its
// ~/get_type_description service answers the type's TypeDescription (the type and every type
// it references). build_dynamic_message_type turns that description into the same constant
// MessageTypeSupport table the generator emits, so YAML, the generic nodes, typed message
// objects and the wire use a runtime type exactly as a generated one: nothing downstream knows
// the difference.
//
// The in-memory form of a dynamic message is a block of `struct_size` bytes: a hidden pointer
// to its type at offset 0 (so destroy/copy/serialize need no per-type function), then the
// fields at naturally aligned offsets: primitives as themselves, std::string, std::u16string,
// nested messages inline, and every array or sequence as a DynamicContainer (contiguous
// elements, constructed in place). The seam's function pointers take no context, so create()
// and FieldInfo::nested come from a fixed pool of slot functions (kMaxDynamicTypes).
//
// Descriptions come from the network: every limit below is checked and every malformed
// description is refused with a reason, before anything is allocated for it. Built types live
// until the process ends (find_message_type hands out raw pointers), cached by type hash.
#ifndef ros2vtk_wire_DynamicType_hpp
#define ros2vtk_wire_DynamicType_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ros2vtk {
namespace wire {

/// type_description_interfaces/msg/Field as plain C++ (Message cannot depend on the generated
/// type_description_interfaces types; Wire converts them, see TypeDescriptionClient.hpp).
struct DescriptionField
{
  std::string name;
  uint8_t type_id = 0;
  uint64_t capacity = 0;
  uint64_t string_capacity = 0;
  std::string nested_type_name;
  std::string default_value;
};

/// A constant of a type (`uint8 BOOL=1`). REP 2011 descriptions carry none: they come from the
/// type's .msg source (GetTypeDescription's type_sources), read by parse_msg_constants.
struct DescriptionConstant
{
  std::string name;
  FieldType type = FieldType::Bool;
  std::string value; ///< normalised as the generator's ConstantInfo values (strings unquoted)
};

/// type_description_interfaces/msg/IndividualTypeDescription.
struct IndividualDescription
{
  std::string type_name;
  std::vector<DescriptionField> fields;
  /// Not part of the description (nor of its hash): from the type's .msg source when the peer
  /// sent it; a built type offers them as the generated tables do (MessageTypeSupport::constants).
  std::vector<DescriptionConstant> constants;
  /// The type's source as the peer sent it (TypeSource encoding and raw_file_contents), served
  /// again by our node; an empty encoding when none came (served as "dynamic", REP 2011's
  /// word for a type without a source file).
  std::string source_encoding;
  std::string source_contents;
};

/// type_description_interfaces/msg/TypeDescription.
struct TypeDescriptionData
{
  IndividualDescription type;
  std::vector<IndividualDescription> referenced;
};

/// What a description may ask for. Defaults fit every ROS 2 common interface many times over.
struct DynamicTypeLimits
{
  size_t max_depth = 32;                    ///< nesting levels below the top type
  size_t max_fields = 1024;                 ///< fields of one type
  size_t max_types = 256;                   ///< referenced types of one description
  size_t max_name_length = 256;             ///< type and field names
  uint64_t max_array_size = 1u << 20;       ///< N of a fixed array T[N]
  uint64_t max_default_elements = 1u << 20; ///< elements a default message holds in total
  size_t max_default_value_length = 1u << 16;
};

/// How many dynamic types one process can hold (the slot pool of create / nested).
constexpr size_t kMaxDynamicTypes = 1024;

/// The RIHS01 hash ("RIHS01_<64 hex>") of a description, as rosidl_generator_type_description
/// and rcl compute it: SHA-256 of the JSON of the description without default values,
/// referenced types sorted by name. Empty, with `error`, when a name is not valid UTF-8.
std::string type_description_hash(const TypeDescriptionData& description, std::string* error);

/// The table of the description's main type, built (with every referenced type) on first use
/// and cached by type hash; types not yet registered under their name are registered, so
/// find_message_type finds them. When `expected_hash` is not empty (the peer's USER_DATA
/// `typehash=`), a description whose hash differs is refused. nullptr and `error` (the reason,
/// naming the type and field) for a malformed or too large description.
const MessageTypeSupport* build_dynamic_message_type(const TypeDescriptionData& description,
  const std::string& expected_hash, std::string* error, const DynamicTypeLimits& limits = {});

/// The constants of a .msg text (a type_source of encoding "msg"), in order. Only constant lines
/// (`TYPE NAME=VALUE`) are read; fields come from the description. False with a reason (the
/// line and what is wrong) for a constant of a non-primitive type, a bad name or a value that
/// does not read as its type.
bool parse_msg_constants(
  const std::string& text, std::vector<DescriptionConstant>* constants, std::string* error);

/// True when `type` was built by build_dynamic_message_type.
bool is_dynamic_message_type(const MessageTypeSupport* type);

/// Dynamic types built so far in this process.
size_t dynamic_message_type_count();

} // namespace wire
} // namespace ros2vtk

#endif
