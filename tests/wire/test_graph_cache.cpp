// ros2vtk — unit tests of GraphCache's bookkeeping (no DDS: endpoints are fed by hand as
// discovery would): `ros2 topic list -t` style names and types, endpoint counts per side, and
// the removal of everything a vanished participant owned (its endpoints share its GUID prefix),
// and the writer -> node matching through ros_discovery_info announcements (what `ros2 topic info
// -v` shows and the app's tf panel credits each frame to): a writer belongs to the node whose
// announcement lists its gid among its writers, as rmw_dds_common's graph cache decides.
#include "GraphCache.hpp"

#include "ros2vtk/rmw_dds_common/msg/participant_entities_info.hpp"

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
  graph.add_remote_endpoint(
    gid(3, 1), true, "rt/ns/pose", "geometry_msgs::msg::dds_::PoseStamped_");
  graph.add_remote_endpoint(gid(3, 2), true, "rt/ns/pose", "geometry_msgs::msg::dds_::Pose_");
  // Service topics and the graph topic are not ROS topics.
  graph.add_remote_endpoint(gid(3, 3), false, "rq/slicer/get_parametersRequest",
    "rcl_interfaces::srv::dds_::GetParameters_Request_");
  graph.add_remote_endpoint(
    gid(3, 4), false, "ros_discovery_info", "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");

  const auto topics = graph.topic_names_and_types();
  ASSERT_EQ(topics.size(), 2u);
  EXPECT_EQ(topics[0].name, "/chatter");
  EXPECT_EQ(topics[0].types, std::vector<std::string>{ "std_msgs/msg/String" });
  EXPECT_EQ(topics[1].name, "/ns/pose");
  EXPECT_EQ(topics[1].types,
    (std::vector<std::string>{ "geometry_msgs/msg/Pose", "geometry_msgs/msg/PoseStamped" }));
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

using ros2vtk::rmw_dds_common::msg::NodeEntitiesInfo;
using ros2vtk::rmw_dds_common::msg::ParticipantEntitiesInfo;

ros2vtk::rmw_dds_common::msg::Gid wire_gid(const Gid& g)
{
  ros2vtk::rmw_dds_common::msg::Gid result;
  result.data = g;
  return result;
}

Gid participant_gid(uint8_t participant)
{
  Gid g = gid(participant, 0);
  g[14] = 0x01;
  g[15] = 0xc1; // participant entity id 00 00 01 c1
  return g;
}

/// One participant's announcement: each node (namespace, name) with its writer and reader gids.
struct AnnouncedNode
{
  std::string ns;
  std::string name;
  std::vector<Gid> writers;
  std::vector<Gid> readers;
};

ParticipantEntitiesInfo announcement(uint8_t participant, const std::vector<AnnouncedNode>& nodes)
{
  ParticipantEntitiesInfo info;
  info.gid = wire_gid(participant_gid(participant));
  for (const auto& node : nodes)
  {
    NodeEntitiesInfo entry;
    entry.node_namespace = node.ns;
    entry.node_name = node.name;
    for (const auto& w : node.writers)
      entry.writer_gid_seq.push_back(wire_gid(w));
    for (const auto& r : node.readers)
      entry.reader_gid_seq.push_back(wire_gid(r));
    info.node_entities_info_seq.push_back(entry);
  }
  return info;
}

