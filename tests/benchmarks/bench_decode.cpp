// bench_decode — decode time of one large message with the generated type support and with the
// same type built at run time from its REP 2011 type description (DynamicType, issue 13): what a
// subscriber to a type nobody shipped a spec for pays per message.
//
// The message is read from YAML (written by the driver, run_benchmarks.py), serialized once with
// the generated type, and the same CDR bytes are then decoded `count` times by each side,
// alternating so both see the same machine state. The runtime type is built the way a subscriber
// builds it: the generated type's description goes through type_description_interfaces (as the
// publisher's ~/get_type_description would answer) and build_dynamic_message_type. Both decoded
// messages are serialized again and compared with the input bytes before any time is taken.
//
//   bench_decode --type sensor_msgs/msg/PointCloud2 --yaml FILE [--count 200]
#include "BenchCommon.hpp"

#include "ros2vtk/ros2vtkMessagesRegister.hpp"
#include "ros2vtk/type_description_interfaces/msg/type_description.hpp"
#include "ros2vtk/wire/DynamicType.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"
#include "ros2vtk/wire/TypeDescriptionService.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace wire = ros2vtk::wire;

namespace {

using MessagePtr = std::unique_ptr<void, void (*)(void*)>;

MessagePtr make(const wire::MessageTypeSupport& type)
{
  return MessagePtr(type.create(), type.destroy);
}

int fail(const std::string& what)
{
  std::fprintf(stderr, "bench_decode: %s\n", what.c_str());
  return 1;
}

} // namespace

int main(int argc, char** argv)
{
  std::string ros_type, yaml_path;
  int count = 200;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if (arg == "--type")
      ros_type = argv[i + 1];
    else if (arg == "--yaml")
      yaml_path = argv[i + 1];
    else if (arg == "--count")
      count = std::atoi(argv[i + 1]);
  }
  std::ifstream file(yaml_path);
  if (ros_type.empty() || !file || count < 1)
  {
    std::fprintf(stderr, "usage: bench_decode --type PKG/msg/TYPE --yaml FILE [--count N]\n");
    return 2;
  }
  const std::string yaml((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());

  ros2vtk_register_ros2vtkMessages_types();
  const wire::MessageTypeSupport* generated = wire::find_message_type(ros_type);
  if (!generated || !generated->description)
    return fail("no generated type with a description: " + ros_type);

  // The runtime type, as a subscriber learns it from the publisher's type description service.
  ros2vtk::type_description_interfaces::msg::TypeDescription served;
  wire::to_message(*generated->description, served);
  std::string error;
  const auto started_build = bench::Clock::now();
  const wire::MessageTypeSupport* dynamic =
    wire::build_dynamic_message_type(wire::from_message(served), generated->type_hash, &error);
  const double build_ms = bench::ms_between(started_build, bench::Clock::now());
  if (!dynamic)
    return fail("runtime type not built: " + error);

  MessagePtr source = make(*generated);
  if (!wire::from_yaml(*generated, yaml, source.get(), &error))
    return fail("YAML not read: " + error);
  std::vector<uint8_t> bytes;
  wire::serialize_message(*generated, source.get(), bytes);

  // Both sides must decode the bytes to the same message before their times mean anything.
  for (const wire::MessageTypeSupport* type : { generated, dynamic })
  {
    MessagePtr decoded = make(*type);
    if (!wire::deserialize_message(*type, bytes.data(), bytes.size(), decoded.get(), &error))
      return fail(
        std::string(type == dynamic ? "runtime" : "generated") + " decode failed: " + error);
    std::vector<uint8_t> again;
    wire::serialize_message(*type, decoded.get(), again);
    if (again != bytes)
      return fail(
        std::string(type == dynamic ? "runtime" : "generated") + " decode does not round-trip");
  }

  std::vector<double> generated_ms, dynamic_ms;
  for (int i = 0; i < count; ++i)
  {
    for (const wire::MessageTypeSupport* type : { generated, dynamic })
    {
      MessagePtr decoded = make(*type); // a subscriber decodes into a fresh message per sample
      const auto start = bench::Clock::now();
      const bool ok =
        wire::deserialize_message(*type, bytes.data(), bytes.size(), decoded.get(), &error);
      const double ms = bench::ms_between(start, bench::Clock::now());
      if (!ok)
        return fail(error);
      (type == dynamic ? dynamic_ms : generated_ms).push_back(ms);
    }
  }
  bench::JsonObject()
    .text("type", ros_type)
    .number("bytes", static_cast<double>(bytes.size()))
    .number("count", count)
    .number("build_runtime_type_ms", build_ms)
    .numbers("generated_ms", generated_ms)
    .numbers("runtime_ms", dynamic_ms)
    .print();
  return 0;
}
