// MessageYaml against PyYAML: a hand-written type-support table with every field shape
// (the generated types have no wstring, bounded sequence or nested empty message), the
// scalar table that PyYAML itself wrote (tests/fixtures/yaml_scalars.json), and from_yaml's
// errors. Expected texts here were printed by PyYAML 6.0 (message_to_yaml's options), not by us.
#include "ros2vtk/wire/FieldAccess.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include "SampleType.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace wire = ros2vtk::wire;

Sample filled_sample()
{
  Sample s;
  s.flag = true;
  s.byte_value = 'A';
  s.small = -7;
  s.u16 = 65535;
  s.f32 = 0.1f;
  s.f64 = -1234.5678901234567;
  s.text = "a: b";
  s.wide = u"w\u00e9";
  s.fixed = { 1.0, 1e-05, 2.5e+16 };
  s.bounded = { INT64_MIN, 42 };
  s.flags = { true, false };
  s.bytes = { 0x00, 0x0A, 0x7F };
  s.inner = { -1, "" };
  s.inners = { { 1, "x" }, { 2, "it's" } };
  return s;
}

// yaml.dump(<the same value>, allow_unicode=True, width=sys.maxsize, default_flow_style=False)
const char* const kPyYamlText = "flag: true\nbyte_value: A\nsmall: -7\nu16: 65535\n"
                                "f32: 0.10000000149011612\nf64: -1234.5678901234567\n"
                                "text: 'a: b'\nwide: w\xc3\xa9\nfixed:\n- 1.0\n- 1.0e-05\n"
                                "- 2.5e+16\nbounded:\n- -9223372036854775808\n- 42\nflags:\n"
                                "- true\n- false\nbytes:\n- \"\\0\"\n- '\n\n  '\n- \"\\x7F\"\n"
                                "inner:\n  a: -1\n  s: ''\ninners:\n- a: 1\n  s: x\n- a: 2\n"
                                "  s: it's\nempty: {}\n";

TEST(MessageYaml, WritesWhatPyYamlWrites)
{
  const Sample sample = filled_sample();
  EXPECT_EQ(wire::to_yaml(sample_type(), &sample), kPyYamlText);
}

const wire::FieldInfo kDummyFields[] = {
  { "structure_needs_at_least_one_member", wire::FieldType::UInt8, wire::Container::None, 0, 0,
    offsetof(Nothing, structure_needs_at_least_one_member), nullptr, nullptr, nullptr, nullptr,
    nullptr, nullptr },
};

TEST(MessageYaml, EmptyMessageIsAnEmptyMapping)
{
  const Nothing nothing;
  EXPECT_EQ(wire::to_yaml(*nothing_type(), &nothing), "{}\n");
  // rosidl's dummy member of an empty message is hidden, as rosidl_runtime_py hides it.
  const wire::MessageTypeSupport with_dummy =
    table<Nothing>("test_msgs/msg/Dummy", 1, kDummyFields);
  EXPECT_EQ(wire::to_yaml(with_dummy, &nothing), "{}\n");
  Nothing read;
  std::string error;
  EXPECT_TRUE(wire::from_yaml(*nothing_type(), "{}\n", &read, &error)) << error;
}

TEST(MessageYaml, ReadsPyYamlTextBack)
{
  Sample read;
  std::string error;
  ASSERT_TRUE(wire::from_yaml(sample_type(), kPyYamlText, &read, &error)) << error;
  EXPECT_TRUE(read == filled_sample());
}

TEST(MessageYaml, MissingFieldsKeepDefaults)
{
  Sample read = filled_sample(); // from_yaml starts from a default message, not from this one
  std::string error;
  ASSERT_TRUE(wire::from_yaml(sample_type(), "small: 5\ninner: {s: hi}\n", &read, &error)) << error;
  Sample expected;
  expected.small = 5;
  expected.inner.s = "hi";
  EXPECT_TRUE(read == expected);
}

