// ros2vtk tests — a hand-written message type covering every field kind MessageYaml handles
// (scalars, bounded string, wstring, fixed array, bounded and unbounded sequences, bools, bytes,
// nested and empty messages), shared by the YAML unit tests and the YAML fuzz target.
#ifndef ros2vtk_tests_message_SampleType_hpp
#define ros2vtk_tests_message_SampleType_hpp

#include "ros2vtk/wire/FieldAccess.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

namespace wire = ros2vtk::wire;

struct Inner
{
  int32_t a = 0;
  std::string s;
  bool operator==(const Inner& o) const { return a == o.a && s == o.s; }
};

struct Nothing
{
  uint8_t structure_needs_at_least_one_member = 0;
  bool operator==(const Nothing&) const { return true; }
};

struct Sample
{
  bool flag = false;
  uint8_t byte_value = 0;
  int8_t small = 0;
  uint16_t u16 = 0;
  float f32 = 0.0f;
  double f64 = 0.0;
  std::string text;    // string<=5
  std::u16string wide; // wstring
  std::array<double, 3> fixed{};
  std::vector<int64_t> bounded; // int64[<=2]
  std::vector<bool> flags;
  std::vector<uint8_t> bytes; // byte[]
  Inner inner;
  std::vector<Inner> inners;
  Nothing empty;
  bool operator==(const Sample& o) const
  {
    return flag == o.flag && byte_value == o.byte_value && small == o.small && u16 == o.u16 &&
      f32 == o.f32 && f64 == o.f64 && text == o.text && wide == o.wide && fixed == o.fixed &&
      bounded == o.bounded && flags == o.flags && bytes == o.bytes && inner == o.inner &&
      inners == o.inners && empty == o.empty;
  }
};

template<typename T>
wire::MessageTypeSupport table(
  const char* name, uint32_t field_count, const wire::FieldInfo* fields)
{
  wire::MessageTypeSupport type{};
  type.ros_type = name;
  type.dds_type_name = name;
  type.type_hash = "";
  type.struct_size = sizeof(T);
  type.field_count = field_count;
  type.fields = fields;
  type.create = [] {
    return static_cast<void*>(new T());
  };
  type.destroy = [](void* m) {
    delete static_cast<T*>(m);
  };
  type.copy = [](const void* from, void* to) {
    *static_cast<T*>(to) = *static_cast<const T*>(from);
  };
  type.equal = [](const void* a, const void* b) {
    return *static_cast<const T*>(a) == *static_cast<const T*>(b);
  };
  return type; // serialization is not used by MessageYaml
}

const wire::MessageTypeSupport* inner_type();
const wire::MessageTypeSupport* nothing_type();

const wire::FieldInfo kInnerFields[] = {
  { "a", wire::FieldType::Int32, wire::Container::None, 0, 0, offsetof(Inner, a), nullptr, nullptr,
    nullptr, nullptr, nullptr, nullptr },
  { "s", wire::FieldType::String, wire::Container::None, 0, 0, offsetof(Inner, s), nullptr, nullptr,
    nullptr, nullptr, nullptr, nullptr },
};

const wire::MessageTypeSupport* inner_type()
{
  static const wire::MessageTypeSupport type = table<Inner>("test_msgs/msg/Inner", 2, kInnerFields);
  return &type;
}

const wire::MessageTypeSupport* nothing_type()
{
  // A message without fields, as the generator describes std_msgs/Empty: no FieldInfo.
  static const wire::MessageTypeSupport type = table<Nothing>("test_msgs/msg/Nothing", 0, nullptr);
  return &type;
}

#define R2V_SCALAR(member, kind)                                                                   \
  {                                                                                                \
#member, wire::FieldType::kind, wire::Container::None, 0, 0, offsetof(Sample, member),         \
      nullptr, nullptr, nullptr, nullptr, nullptr, nullptr                                         \
  }

const wire::FieldInfo kSampleFields[] = {
  R2V_SCALAR(flag, Bool),
  R2V_SCALAR(byte_value, Byte),
  R2V_SCALAR(small, Int8),
  R2V_SCALAR(u16, UInt16),
  R2V_SCALAR(f32, Float32),
  R2V_SCALAR(f64, Float64),
  { "text", wire::FieldType::String, wire::Container::None, 0, 5, offsetof(Sample, text), nullptr,
    nullptr, nullptr, nullptr, nullptr, nullptr },
  R2V_SCALAR(wide, WString),
  { "fixed", wire::FieldType::Float64, wire::Container::Array, 3, 0, offsetof(Sample, fixed),
    nullptr, &wire::container_size<std::array<double, 3>>,
    &wire::container_element<std::array<double, 3>>, &wire::array_resize<std::array<double, 3>>,
    nullptr, nullptr },
  { "bounded", wire::FieldType::Int64, wire::Container::BoundedSequence, 2, 0,
    offsetof(Sample, bounded), nullptr, &wire::container_size<std::vector<int64_t>>,
    &wire::container_element<std::vector<int64_t>>, &wire::vector_resize<std::vector<int64_t>>,
    nullptr, nullptr },
  { "flags", wire::FieldType::Bool, wire::Container::Sequence, 0, 0, offsetof(Sample, flags),
    nullptr, &wire::container_size<std::vector<bool>>, nullptr,
    &wire::vector_resize<std::vector<bool>>, &wire::container_get_bool<std::vector<bool>>,
    &wire::container_set_bool<std::vector<bool>> },
  { "bytes", wire::FieldType::Byte, wire::Container::Sequence, 0, 0, offsetof(Sample, bytes),
    nullptr, &wire::container_size<std::vector<uint8_t>>,
    &wire::container_element<std::vector<uint8_t>>, &wire::vector_resize<std::vector<uint8_t>>,
    nullptr, nullptr },
  { "inner", wire::FieldType::Message, wire::Container::None, 0, 0, offsetof(Sample, inner),
    &inner_type, nullptr, nullptr, nullptr, nullptr, nullptr },
  { "inners", wire::FieldType::Message, wire::Container::Sequence, 0, 0, offsetof(Sample, inners),
    &inner_type, &wire::container_size<std::vector<Inner>>,
    &wire::container_element<std::vector<Inner>>, &wire::vector_resize<std::vector<Inner>>, nullptr,
    nullptr },
  { "empty", wire::FieldType::Message, wire::Container::None, 0, 0, offsetof(Sample, empty),
    &nothing_type, nullptr, nullptr, nullptr, nullptr, nullptr },
};
#undef R2V_SCALAR

const wire::MessageTypeSupport& sample_type()
{
  static const wire::MessageTypeSupport type = table<Sample>(
    "test_msgs/msg/Sample", sizeof(kSampleFields) / sizeof(kSampleFields[0]), kSampleFields);
  return type;
}

} // namespace

#endif
