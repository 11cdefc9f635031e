// Service nodes of two ROS nodes in one process: a client node calls a server node (sync and
// async, events on the spinning thread), malformed requests from a hostile peer are rejected
// with a reason while the server keeps answering, and bad use gets a clear error.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2ServiceClientNode.h"
#include "vtkROS2ServiceServerNode.h"

#include "ros2vtk/wire/CdrWriter.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/QoS.hpp"
#include "ros2vtk/wire/Service.hpp"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk_test::SpinUntil;

class ServiceTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    vtkOutputWindow::SetInstance(this->Output);
    this->Other = vtkSmartPointer<vtkROS2NodeNode>::New();
    this->Logic->GetScene()->AddNode(this->Other);
    ASSERT_TRUE(this->Other->Create("service_peer"));
    this->Node = this->Logic->GetDefaultROS2Node();
    ASSERT_NE(this->Node, nullptr);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  // A SetBool server on `service` answering success = data, message "set <data>".
  vtkROS2ServiceServerNode* AddSetBoolServer(const char* service)
  {
    auto* server = this->Other->CreateAndAddServiceServerNode("std_srvs/srv/SetBool", service);
    if (server)
    {
      this->Answer->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
        auto* self = static_cast<vtkROS2ServiceServerNode*>(caller);
        const std::string data = self->GetRequestField("data");
        self->SetResponseField("success", data.c_str());
        self->SetResponseField("message", ("set " + data).c_str());
      });
      server->AddObserver(vtkROS2ServiceServerNode::RequestReceivedEvent, this->Answer);
    }
    return server;
  }

  vtkNew<ros2vtk_test::CapturingOutputWindow> Output;
  vtkNew<vtkROS2Logic> Logic;
  vtkSmartPointer<vtkROS2NodeNode> Other;
  vtkROS2NodeNode* Node = nullptr;
  vtkNew<vtkCallbackCommand> Answer;
};
} // namespace

TEST_F(ServiceTest, SynchronousAndAsynchronousCallsAreAnsweredOnSpin)
{
  auto* server = this->AddSetBoolServer("/enable");
  ASSERT_NE(server, nullptr) << this->Output->Errors;
  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/SetBool", "enable");
  ASSERT_NE(client, nullptr) << this->Output->Errors;
  EXPECT_STREQ(client->GetServiceName(), "/enable");
  EXPECT_EQ(client->GetRequestYAML(), "data: false\n"); // the blank request
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return client->IsServiceReady(); }));

  EXPECT_EQ(client->Call("{data: true}", 5.0), "success: true\nmessage: set true\n");
  EXPECT_EQ(client->GetStatus(), vtkROS2ServiceClientNode::Succeeded);

  int responses = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&responses);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  client->AddObserver(vtkROS2ServiceClientNode::ResponseReceivedEvent, count);
  ASSERT_TRUE(client->SetRequestField("data", "false"));
  const vtkTypeInt64 id = client->SendAsyncRequest();
  EXPECT_GT(id, 0);
  EXPECT_EQ(responses, 0) << "responses arrive on a spin, never inside the send";
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return responses == 1; })) << client->GetLastError();
  EXPECT_EQ(client->GetLastResponseRequestId(), id);
  EXPECT_EQ(client->GetResponseField("success"), "false");
  EXPECT_EQ(client->GetResponseField("message"), "set false");
  EXPECT_EQ(server->GetNumberOfRequests(), 2);
  EXPECT_EQ(server->GetNumberOfResponses(), 2);
}

