// Spin semantics with two ROS nodes of one process talking to each other: events fire on the
// spinning thread only, once per spin, with the count; malformed samples are counted and
// reported rate-limited; QoS and save/restore act on the real DDS endpoints.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "TestStringNodes.h"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberGenericNode.h"

#include "ros2vtk/std_msgs/msg/string.hpp"
#include "ros2vtk/wire/CdrWriter.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <poll.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk_test::SpinUntil;

// Every ModifiedEvent of one subscriber: call data count and the thread it fired on.
struct ModifiedLog
{
  std::vector<int> counts;
  std::vector<std::thread::id> threads;
  vtkNew<vtkCallbackCommand> command;

  explicit ModifiedLog(vtkObject* observed)
  {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
      auto* self = static_cast<ModifiedLog*>(clientData);
      self->counts.push_back(callData ? *static_cast<int*>(callData) : -1);
      self->threads.push_back(std::this_thread::get_id());
    });
    this->Observed = observed;
    this->Tag = observed->AddObserver(vtkCommand::ModifiedEvent, command);
  }
  ~ModifiedLog() { this->Observed->RemoveObserver(this->Tag); }
  vtkSmartPointer<vtkObject> Observed;
  unsigned long Tag = 0;
};

class SpinTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    RegisterTestStringNodes();
    vtkOutputWindow::SetInstance(this->Output);
    this->Talker = vtkSmartPointer<vtkROS2NodeNode>::New();
    this->Logic->GetScene()->AddNode(this->Talker);
    ASSERT_TRUE(this->Talker->Create("talker"));
    this->Listener = this->Logic->GetDefaultROS2Node();
    ASSERT_NE(this->Listener, nullptr);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  // A connected pair on `topic`.
  void Connect(const char* topic)
  {
    this->Publisher = vtkROS2PublisherTestStringNode::SafeDownCast(
      this->Talker->CreateAndAddPublisherNode("TestString", topic));
    this->Subscriber = vtkROS2SubscriberTestStringNode::SafeDownCast(
      this->Listener->CreateAndAddSubscriberNode("TestString", topic));
    ASSERT_NE(this->Publisher, nullptr) << this->Output->Errors;
    ASSERT_NE(this->Subscriber, nullptr) << this->Output->Errors;
    ASSERT_TRUE(SpinUntil(this->Logic,
      [this] {
        return this->Publisher->GetNumberOfMatchedSubscriptions() > 0 &&
          this->Subscriber->GetNumberOfMatchedPublications() > 0;
      }))
      << "publisher and subscriber never matched";
  }

  vtkNew<ros2vtk_test::CapturingOutputWindow> Output;
  vtkNew<vtkROS2Logic> Logic;
  vtkSmartPointer<vtkROS2NodeNode> Talker;
  vtkROS2NodeNode* Listener = nullptr;
  vtkROS2PublisherTestStringNode* Publisher = nullptr;
  vtkROS2SubscriberTestStringNode* Subscriber = nullptr;
};
} // namespace

