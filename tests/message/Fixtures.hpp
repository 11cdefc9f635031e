// Loads the rclpy fixtures of tests/fixtures/cdr (made by tests/fixtures/make_cdr_fixtures.py).
#ifndef ros2vtk_tests_message_Fixtures_hpp
#define ros2vtk_tests_message_Fixtures_hpp

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ros2vtk_test {

/// One serialized sample as rclpy wrote it.
struct CdrFixture
{
  std::string file;             ///< "sensor_msgs__Image__2.json"
  std::string ros_type;         ///< "sensor_msgs/msg/Image"
  std::vector<uint8_t> payload; ///< header included; padding zeroed by the script
  std::vector<size_t> padding;  ///< offsets rclpy left uninitialised (zeroed here)
  size_t trailing = 0;          ///< bytes after the last field (rmw's size estimate)
  std::string yaml;             ///< as `ros2 topic echo` prints it
  std::map<std::string, std::string> wheel_versions;
};

inline std::vector<uint8_t> decode_hex(const std::string& hex)
{
  if (hex.size() % 2 != 0)
  {
    throw std::runtime_error("odd hex length");
  }
  std::vector<uint8_t> bytes(hex.size() / 2);
  for (size_t i = 0; i < bytes.size(); ++i)
  {
    bytes[i] = static_cast<uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
  }
  return bytes;
}

inline CdrFixture load_fixture(const std::filesystem::path& path)
{
  std::ifstream stream(path);
  const nlohmann::json document = nlohmann::json::parse(stream);
  CdrFixture fixture;
  fixture.file = path.filename().string();
  fixture.ros_type = document.at("ros_type").get<std::string>();
  fixture.payload = decode_hex(document.at("hex").get<std::string>());
  fixture.padding = document.at("padding").get<std::vector<size_t>>();
  fixture.trailing = document.at("trailing").get<size_t>();
  fixture.yaml = document.at("yaml").get<std::string>();
  fixture.wheel_versions = document.at("wheel_versions").get<std::map<std::string, std::string>>();
  return fixture;
}

/// Every fixture, sorted by file name (a stable test order).
inline std::vector<CdrFixture> load_all_fixtures()
{
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(ROS2VTK_FIXTURES_DIR "/cdr"))
  {
    if (entry.path().extension() == ".json")
    {
      paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  std::vector<CdrFixture> fixtures;
  for (const auto& path : paths)
  {
    fixtures.push_back(load_fixture(path));
  }
  return fixtures;
}

} // namespace ros2vtk_test

#endif
