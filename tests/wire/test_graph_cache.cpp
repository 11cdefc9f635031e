// ros2vtk — unit tests of GraphCache's bookkeeping (no DDS: endpoints are fed by hand as
// discovery would): `ros2 topic list -t` style names and types, endpoint counts per side, and
// the removal of everything a vanished participant owned (its endpoints share its GUID prefix).
#include "GraphCache.hpp"

#include <gtest/gtest.h>

namespace {

using namespace ros2vtk::wire;

Gid gid(uint8_t participant, uint8_t entity)
{
  Gid g{};
  g.fill(participant);
  g[12] = 0;
  g[13] = 0;
  g[14] = entity;
  g[15] = 0x03;
  return g;
}

TEST(GraphCache, TopicsTypesAndCountsFromLocalAndRemoteEndpoints)
{
  GraphCache graph; // not init()ed: no DDS, nothing announced
  graph.add_local_endpoint(gid(1, 1), true, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(2, 1), false, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(2, 2), false, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(3, 1), true, "rt/ns/pose", "geometry_msgs::msg::dds_::PoseStamped_");
  graph.add_remote_endpoint(gid(3, 2), true, "rt/ns/pose", "geometry_msgs::msg::dds_::Pose_");
  // Service topics and the graph topic are not ROS topics.
  graph.add_remote_endpoint(gid(3, 3), false, "rq/slicer/get_parametersRequest",
                            "rcl_interfaces::srv::dds_::GetParameters_Request_");
  graph.add_remote_endpoint(gid(3, 4), false, "ros_discovery_info",
                            "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");

  const auto topics = graph.topic_names_and_types();
  ASSERT_EQ(topics.size(), 2u);
  EXPECT_EQ(topics[0].name, "/chatter");
  EXPECT_EQ(topics[0].types, std::vector<std::string>{ "std_msgs/msg/String" });
  EXPECT_EQ(topics[1].name, "/ns/pose");
  EXPECT_EQ(topics[1].types, (std::vector<std::string>{ "geometry_msgs/msg/Pose", "geometry_msgs/msg/PoseStamped" }));
  EXPECT_EQ(graph.count_endpoints("rt/chatter", true), 1u);
  EXPECT_EQ(graph.count_endpoints("rt/chatter", false), 2u);
  EXPECT_EQ(graph.count_endpoints("rt/none", false), 0u);
}

TEST(GraphCache, VanishedParticipantTakesItsEndpointsAlong)
{
  GraphCache graph;
  graph.add_remote_endpoint(gid(2, 1), false, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(2, 2), true, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(4, 1), true, "rt/chatter", "std_msgs::msg::dds_::String_");
  Gid participant = gid(2, 0);
  participant[14] = 0x01;
  participant[15] = 0xc1; // participant entity id 00 00 01 c1
  graph.remove_remote_participant(participant);
  EXPECT_EQ(graph.count_endpoints("rt/chatter", false), 0u);
  EXPECT_EQ(graph.count_endpoints("rt/chatter", true), 1u); // participant 4's writer stays
  graph.remove_remote_endpoint(gid(4, 1));
  EXPECT_TRUE(graph.topic_names_and_types().empty());
}

} // namespace