TEST_F(SpinTest, NothingFiresUntilSpinThenOncePerSpinWithTheCountOnTheSpinningThread)
{
  this->Connect("/spin_semantics");
  ModifiedLog log(this->Subscriber);
  for (const char* text : { "m0", "m1", "m2", "m3", "m4" })
  {
    ASSERT_TRUE(this->Publisher->Publish(text));
  }
  // DDS threads only queue: without a spin, nothing is delivered to the scene.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_TRUE(log.counts.empty());
  EXPECT_EQ(this->Subscriber->GetNumberOfMessages(), 0);

  std::vector<int> spinResults;
  const auto end = Clock::now() + std::chrono::seconds(10);
  while (this->Subscriber->GetNumberOfMessages() < 5 && Clock::now() < end)
  {
    const size_t eventsBefore = log.counts.size();
    const int handled = this->Logic->Spin();
    const size_t eventsOfThisSpin = log.counts.size() - eventsBefore;
    EXPECT_EQ(eventsOfThisSpin, handled > 0 ? 1u : 0u) << "one event per spin with messages";
    if (handled > 0)
    {
      EXPECT_EQ(log.counts.back(), handled) << "call data is the count of new messages";
      spinResults.push_back(handled);
    }
  }
  ASSERT_EQ(this->Subscriber->GetNumberOfMessages(), 5);
  for (const auto& id : log.threads)
  {
    EXPECT_EQ(id, std::this_thread::get_id());
  }
  // The raw messages of each spin reached OnNewMessages in order, newest last.
  std::vector<std::string> seen;
  ASSERT_EQ(this->Subscriber->Batches.size(), spinResults.size());
  for (size_t i = 0; i < spinResults.size(); ++i)
  {
    EXPECT_EQ(static_cast<int>(this->Subscriber->Batches[i].size()), spinResults[i]);
    seen.insert(
      seen.end(), this->Subscriber->Batches[i].begin(), this->Subscriber->Batches[i].end());
  }
  EXPECT_EQ(seen, (std::vector<std::string>{ "m0", "m1", "m2", "m3", "m4" }));
  EXPECT_EQ(this->Subscriber->GetLastMessage(), "m4");
  EXPECT_EQ(this->Publisher->GetNumberOfCalls(), 5);
  EXPECT_EQ(this->Publisher->GetNumberOfMessagesSent(), 5);

  // A spin with nothing new fires nothing and keeps the last message.
  const size_t events = log.counts.size();
  EXPECT_EQ(this->Listener->Spin(), 0);
  EXPECT_EQ(log.counts.size(), events);
  EXPECT_EQ(this->Subscriber->GetLastMessage(), "m4");
}

TEST_F(SpinTest, MalformedSamplesAreCountedAndReportedRateLimited)
{
  this->Connect("/malformed");
  std::string error;
  auto raw = ros2vtk::wire::Participant::create(
    "garbage_maker", "", ros2vtk::wire::ParticipantOptions::from_environment(), &error);
  ASSERT_TRUE(raw) << error;
  // A table that claims to be std_msgs/String on the wire but writes a string length far
  // beyond the payload: what a broken or hostile peer would send (Publisher::publish_serialized
  // validates, so the bytes must come from the type's own serializer).
  static ros2vtk::wire::MessageTypeSupport hostile = ros2vtk::std_msgs::msg::String::type_support();
  hostile.serialized_size = [](const void*) -> size_t {
    return 4 + 4 + 1;
  };
  hostile.serialize = [](const void*, ros2vtk::wire::CdrWriter& writer) {
    writer.write(static_cast<uint32_t>(0xffffff00u));
    writer.write(static_cast<uint8_t>('x'));
  };
  auto rawPublisher = raw->create_publisher(hostile, "/malformed", ros2vtk::wire::QoS{}, &error);
  ASSERT_TRUE(rawPublisher) << error;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return rawPublisher->matched_subscriptions() > 0; }));

  // Two bursts, each counted in its own spins: the first is reported at once, the second
  // falls inside the report interval and must not produce another line.
  const ros2vtk::std_msgs::msg::String ignored;
  int sent = 0;
  for (int burst : { 10, 20 })
  {
    for (int i = 0; i < burst; ++i, ++sent)
    {
      ASSERT_TRUE(rawPublisher->publish(&ignored));
    }
    ASSERT_TRUE(SpinUntil(
      this->Logic, [&] { return this->Subscriber->GetNumberOfRejectedMessages() == sent; }))
      << "rejected " << this->Subscriber->GetNumberOfRejectedMessages() << " of " << sent;
    EXPECT_EQ(this->Output->NumberOfWarnings, 1) << this->Output->Warnings;
  }
  ASSERT_TRUE(this->Publisher->Publish("still fine"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Subscriber->GetNumberOfMessages() == 1; }));
  // Keep spinning: the count must not be reported again within the interval.
  for (int i = 0; i < 50; ++i)
  {
    this->Logic->Spin();
  }
  EXPECT_EQ(this->Output->NumberOfWarnings, 1) << this->Output->Warnings;
  EXPECT_NE(this->Output->Warnings.find("/malformed"), std::string::npos) << this->Output->Warnings;
  EXPECT_STRNE(this->Subscriber->GetLastRejectionReason(), "");
  EXPECT_EQ(this->Subscriber->GetLastMessage(), "still fine");
  rawPublisher.reset();
}

