// In-process self-test of the generated node plumbing: a generated publisher on one ROS node,
// the generated subscriber on another (two DDS participants of this process), Spin, and the
// converted values on the other side. Real-peer interop lives in tests/interop.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherDoubleTableNode.h"
#include "vtkROS2PublisherEmptyNode.h"
#include "vtkROS2PublisherImageNode.h"
#include "vtkROS2PublisherPoseStampedNode.h"
#include "vtkROS2PublisherStringNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberDoubleTableNode.h"
#include "vtkROS2SubscriberEmptyNode.h"
#include "vtkROS2SubscriberImageNode.h"
#include "vtkROS2SubscriberPoseStampedNode.h"
#include "vtkROS2SubscriberStringNode.h"

#include "vtkCallbackCommand.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <functional>
#include <thread>

namespace {
using Clock = std::chrono::steady_clock;
using ros2vtk_test::SpinUntil;

class NodesRoundTrip : public ::testing::Test
{
protected:
  void SetUp() override
  {
    this->Talker = vtkSmartPointer<vtkROS2NodeNode>::New();
    this->Logic->GetScene()->AddNode(this->Talker);
    ASSERT_TRUE(this->Talker->Create("nodes_talker"));
    this->Listener = this->Logic->GetDefaultROS2Node();
    ASSERT_NE(this->Listener, nullptr);
  }

  // Creates a matched pair through the SlicerROS2-style calls (by short name).
  template<typename Pub, typename Sub>
  void Connect(const char* type, const char* topic, Pub*& pub, Sub*& sub)
  {
    pub = Pub::SafeDownCast(this->Talker->CreateAndAddPublisherNode(type, topic));
    sub = Sub::SafeDownCast(this->Listener->CreateAndAddSubscriberNode(type, topic));
    ASSERT_NE(pub, nullptr);
    ASSERT_NE(sub, nullptr);
    ASSERT_TRUE(SpinUntil(this->Logic, [&] {
      return pub->GetNumberOfMatchedSubscriptions() > 0 &&
        sub->GetNumberOfMatchedPublications() > 0;
    }));
  }

  vtkNew<vtkROS2Logic> Logic;
  vtkSmartPointer<vtkROS2NodeNode> Talker;
  vtkROS2NodeNode* Listener = nullptr;
};
} // namespace

TEST_F(NodesRoundTrip, StringValue)
{
  vtkROS2PublisherStringNode* pub = nullptr;
  vtkROS2SubscriberStringNode* sub = nullptr;
  this->Connect("String", "/nodes_string", pub, sub);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(sub->GetLastMessage(), "") << "default before the first message";
  EXPECT_EQ(pub->Publish("Hello world."), 1);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return sub->GetNumberOfMessages() >= 1; }));
  EXPECT_EQ(sub->GetLastMessage(), "Hello world.");
  EXPECT_EQ(sub->GetNewMessage(sub->GetNumberOfNewMessages() - 1), "Hello world.");
}

TEST_F(NodesRoundTrip, PoseStampedMillimetresStampAndFrame)
{
  vtkROS2PublisherPoseStampedNode* pub = nullptr;
  vtkROS2SubscriberPoseStampedNode* sub = nullptr;
  this->Connect("PoseStamped", "/nodes_pose", pub, sub);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(sub->GetLastMessage(), nullptr) << "nothing before the first message";
  pub->SetFrameID("world");
  vtkSmartPointer<vtkMatrix4x4> matrix;
  matrix.TakeReference(pub->GetBlankMessage());
  matrix->SetElement(0, 3, 100.0); // mm
  matrix->SetElement(1, 3, -20.0);
  int events = 0;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&events);
  observer->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  // `events` lives on this test's stack: the observer must go before the fixture's teardown
  // spins and removes `sub` (it fired into a dead stack frame there and corrupted it).
  struct RemoveObserverAtExit
  {
    vtkObject* Subject;
    unsigned long Tag;
    ~RemoveObserverAtExit() { this->Subject->RemoveObserver(this->Tag); }
  } removeAtExit{ sub, sub->AddObserver(vtkCommand::ModifiedEvent, observer) };

  const double before = static_cast<double>(std::time(nullptr));
  EXPECT_EQ(pub->Publish(matrix), 1);
  ASSERT_TRUE(SpinUntil(this->Logic, [&] { return sub->GetNumberOfMessages() >= 1; }));
  EXPECT_GE(events, 1);
  vtkMatrix4x4* received = sub->GetLastMessage();
  ASSERT_NE(received, nullptr) << sub->GetLastConversionError();
  EXPECT_NEAR(received->GetElement(0, 3), 100.0, 1e-9);
  EXPECT_NEAR(received->GetElement(1, 3), -20.0, 1e-9);
  EXPECT_EQ(sub->GetLastMessage(), received) << "cached node-owned object";
  EXPECT_EQ(sub->GetLastMessageFrameID(), "world");
  EXPECT_GE(sub->GetLastMessageTime(), before - 1.0) << "stamped with the current time";

  // ScaleLengths off on the subscriber: the same message reads in metres.
  sub->ScaleLengthsOff();
  ASSERT_NE(sub->GetLastMessage(), nullptr);
  EXPECT_NEAR(sub->GetLastMessage()->GetElement(0, 3), 0.1, 1e-12) << "cache follows the scale";
  vtkNew<vtkMatrix4x4> metres;
  ASSERT_TRUE(sub->GetLastMessage(metres));
  EXPECT_NEAR(metres->GetElement(0, 3), 0.1, 1e-12);
}

