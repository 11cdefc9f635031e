// Action nodes of two ROS nodes in one process: a client node sends goals to a server node
// (feedback, result, cancel, rejection, events on the spinning thread), feedback of other goals
// is ignored, bad use gets a clear error, and a saved scene restores both. The wire against
// rclpy is proven in tests/interop/test_scene_actions.py.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "vtkROS2ActionClientNode.h"
#include "vtkROS2ActionServerNode.h"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "Internal/ActionMembers.hpp"

#include "ros2vtk/wire/CdrWriter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/NodeTypeCache.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Publisher.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Service.hpp"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <string>

namespace {
using ros2vtk_test::SpinUntil;

class ActionTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    vtkOutputWindow::SetInstance(this->Output);
    this->Other = vtkSmartPointer<vtkROS2NodeNode>::New();
    this->Logic->GetScene()->AddNode(this->Other);
    ASSERT_TRUE(this->Other->Create("action_peer"));
    this->Node = this->Logic->GetDefaultROS2Node();
    ASSERT_NE(this->Node, nullptr);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  // A Fibonacci server on the other node and our client of it, matched.
  void MakePair(const char* action)
  {
    this->Server = this->Other->CreateAndAddActionServerNode("test_msgs/action/Fibonacci", action);
    ASSERT_NE(this->Server, nullptr) << this->Output->Errors;
    this->Client = this->Node->CreateAndAddActionClientNode("test_msgs/Fibonacci", action);
    ASSERT_NE(this->Client, nullptr) << this->Output->Errors;
    ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->IsServerReady(); }));
  }

  vtkNew<ros2vtk_test::CapturingOutputWindow> Output;
  vtkNew<vtkROS2Logic> Logic;
  vtkSmartPointer<vtkROS2NodeNode> Other;
  vtkROS2NodeNode* Node = nullptr;
  vtkROS2ActionServerNode* Server = nullptr;
  vtkROS2ActionClientNode* Client = nullptr;
};

void Count(vtkObject*, unsigned long, void* counter, void*)
{
  ++*static_cast<int*>(counter);
}
} // namespace

TEST_F(ActionTest, GoalFeedbackAndResultArriveOnSpin)
{
  this->MakePair("/fibonacci");
  int feedbacks = 0;
  vtkNew<vtkCallbackCommand> countFeedback;
  countFeedback->SetClientData(&feedbacks);
  countFeedback->SetCallback(&Count);
  this->Client->AddObserver(vtkROS2ActionClientNode::FeedbackReceivedEvent, countFeedback);

  ASSERT_GT(this->Client->SendGoalYAML("{order: 3}"), 0);
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::WaitingForAcceptance);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->HasActiveGoal(); }))
    << this->Output->Errors;
  EXPECT_EQ(this->Server->GetGoalField("order"), "3");
  EXPECT_EQ(this->Server->GetGoalIdAsString(), this->Client->GetGoalIdAsString());
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] { return this->Client->GetGoalStatus() == vtkROS2ActionClientNode::Executing; }))
    << this->Client->GetStatusAsString();

  ASSERT_TRUE(this->Server->PublishFeedbackYAML("{sequence: [0, 1, 1]}"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return feedbacks == 1; }));
  EXPECT_EQ(this->Client->GetFeedbackField("sequence[2]"), "1");

  ASSERT_TRUE(this->Server->SucceedGoal("{sequence: [0, 1, 1, 2]}"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->IsGoalDone(); }));
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Succeeded)
    << this->Client->GetLastError();
  EXPECT_EQ(this->Client->GetResultStatus(), 4);
  EXPECT_EQ(this->Client->GetResultYAML(), "sequence:\n- 0\n- 1\n- 1\n- 2\n");
  EXPECT_FALSE(this->Server->HasActiveGoal());
  EXPECT_EQ(this->Server->GetNumberOfResultsSent(), 1);
  EXPECT_EQ(this->Server->GetNumberOfGoals(), 1); // finished goals are kept
}