TEST(MessageYaml, BytesAcceptCharactersAndNumbers)
{
  Sample read;
  std::string error;
  ASSERT_TRUE(wire::from_yaml(
    sample_type(), "byte_value: 255\nbytes: [A, '7', 7, \"\\xFF\"]\n", &read, &error))
    << error;
  EXPECT_EQ(read.byte_value, 255);
  EXPECT_EQ(read.bytes, (std::vector<uint8_t>{ 'A', '7', 7, 0xFF }));
}

TEST(MessageYaml, StringsRoundTripThroughTheirYaml)
{
  // Blank multi-line strings are where yaml-cpp and PyYAML disagree; MessageYaml repairs it.
  for (const char* text : { "\n", "\n\n", " ", "", " \n ", "a\n", "\n\nb", "it's\n", "\t",
         "x:", "- y", "caf\xc3\xa9", "\x01", "null", "1.5" })
  {
    Sample sample;
    sample.inner.s = text;
    sample.inners = { { 3, text } };
    const std::string yaml = wire::to_yaml(sample_type(), &sample);
    Sample read;
    std::string error;
    ASSERT_TRUE(wire::from_yaml(sample_type(), yaml, &read, &error)) << error << "\n" << yaml;
    EXPECT_EQ(read.inner.s, text) << yaml;
    ASSERT_EQ(read.inners.size(), 1u);
    EXPECT_EQ(read.inners[0].s, text) << yaml;
  }
}

struct BadInput
{
  const char* yaml;
  const char* error_start; // the field path (and what) the error must begin with
};

class MessageYamlErrors : public ::testing::TestWithParam<BadInput>
{
};

TEST_P(MessageYamlErrors, NameTheFieldAndLeaveTheMessageAlone)
{
  Sample target = filled_sample();
  std::string error;
  EXPECT_FALSE(wire::from_yaml(sample_type(), GetParam().yaml, &target, &error));
  EXPECT_EQ(error.rfind(GetParam().error_start, 0), 0u) << "error was: " << error;
  EXPECT_TRUE(target == filled_sample());
}

INSTANTIATE_TEST_SUITE_P(Inputs, MessageYamlErrors,
  ::testing::Values(
    BadInput{ "nope: 1\n", "nope: unknown field of test_msgs/msg/Sample (fields: flag," },
    BadInput{ "inner:\n  b: 1\n", "inner.b: unknown field" },
    BadInput{ "inners:\n- a: 1\n- zz: 2\n", "inners[1].zz: unknown field" },
    BadInput{ "small: abc\n", "small: expected an integer (int8)" },
    BadInput{ "small: 128\n", "small: 128 is out of range for int8" },
    BadInput{ "small: -129\n", "small: -129 is out of range for int8" },
    BadInput{ "u16: -1\n", "u16: -1 is out of range for uint16" },
    BadInput{ "u16: 1.5\n", "u16: expected an integer" },
    BadInput{ "u16: '5'\n", "u16: expected an integer" },
    BadInput{
      "bounded: [1, 99999999999999999999]\n", "bounded[1]: 99999999999999999999 is out of range" },
    BadInput{ "f32: 1e39\n", "f32: 1e39 is out of range for float32" },
    BadInput{ "f64: 1e999\n", "f64: 1e999 is out of range for float64" },
    BadInput{ "f64: nan\n", "f64: expected a number (float64)" },
    BadInput{ "flag: maybe\n", "flag: expected true or false" },
    BadInput{ "flags: [true, 2]\n", "flags[1]: expected true or false" },
    BadInput{ "byte_value: 256\n", "byte_value: 256 is out of range for byte" },
    BadInput{ "byte_value: AB\n", "byte_value: expected a byte" },
    BadInput{ "text: abcdef\n", "text: string of 6 bytes exceeds its bound 5" },
    BadInput{ "text: [a]\n", "text: expected a string, got a sequence" },
    BadInput{ "fixed: [1, 2]\n", "fixed: expected exactly 3 elements, got 2" },
    BadInput{ "bounded: [1, 2, 3]\n", "bounded: at most 2 elements allowed, got 3" },
    BadInput{ "inners: 5\n", "inners: expected a sequence of message" },
    BadInput{ "inner: 5\n", "inner: expected a mapping for test_msgs/msg/Inner" },
    BadInput{ "- 1\n- 2\n", "<message>: expected a mapping for test_msgs/msg/Sample" },
    BadInput{ "flag: [unclosed\n", "invalid YAML" }, BadInput{ "a: b: c\n", "invalid YAML" }));