TEST_F(SpinTest, QoSChangesRecreateTheEndpointAndLatchedMessagesReachLateJoiners)
{
  auto* pub = this->Talker->CreateAndAddPublisherNode("TestString", "/latched");
  ASSERT_NE(pub, nullptr);
  EXPECT_STREQ(pub->GetDurability(), "volatile");
  ASSERT_TRUE(pub->SetQoSProfile("transient_local"));
  EXPECT_STREQ(pub->GetDurability(), "transient_local");
  EXPECT_TRUE(pub->IsAddedToROS2Node()) << "re-created with the new QoS";
  ASSERT_TRUE(vtkROS2PublisherTestStringNode::SafeDownCast(pub)->Publish("before you came"));

  auto* late = vtkROS2SubscriberTestStringNode::SafeDownCast(
    this->Listener->CreateAndAddSubscriberNode("TestString", "/latched"));
  ASSERT_NE(late, nullptr);
  ASSERT_TRUE(late->SetDurability("transient_local"));
  ASSERT_TRUE(late->SetHistoryDepth(1));
  EXPECT_EQ(late->GetHistoryDepth(), 1);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return late->GetNumberOfMessages() == 1; }));
  EXPECT_EQ(late->GetLastMessage(), "before you came");

  EXPECT_FALSE(late->SetReliability("sometimes"));
  EXPECT_FALSE(late->SetDurability("forever"));
  EXPECT_FALSE(late->SetQoSProfile("fastest"));
  EXPECT_FALSE(late->SetHistoryDepth(0));
  EXPECT_STREQ(late->GetReliability(), "reliable");
  ASSERT_TRUE(late->SetReliability("best_effort"));
  EXPECT_STREQ(late->GetReliability(), "best_effort");
  EXPECT_TRUE(late->IsAddedToROS2Node());
}

TEST_F(SpinTest, SpinOnWakeUpWaitsForDataAndTimesOut)
{
  this->Connect("/wake");
  const auto start = Clock::now();
  EXPECT_EQ(this->Logic->SpinOnWakeUp(0.2), 0);
  EXPECT_GE(Clock::now() - start, std::chrono::milliseconds(150));

  const int fd = this->Logic->GetWakeUpFileDescriptor();
  ASSERT_GE(fd, 0);
  ASSERT_TRUE(this->Publisher->Publish("wake up"));
  pollfd pfd{ fd, POLLIN, 0 };
  ASSERT_EQ(::poll(&pfd, 1, 5000), 1) << "the logic's descriptor became readable";
  int handled = 0;
  const auto end = Clock::now() + std::chrono::seconds(5);
  while (handled == 0 && Clock::now() < end)
  {
    handled += this->Logic->SpinOnWakeUp(1.0);
  }
  EXPECT_EQ(handled, 1);
  EXPECT_EQ(this->Subscriber->GetLastMessage(), "wake up");
  EXPECT_GT(this->Logic->GetNumberOfSpins(), 0);
  EXPECT_GE(this->Logic->GetMeanSpinDuration(), 0.0);
}

