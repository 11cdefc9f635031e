// The REP 2011 type description lookup of a node (NodeTypeCache + the request handler behind
// ~/get_type_description), without DDS. Expected values are rosidl's: the hashes and the
// descriptions of share/<pkg>/{msg,srv}/<Type>.json in the ROS 2 Kilted wheels, and rcl's
// failure reasons (rcl_node_type_description_service_handle_request).
#include "ros2vtk/geometry_msgs/msg/pose_stamped.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/std_msgs/msg/string.hpp"
#include "ros2vtk/std_srvs/srv/set_bool.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"
#include "ros2vtk/wire/ParameterStore.hpp"
#include "ros2vtk/wire/TypeDescriptionService.hpp"

#include <gtest/gtest.h>

#include <cctype>

#include <string>
#include <utility>
#include <vector>

namespace {

namespace wire = ::ros2vtk::wire;
namespace tdi = ::ros2vtk::type_description_interfaces;

// rosidl's hashes (share/std_msgs/msg/String.json, geometry_msgs/msg/PoseStamped.json,
// std_srvs/srv/SetBool.json).
const char* const kStringHash =
  "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18";
const char* const kPoseStampedHash =
  "RIHS01_10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232d73b4cd8";
const char* const kSetBoolHash =
  "RIHS01_abe9e4bb6b41b40e6789712c00ec8871923e089af3f667a79992a428cff2da0a";

tdi::srv::GetTypeDescription_Response ask(
  const wire::NodeTypeCache& types, const std::string& type_name, const std::string& type_hash)
{
  tdi::srv::GetTypeDescription_Request request;
  request.type_name = type_name;
  request.type_hash = type_hash;
  tdi::srv::GetTypeDescription_Response response;
  response.successful = true; // the handler must overwrite what it is given
  response.failure_reason = "stale";
  wire::answer_type_description_request(types, request, response);
  return response;
}

std::vector<std::string> referenced_names(const tdi::msg::TypeDescription& description)
{
  std::vector<std::string> names;
  for (const auto& item : description.referenced_type_descriptions)
  {
    names.push_back(item.type_name);
  }
  return names;
}

} // namespace

TEST(NodeTypeCache, GeneratedTablesCarryRosidlsHash)
{
  EXPECT_STREQ(ros2vtk::std_msgs::msg::String::type_support().type_hash, kStringHash);
  EXPECT_STREQ(ros2vtk::std_srvs::srv::SetBool::type_support().type_hash, kSetBoolHash);
  ASSERT_NE(ros2vtk::std_msgs::msg::String::type_support().description, nullptr);
  ASSERT_NE(ros2vtk::std_srvs::srv::SetBool::type_support().description, nullptr);
}

TEST(NodeTypeCache, ServesATypeWhileAnEndpointHoldsIt)
{
  wire::NodeTypeCache types;
  const auto& string_type = ros2vtk::std_msgs::msg::String::type_support();
  EXPECT_EQ(types.find(kStringHash), nullptr);
  {
    wire::NodeTypeCache::Registration publisher =
      types.add(string_type.type_hash, string_type.description);
    wire::NodeTypeCache::Registration subscription =
      types.add(string_type.type_hash, string_type.description);
    EXPECT_EQ(types.size(), 1u);
    EXPECT_EQ(types.find(kStringHash), string_type.description);
    std::string upper = kStringHash;
    for (size_t i = 7; i < upper.size(); ++i)
    {
      upper[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(upper[i])));
    }
    EXPECT_EQ(types.find(upper), string_type.description); // rosidl parses hex either way
    {
      wire::NodeTypeCache::Registration gone = std::move(publisher);
    }
    EXPECT_EQ(types.find(kStringHash), string_type.description); // the subscription still uses it
  }
  EXPECT_EQ(types.find(kStringHash), nullptr);
  EXPECT_EQ(types.size(), 0u);
}

TEST(NodeTypeCache, HandWrittenTablesAreNotRegistered)
{
  wire::NodeTypeCache types;
  wire::NodeTypeCache::Registration none = types.add("", nullptr);
  EXPECT_EQ(types.size(), 0u);
}