// PyYAML's own rendering of tricky scalars, written by tests/fixtures/make_cdr_fixtures.py.
TEST(MessageYaml, ScalarsMatchPyYamlTable)
{
  std::ifstream stream(ROS2VTK_FIXTURES_DIR "/yaml_scalars.json");
  ASSERT_TRUE(stream.good());
  const nlohmann::json table = nlohmann::json::parse(stream);
  ASSERT_GT(table.at("strings").size(), 60u);
  for (const auto& entry : table.at("strings"))
  {
    const std::string value = entry.at("value").get<std::string>();
    EXPECT_EQ(
      "k: " + wire::format_yaml_string(value, 2) + "\n", entry.at("yaml").get<std::string>())
      << "string " << nlohmann::json(value).dump();
  }
  ASSERT_GT(table.at("floats").size(), 20u);
  for (const auto& entry : table.at("floats"))
  {
    const double value = entry.at("value").get<double>();
    EXPECT_EQ("k: " + wire::format_yaml_float(value) + "\n", entry.at("yaml").get<std::string>())
      << "float " << entry.at("value").dump();
  }
}

TEST(MessageYaml, NonFiniteFloats)
{
  EXPECT_EQ(wire::format_yaml_float(std::numeric_limits<double>::quiet_NaN()), ".nan");
  EXPECT_EQ(wire::format_yaml_float(std::numeric_limits<double>::infinity()), ".inf");
  EXPECT_EQ(wire::format_yaml_float(-std::numeric_limits<double>::infinity()), "-.inf");
  Sample read;
  std::string error;
  ASSERT_TRUE(wire::from_yaml(sample_type(), "f64: -.inf\nf32: .nan\n", &read, &error)) << error;
  EXPECT_TRUE(std::isinf(read.f64) && read.f64 < 0);
  EXPECT_TRUE(std::isnan(read.f32));
}

} // namespace

// Issue 11.5: input-controlled depth and expansion. yaml-cpp bounds its own recursion (a depth
// guard); the reader bounds what aliases can expand to.
TEST(MessageYaml, DeeplyNestedYamlIsAnErrorNotACrash)
{
  Sample read = filled_sample();
  std::string error;
  for (const std::string open : { "[", "{a: ", "- " })
  {
    std::string yaml = "inners: ";
    for (int i = 0; i < 100000; ++i)
      yaml += open;
    error.clear();
    EXPECT_FALSE(wire::from_yaml(sample_type(), yaml, &read, &error)) << open;
    EXPECT_FALSE(error.empty());
  }
  EXPECT_EQ(read.text, "a: b"); // untouched
}

TEST(MessageYaml, AliasesCannotExpandBeyondTheText)
{
  std::string yaml = "inners: [{s: &t " + std::string(1000, 'x') + "}";
  for (int i = 0; i < 2000; ++i)
    yaml += ", {s: *t}";
  yaml += "]\n";
  Sample read;
  std::string error;
  EXPECT_FALSE(wire::from_yaml(sample_type(), yaml, &read, &error));
  EXPECT_NE(error.find("(aliases?)"), std::string::npos) << error;
  // A few aliases are fine.
  ASSERT_TRUE(wire::from_yaml(sample_type(), "inners: [{s: &t abc}, {s: *t}]\n", &read, &error))
    << error;
  ASSERT_EQ(read.inners.size(), 2u);
  EXPECT_EQ(read.inners[1].s, "abc");
}

TEST(MessageYaml, InvalidUtf8InStringsIsReplaced)
{
  Sample read;
  std::string error;
  ASSERT_TRUE(wire::from_yaml(sample_type(),
    "text: \"a\xff"
    "b\"\n",
    &read, &error))
    << error;
  EXPECT_EQ(read.text,
    "a\xEF\xBF\xBD"
    "b");
}
