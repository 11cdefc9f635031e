// The invalid-UTF-8 policy (Utf8.hpp): each maximal invalid subpart becomes one U+FFFD, as
// Python's "replace" decoding does (the expected strings are what CPython 3.11 prints for
// bytes.decode('utf-8', 'replace')), and strings read from CDR go through it.
#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/Utf8.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace ros2vtk::wire;

namespace {

const std::string kReplacement = "\xEF\xBF\xBD";

std::string repaired(std::string text, size_t expected_count)
{
  EXPECT_EQ(repair_utf8(text), expected_count);
  return text;
}

TEST(Utf8, InvalidSequencesBecomeOneReplacementEachLikePython)
{
  EXPECT_EQ(repaired("a\xff"
                     "b",
              1),
    "a" + kReplacement + "b");
  EXPECT_EQ(repaired("\xe2\x82", 1), kReplacement);                                   // truncated
  EXPECT_EQ(repaired("\xed\xa0\x80", 3), kReplacement + kReplacement + kReplacement); // surrogate
  EXPECT_EQ(repaired("\xf0\x9f\x98", 1), kReplacement);
  EXPECT_EQ(repaired("\xc0\xaf", 2), kReplacement + kReplacement); // overlong
  EXPECT_EQ(repaired("\xf0\x9f\x98\x80x\xe2\x82\xac", 0), "\xf0\x9f\x98\x80x\xe2\x82\xac");
  EXPECT_EQ(repaired(std::string("a\0b", 3), 0), std::string("a\0b", 3));
}

TEST(Utf8, ClippedTextKeepsWholeCharacters)
{
  EXPECT_EQ(clip_for_message("short"), "short");
  std::string text = "ab";
  for (int i = 0; i < 100; ++i)
    text += "\xe2\x82\xac"; // 3 bytes each
  const std::string clipped = clip_for_message(text, 10);
  EXPECT_EQ(clipped, "ab\xe2\x82\xac\xe2\x82\xac... (302 bytes)");
  std::string copy = clipped;
  EXPECT_EQ(repair_utf8(copy), 0u);
}

TEST(Utf8, StringsReadFromCdrAreRepairedAndCounted)
{
  // CDR_LE header, length 4, 'a' 0xff 'b' NUL: what an rclcpp peer may put in a std::string.
  const std::vector<uint8_t> payload{ 0x00, 0x01, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 'a', 0xff,
    'b', 0x00 };
  const uint64_t before = invalid_utf8_replacements();
  CdrReader reader(payload.data(), payload.size());
  std::string value;
  ASSERT_TRUE(reader.read_string(value));
  EXPECT_EQ(value, "a" + kReplacement + "b");
  EXPECT_EQ(reader.invalid_utf8_replaced(), 1u);
  EXPECT_EQ(invalid_utf8_replacements(), before + 1);
}

} // namespace