TEST_F(SpinTest, LinkStateChangedEventFiresOnTheSpinningThreadWhenAPeerComesAndGoes)
{
  // Every event of the default node: call data (the link state) and thread.
  struct LinkLog
  {
    std::vector<std::string> states;
    std::vector<std::thread::id> threads;
  } log;
  vtkNew<vtkCallbackCommand> command;
  command->SetClientData(&log);
  command->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* self = static_cast<LinkLog*>(clientData);
    self->states.emplace_back(callData ? static_cast<const char*>(callData) : "(null)");
    self->threads.push_back(std::this_thread::get_id());
  });
  this->Listener->AddObserver(vtkROS2NodeNode::LinkStateChangedEvent, command);
  // The talker, a participant of this process, is found: "peers" (once, whatever else runs).
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return !log.states.empty(); }))
    << "no event for the talker";
  EXPECT_EQ(log.states.front(), "peers");
  EXPECT_STREQ(this->Listener->GetLinkState(), "peers");
  const size_t afterFound = log.states.size();
  for (int i = 0; i < 20; ++i)
  {
    this->Logic->Spin();
  }
  EXPECT_EQ(log.states.size(), afterFound) << "spins without a change fire nothing";
  // The talker goes away: DDS removes it on one of its threads; nothing fires there, the
  // listener's descriptor wakes the spinner, and the spin fires the event.
  const int fd = this->Listener->GetWakeUpFileDescriptor();
  ASSERT_TRUE(this->Talker->Destroy());
  pollfd pfd{ fd, POLLIN, 0 };
  EXPECT_EQ(::poll(&pfd, 1, 5000), 1) << "losing a peer wakes the spinner";
  EXPECT_EQ(log.states.size(), afterFound) << "fired before any spin";
  ASSERT_TRUE(SpinUntil(
    this->Logic, [&] { return this->Listener->GetNumberOfDiscoveredParticipants() == 0; }))
    << this->Listener->GetNumberOfDiscoveredParticipants() << " peers left";
  ASSERT_GT(log.states.size(), afterFound);
  EXPECT_EQ(log.states.back(), "no peers");
  for (const auto& id : log.threads)
  {
    EXPECT_EQ(id, std::this_thread::get_id());
  }
}

TEST_F(SpinTest, SpinForSpinsAtTheRateForTheDuration)
{
  // Behaviour, not timing (timings belong to tests/benchmarks; a loaded machine stretches any
  // wall-clock bound): SpinFor returns, spins repeatedly, never more often than the rate
  // allows, and returns what its spins handled.
  this->Connect("/spin_for");
  ASSERT_TRUE(this->Publisher->Publish("during SpinFor"));
  this->Logic->SetSpinRate(100.0);
  const auto before = this->Logic->GetNumberOfSpins();
  int handled = this->Logic->SpinFor(0.5);
  const auto spins = this->Logic->GetNumberOfSpins() - before;
  // The second spin is due 10 ms in, the last one no later than 0.5 s in: only a stall of
  // nearly the whole duration could leave a single spin.
  EXPECT_GE(spins, 2) << "spins repeatedly within the duration";
  EXPECT_LE(spins, 51) << "at most one spin per period: 100 Hz over 0.5 s, both ends included";
  // The message may still be in flight on the loopback when SpinFor ends: spin until it lands
  // (a deadline, not a timing assertion).
  const auto deadline = Clock::now() + std::chrono::seconds(10);
  while (handled == 0 && Clock::now() < deadline)
  {
    handled += this->Logic->SpinFor(0.01);
  }
  EXPECT_EQ(handled, 1) << "SpinFor returns the number of messages its spins handled";
  EXPECT_EQ(this->Subscriber->GetNumberOfMessages(), 1);

  // No duration (or a negative one) is a single spin.
  const auto beforeSingle = this->Logic->GetNumberOfSpins();
  this->Logic->SpinFor(0.0);
  this->Logic->SpinFor(-1.0);
  EXPECT_EQ(this->Logic->GetNumberOfSpins() - beforeSingle, 2);

  // A rate that is not a positive number is refused and the rate stays.
  for (double refused : { -1.0, 0.0, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity() })
  {
    this->Logic->SetSpinRate(refused);
    EXPECT_EQ(this->Logic->GetSpinRate(), 100.0) << "refused " << refused;
  }
  EXPECT_NE(this->Output->Errors.find("SetSpinRate"), std::string::npos) << this->Output->Errors;
}