TEST(GraphCache, WriterIsMatchedToTheNodeWhoseAnnouncementListsIt)
{
  GraphCache graph;
  // Participant 2 (e.g. robot_state_publisher's process) and 3 (an rclpy node in a namespace)
  // both publish /tf_static; a writer of participant 4 has not been announced yet.
  graph.add_remote_endpoint(gid(2, 1), true, "rt/tf_static", "tf2_msgs::msg::dds_::TFMessage_");
  graph.add_remote_endpoint(gid(2, 2), true, "rt/tf", "tf2_msgs::msg::dds_::TFMessage_");
  graph.add_remote_endpoint(gid(3, 1), true, "rt/tf_static", "tf2_msgs::msg::dds_::TFMessage_");
  graph.add_remote_endpoint(gid(3, 2), false, "rt/tf_static", "tf2_msgs::msg::dds_::TFMessage_");
  graph.add_remote_endpoint(gid(4, 1), true, "rt/tf_static", "tf2_msgs::msg::dds_::TFMessage_");
  EXPECT_EQ(graph.node_of_writer(gid(2, 1)), ""); // before any announcement
  EXPECT_EQ(graph.publisher_nodes("rt/tf_static"), std::vector<std::string>{ "?" });

  graph.record_announcement(
    announcement(2, { { "/", "robot_state_publisher", { gid(2, 1), gid(2, 2) }, {} } }));
  // Two nodes in one participant: each writer goes to the node listing it, in its namespace.
  graph.record_announcement(announcement(3,
    { { "/", "other", {}, { gid(3, 1) } },
      { "/cameras", "camera_mount", { gid(3, 1) }, { gid(3, 2) } } }));
  EXPECT_EQ(graph.node_of_writer(gid(2, 1)), "/robot_state_publisher");
  EXPECT_EQ(graph.node_of_writer(gid(2, 2)), "/robot_state_publisher");
  EXPECT_EQ(graph.node_of_writer(gid(3, 1)),
    "/cameras/camera_mount");                     // not "other", which lists it as a reader
  EXPECT_EQ(graph.node_of_writer(gid(3, 2)), ""); // a reader is nobody's writer
  EXPECT_EQ(graph.node_of_writer(gid(4, 1)), ""); // participant 4 has not announced
  EXPECT_EQ(graph.node_of_writer(gid(9, 9)), ""); // unknown everywhere
  EXPECT_EQ(graph.publisher_nodes("rt/tf_static"),
    (std::vector<std::string>{ "/cameras/camera_mount", "/robot_state_publisher", "?" }));
  EXPECT_EQ(graph.publisher_nodes("rt/tf"), std::vector<std::string>{ "/robot_state_publisher" });
  const auto publishers = graph.remote_publishers("rt/tf_static");
  ASSERT_EQ(publishers.size(), 3u); // by writer gid: participant 2's, 3's, 4's
  EXPECT_EQ(publishers[0].node_name, "robot_state_publisher");
  EXPECT_EQ(publishers[1].node_namespace, "/cameras");
  EXPECT_EQ(publishers[1].node_name, "camera_mount");
  EXPECT_EQ(publishers[2].node_name, "");
}

TEST(GraphCache, ReaderIsMatchedToTheNodeWhoseAnnouncementListsItAsReader)
{
  // A publisher of ours learning its type asks a subscription's node (issue 13): readers are
  // found by the reader gids of the announcements, with the type hash of their USER_DATA.
  GraphCache graph;
  graph.add_remote_endpoint(gid(3, 1), true, "rt/chatter", "std_msgs::msg::dds_::String_", "W");
  graph.add_remote_endpoint(gid(3, 2), false, "rt/chatter", "std_msgs::msg::dds_::String_", "R");
  graph.add_remote_endpoint(gid(5, 1), false, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.record_announcement(announcement(
    3, { { "/", "talker", { gid(3, 1) }, {} }, { "/ns", "listener", {}, { gid(3, 2) } } }));
  const auto readers = graph.remote_endpoints("rt/chatter", false);
  ASSERT_EQ(readers.size(), 2u); // by reader gid: participant 3's, then 5's (not announced)
  EXPECT_EQ(readers[0].node_namespace, "/ns");
  EXPECT_EQ(readers[0].node_name, "listener"); // not "talker", which lists only the writer
  EXPECT_EQ(readers[0].ros_type, "std_msgs/msg/String");
  EXPECT_EQ(readers[0].type_hash, "R");
  EXPECT_EQ(readers[1].node_name, "");
  const auto writers = graph.remote_endpoints("rt/chatter", true);
  ASSERT_EQ(writers.size(), 1u);
  EXPECT_EQ(writers[0].node_name, "talker");
  EXPECT_EQ(writers[0].type_hash, "W");
}

TEST(GraphCache, NewerAnnouncementReplacesTheParticipantsNodes)
{
  GraphCache graph;
  graph.add_remote_endpoint(gid(2, 1), true, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.add_remote_endpoint(gid(2, 2), true, "rt/chatter", "std_msgs::msg::dds_::String_");
  graph.record_announcement(announcement(2, { { "/", "talker", { gid(2, 1) }, {} } }));
  EXPECT_EQ(graph.node_of_writer(gid(2, 2)), "");
  // The participant creates a second node owning the second writer: its next announcement lists
  // both nodes (rmw republishes the whole participant's state on every change).
  graph.record_announcement(announcement(
    2, { { "/", "talker", { gid(2, 1) }, {} }, { "/ns", "second", { gid(2, 2) }, {} } }));
  EXPECT_EQ(graph.node_of_writer(gid(2, 1)), "/talker");
  EXPECT_EQ(graph.node_of_writer(gid(2, 2)), "/ns/second");
  // The first node is destroyed: its writer is no longer anybody's.
  graph.record_announcement(announcement(2, { { "/ns", "second", { gid(2, 2) }, {} } }));
  EXPECT_EQ(graph.node_of_writer(gid(2, 1)), "");
  EXPECT_EQ(graph.node_of_writer(gid(2, 2)), "/ns/second");
  // The participant vanishes: its nodes go with it.
  graph.remove_remote_participant(participant_gid(2));
  EXPECT_EQ(graph.node_of_writer(gid(2, 2)), "");
  EXPECT_TRUE(graph.publisher_nodes("rt/chatter").empty());
}

} // namespace