TEST_F(NodesRoundTrip, ImageAndTableAndEmpty)
{
  vtkROS2PublisherImageNode* imagePub = nullptr;
  vtkROS2SubscriberImageNode* imageSub = nullptr;
  this->Connect("UInt8Image", "/nodes_image", imagePub, imageSub);
  ASSERT_FALSE(HasFatalFailure());
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 3, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  for (int y = 0; y < 3; ++y)
  {
    for (int x = 0; x < 4; ++x)
    {
      image->SetScalarComponentFromDouble(x, y, 0, 0, 10 * y + x);
    }
  }
  EXPECT_EQ(imagePub->Publish(image), 1);

  vtkROS2PublisherDoubleTableNode* tablePub = nullptr;
  vtkROS2SubscriberDoubleTableNode* tableSub = nullptr;
  this->Connect("DoubleTable", "/nodes_table", tablePub, tableSub);
  ASSERT_FALSE(HasFatalFailure());
  vtkNew<vtkTable> table;
  for (int c = 0; c < 2; ++c)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(std::to_string(c).c_str());
    column->InsertNextValue(c + 0.5);
    column->InsertNextValue(c + 1.5);
    column->InsertNextValue(c + 2.5);
    table->AddColumn(column);
  }
  EXPECT_EQ(tablePub->Publish(table), 1);

  vtkROS2PublisherEmptyNode* emptyPub = nullptr;
  vtkROS2SubscriberEmptyNode* emptySub = nullptr;
  this->Connect("Empty", "/nodes_empty", emptyPub, emptySub);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(emptyPub->Publish(), 1);

  ASSERT_TRUE(SpinUntil(this->Logic, [&] {
    return imageSub->GetNumberOfMessages() >= 1 && tableSub->GetNumberOfMessages() >= 1 &&
      emptySub->GetNumberOfMessages() >= 1;
  }));
  vtkImageData* received = imageSub->GetLastMessage();
  ASSERT_NE(received, nullptr) << imageSub->GetLastConversionError();
  int dims[3];
  received->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4);
  EXPECT_EQ(dims[1], 3);
  EXPECT_EQ(received->GetScalarComponentAsDouble(3, 2, 0, 0), 23.0);
  EXPECT_EQ(received->GetScalarComponentAsDouble(1, 0, 0, 0), 1.0);

  vtkTable* receivedTable = tableSub->GetLastMessage();
  ASSERT_NE(receivedTable, nullptr) << tableSub->GetLastConversionError();
  EXPECT_EQ(receivedTable->GetNumberOfRows(), 3);
  EXPECT_EQ(receivedTable->GetNumberOfColumns(), 2);
  EXPECT_EQ(receivedTable->GetValue(2, 1).ToDouble(), 3.5);
}

TEST_F(NodesRoundTrip, UnconvertiblePublishIsCountedNotSent)
{
  vtkROS2PublisherPoseStampedNode* pub = nullptr;
  vtkROS2SubscriberPoseStampedNode* sub = nullptr;
  this->Connect("PoseStamped", "/nodes_bad_pose", pub, sub);
  ASSERT_FALSE(HasFatalFailure());
  vtkNew<vtkMatrix4x4> sheared;
  sheared->SetElement(0, 1, 0.5); // not a rotation
  pub->GlobalWarningDisplayOff();
  EXPECT_EQ(pub->Publish(sheared), 0);
  EXPECT_EQ(pub->Publish(static_cast<vtkMatrix4x4*>(nullptr)), 0);
  pub->GlobalWarningDisplayOn();
  EXPECT_NE(std::string(pub->GetLastConversionError()), "");
  EXPECT_EQ(pub->GetNumberOfCalls(), 2);
  EXPECT_EQ(pub->GetNumberOfMessagesSent(), 0);
}