TEST_F(ServiceTest, MalformedRequestsAreRejectedWithAReasonAndTheServerKeepsAnswering)
{
  auto* server = this->AddSetBoolServer("/hostile");
  ASSERT_NE(server, nullptr);
  std::string error;
  auto raw = ros2vtk::wire::Participant::create(
    "garbage_maker", "", ros2vtk::wire::ParticipantOptions::from_environment(), &error);
  ASSERT_TRUE(raw) << error;
  // A request table that is SetBool_Request on the wire but writes 7 as the bool (a CDR bool is
  // 0 or 1): what a broken or hostile client would send.
  const ros2vtk::wire::ServiceTypeSupport* setBool =
    ros2vtk::wire::find_service_type("std_srvs/srv/SetBool");
  ASSERT_NE(setBool, nullptr);
  static ros2vtk::wire::MessageTypeSupport hostileRequest = *setBool->request();
  static const ros2vtk::wire::MessageTypeSupport* realResponse = setBool->response();
  hostileRequest.serialize = [](const void*, ros2vtk::wire::CdrWriter& writer) {
    writer.write(static_cast<uint8_t>(7));
  };
  static const ros2vtk::wire::ServiceTypeSupport hostile{ "std_srvs/srv/SetBool",
    [] { return static_cast<const ros2vtk::wire::MessageTypeSupport*>(&hostileRequest); },
    [] { return realResponse; }, setBool->type_hash, setBool->description };
  auto rawClient =
    raw->create_service_client(hostile, "/hostile", ros2vtk::wire::QoS::services(), &error);
  ASSERT_TRUE(rawClient) << error;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return rawClient->is_server_available(); }));
  void* ignored = hostileRequest.create();
  for (int i = 0; i < 5; ++i)
  {
    ASSERT_GT(rawClient->send_request(ignored), 0);
  }
  hostileRequest.destroy(ignored);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return server->GetNumberOfRejectedRequests() == 5; }))
    << "rejected " << server->GetNumberOfRejectedRequests();
  EXPECT_EQ(server->GetNumberOfRequests(), 0) << "no malformed request reached the observer";
  EXPECT_NE(server->GetLastRejection(), "");
  EXPECT_NE(this->Output->Errors.find("malformed request"), std::string::npos)
    << this->Output->Errors;
  EXPECT_NE(this->Output->Errors.find("/hostile"), std::string::npos) << this->Output->Errors;

  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/srv/SetBool", "/hostile");
  ASSERT_NE(client, nullptr);
  EXPECT_EQ(client->Call("{data: true}", 5.0), "success: true\nmessage: set true\n")
    << client->GetLastError();
}

TEST_F(ServiceTest, UnansweredRequestGetsTheDefaultResponseAfterTheTimeout)
{
  auto* server = this->Other->CreateAndAddServiceServerNode("std_srvs/srv/Trigger", "/silent");
  ASSERT_NE(server, nullptr);
  server->SetResponseTimeout(0.3);
  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/srv/Trigger", "/silent");
  ASSERT_NE(client, nullptr);
  EXPECT_EQ(client->Call("{}", 5.0), "success: false\nmessage: ''\n") << client->GetLastError();
  EXPECT_EQ(server->GetNumberOfUnansweredRequests(), 1);
  EXPECT_NE(this->Output->Warnings.find("sending the default response"), std::string::npos);

  // Dropped instead: the client times out.
  server->SetAnswerUnansweredWithDefault(false);
  EXPECT_EQ(client->Call("{}", 1.0), "");
  EXPECT_EQ(client->GetStatus(), vtkROS2ServiceClientNode::TimedOut);
  EXPECT_STREQ(client->GetLastError(), "timed out: /silent sent no response within 1 s");
  EXPECT_NE(this->Output->Errors.find("dropped without a response"), std::string::npos)
    << this->Output->Errors;
}

TEST_F(ServiceTest, DeferredAnswerFromALaterSpin)
{
  auto* server = this->Other->CreateAndAddServiceServerNode("std_srvs/srv/Trigger", "/later");
  ASSERT_NE(server, nullptr);
  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/srv/Trigger", "/later");
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return client->IsServiceReady(); }));
  ASSERT_GT(client->SendAsyncRequestYAML("{}"), 0);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return server->GetNumberOfPendingRequests() == 1; }));
  ASSERT_TRUE(server->SendResponseYAML("{success: true, message: done later}"));
  ASSERT_TRUE(SpinUntil(
    this->Logic, [&] { return client->GetStatus() == vtkROS2ServiceClientNode::Succeeded; }));
  EXPECT_EQ(client->GetResponseField("message"), "done later");
}

