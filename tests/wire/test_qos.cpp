// ros2vtk — unit tests of Wire's QoS profiles against rmw's profile values (WIRE_NOTES §2.1).
#include "ros2vtk/wire/QoS.hpp"

#include "ParticipantImpl.hpp" // make_writer_qos (private)

#include <gtest/gtest.h>

namespace {

using ros2vtk::wire::QoS;

TEST(QoS, RmwProfileValues)
{
  const QoS defaults = QoS::default_profile();
  EXPECT_EQ(defaults.history, QoS::History::KeepLast);
  EXPECT_EQ(defaults.depth, 10u);
  EXPECT_EQ(defaults.reliability, QoS::Reliability::Reliable);
  EXPECT_EQ(defaults.durability, QoS::Durability::Volatile);

  const QoS sensor = QoS::sensor_data();
  EXPECT_EQ(sensor.depth, 5u);
  EXPECT_EQ(sensor.reliability, QoS::Reliability::BestEffort);
  EXPECT_EQ(sensor.durability, QoS::Durability::Volatile);

  const QoS parameters = QoS::parameters();
  EXPECT_EQ(parameters.depth, 1000u);
  EXPECT_EQ(parameters.reliability, QoS::Reliability::Reliable);

  const QoS latched = QoS::transient_local();
  EXPECT_EQ(latched.depth, 1u);
  EXPECT_EQ(latched.durability, QoS::Durability::TransientLocal);
  EXPECT_EQ(latched.reliability, QoS::Reliability::Reliable);
}

TEST(QoS, ProfilesByRosName)
{
  QoS qos;
  ASSERT_TRUE(QoS::from_name("sensor_data", qos));
  EXPECT_EQ(qos, QoS::sensor_data());
  ASSERT_TRUE(QoS::from_name("default", qos));
  EXPECT_EQ(qos, QoS::default_profile());
  ASSERT_TRUE(QoS::from_name("parameter_events", qos));
  EXPECT_EQ(qos, QoS::parameters());
  ASSERT_TRUE(QoS::from_name("transient_local", qos));
  EXPECT_EQ(qos, QoS::transient_local());
  ASSERT_TRUE(QoS::from_name("keep_all", qos));
  EXPECT_EQ(qos.history, QoS::History::KeepAll);
  EXPECT_EQ(qos.reliability, QoS::Reliability::Reliable);
  const QoS before = qos;
  EXPECT_FALSE(QoS::from_name("reliable_please", qos));
  EXPECT_FALSE(QoS::from_name("", qos));
  EXPECT_EQ(qos, before); // an unknown name leaves the QoS alone
}

TEST(QoS, EveryListedProfileNameParsesAndTheAliasesToo)
{
  // profile_names() is what error messages list: each entry must be accepted.
  const std::string names = QoS::profile_names();
  size_t start = 0;
  int count = 0;
  while (start < names.size())
  {
    size_t end = names.find(", ", start);
    end = end == std::string::npos ? names.size() : end;
    QoS qos;
    EXPECT_TRUE(QoS::from_name(names.substr(start, end - start), qos))
      << names.substr(start, end - start);
    ++count;
    start = end + 2;
  }
  EXPECT_EQ(count, 11);
  for (const char* alias : { "system_default", "best_effort", "services", "latched" })
  {
    EXPECT_NE(names.find(alias), std::string::npos) << alias;
  }
}

TEST(QoS, PolicyNamesBothWays)
{
  QoS::Reliability reliability = QoS::Reliability::Reliable;
  ASSERT_TRUE(QoS::parse("best_effort", reliability));
  EXPECT_EQ(reliability, QoS::Reliability::BestEffort);
  EXPECT_STREQ(QoS::name_of(reliability), "best_effort");
  QoS::Durability durability = QoS::Durability::Volatile;
  ASSERT_TRUE(QoS::parse("transient_local", durability));
  EXPECT_STREQ(QoS::name_of(durability), "transient_local");
  QoS::History history = QoS::History::KeepLast;
  ASSERT_TRUE(QoS::parse("keep_all", history));
  EXPECT_STREQ(QoS::name_of(history), "keep_all");
  EXPECT_FALSE(QoS::parse("Reliable", reliability)); // ROS spells them in lower case
  EXPECT_FALSE(QoS::parse(static_cast<const char*>(nullptr), history));
  EXPECT_EQ(reliability, QoS::Reliability::BestEffort); // unknown names leave the value alone
  EXPECT_EQ(history, QoS::History::KeepAll);
}

TEST(QoS, TextForLogs)
{
  EXPECT_EQ(QoS::default_profile().to_string(), "reliable, volatile, keep_last(10)");
  EXPECT_EQ(QoS::sensor_data().to_string(), "best_effort, volatile, keep_last(5)");
  QoS all;
  ASSERT_TRUE(QoS::from_name("keep_all", all));
  EXPECT_EQ(all.to_string(), "reliable, volatile, keep_all");
}

} // namespace