TEST(TypeDescriptionRequest, KnownMessageTypeAsRosidlDescribesIt)
{
  wire::NodeTypeCache types;
  const auto& pose = ros2vtk::geometry_msgs::msg::PoseStamped::type_support();
  auto held = types.add(pose.type_hash, pose.description);
  const auto response = ask(types, "geometry_msgs/msg/PoseStamped", kPoseStampedHash);
  ASSERT_TRUE(response.successful) << response.failure_reason;
  EXPECT_EQ(response.failure_reason, "");
  const auto& description = response.type_description;
  EXPECT_EQ(description.type_description.type_name, "geometry_msgs/msg/PoseStamped");
  ASSERT_EQ(description.type_description.fields.size(), 2u);
  EXPECT_EQ(description.type_description.fields[0].name, "header");
  EXPECT_EQ(description.type_description.fields[0].type.type_id, 1); // FIELD_TYPE_NESTED_TYPE
  EXPECT_EQ(description.type_description.fields[0].type.nested_type_name, "std_msgs/msg/Header");
  EXPECT_EQ(referenced_names(description),
    (std::vector<std::string>{ "builtin_interfaces/msg/Time", "geometry_msgs/msg/Point",
      "geometry_msgs/msg/Pose", "geometry_msgs/msg/Quaternion", "std_msgs/msg/Header" }));
  // geometry_msgs/msg/Quaternion.json: "float64 w 1" is written "1.0".
  const auto& quaternion = description.referenced_type_descriptions[3];
  ASSERT_EQ(quaternion.fields.size(), 4u);
  EXPECT_EQ(quaternion.fields[3].name, "w");
  EXPECT_EQ(quaternion.fields[3].type.type_id, 11); // FIELD_TYPE_DOUBLE
  EXPECT_EQ(quaternion.fields[3].default_value, "1.0");
  const auto& header = description.referenced_type_descriptions[4];
  ASSERT_EQ(header.fields.size(), 2u);
  EXPECT_EQ(header.fields[1].name, "frame_id");
  EXPECT_EQ(header.fields[1].type.type_id, 17); // FIELD_TYPE_STRING
  // Asked with include_type_sources (the request's default): the type's and each referenced
  // type's .msg text, as rcl answers.
  ASSERT_EQ(response.type_sources.size(), 6u);
  for (const auto& source : response.type_sources)
  {
    EXPECT_EQ(source.encoding, "msg") << source.type_name;
    EXPECT_FALSE(source.raw_file_contents.empty()) << source.type_name;
  }
  EXPECT_TRUE(response.extra_information.empty());
}

TEST(TypeDescriptionRequest, KnownServiceTypeWithItsSynthesizedEvent)
{
  wire::NodeTypeCache types;
  const auto& set_bool = ros2vtk::std_srvs::srv::SetBool::type_support();
  auto held = types.add(set_bool.type_hash, set_bool.description);
  const auto response = ask(types, "std_srvs/srv/SetBool", kSetBoolHash);
  ASSERT_TRUE(response.successful) << response.failure_reason;
  const auto& fields = response.type_description.type_description.fields;
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[2].name, "event_message");
  EXPECT_EQ(fields[2].type.nested_type_name, "std_srvs/srv/SetBool_Event");
  EXPECT_EQ(referenced_names(response.type_description),
    (std::vector<std::string>{ "builtin_interfaces/msg/Time", "service_msgs/msg/ServiceEventInfo",
      "std_srvs/srv/SetBool_Event", "std_srvs/srv/SetBool_Request",
      "std_srvs/srv/SetBool_Response" }));
  const auto& event = response.type_description.referenced_type_descriptions[2];
  ASSERT_EQ(event.fields.size(), 3u);
  EXPECT_EQ(event.fields[1].type.type_id, 97); // FIELD_TYPE_NESTED_TYPE_BOUNDED_SEQUENCE
  EXPECT_EQ(event.fields[1].type.capacity, 1u);
}

// What rclpy's node answered for SetBool with include_type_sources (Kilted): the .srv text
// (172 characters, no last newline), then per referenced type its .msg text or "implicit".
TEST(TypeDescriptionRequest, TypeSourcesOnlyWhenAskedAndInTheDescriptionsOrder)
{
  wire::NodeTypeCache types;
  const auto& set_bool = ros2vtk::std_srvs::srv::SetBool::type_support();
  auto held = types.add(set_bool.type_hash, set_bool.description);
  tdi::srv::GetTypeDescription_Request request;
  request.type_name = "std_srvs/srv/SetBool";
  request.type_hash = kSetBoolHash;
  request.include_type_sources = false;
  tdi::srv::GetTypeDescription_Response response;
  wire::answer_type_description_request(types, request, response);
  ASSERT_TRUE(response.successful);
  EXPECT_TRUE(response.type_sources.empty());

  request.include_type_sources = true;
  wire::answer_type_description_request(types, request, response);
  ASSERT_TRUE(response.successful);
  std::vector<std::string> names, encodings;
  for (const auto& source : response.type_sources)
  {
    names.push_back(source.type_name);
    encodings.push_back(source.encoding);
  }
  EXPECT_EQ(names,
    (std::vector<std::string>{ "std_srvs/srv/SetBool", "builtin_interfaces/msg/Time",
      "service_msgs/msg/ServiceEventInfo", "std_srvs/srv/SetBool_Event",
      "std_srvs/srv/SetBool_Request", "std_srvs/srv/SetBool_Response" }));
  EXPECT_EQ(encodings,
    (std::vector<std::string>{ "srv", "msg", "msg", "implicit", "implicit", "implicit" }));
  const std::string& own = response.type_sources[0].raw_file_contents;
  EXPECT_EQ(own.size(), 172u);
  EXPECT_EQ(own.rfind("bool data # e.g. for hardware enabling / disabling\n---\n", 0), 0u) << own;
  EXPECT_EQ(response.type_sources[1].raw_file_contents.size(), 244u); // Time.msg
  EXPECT_EQ(response.type_sources[2].raw_file_contents.size(), 691u); // ServiceEventInfo.msg
  for (size_t i = 3; i < response.type_sources.size(); ++i)
  {
    EXPECT_EQ(response.type_sources[i].raw_file_contents, "") << names[i];
  }
}

