// Hostile bytes for every shipped type: random buffers and mutations of rclpy's fixture bytes
// (truncation at every length, every bit flipped, huge sequence/string lengths, bool bytes >= 2,
// bad encapsulation). Deserialization must answer true or false; this target is built with
// AddressSanitizer + UBSan (ROS2VTK_ENABLE_ASAN) over the generated deserializers themselves,
// and ASAN_OPTIONS caps single allocations, so an out-of-bounds access or a giant allocation
// fails the test. Fixed seed, bounded iteration counts.
#include "Fixtures.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <map>
#include <memory>
#include <random>

namespace {

using ros2vtk::wire::MessageTypeSupport;

struct Outcome
{
  size_t accepted = 0;
  size_t rejected = 0;
};

/// Deserializes one buffer into a fresh message. When accepted, the message must serialize
/// and read back again (a decoded value is always a valid value).
void exercise(const MessageTypeSupport& type, const std::vector<uint8_t>& bytes, Outcome& outcome)
{
  void* message = type.create();
  std::string error;
  const bool ok =
    ros2vtk::wire::deserialize_message(type, bytes.data(), bytes.size(), message, &error);
  if (ok)
  {
    ++outcome.accepted;
    std::vector<uint8_t> again;
    ros2vtk::wire::serialize_message(type, message, again);
    void* copy = type.create();
    EXPECT_TRUE(ros2vtk::wire::deserialize_message(type, again.data(), again.size(), copy, &error))
      << type.ros_type << ": our own bytes of an accepted sample are rejected: " << error;
    type.destroy(copy);
  }
  else
  {
    ++outcome.rejected;
    EXPECT_FALSE(error.empty()) << type.ros_type << ": rejected without a reason";
  }
  type.destroy(message);
}

std::map<std::string, std::vector<std::vector<uint8_t>>> fixture_payloads()
{
  std::map<std::string, std::vector<std::vector<uint8_t>>> payloads;
  for (const auto& fixture : ros2vtk_test::load_all_fixtures())
  {
    payloads[fixture.ros_type].push_back(fixture.payload);
  }
  return payloads;
}

class CdrFuzz : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { payloads_ = fixture_payloads(); }
  static std::map<std::string, std::vector<std::vector<uint8_t>>> payloads_;
  std::mt19937 random_{ 20240611u };
};
std::map<std::string, std::vector<std::vector<uint8_t>>> CdrFuzz::payloads_;

std::vector<const MessageTypeSupport*> shipped_types()
{
  std::vector<const MessageTypeSupport*> types;
  for (const std::string& name : ros2vtk::wire::registered_message_types())
  {
    types.push_back(ros2vtk::wire::find_message_type(name));
  }
  return types;
}

TEST_F(CdrFuzz, RegistryHoldsTheShippedTypes)
{
  // Guards the other tests against passing vacuously over an empty registry.
  EXPECT_GE(shipped_types().size(), 14u);
  EXPECT_NE(ros2vtk::wire::find_message_type("sensor_msgs/msg/Image"), nullptr);
}

TEST_F(CdrFuzz, RandomBuffers)
{
  for (const MessageTypeSupport* type : shipped_types())
  {
    Outcome outcome;
    for (int i = 0; i < 300; ++i)
    {
      std::vector<uint8_t> bytes(random_() % 96);
      for (auto& b : bytes)
      {
        b = static_cast<uint8_t>(random_());
      }
      if (i % 2 == 0 && bytes.size() >= 4)
      {
        const uint8_t header[4] = { 0, 1, 0, 0 }; // valid header, random body
        std::memcpy(bytes.data(), header, 4);
      }
      exercise(*type, bytes, outcome);
    }
    EXPECT_EQ(outcome.accepted + outcome.rejected, 300u);
  }
}