// rcl_action_expire_goals: a finished goal leaves the server after the result timeout (node
// time), a running one never does; the timeout is saved with the scene.
TEST_F(ActionTest, FinishedGoalsExpireAfterTheResultTimeout)
{
  this->MakePair("/fibonacci_expiry");
  EXPECT_EQ(this->Server->GetResultTimeout(), 900.0); // rclpy's ActionServer default
  this->Server->SetResultTimeout(0.3);
  ASSERT_GT(this->Client->SendGoalYAML("{order: 3}"), 0);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->HasActiveGoal(); }))
    << this->Output->Errors;
  ASSERT_TRUE(this->Server->SucceedGoal("{sequence: [0, 1, 1, 2]}"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->IsGoalDone(); }));
  ASSERT_GT(this->Client->SendGoalYAML("{order: 4}"), 0); // a second goal, left running
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->GetNumberOfActiveGoals() == 1; }));
  EXPECT_EQ(this->Server->GetNumberOfGoals(), 2);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->GetNumberOfExpiredGoals() == 1; }));
  EXPECT_EQ(this->Server->GetNumberOfGoals(), 1);
  EXPECT_EQ(this->Server->GetNumberOfActiveGoals(), 1);
  ros2vtk_test::SpinUntil(
    this->Logic, [] { return false; }, 0.5);
  EXPECT_EQ(this->Server->GetNumberOfGoals(), 1); // running goals never expire

  this->Server->SetResultTimeout(-1);
  EXPECT_NE(
    this->Output->Errors.find("SetResultTimeout: -1 is not a non-negative number of seconds"),
    std::string::npos);
  EXPECT_EQ(this->Server->GetResultTimeout(), 0.3);
  const std::string saved = this->Logic->GetScene()->WriteToXMLString();
  EXPECT_NE(saved.find("resultTimeout=\"0.3\""), std::string::npos) << saved;
}

TEST_F(ActionTest, CancelRequestedAndConfirmed)
{
  this->MakePair("/to_cancel");
  int cancels = 0;
  vtkNew<vtkCallbackCommand> countCancel;
  countCancel->SetClientData(&cancels);
  countCancel->SetCallback(&Count);
  this->Server->AddObserver(vtkROS2ActionServerNode::CancelRequestedEvent, countCancel);
  ASSERT_GT(this->Client->SendGoalYAML("{order: 10}"), 0);
  ASSERT_TRUE(
    SpinUntil(this->Logic, [&] { return this->Client->GetNumberOfGoalsAccepted() == 1; }));
  EXPECT_FALSE(this->Server->ConfirmGoalCanceled("")) << "no cancel was requested yet";
  ASSERT_TRUE(this->Client->CancelGoal());
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->IsCancelRequested(); }));
  EXPECT_EQ(cancels, 1);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->GetLastCancelReturnCode() == 0; }));
  ASSERT_TRUE(this->Server->ConfirmGoalCanceled("{sequence: [0, 1]}"));
  ASSERT_TRUE(this->Client->WaitForGoal(10.0));
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Canceled);
  EXPECT_EQ(this->Client->GetResultYAML(), "sequence:\n- 0\n- 1\n");
  EXPECT_FALSE(this->Client->CancelGoal()) << "the goal is over";
}

