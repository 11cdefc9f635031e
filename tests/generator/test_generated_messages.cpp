// Compiled fixture specs (msg_specs/fixtures/ros2vtk_test_msgs) and shipped types: round trips
// through the type-support tables, and byte layouts worked out by hand from the CDR rules of
// docs/wire-notes.md §7 (or copied from its §7.10 dumps made with Fast CDR), never from
// our own serializer.
#include "ros2vtk/geometry_msgs/msg/transform_stamped.hpp"
#include "ros2vtk/rmw_dds_common/msg/participant_entities_info.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/arrays.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/bounded_sequences.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/constants.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/defaults.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/empty.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/inner.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/nested.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/primitives.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/strings.hpp"
#include "ros2vtk/ros2vtk_test_msgs/msg/unbounded_sequences.hpp"
#include "ros2vtk/ros2vtk_test_msgs/srv/echo.hpp"
#include "ros2vtk/sensor_msgs/msg/joint_state.hpp"
#include "ros2vtk/std_msgs/msg/string.hpp"

#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/CdrWriter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "ros2vtk/ros2vtkTestMessagesRegister.hpp" // ros2vtk_register_ros2vtkTestMessages_types()

namespace {

namespace wire = ros2vtk::wire;
namespace test_msgs = ros2vtk::ros2vtk_test_msgs::msg;
using Bytes = std::vector<uint8_t>;

template<typename T>
Bytes serialize(const T& message)
{
  Bytes buffer;
  wire::serialize_message(T::type_support(), &message, buffer);
  return buffer;
}

template<typename T>
bool deserialize(const Bytes& bytes, T& message, std::string* error = nullptr)
{
  return wire::deserialize_message(T::type_support(), bytes.data(), bytes.size(), &message, error);
}

// Serializes, checks the size function agrees with the bytes, reads back, compares.
template<typename T>
void expect_round_trip(const T& message)
{
  const Bytes bytes = serialize(message);
  EXPECT_EQ(bytes.size(), T::type_support().serialized_size(&message));
  T back;
  std::string error;
  ASSERT_TRUE(deserialize(bytes, back, &error)) << error;
  EXPECT_TRUE(back == message);
  EXPECT_TRUE(T::type_support().equal(&back, &message));
}

test_msgs::Inner make_inner(uint8_t tag)
{
  test_msgs::Inner inner;
  inner.tag = tag;
  inner.value = 0.25 * tag;
  inner.label = "inner" + std::to_string(tag);
  return inner;
}

test_msgs::Nested make_nested(uint8_t tag)
{
  test_msgs::Nested nested;
  nested.stamp.sec = -tag;
  nested.stamp.nanosec = 1000u * tag;
  nested.inner = make_inner(tag);
  return nested;
}

TEST(GeneratedMessages, PrimitivesMatchHandDerivedBytes)
{
  test_msgs::Primitives m;
  m.bool_value = true;
  m.byte_value = 0xab;
  m.char_value = 0x41;
  m.float32_value = 1.0f;
  m.float64_value = -2.0;
  m.int8_value = -1;
  m.uint8_value = 200;
  m.int16_value = -2;
  m.uint16_value = 0x1234;
  m.int32_value = -3;
  m.uint32_value = 0xdeadbeef;
  m.int64_value = -4;
  m.uint64_value = 0x0102030405060708ULL;
  m.string_value = "ab";
  // Body offsets: 0 bool, 1 byte, 2 char, 3 pad, 4 float32, 8 float64, 16 int8, 17 uint8,
  // 18 int16, 20 uint16, 22..23 pad, 24 int32, 28 uint32, 32 int64, 40 uint64, 48 string.
  const Bytes expected = {
    0x00, 0x01, 0x00, 0x00,                         // encapsulation CDR_LE
    0x01, 0xab, 0x41, 0x00, 0x00, 0x00, 0x80, 0x3f, // bool byte char pad float32 1.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xc0, // float64 -2.0
    0xff, 0xc8, 0xfe, 0xff, 0x34, 0x12, 0x00, 0x00, // int8 uint8 int16 uint16 pad
    0xfd, 0xff, 0xff, 0xff, 0xef, 0xbe, 0xad, 0xde, // int32 -3, uint32
    0xfc, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, // int64 -4
    0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01, // uint64
    0x03, 0x00, 0x00, 0x00, 0x61, 0x62, 0x00,       // string "ab" with NUL
  };
  EXPECT_EQ(serialize(m), expected);
  expect_round_trip(m);
}

TEST(GeneratedMessages, EmptySequencesHaveNoPaddingAndDoublesAlignTo8)
{
  test_msgs::UnboundedSequences m;
  m.bool_values = { true, false };
  m.float64_values = { 1.5 };
  const Bytes expected = {
    0x00, 0x01, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00,
    0x00,                                           // bool[2], then pad to 4
    0x00, 0x00, 0x00, 0x00,                         // byte[] empty
    0x00, 0x00, 0x00, 0x00,                         // uint8[] empty
    0x00, 0x00, 0x00, 0x00,                         // int16[] empty
    0x00, 0x00, 0x00, 0x00,                         // float32[] empty
    0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, // float64[1] count at 24, pad to 32
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf8, 0x3f, // 1.5
    0x00, 0x00, 0x00, 0x00,                         // int64[] empty
    0x00, 0x00, 0x00, 0x00,                         // string[] empty
    0x00, 0x00, 0x00, 0x00,                         // Nested[] empty
  };
  EXPECT_EQ(serialize(m), expected);
  expect_round_trip(m);
}

TEST(GeneratedMessages, EmptyMessageIsOneZeroByte)
{
  EXPECT_EQ(serialize(test_msgs::Empty{}), (Bytes{ 0x00, 0x01, 0x00, 0x00, 0x00 }));
  expect_round_trip(test_msgs::Empty{});
  EXPECT_EQ(test_msgs::Empty::type_support().field_count, 1u);
}

TEST(GeneratedMessages, NestedMembersAlignRelativeToTheBody)
{
  test_msgs::Inner inner;
  inner.tag = 7;
  inner.value = 0.5;
  const Bytes expected = {
    0x00, 0x01, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, // tag, pad to 8
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xe0, 0x3f,                         // 0.5
    0x01, 0x00, 0x00, 0x00, 0x00,                                           // ""
  };
  EXPECT_EQ(serialize(inner), expected);
}

TEST(GeneratedMessages, ShippedTypesMatchFastCdrDumps)
{
  // WIRE_NOTES §7.10: std_msgs/String "hi" and TransformStamped, produced with libfastcdr.
  ros2vtk::std_msgs::msg::String text;
  text.data = "hi";
  EXPECT_EQ(
    serialize(text), (Bytes{ 0x00, 0x01, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x68, 0x69, 0x00 }));

  ros2vtk::geometry_msgs::msg::TransformStamped t;
  t.header.stamp.sec = 1;
  t.header.stamp.nanosec = 2;
  t.header.frame_id = "world";
  t.child_frame_id = "base";
  t.transform.translation.x = 1;
  t.transform.translation.y = 2;
  t.transform.translation.z = 3;
  const Bytes bytes = serialize(t);
  ASSERT_EQ(bytes.size(), 92u);
  const Bytes head = { 0x00, 0x01, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x06,
    0x00, 0x00, 0x00, 0x77, 0x6f, 0x72, 0x6c, 0x64, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x62,
    0x61, 0x73, 0x65, 0x00, 0x00, 0x00, 0x00 };
  EXPECT_EQ(Bytes(bytes.begin(), bytes.begin() + 36), head);
  double qw = 0;
  std::memcpy(&qw, bytes.data() + 84, 8); // body offset 80
  EXPECT_EQ(qw, 1.0);                     // Quaternion default w = 1 from the spec
  expect_round_trip(t);

  ros2vtk::sensor_msgs::msg::JointState joints;
  joints.name = { "j1" };
  joints.position = { 0.5 };
  const Bytes joint_bytes = {
    0x00,
    0x01,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x01,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x01,
    0x00,
    0x00,
    0x00,
    0x03,
    0x00,
    0x00,
    0x00,
    0x6a,
    0x31,
    0x00,
    0x00,
    0x01,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0xe0,
    0x3f,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
    0x00,
  };
  EXPECT_EQ(serialize(joints), joint_bytes);
}

TEST(GeneratedMessages, GidIsSixteenRawBytes)
{
  ros2vtk::rmw_dds_common::msg::ParticipantEntitiesInfo info;
  for (uint8_t i = 0; i < 16; ++i)
  {
    info.gid.data[i] = static_cast<uint8_t>(0xa0 + i);
  }
  const Bytes bytes = serialize(info);
  ASSERT_EQ(bytes.size(), 4u + 16u + 4u);
  EXPECT_EQ(bytes[4], 0xa0);
  EXPECT_EQ(bytes[19], 0xaf);
  expect_round_trip(info);
}

TEST(GeneratedMessages, EveryFixtureRoundTrips)
{
  test_msgs::Arrays arrays;
  arrays.bool_values = { { true, false, true } };
  arrays.byte_values = { { 1, 2, 3 } };
  arrays.char_values = { { 'a', 'b', 'c' } };
  arrays.int16_values = { { -1, 300 } };
  arrays.float64_values = { { 1.0, -2.5, 3.25 } };
  arrays.uint64_values = { { 1ULL << 40, 7 } };
  arrays.string_values = { { "one", "" } };
  arrays.nested_values = { { make_nested(1), make_nested(2) } };
  expect_round_trip(arrays);

  test_msgs::BoundedSequences bounded;
  bounded.bool_values = { true, true };
  bounded.uint8_values = { 9, 8, 7, 6 };
  bounded.int32_values = { -5 };
  bounded.float64_values = { 0.125, 8.0 };
  bounded.string_values = { "a", "bb" };
  bounded.nested_values = { make_nested(3) };
  expect_round_trip(bounded);

  test_msgs::UnboundedSequences unbounded;
  unbounded.bool_values = { false, true, true };
  unbounded.byte_values = { 0, 255 };
  unbounded.uint8_values = { 1 };
  unbounded.int16_values = { -300, 300 };
  unbounded.float32_values = { 0.5f };
  unbounded.float64_values = { -1.0, 2.0 };
  unbounded.int64_values = { -(1LL << 50) };
  unbounded.string_values = { "x", "yy", "" };
  unbounded.nested_values = { make_nested(4), make_nested(5) };
  expect_round_trip(unbounded);

  test_msgs::Strings strings;
  strings.plain = "plain text";
  strings.bounded = "12345";
  strings.bounded_array = { { "abc", "d" } };
  strings.bounded_in_bounded_sequence = { "wxyz" };
  strings.bounded_in_sequence = { "ab", "c", "" };
  strings.wide = u"w\u00e9";
  expect_round_trip(strings);

  test_msgs::Constants constants;
  constants.value = -42;
  expect_round_trip(constants);
  expect_round_trip(test_msgs::Defaults{});
  expect_round_trip(make_nested(6));
  expect_round_trip(make_inner(7));

  test_msgs::Primitives primitives;
  primitives.uint64_value = ~0ULL;
  primitives.string_value = "tail";
  expect_round_trip(primitives);

  ros2vtk::ros2vtk_test_msgs::srv::Echo_Request request;
  request.mode = ros2vtk::ros2vtk_test_msgs::srv::Echo_Request::MODE_ECHO;
  request.text = "hello";
  expect_round_trip(request);
  ros2vtk::ros2vtk_test_msgs::srv::Echo_Response response;
  response.reply = make_inner(8);
  response.ok = true;
  expect_round_trip(response);
}

TEST(GeneratedMessages, DefaultsAndConstantsComeFromTheSpec)
{
  const test_msgs::Defaults d;
  EXPECT_TRUE(d.flag);
  EXPECT_EQ(d.small, -5);
  EXPECT_EQ(d.medium, 1000);
  EXPECT_EQ(d.big, -9000000000LL);
  EXPECT_EQ(d.ratio, 0.25f);
  EXPECT_EQ(d.scale, 1000.0);
  EXPECT_EQ(d.name, "a \"quoted\" name");
  EXPECT_EQ(d.bare, "word");
  EXPECT_EQ(d.short_name, "robot");
  EXPECT_EQ(d.triple, (std::array<int32_t, 3>{ { 1, 2, 3 } }));
  EXPECT_EQ(d.weights, (std::vector<double>{ 0.5, -1.5 }));
  EXPECT_EQ(d.switches, (std::vector<bool>{ true, false }));
  EXPECT_EQ(d.labels[1], "y");

  EXPECT_EQ(test_msgs::Constants::LOWEST_INT64, -9223372036854775807LL - 1);
  EXPECT_EQ(test_msgs::Constants::TOP_UINT64, 18446744073709551615ULL);
  EXPECT_EQ(test_msgs::Constants::LOWEST_INT32, -2147483647 - 1);
  EXPECT_EQ(std::string(test_msgs::Constants::GREETING), "hello");
  EXPECT_EQ(std::string(test_msgs::Constants::QUOTED), "say \"hi\"");
  EXPECT_EQ(test_msgs::Constants::CHAR_A, 65);
  const wire::MessageTypeSupport& type = test_msgs::Constants::type_support();
  ASSERT_EQ(type.constant_count, 15u);
  EXPECT_STREQ(type.constants[0].name, "FLAG");
  EXPECT_STREQ(type.constants[0].value, "true");
  ASSERT_EQ(type.field_count, 1u); // constants are not fields
}

TEST(GeneratedMessages, HostileBytesAreRejectedNotAllocated)
{
  test_msgs::UnboundedSequences m;
  std::string error;
  // bool[] claims 0xffffffff elements in a 4-byte body.
  EXPECT_FALSE(deserialize(Bytes{ 0x00, 0x01, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff }, m, &error));
  EXPECT_NE(error.find("exceeds"), std::string::npos) << error;

  // Nested[] of 3 elements needs at least 3 * (4+4+1+8+4) bytes; offer a handful.
  // Eight empty sequences, then nested_values claims 3 elements with no byte left.
  Bytes few(4 + 36, 0);
  few[1] = 0x01;
  few[4 + 32] = 3;
  EXPECT_FALSE(deserialize(few, m, &error));
  EXPECT_NE(error.find("exceeds"), std::string::npos) << error;

  test_msgs::Primitives p;
  Bytes truncated = serialize(p);
  truncated.resize(truncated.size() - 2);
  EXPECT_FALSE(deserialize(truncated, p, &error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
}

TEST(GeneratedMessages, BoundsAreEnforcedOnReadAndWrite)
{
  // BoundedSequences whose bool[<=3] claims 4 elements.
  test_msgs::BoundedSequences m;
  std::string error;
  EXPECT_FALSE(
    deserialize(Bytes{ 0x00, 0x01, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 1, 1, 1, 1 }, m, &error));
  EXPECT_NE(error.find("bound"), std::string::npos) << error;

  // Strings whose string<=5 carries 6 characters: "" then "abcdef".
  const Bytes long_string = { 0x00, 0x01, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x07, 0x00, 0x00, 0x00, 'a', 'b', 'c', 'd', 'e', 'f', 0x00 };
  test_msgs::Strings s;
  EXPECT_FALSE(deserialize(long_string, s, &error));
  EXPECT_NE(error.find("bound"), std::string::npos) << error;

  // The writer cannot fail: an over-long bounded sequence is written truncated to its bound.
  m.uint8_values = { 1, 2, 3, 4, 5, 6 };
  const Bytes bytes = serialize(m);
  EXPECT_EQ(bytes.size(), test_msgs::BoundedSequences::type_support().serialized_size(&m));
  test_msgs::BoundedSequences back;
  ASSERT_TRUE(deserialize(bytes, back, &error)) << error;
  EXPECT_EQ(back.uint8_values, (std::vector<uint8_t>{ 1, 2, 3, 4 }));
}

TEST(GeneratedMessages, TablesDescribeNamesHashesAndFields)
{
  ros2vtk_register_ros2vtkTestMessages_types();
  const wire::MessageTypeSupport* type = wire::find_message_type("ros2vtk_test_msgs/Arrays");
  ASSERT_NE(type, nullptr);
  EXPECT_STREQ(type->dds_type_name, "ros2vtk_test_msgs::msg::dds_::Arrays_");
  EXPECT_EQ(std::string(type->type_hash).rfind("RIHS01_", 0), 0u);
  EXPECT_EQ(std::strlen(type->type_hash), 71u);
  // Registering the fixtures registers their dependency (the shipped types) too.
  ASSERT_NE(wire::find_message_type("std_msgs/msg/Header"), nullptr);
  EXPECT_STREQ(wire::find_message_type("std_msgs/msg/Header")->type_hash,
    "RIHS01_f49fb3ae2cf070f793645ff749683ac6b06203e41c891e17701b1cb597ce6a01");

  const wire::ServiceTypeSupport* echo = wire::find_service_type("ros2vtk_test_msgs/srv/Echo");
  ASSERT_NE(echo, nullptr);
  EXPECT_STREQ(echo->request()->dds_type_name, "ros2vtk_test_msgs::srv::dds_::Echo_Request_");
  EXPECT_STREQ(echo->response()->ros_type, "ros2vtk_test_msgs/srv/Echo_Response");

  // Introspection: write through the field table, read through the struct.
  test_msgs::Arrays arrays;
  ASSERT_EQ(type->field_count, 8u);
  const wire::FieldInfo& bools = type->fields[0];
  EXPECT_STREQ(bools.name, "bool_values");
  EXPECT_EQ(bools.container, wire::Container::Array);
  EXPECT_EQ(bools.array_size, 3u);
  void* bools_member = reinterpret_cast<char*>(&arrays) + bools.offset;
  bools.set_bool(bools_member, 1, true);
  EXPECT_TRUE(arrays.bool_values[1]);
  EXPECT_FALSE(bools.resize(bools_member, 4));

  const wire::FieldInfo& nested = type->fields[7];
  EXPECT_EQ(nested.type, wire::FieldType::Message);
  EXPECT_EQ(nested.nested(), &test_msgs::Nested::type_support());
  void* element = nested.element(reinterpret_cast<char*>(&arrays) + nested.offset, 1);
  EXPECT_EQ(element, &arrays.nested_values[1]);

  const wire::MessageTypeSupport& sequences = test_msgs::UnboundedSequences::type_support();
  test_msgs::UnboundedSequences u;
  const wire::FieldInfo& bool_sequence = sequences.fields[0];
  EXPECT_EQ(bool_sequence.element, nullptr); // std::vector<bool> has no addressable elements
  void* member = reinterpret_cast<char*>(&u) + bool_sequence.offset;
  ASSERT_TRUE(bool_sequence.resize(member, 2));
  bool_sequence.set_bool(member, 1, true);
  EXPECT_EQ(u.bool_values, (std::vector<bool>{ false, true }));

  const wire::FieldInfo& bounded = test_msgs::Strings::type_support().fields[1];
  EXPECT_EQ(bounded.string_bound, 5u);
}

} // namespace
