// ros2vtk — unit tests of Wire's ROS name rules (rcl's validation and expansion) and
// rmw_fastrtps's DDS mangling, with rcl's documented results as the expected values.
#include "ros2vtk/wire/Names.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace ros2vtk::wire;

TEST(Names, NodeNamesFollowRcl)
{
  std::string error;
  EXPECT_TRUE(validate_node_name("my_node", &error));
  EXPECT_TRUE(validate_node_name("_hidden2", &error));
  EXPECT_TRUE(validate_node_name(std::string(255, 'a'), &error));
  EXPECT_FALSE(validate_node_name(std::string(256, 'a'), &error));
  EXPECT_FALSE(validate_node_name("", &error));
  EXPECT_FALSE(validate_node_name("2fast", &error));
  EXPECT_FALSE(validate_node_name("with-dash", &error));
  EXPECT_FALSE(validate_node_name("ns/node", &error));
  EXPECT_FALSE(error.empty());
}

TEST(Names, NamespacesAreNormalizedOrRefused)
{
  std::string ns, error;
  ASSERT_TRUE(normalize_namespace("", ns, &error));
  EXPECT_EQ(ns, "/");
  ASSERT_TRUE(normalize_namespace("robot1", ns, &error));
  EXPECT_EQ(ns, "/robot1");
  ASSERT_TRUE(normalize_namespace("/PSM1/arm", ns, &error));
  EXPECT_EQ(ns, "/PSM1/arm");
  EXPECT_FALSE(normalize_namespace("/a//b", ns, &error));
  EXPECT_FALSE(normalize_namespace("/1a", ns, &error));
  EXPECT_FALSE(normalize_namespace("/a b", ns, &error));
}

TEST(Names, FullyQualifiedNodeName)
{
  EXPECT_EQ(fully_qualified_node_name("/", "talker"), "/talker");
  EXPECT_EQ(fully_qualified_node_name("/ns", "talker"), "/ns/talker");
}

TEST(Names, TopicExpansionAsRclDoesIt)
{
  std::string out, error;
  ASSERT_TRUE(expand_topic_name("chatter", "node", "/", out, &error));
  EXPECT_EQ(out, "/chatter");
  ASSERT_TRUE(expand_topic_name("chatter", "node", "/ns", out, &error));
  EXPECT_EQ(out, "/ns/chatter");
  ASSERT_TRUE(expand_topic_name("/abs/topic", "node", "/ns", out, &error));
  EXPECT_EQ(out, "/abs/topic");
  ASSERT_TRUE(expand_topic_name("~", "node", "/ns", out, &error));
  EXPECT_EQ(out, "/ns/node");
  ASSERT_TRUE(expand_topic_name("~/state", "node", "/ns", out, &error));
  EXPECT_EQ(out, "/ns/node/state");
  EXPECT_FALSE(expand_topic_name("", "node", "/", out, &error));
  EXPECT_FALSE(expand_topic_name("/a//b", "node", "/", out, &error));
  EXPECT_FALSE(expand_topic_name("/a b", "node", "/", out, &error));
  EXPECT_FALSE(expand_topic_name("/3d/points", "node", "/", out, &error));
  EXPECT_FALSE(expand_topic_name("/trailing/", "node", "/", out, &error));
}

TEST(Names, DdsManglingOfRmwFastrtps)
{
  EXPECT_EQ(topic_to_dds("/chatter"), "rt/chatter");
  EXPECT_EQ(topic_to_dds("/ns/tf"), "rt/ns/tf");
  EXPECT_EQ(service_request_to_dds("/slicer/get_parameters"), "rq/slicer/get_parametersRequest");
  EXPECT_EQ(service_reply_to_dds("/slicer/get_parameters"), "rr/slicer/get_parametersReply");
  std::string topic;
  ASSERT_TRUE(dds_to_topic("rt/ns/chatter", topic));
  EXPECT_EQ(topic, "/ns/chatter");
  EXPECT_FALSE(dds_to_topic("ros_discovery_info", topic));
  EXPECT_FALSE(dds_to_topic("rq/slicer/get_parametersRequest", topic));
  EXPECT_EQ(dds_type_to_ros("std_msgs::msg::dds_::String_"), "std_msgs/msg/String");
  EXPECT_EQ(dds_type_to_ros("rcl_interfaces::srv::dds_::GetParameters_Request_"),
    "rcl_interfaces/srv/GetParameters_Request");
  EXPECT_EQ(dds_type_to_ros("NotARosType"), "NotARosType");
}

} // namespace