TEST_F(SpinTest, RemovingTheROSNodeDetachesItsEndpoints)
{
  this->Connect("/teardown");
  vtkSmartPointer<vtkROS2PublisherNode> pub = this->Publisher;
  ASSERT_TRUE(this->Logic->GetScene()->RemoveNode(this->Talker));
  EXPECT_FALSE(this->Talker->IsCreated());
  EXPECT_FALSE(pub->IsAddedToROS2Node());
  EXPECT_FALSE(vtkROS2PublisherTestStringNode::SafeDownCast(pub)->Publish("into the void"));
  EXPECT_EQ(pub->GetNumberOfCalls(), 1);
  EXPECT_EQ(pub->GetNumberOfMessagesSent(), 0);
}

TEST_F(SpinTest, SavedSceneRestoresNodesEndpointsAndQoS)
{
  this->Connect("/saved");
  ASSERT_TRUE(this->Subscriber->SetReliability("best_effort"));
  this->Subscriber->SetScaleLengths(false);
  auto* generic = this->Talker->CreateAndAddPublisherNode("geometry_msgs/msg/Point", "/point");
  ASSERT_NE(generic, nullptr);
  const std::string xml = this->Logic->GetScene()->WriteToXMLString();
  const std::string subscriberID = this->Subscriber->GetID();
  const std::string genericID = generic->GetID();

  vtkNew<vtkROS2Logic> other;
  ASSERT_TRUE(other->GetScene()->ReadFromXMLString(xml.c_str())) << this->Output->Errors << xml;
  auto* restoredSub = vtkROS2SubscriberTestStringNode::SafeDownCast(
    other->GetScene()->GetNodeByID(subscriberID.c_str()));
  ASSERT_NE(restoredSub, nullptr) << xml;
  EXPECT_TRUE(restoredSub->IsAddedToROS2Node()) << this->Output->Errors;
  EXPECT_STREQ(restoredSub->GetTopic(), "/saved");
  EXPECT_STREQ(restoredSub->GetReliability(), "best_effort");
  EXPECT_FALSE(restoredSub->GetScaleLengths());
  ASSERT_NE(restoredSub->GetROS2Node(), nullptr);
  EXPECT_STREQ(restoredSub->GetROS2Node()->GetROS2NodeName(), "slicer");
  auto* restoredGeneric =
    vtkROS2PublisherGenericNode::SafeDownCast(other->GetScene()->GetNodeByID(genericID.c_str()));
  ASSERT_NE(restoredGeneric, nullptr);
  EXPECT_STREQ(restoredGeneric->GetROSType(), "geometry_msgs/msg/Point");
  EXPECT_TRUE(restoredGeneric->IsAddedToROS2Node());
  // The restored subscriber receives from the original talker.
  // Both sides must know each other before a volatile message can reach the new reader; the
  // restored reader also matches the restored talker's publisher, hence 2.
  ASSERT_TRUE(SpinUntil(other, [&] {
    return restoredSub->GetNumberOfMatchedPublications() >= 2 &&
      this->Publisher->GetNumberOfMatchedSubscriptions() >= 2;
  }));
  ASSERT_TRUE(this->Publisher->Publish("to the restored scene"));
  ASSERT_TRUE(SpinUntil(other, [&] { return restoredSub->GetNumberOfMessages() > 0; }));
  EXPECT_EQ(restoredSub->GetLastMessage(), "to the restored scene");
}