TEST_F(ActionTest, TwoGoalsInFlightEachByIdAndCancelAll)
{
  this->MakePair("/pair");
  std::string feedbackGoal;
  vtkNew<vtkCallbackCommand> onFeedback;
  onFeedback->SetClientData(&feedbackGoal);
  onFeedback->SetCallback([](vtkObject* caller, unsigned long, void* goal, void*) {
    *static_cast<std::string*>(goal) =
      static_cast<vtkROS2ActionClientNode*>(caller)->GetLastEventGoalId();
  });
  this->Client->AddObserver(vtkROS2ActionClientNode::FeedbackReceivedEvent, onFeedback);

  ASSERT_GT(this->Client->SendGoalYAML("{order: 3}"), 0);
  const std::string first = this->Client->GetGoalIdAsString();
  ASSERT_GT(this->Client->SendGoalYAML("{order: 4}"), 0);
  const std::string second = this->Client->GetGoalIdAsString();
  ASSERT_NE(first, second);
  EXPECT_EQ(this->Client->GetNumberOfGoals(), 2);
  EXPECT_EQ(this->Client->GetNthGoalId(0), first);
  EXPECT_EQ(this->Client->GetNthGoalId(1), second);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->GetNumberOfGoalsAccepted() == 2; }))
    << this->Client->GetStatusAsStringById(first.c_str()) << ", "
    << this->Client->GetStatusAsString();

  // The server's current goal is the oldest running one: feedback and result for the first.
  // Published until it arrives: the client knowing the server's feedback writer (IsServerReady)
  // does not mean the writer has matched the client's reader yet (seen under ASan at -j3).
  ASSERT_EQ(this->Server->GetGoalIdAsString(), first);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] {
    EXPECT_TRUE(this->Server->PublishFeedbackYAML("{sequence: [0, 1, 1]}"));
    return this->Client->GetNumberOfFeedbacksById(first.c_str()) >= 1;
  }));
  EXPECT_EQ(feedbackGoal, first);
  EXPECT_EQ(this->Client->GetNumberOfFeedbacksById(second.c_str()), 0);
  EXPECT_EQ(this->Client->GetNumberOfFeedbacks(), 0)
    << "the single-goal API reads the last goal sent";
  ASSERT_TRUE(this->Server->SucceedGoal("{sequence: [0, 1, 1, 2]}"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->IsGoalDoneById(first.c_str()); }));
  EXPECT_EQ(this->Client->GetGoalStatusById(first.c_str()), vtkROS2ActionClientNode::Succeeded);
  EXPECT_EQ(this->Client->GetResultYAMLById(first.c_str()), "sequence:\n- 0\n- 1\n- 1\n- 2\n");
  EXPECT_FALSE(this->Client->IsGoalDone());
  EXPECT_FALSE(this->Client->AreAllGoalsDone());

  // Cancel-all: one request with a zero id and stamp; the server cancels what still runs.
  ASSERT_EQ(this->Server->GetGoalIdAsString(), second);
  ASSERT_TRUE(this->Client->CancelAllGoals());
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->IsCancelRequested(); }));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->GetLastCancelReturnCode() == 0; }));
  ASSERT_TRUE(this->Server->ConfirmGoalCanceled("{sequence: [0, 1]}"));
  ASSERT_TRUE(this->Client->WaitForAllGoals(10.0));
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Canceled);
  EXPECT_EQ(this->Client->GetResultStatusById(second.c_str()), 5);
  EXPECT_EQ(this->Client->GetGoalStatusById(first.c_str()), vtkROS2ActionClientNode::Succeeded);
  EXPECT_EQ(this->Client->GetNumberOfResults(), 2);
  EXPECT_EQ(this->Client->GetGoalStatusById("not a goal"), vtkROS2ActionClientNode::Idle);
  EXPECT_FALSE(this->Client->CancelGoalById(first.c_str())) << "the goal is over";
}

TEST_F(ActionTest, RejectedGoalAndBlockingSend)
{
  this->MakePair("/picky");
  vtkNew<vtkCallbackCommand> reject;
  reject->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    auto* server = static_cast<vtkROS2ActionServerNode*>(caller);
    if (server->GetGoalField("order") == "13")
    {
      server->RejectGoal();
    }
  });
  this->Server->AddObserver(vtkROS2ActionServerNode::GoalReceivedEvent, reject);
  EXPECT_EQ(this->Client->SendGoalAndWait("{order: 13}", 5.0), "");
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Rejected);
  EXPECT_EQ(std::string(this->Client->GetLastError()), "goal rejected by /picky");
  EXPECT_EQ(this->Server->GetNumberOfGoalsRejected(), 1);
  EXPECT_FALSE(this->Server->HasActiveGoal());
  EXPECT_FALSE(this->Server->RejectGoal()) << "only inside the event";
}