TEST_F(ServiceTest, BadUseGivesClearErrors)
{
  EXPECT_EQ(this->Node->CreateAndAddServiceClientNode("std_srvs/srv/Nope", "/x"), nullptr);
  EXPECT_NE(
    this->Output->Errors.find("unknown service type 'std_srvs/srv/Nope'"), std::string::npos);
  EXPECT_NE(this->Output->Errors.find("std_srvs/srv/Trigger"), std::string::npos)
    << "known types listed";
  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/srv/SetBool", "/x");
  ASSERT_NE(client, nullptr);
  EXPECT_EQ(this->Node->CreateAndAddServiceClientNode("std_srvs/srv/SetBool", "/x"), nullptr);
  EXPECT_FALSE(client->SetRequestField("dta", "true"));
  EXPECT_NE(this->Output->Errors.find("has no field 'dta'"), std::string::npos)
    << this->Output->Errors;
  EXPECT_FALSE(client->SetRequestField("data", "maybe"));
  EXPECT_FALSE(client->SetRequestYAML("{data: [1, 2]}"));
  EXPECT_EQ(client->Call("{data: 3.5}", 0.2), "");
  EXPECT_EQ(client->GetStatus(), vtkROS2ServiceClientNode::Failed);

  // The ROS node destroyed: the client stays in the scene, detached, and says so.
  ASSERT_TRUE(this->Node->Destroy());
  EXPECT_EQ(client->SendAsyncRequest(), -1);
  EXPECT_EQ(client->Call("{}", 0.2), "");
  EXPECT_FALSE(client->IsServiceReady());
  EXPECT_TRUE(this->Node->RemoveAndDeleteServiceClientNode("/x"));
}

TEST_F(ServiceTest, SavedSceneRestoresClientAndServer)
{
  auto* server = this->AddSetBoolServer("/saved");
  ASSERT_NE(server, nullptr);
  server->SetResponseTimeout(2.5);
  auto* client = this->Node->CreateAndAddServiceClientNode("std_srvs/srv/SetBool", "/saved");
  ASSERT_NE(client, nullptr);
  client->SetTimeout(3.0);
  vtkROS2Scene* scene = this->Logic->GetScene();
  const std::string xml = scene->WriteToXMLString();
  this->Other = nullptr;
  ASSERT_TRUE(scene->ReadFromXMLString(xml.c_str())) << this->Output->Errors;

  auto* restoredServer =
    vtkROS2ServiceServerNode::SafeDownCast(scene->GetNthNodeByClass(0, "vtkROS2ServiceServerNode"));
  auto* restoredClient =
    vtkROS2ServiceClientNode::SafeDownCast(scene->GetNthNodeByClass(0, "vtkROS2ServiceClientNode"));
  ASSERT_NE(restoredServer, nullptr) << xml;
  ASSERT_NE(restoredClient, nullptr) << xml;
  EXPECT_STREQ(restoredClient->GetServiceType(), "std_srvs/srv/SetBool");
  EXPECT_EQ(restoredClient->GetTimeout(), 3.0);
  EXPECT_EQ(restoredServer->GetResponseTimeout(), 2.5);
  ASSERT_NE(restoredClient->GetROS2Node(), nullptr);
  EXPECT_NE(restoredClient->GetROS2Node()->GetServiceClientNodeByService("/saved"), nullptr)
    << "the ROS node references its restored client";
  // Observers are code, not scene content: attach the answer again.
  restoredServer->AddObserver(vtkROS2ServiceServerNode::RequestReceivedEvent, this->Answer);
  EXPECT_EQ(restoredClient->Call("{data: true}", 5.0), "success: true\nmessage: set true\n")
    << restoredClient->GetLastError();
}
