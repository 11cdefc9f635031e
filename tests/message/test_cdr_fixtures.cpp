// Byte-exactness against rclpy: for every fixture of a type we ship, our deserializer reads
// rclpy's bytes, the value equals the one rclpy serialized (through its YAML, compared with the
// generated equality), to_yaml prints what `ros2 topic echo` prints, and our serializer writes
// exactly rclpy's bytes.
#include "Fixtures.hpp"

#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <set>

#include "ros2vtk/ros2vtkMessagesRegister.hpp" // ros2vtk_register_ros2vtkMessages_types()

namespace {

using ros2vtk::wire::MessageTypeSupport;
using ros2vtk_test::CdrFixture;

const std::vector<CdrFixture>& fixtures()
{
  static const std::vector<CdrFixture> all = ros2vtk_test::load_all_fixtures();
  return all;
}

struct Deleter
{
  const MessageTypeSupport* type;
  void operator()(void* message) const { type->destroy(message); }
};
using MessagePtr = std::unique_ptr<void, Deleter>;

MessagePtr make(const MessageTypeSupport& type)
{
  return MessagePtr(type.create(), Deleter{ &type });
}

std::string hex(const std::vector<uint8_t>& bytes)
{
  static const char digits[] = "0123456789abcdef";
  std::string text;
  for (uint8_t b : bytes)
  {
    text += digits[b >> 4];
    text += digits[b & 15];
  }
  return text;
}

class WheelVersions : public ::testing::Environment
{
public:
  void SetUp() override
  {
    ros2vtk_register_ros2vtkMessages_types();
    ASSERT_FALSE(fixtures().empty()) << "no fixtures in " ROS2VTK_FIXTURES_DIR "/cdr";
    std::cout << "[fixtures] " << fixtures().size() << " rclpy fixtures made with:";
    for (const auto& entry : fixtures().front().wheel_versions)
    {
      std::cout << " " << entry.first << "==" << entry.second;
    }
    std::cout << std::endl;
  }
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new WheelVersions);

class RclpyFixture : public ::testing::TestWithParam<size_t>
{
};

TEST_P(RclpyFixture, MatchesOurCdrAndYaml)
{
  const CdrFixture& fixture = fixtures().at(GetParam());
  const MessageTypeSupport* type = ros2vtk::wire::find_message_type(fixture.ros_type);
  ASSERT_NE(type, nullptr);
  SCOPED_TRACE(fixture.file);

  // 1. Our deserializer reads rclpy's bytes; only the trailing bytes the Python walk predicts
  //    (rmw's size estimate) are left over.
  MessagePtr decoded = make(*type);
  ros2vtk::wire::CdrReader reader(fixture.payload.data(), fixture.payload.size());
  ASSERT_TRUE(reader.ok() && type->deserialize(decoded.get(), reader) && reader.ok())
    << reader.error();
  EXPECT_EQ(reader.remaining(), fixture.trailing);

  // 2. The value is the one rclpy serialized: its YAML read back gives an equal message.
  MessagePtr from_yaml = make(*type);
  std::string error;
  ASSERT_TRUE(ros2vtk::wire::from_yaml(*type, fixture.yaml, from_yaml.get(), &error)) << error;
  EXPECT_TRUE(type->equal(decoded.get(), from_yaml.get()))
    << "decoded:\n"
    << ros2vtk::wire::to_yaml(*type, decoded.get()) << "from YAML:\n"
    << ros2vtk::wire::to_yaml(*type, from_yaml.get());

  // 3. We print it exactly as `ros2 topic echo` does.
  EXPECT_EQ(ros2vtk::wire::to_yaml(*type, decoded.get()), fixture.yaml);

  // 4. Our serializer writes rclpy's bytes (its padding zeroed, without the trailing bytes
  //    that only rmw's size estimate adds), and serialized_size() tells the truth.
  std::vector<uint8_t> expected(
    fixture.payload.begin(), fixture.payload.end() - static_cast<long>(fixture.trailing));
  std::vector<uint8_t> ours;
  ros2vtk::wire::serialize_message(*type, from_yaml.get(), ours);
  EXPECT_EQ(hex(ours), hex(expected));
  EXPECT_EQ(type->serialized_size(from_yaml.get()), ours.size());
}

std::string fixture_name(const ::testing::TestParamInfo<size_t>& info)
{
  std::string name = fixtures().at(info.param).file;
  name = name.substr(0, name.size() - 5); // ".json"
  for (char& c : name)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)))
    {
      c = '_';
    }
  }
  return name;
}

/// Fixtures of the types we ship (the fixture set also covers types of the same packages that
/// ros2vtk does not ship; CoverEveryShippedType lists those).
std::vector<size_t> fixture_indices()
{
  ros2vtk_register_ros2vtkMessages_types();
  std::vector<size_t> indices;
  for (size_t i = 0; i < fixtures().size(); ++i)
  {
    if (ros2vtk::wire::find_message_type(fixtures()[i].ros_type))
    {
      indices.push_back(i);
    }
  }
  return indices;
}

INSTANTIATE_TEST_SUITE_P(Rclpy, RclpyFixture, ::testing::ValuesIn(fixture_indices()), fixture_name);

// tf2_msgs has no wheel; the fixture script builds it (tests/fixtures/README.md), so every
// shipped type has rclpy bytes.
TEST(RclpyFixtures, CoverEveryShippedType)
{
  std::set<std::string> covered;
  std::set<std::string> not_shipped;
  for (const CdrFixture& fixture : fixtures())
  {
    covered.insert(fixture.ros_type);
    if (!ros2vtk::wire::find_message_type(fixture.ros_type))
    {
      not_shipped.insert(fixture.ros_type);
    }
  }
  std::cout << "[fixtures] " << not_shipped.size() << " fixture types are not shipped (unused):";
  for (const std::string& name : not_shipped)
  {
    std::cout << " " << name;
  }
  std::cout << std::endl;
  EXPECT_GE(fixture_indices().size(), 100u);
  for (const std::string& name : ros2vtk::wire::registered_message_types())
  {
    EXPECT_TRUE(covered.count(name))
      << name << " is shipped but has no rclpy fixture: add its package to PACKAGES in "
      << "tests/fixtures/make_cdr_fixtures.py (a package without a wheel: scripts/"
      << "make-rclpy-type.sh, see docs/extending.md) and run that script";
  }
}

} // namespace