TEST_F(ActionTest, ForeignFeedbackAndMalformedStatusAreIgnored)
{
  this->MakePair("/crowded");
  std::string error;
  auto raw = ros2vtk::wire::Participant::create(
    "stranger", "", ros2vtk::wire::ParticipantOptions::from_environment(), &error);
  ASSERT_TRUE(raw) << error;
  const ros2vtk::wire::ActionTypeSupport* type =
    ros2vtk::wire::find_action_type("test_msgs/action/Fibonacci");
  ASSERT_NE(type, nullptr);
  ros2vtk::scene::ActionMembers at;
  ASSERT_TRUE(ros2vtk::scene::find_action_members(*type, at, &error)) << error;
  auto feedback = raw->create_publisher(*type->feedback_message(), "/crowded/_action/feedback",
    ros2vtk::wire::QoS::default_profile(), &error);
  // A status table that writes a sequence length far beyond the payload (what a broken or
  // hostile server would send): the client's reader must reject it.
  static ros2vtk::wire::MessageTypeSupport hostileStatus = *type->status();
  hostileStatus.serialize = [](const void*, ros2vtk::wire::CdrWriter& writer) {
    writer.write(static_cast<uint32_t>(0x7fffffff));
  };
  auto status = raw->create_publisher(
    hostileStatus, "/crowded/_action/status", ros2vtk::wire::QoS::transient_local(1), &error);
  ASSERT_TRUE(feedback && status) << error;
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] { return feedback->matched_subscriptions() > 0 && status->matched_subscriptions() > 0; }));

  ASSERT_GT(this->Client->SendGoalYAML("{order: 4}"), 0);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->HasActiveGoal(); }));
  // Feedback of another client's goal (another id) and a malformed status sample.
  void* other = type->feedback_message()->create();
  ros2vtk::scene::member<uint8_t>(other, at.FeedbackId) = 0x5a; // first byte of the goal id
  ASSERT_TRUE(feedback->publish(other));
  type->feedback_message()->destroy(other);
  void* blank = hostileStatus.create();
  ASSERT_TRUE(status->publish(blank));
  hostileStatus.destroy(blank);
  ros2vtk_test::SpinUntil(
    this->Logic, [] { return false; }, 0.5);
  EXPECT_EQ(this->Client->GetNumberOfFeedbacks(), 0) << "feedback of another goal is not ours";
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] {
      return this->Output->Warnings.find("malformed feedback/status sample(s) rejected") !=
        std::string::npos;
    }))
    << this->Output->Warnings;
  EXPECT_NE(this->Output->Warnings.find("action '/crowded'"), std::string::npos)
    << this->Output->Warnings;

  ASSERT_TRUE(this->Server->PublishFeedbackYAML("{sequence: [0, 1, 1]}"));
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Client->GetNumberOfFeedbacks() == 1; }));
  ASSERT_TRUE(this->Server->SucceedGoal("{sequence: [0, 1, 1, 2, 3]}"));
  ASSERT_TRUE(this->Client->WaitForGoal(10.0));
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Succeeded)
    << this->Client->GetLastError();
}

TEST_F(ActionTest, MalformedGoalRequestsAreRejectedAndTheServerKeepsServing)
{
  this->MakePair("/hostile_goals");
  std::string error;
  auto raw = ros2vtk::wire::Participant::create(
    "goal_garbler", "", ros2vtk::wire::ParticipantOptions::from_environment(), &error);
  ASSERT_TRUE(raw) << error;
  const ros2vtk::wire::ServiceTypeSupport* sendGoal =
    ros2vtk::wire::find_action_type("test_msgs/action/Fibonacci")->send_goal();
  // X_SendGoal_Request on the wire, cut after 3 bytes of the goal id.
  static ros2vtk::wire::MessageTypeSupport hostileRequest = *sendGoal->request();
  static const ros2vtk::wire::MessageTypeSupport* realResponse = sendGoal->response();
  hostileRequest.serialize = [](const void*, ros2vtk::wire::CdrWriter& writer) {
    writer.write(static_cast<uint8_t>(1));
    writer.write(static_cast<uint8_t>(2));
    writer.write(static_cast<uint8_t>(3));
  };
  static const ros2vtk::wire::ServiceTypeSupport hostile{ sendGoal->ros_type,
    [] { return static_cast<const ros2vtk::wire::MessageTypeSupport*>(&hostileRequest); },
    [] { return realResponse; }, sendGoal->type_hash, sendGoal->description };
  auto client = raw->create_service_client(
    hostile, "/hostile_goals/_action/send_goal", ros2vtk::wire::QoS::services(), &error);
  ASSERT_TRUE(client) << error;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return client->is_server_available(); }));
  void* ignored = hostileRequest.create();
  ASSERT_GT(client->send_request(ignored), 0);
  hostileRequest.destroy(ignored);
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] {
      return this->Output->Warnings.find("malformed request(s) rejected") != std::string::npos;
    }))
    << this->Output->Warnings;
  EXPECT_NE(this->Output->Warnings.find("action '/hostile_goals'"), std::string::npos);
  EXPECT_EQ(this->Server->GetNumberOfGoalsReceived(), 0) << "no malformed goal reached the script";

  ASSERT_GT(this->Client->SendGoalYAML("{order: 1}"), 0);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->HasActiveGoal(); }));
  ASSERT_TRUE(this->Server->AbortGoal(""));
  ASSERT_TRUE(this->Client->WaitForGoal(10.0));
  EXPECT_EQ(this->Client->GetGoalStatus(), vtkROS2ActionClientNode::Aborted)
    << this->Client->GetLastError();
  EXPECT_EQ(this->Client->GetResultStatus(), 6);
}