TEST_F(CdrFuzz, TruncationAtEveryLength)
{
  size_t checked = 0;
  for (const MessageTypeSupport* type : shipped_types())
  {
    for (const auto& payload : payloads_[type->ros_type])
    {
      // The body needs every byte up to its last field: any shorter prefix must be refused,
      // except where only trailing padding/estimate bytes are cut.
      void* full = type->create();
      std::string error;
      ASSERT_TRUE(
        ros2vtk::wire::deserialize_message(*type, payload.data(), payload.size(), full, &error))
        << type->ros_type << ": " << error;
      std::vector<uint8_t> exact;
      ros2vtk::wire::serialize_message(*type, full, exact);
      type->destroy(full);
      for (size_t length = 0; length < payload.size(); ++length)
      {
        std::vector<uint8_t> cut(payload.begin(), payload.begin() + static_cast<long>(length));
        Outcome outcome;
        exercise(*type, cut, outcome);
        if (length < exact.size())
        {
          EXPECT_EQ(outcome.rejected, 1u)
            << type->ros_type << " accepted a payload cut to " << length << " of " << exact.size();
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000u);
}

TEST_F(CdrFuzz, EveryBitFlipped)
{
  for (const MessageTypeSupport* type : shipped_types())
  {
    for (const auto& payload : payloads_[type->ros_type])
    {
      Outcome outcome;
      const size_t bits = payload.size() * 8;
      const size_t step = bits > 2048 ? bits / 2048 : 1; // bounded for big payloads
      for (size_t bit = 0; bit < bits; bit += step)
      {
        std::vector<uint8_t> flipped = payload;
        flipped[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
        exercise(*type, flipped, outcome);
      }
      // Flipping a header bit (e.g. 00 01 -> 00 03) must be refused at least somewhere.
      EXPECT_GT(outcome.rejected, 0u) << type->ros_type;
    }
  }
}

TEST_F(CdrFuzz, HugeLengthsAndBoolBytes)
{
  const uint32_t huge[] = { 0xFFFFFFFFu, 0x80000000u, 0x7FFFFFFFu, 0x10000000u, 0x00100000u };
  for (const MessageTypeSupport* type : shipped_types())
  {
    for (const auto& payload : payloads_[type->ros_type])
    {
      Outcome outcome;
      // Any 4-aligned word of the body may be a length: make each one huge in turn (every one
      // up to 512 words; a spread of 512 in bigger payloads, whose fields repeat: the cost is
      // quadratic in the size, and test_msgs/MultiNested is 2.8 KB).
      const size_t words = payload.size() / 4;
      const size_t word_step = words > 512 ? words / 512 : 1;
      for (size_t offset = 4; offset + 4 <= payload.size(); offset += 4 * word_step)
      {
        for (uint32_t length : huge)
        {
          std::vector<uint8_t> mutated = payload;
          std::memcpy(mutated.data() + offset, &length, 4); // little endian host, LE payload
          exercise(*type, mutated, outcome);
        }
      }
      // Any byte may be a bool: 2 and 0xFF are not bools (bounded as above).
      const size_t byte_step = payload.size() > 1024 ? payload.size() / 1024 : 1;
      for (size_t offset = 4; offset < payload.size(); offset += byte_step)
      {
        for (uint8_t value : { uint8_t(2), uint8_t(0xFF) })
        {
          std::vector<uint8_t> mutated = payload;
          mutated[offset] = value;
          exercise(*type, mutated, outcome);
        }
      }
    }
  }
}

TEST_F(CdrFuzz, BadEncapsulationIsRefused)
{
  const uint8_t bad_headers[][4] = { { 0, 2, 0, 0 }, { 0, 3, 0, 0 }, { 1, 1, 0, 0 }, { 0, 6, 0, 0 },
    { 0xFF, 0xFF, 0, 0 } };
  for (const MessageTypeSupport* type : shipped_types())
  {
    for (const auto& payload : payloads_[type->ros_type])
    {
      for (const auto& header : bad_headers)
      {
        std::vector<uint8_t> mutated = payload;
        std::memcpy(mutated.data(), header, 4);
        Outcome outcome;
        exercise(*type, mutated, outcome);
        EXPECT_EQ(outcome.rejected, 1u) << type->ros_type;
      }
      // Big-endian header over little-endian data: must not crash (true or false both fine).
      std::vector<uint8_t> big_endian = payload;
      big_endian[1] = 0;
      Outcome outcome;
      exercise(*type, big_endian, outcome);
    }
  }
}

TEST_F(CdrFuzz, RandomMutationsOfFixtures)
{
  for (const MessageTypeSupport* type : shipped_types())
  {
    for (const auto& payload : payloads_[type->ros_type])
    {
      Outcome outcome;
      for (int i = 0; i < 200; ++i)
      {
        std::vector<uint8_t> mutated = payload;
        const int edits = 1 + static_cast<int>(random_() % 4);
        for (int e = 0; e < edits && mutated.size() > 4; ++e)
        {
          const size_t at = 4 + random_() % (mutated.size() - 4);
          switch (random_() % 3)
          {
            case 0:
              mutated[at] = static_cast<uint8_t>(random_());
              break;
            case 1:
              mutated.erase(mutated.begin() + static_cast<long>(at));
              break;
            default:
              mutated.insert(
                mutated.begin() + static_cast<long>(at), static_cast<uint8_t>(random_()));
              break;
          }
        }
        exercise(*type, mutated, outcome);
      }
    }
  }
}

} // namespace