TEST_F(SpinTest, GenericNodesCarryAnyRegisteredTypeAsYAML)
{
  auto* pub = vtkROS2PublisherGenericNode::SafeDownCast(
    this->Talker->CreateAndAddPublisherNode("geometry_msgs/Point", "/generic_point"));
  auto* sub = vtkROS2SubscriberGenericNode::SafeDownCast(
    this->Listener->CreateAndAddSubscriberNode("geometry_msgs/msg/Point", "/generic_point"));
  ASSERT_TRUE(pub && sub) << this->Output->Errors;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] {
    return pub->GetNumberOfMatchedSubscriptions() > 0 && sub->GetNumberOfMatchedPublications() > 0;
  }));
  ASSERT_TRUE(pub->PublishYAML("{x: 1.5, y: -2.0, z: 3.0}")) << this->Output->Errors;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return sub->GetNumberOfMessages() == 1; }));
  EXPECT_EQ(sub->GetLastMessage(), "x: 1.5\ny: -2.0\nz: 3.0\n");
  EXPECT_FALSE(pub->PublishYAML("{x: [not a number}"));
  EXPECT_EQ(pub->GetNumberOfCalls(), 2);
  EXPECT_EQ(pub->GetNumberOfMessagesSent(), 1);
}

TEST_F(SpinTest, GenericNodeTypeIsFixedWhileAddedAndUnknownTypesAreNamed)
{
  for (const bool publisher : { true, false })
  {
    vtkSmartPointer<vtkROS2TopicNode> node;
    if (publisher)
    {
      node = vtkSmartPointer<vtkROS2PublisherGenericNode>::New();
    }
    else
    {
      node = vtkSmartPointer<vtkROS2SubscriberGenericNode>::New();
    }
    auto setType = [&](const char* type) {
      return publisher ? vtkROS2PublisherGenericNode::SafeDownCast(node)->SetROSType(type)
                       : vtkROS2SubscriberGenericNode::SafeDownCast(node)->SetROSType(type);
    };
    const vtkMTimeType before = node->GetMTime();
    ASSERT_TRUE(setType("geometry_msgs/Point"));
    EXPECT_GT(node->GetMTime(), before);
    const vtkMTimeType typed = node->GetMTime();
    ASSERT_TRUE(setType("geometry_msgs/msg/Point")); // the same type: not a modification
    EXPECT_EQ(node->GetMTime(), typed);

    this->Output->Errors.clear();
    EXPECT_FALSE(setType("no_pkg/msg/Nothing"));
    EXPECT_NE(
      this->Output->Errors.find("unknown ROS message type 'no_pkg/msg/Nothing'"), std::string::npos)
      << this->Output->Errors;
    EXPECT_NE(this->Output->Errors.find("geometry_msgs/msg/Point"), std::string::npos)
      << "the error lists the registered types";

    this->Logic->GetScene()->AddNode(node);
    ASSERT_TRUE(node->AddToROS2Node(
      this->Talker->GetID(), publisher ? "/generic_fixed_pub" : "/generic_fixed_sub"))
      << this->Output->Errors;
    this->Output->Errors.clear();
    EXPECT_FALSE(setType("std_msgs/msg/String"));
    EXPECT_NE(this->Output->Errors.find("cannot change the type while added to a ROS node"),
      std::string::npos)
      << this->Output->Errors;
  }
}

TEST(DiscoveryServerSettings, ATcpServerOrAMalformedListIsRefusedWithWhatToDoInstead)
{
  for (const auto& [servers, expected] : std::vector<std::pair<std::string, std::string>>{
         { "TCPv4:[198.18.0.1]:42100",
           "TCP discovery servers are not supported with Fast DDS 2.9; run the server on "
           "UDP (fastdds discovery -i 0 -l HOST -p PORT) and list it as HOST:PORT" },
         { "198.18.0.1:not_a_port",
           "is not a list of host:port (';'-separated, position = server id)" } })
  {
    ros2vtk::wire::ParticipantOptions options;
    options.discovery_servers = servers;
    std::string error;
    EXPECT_EQ(ros2vtk::wire::Participant::create("client", "", options, &error), nullptr)
      << servers;
    EXPECT_NE(error.find(expected), std::string::npos) << error;
  }
}