// What a Fast DDS data writer is given for a ROS QoS. A reliable writer asks for a heartbeat
// every 100 ms instead of Fast DDS's 3 s, so a sample lost on a lossy link is repaired within a
// tenth of a second (docs/networking.md: the 5 % loss round trip went from a 5.4 s to a 1.2 s
// median); best effort writers keep the default (they send no heartbeats).
TEST(QoS, ReliableWritersAskForAHeartbeatEveryTenthOfASecond)
{
  const auto reliable = ros2vtk::wire::make_writer_qos(QoS::default_profile(), "");
  EXPECT_EQ(reliable.reliability().kind, eprosima::fastdds::dds::RELIABLE_RELIABILITY_QOS);
  EXPECT_EQ(reliable.reliable_writer_qos().times.heartbeatPeriod.seconds, 0);
  EXPECT_EQ(reliable.reliable_writer_qos().times.heartbeatPeriod.nanosec, 100000000u);
  const auto latched = ros2vtk::wire::make_writer_qos(QoS::transient_local(), "");
  EXPECT_EQ(latched.reliable_writer_qos().times.heartbeatPeriod.nanosec, 100000000u);
  const auto best_effort = ros2vtk::wire::make_writer_qos(QoS::sensor_data(), "");
  const eprosima::fastdds::dds::DataWriterQos defaults;
  EXPECT_EQ(best_effort.reliable_writer_qos().times.heartbeatPeriod,
    defaults.reliable_writer_qos().times.heartbeatPeriod);
  EXPECT_EQ(defaults.reliable_writer_qos().times.heartbeatPeriod.seconds, 3)
    << "Fast DDS's default changed: docs/networking.md compares against 3 s";
}

// A reliable writer ignores NACKs for 5 ms after a send instead of Fast DDS's 0: with 0, each
// write wakes the participant's event thread before its sendto (docs/benchmarks.md, pose_1khz).
// 5 ms is not longer than a Fast DDS reader's heartbeat response delay, so no NACK a reader sends
// in answer to a heartbeat that announced the sample is ignored.
TEST(QoS, ReliableWritersSuppressNacksForNoLongerThanAReaderTakesToAnswerAHeartbeat)
{
  const auto reliable = ros2vtk::wire::make_writer_qos(QoS::default_profile(), "");
  const auto& times = reliable.reliable_writer_qos().times;
  EXPECT_EQ(times.nackSupressionDuration.seconds, 0);
  EXPECT_EQ(times.nackSupressionDuration.nanosec, 5000000u);
  const eprosima::fastdds::dds::DataReaderQos reader_defaults;
  EXPECT_LE(times.nackSupressionDuration,
    reader_defaults.reliable_reader_qos().times.heartbeatResponseDelay);
  const eprosima::fastdds::dds::DataWriterQos defaults;
  EXPECT_EQ(defaults.reliable_writer_qos().times.nackSupressionDuration.seconds, 0);
  EXPECT_EQ(defaults.reliable_writer_qos().times.nackSupressionDuration.nanosec, 0u)
    << "Fast DDS's default changed: the comment in make_writer_qos compares against 0";
}