TEST(TypeDescriptionRequest, UnknownTypeFailsAsRcl)
{
  wire::NodeTypeCache types;
  const auto& string_type = ros2vtk::std_msgs::msg::String::type_support();
  auto held = types.add(string_type.type_hash, string_type.description);
  const auto response = ask(types, "geometry_msgs/msg/PoseStamped", kPoseStampedHash);
  EXPECT_FALSE(response.successful);
  EXPECT_EQ(response.failure_reason, "Type not currently in use by this node");
  EXPECT_EQ(response.type_description.type_description.type_name, "");
}

TEST(TypeDescriptionRequest, HashNotMatchingTheNamedTypeFails)
{
  // rcl looks types up by hash alone: String's name with another version's hash is unknown.
  wire::NodeTypeCache types;
  const auto& string_type = ros2vtk::std_msgs::msg::String::type_support();
  auto held = types.add(string_type.type_hash, string_type.description);
  std::string other = kStringHash;
  other.back() = other.back() == '0' ? '1' : '0';
  const auto response = ask(types, "std_msgs/msg/String", other);
  EXPECT_FALSE(response.successful);
  EXPECT_EQ(response.failure_reason, "Type not currently in use by this node");
}

TEST(TypeDescriptionRequest, MalformedHashesAreRefusedWithAReason)
{
  wire::NodeTypeCache types;
  const auto& string_type = ros2vtk::std_msgs::msg::String::type_support();
  auto held = types.add(string_type.type_hash, string_type.description);
  const std::string good = kStringHash;
  for (const std::string& bad : { std::string(), std::string("garbage"),
         good.substr(0, good.size() - 1), good + "0", "RIHS02_" + good.substr(7),
         "RIHS01_" + std::string(63, '0') + "g", std::string(good).insert(7, 1, '\0') })
  {
    const auto response = ask(types, "std_msgs/msg/String", bad);
    EXPECT_FALSE(response.successful) << bad;
    EXPECT_EQ(response.failure_reason, "Failed to parse type hash") << bad;
  }
}

TEST(TypeDescriptionService, ParameterIsAReadOnlyBoolDefaultTrue)
{
  namespace rcl = ::ros2vtk::rcl_interfaces::msg;
  wire::ParameterStore store;
  std::string error;
  EXPECT_TRUE(wire::TypeDescriptionService::enabled(store, true, &error)) << error;
  const auto descriptors = store.describe_parameters({ "start_type_description_service" });
  ASSERT_EQ(descriptors.size(), 1u);
  EXPECT_TRUE(descriptors[0].read_only);
  EXPECT_EQ(descriptors[0].type, rcl::ParameterType::PARAMETER_BOOL);
  rcl::Parameter off;
  off.name = "start_type_description_service";
  off.value.type = rcl::ParameterType::PARAMETER_BOOL;
  off.value.bool_value = false;
  const auto results = store.set_parameters({ off });
  ASSERT_EQ(results.size(), 1u);
  EXPECT_FALSE(results[0].successful); // read-only, as rclpy declares it

  wire::ParameterStore off_store;
  EXPECT_FALSE(wire::TypeDescriptionService::enabled(off_store, false, &error));
  EXPECT_FALSE(off_store.get("start_type_description_service")->bool_value);

  wire::ParameterStore wrong;
  rcl::ParameterValue text;
  text.type = rcl::ParameterType::PARAMETER_STRING;
  text.string_value = "yes";
  ASSERT_TRUE(wrong.declare("start_type_description_service", text, &error));
  error.clear();
  EXPECT_FALSE(wire::TypeDescriptionService::enabled(wrong, true, &error));
  EXPECT_NE(error.find("should be a bool"), std::string::npos) << error;
}