TEST_F(ActionTest, BadUseGivesClearErrors)
{
  this->MakePair("/misused");
  EXPECT_FALSE(this->Server->SucceedGoal("{sequence: [1]}"));
  EXPECT_NE(this->Output->Errors.find("SucceedGoal: no goal is running"), std::string::npos)
    << this->Output->Errors;
  EXPECT_FALSE(this->Server->PublishFeedbackYAML("{sequence: [1]}"));
  EXPECT_FALSE(this->Client->CancelGoal());
  EXPECT_EQ(this->Client->SendGoalYAML("{order: not a number}"), -1);
  ASSERT_GT(this->Client->SendGoalYAML("{order: 2}"), 0);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return this->Server->HasActiveGoal(); }));
  EXPECT_FALSE(this->Server->SucceedGoal("{sequence: nope}")) << "invalid result YAML";
  EXPECT_TRUE(this->Server->HasActiveGoal()) << "the goal is still running";
  EXPECT_EQ(
    this->Other->CreateAndAddActionServerNode("test_msgs/action/Fibonacci", "/misused"), nullptr);
  EXPECT_EQ(this->Node->CreateAndAddActionClientNode("std_srvs/srv/SetBool", "/x"), nullptr);
  EXPECT_NE(
    this->Output->Errors.find("unknown action type 'std_srvs/srv/SetBool'"), std::string::npos);
}

TEST_F(ActionTest, SavedSceneRestoresClientAndServer)
{
  this->MakePair("/saved_action");
  this->Client->SetTimeout(3.5);
  const std::string xml = this->Logic->GetScene()->WriteToXMLString();
  vtkNew<vtkROS2Logic> other;
  ASSERT_TRUE(other->GetScene()->ReadFromXMLString(xml.c_str())) << this->Output->Errors;
  auto* client = other->GetDefaultROS2Node()->GetActionClientNodeByAction("/saved_action");
  ASSERT_NE(client, nullptr);
  EXPECT_STREQ(client->GetActionType(), "test_msgs/action/Fibonacci");
  EXPECT_EQ(client->GetTimeout(), 3.5);
  auto* otherNode =
    vtkROS2NodeNode::SafeDownCast(other->GetScene()->GetNodeByID(this->Other->GetID()));
  ASSERT_NE(otherNode, nullptr);
  auto* server = otherNode->GetActionServerNodeByAction("/saved_action");
  ASSERT_NE(server, nullptr);
  EXPECT_STREQ(server->GetActionType(), "test_msgs/action/Fibonacci");
  other->GetScene()->Clear();
}

// rcl_action registers the action type (pkg/action/X) in the node's type cache beside its
// services' and topics' types, so ~/get_type_description serves it while a client or server
// exists (tests/interop/test_introspection.py checks the answer against rclpy's node).
TEST_F(ActionTest, ActionTypeIsInTheNodeTypeCacheWhileAClientOrServerExists)
{
  const auto* fibonacci = ros2vtk::wire::find_action_type("test_msgs/action/Fibonacci");
  ASSERT_NE(fibonacci, nullptr);
  ASSERT_NE(fibonacci->description, nullptr);
  const ros2vtk::wire::NodeTypeCache& ours = this->Node->GetParticipant()->type_cache();
  const ros2vtk::wire::NodeTypeCache& others = this->Other->GetParticipant()->type_cache();
  const std::string sendGoalHash = fibonacci->send_goal()->type_hash;
  EXPECT_EQ(ours.find(fibonacci->type_hash), nullptr);
  this->MakePair("/cached");
  EXPECT_EQ(ours.find(fibonacci->type_hash), fibonacci->description);
  EXPECT_EQ(others.find(fibonacci->type_hash), fibonacci->description);
  EXPECT_NE(ours.find(sendGoalHash), nullptr);
  // A second client of the same type counts; the type stays until the last one goes.
  ASSERT_NE(
    this->Node->CreateAndAddActionClientNode("test_msgs/action/Fibonacci", "/cached_too"), nullptr);
  ASSERT_TRUE(this->Node->RemoveAndDeleteActionClientNode("/cached"));
  EXPECT_EQ(ours.find(fibonacci->type_hash), fibonacci->description);
  ASSERT_TRUE(this->Node->RemoveAndDeleteActionClientNode("/cached_too"));
  EXPECT_EQ(ours.find(fibonacci->type_hash), nullptr);
  EXPECT_EQ(ours.find(sendGoalHash), nullptr);
  ASSERT_TRUE(this->Other->RemoveAndDeleteActionServerNode("/cached"));
  EXPECT_EQ(others.find(fibonacci->type_hash), nullptr);
}
