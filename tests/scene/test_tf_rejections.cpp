// The tf intake of a ROS node. Rejected tf transforms are warned at a bounded rate (issue 10, item
// 5): a sender publishing a bad transform on every spin (as a 1 kHz broadcaster would) gives the
// receiving ROS node one warning at once, then at most one a second summing what arrived since,
// never one per spin. The sender is a second ROS node of this process with a generic
// tf2_msgs/TFMessage publisher on /tf.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2Tf2LookupNode.h"
#include "ros2vtk/tf2/BufferCore.hpp"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <string>
#include <thread>

namespace {
using ros2vtk_test::SpinUntil;
using Clock = std::chrono::steady_clock;

/// The "tf2: rejected N transform(s)" warnings in `text`: how many, and the sum of their N.
void CountRejectionWarnings(const std::string& text, int& warnings, long& transforms)
{
  static const std::regex line("tf2: rejected ([0-9]+) transform\\(s\\)");
  warnings = 0;
  transforms = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator();
       ++it)
  {
    ++warnings;
    transforms += std::stol((*it)[1].str());
  }
}

class Tf2RejectionsTest : public ::testing::Test
{
protected:
  void SetUp() override { vtkOutputWindow::SetInstance(this->Output); }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  /// A second ROS node of this->Logic, `name`, with a generic tf2_msgs/TFMessage publisher on
  /// /tf (nullptr when either cannot be made).
  vtkROS2PublisherGenericNode* AddTfSender(const char* name)
  {
    this->Logic->GetScene()->AddNode(this->Sender);
    this->Logic->GetScene()->AddNode(this->TfPublisher);
    const bool made = this->Sender->Create(name) &&
      this->TfPublisher->SetROSType("tf2_msgs/msg/TFMessage") &&
      this->TfPublisher->AddToROS2Node(this->Sender->GetID(), "/tf");
    return made ? this->TfPublisher.GetPointer() : nullptr;
  }

  vtkNew<ros2vtk_test::CapturingOutputWindow> Output;
  vtkNew<vtkROS2Logic> Logic;
  vtkNew<vtkROS2NodeNode> Sender;
  vtkNew<vtkROS2PublisherGenericNode> TfPublisher;
};
} // namespace

TEST_F(Tf2RejectionsTest, ManyBadTransformsAreWarnedAtOnceThenAtMostOnceASecond)
{
  vtkROS2NodeNode* receiver = this->Logic->GetDefaultROS2Node();
  ASSERT_NE(receiver, nullptr);
  // The tf listener starts with the node's first lookup.
  ASSERT_NE(receiver->CreateAndAddTf2LookupNode("world", "tool"), nullptr) << this->Output->Errors;

  vtkROS2PublisherGenericNode* tf = this->AddTfSender("bad_tf_sender");
  ASSERT_NE(tf, nullptr) << this->Output->Errors;
  // frame_id == child_frame_id: tf2 refuses it (TF_SELF_TRANSFORM), whatever the stamp.
  const char* bad = "{transforms: [{header: {frame_id: world}, child_frame_id: world, "
                    "transform: {rotation: {w: 1.0}}}]}";

  // Discovery: bad transforms until the first warning, which comes at once.
  int warnings = 0;
  long transforms = 0;
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] {
      EXPECT_TRUE(tf->PublishYAML(bad));
      CountRejectionWarnings(this->Output->Warnings, warnings, transforms);
      return warnings > 0;
    }))
    << "no rejection warning; warnings: " << this->Output->Warnings;
  const auto first = Clock::now();
  EXPECT_EQ(warnings, 1);
  EXPECT_NE(this->Output->Warnings.find("TF_SELF_TRANSFORM"), std::string::npos)
    << this->Output->Warnings;

  // 1.5 s of one bad transform per spin (hundreds of spins), then 1.2 s of spins without any,
  // so that what was held back is reported.
  int spins = 0;
  for (const auto stop = first + std::chrono::milliseconds(1500); Clock::now() < stop; ++spins)
  {
    ASSERT_TRUE(tf->PublishYAML(bad));
    this->Logic->Spin();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  for (const auto stop = Clock::now() + std::chrono::milliseconds(1200); Clock::now() < stop;)
  {
    this->Logic->Spin();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - first).count();

  CountRejectionWarnings(this->Output->Warnings, warnings, transforms);
  EXPECT_GT(spins, 100);
  // Many transforms were rejected and all of them reported (the sums), in few lines: the first at
  // once, then no two within a second.
  EXPECT_GE(transforms, 100) << this->Output->Warnings;
  EXPECT_GE(warnings, 2) << this->Output->Warnings;
  EXPECT_LE(warnings, 1 + static_cast<int>(elapsed)) << "in " << elapsed << " s:\n"
                                                     << this->Output->Warnings;
  EXPECT_LT(warnings * 10, transforms) << this->Output->Warnings;
}

// The tf intake runs where tf2_ros's listener thread runs it, not in the spin (issue 17): the DDS
// thread that deserialized a /tf message inserts it into the node's buffer, so a buffer that is
// never spun still answers, and the next spin only looks up (and reports what was inserted).
// The receiver is a second logic that this test never spins until the buffer answered.
TEST_F(Tf2RejectionsTest, TransformsReachTheBufferWithoutASpin)
{
  vtkNew<vtkROS2Logic> receiverLogic;
  vtkROS2NodeNode* receiver = receiverLogic->GetDefaultROS2Node();
  ASSERT_NE(receiver, nullptr);
  vtkROS2Tf2LookupNode* lookup = receiver->CreateAndAddTf2LookupNode("world", "tool");
  ASSERT_NE(lookup, nullptr) << this->Output->Errors;
  ros2vtk::tf2::BufferCore* buffer = receiver->GetTf2Buffer();
  ASSERT_NE(buffer, nullptr);

  vtkROS2PublisherGenericNode* tf = this->AddTfSender("good_tf_sender");
  ASSERT_NE(tf, nullptr) << this->Output->Errors;
  const char* good = "{transforms: [{header: {stamp: {sec: 5}, frame_id: world}, "
                     "child_frame_id: tool, transform: {translation: {x: 0.25}, "
                     "rotation: {w: 1.0}}}]}";

  // Publish until the receiver's buffer answers; only the sender's logic spins meanwhile.
  bool answered = false;
  for (const auto stop = Clock::now() + std::chrono::seconds(20); !answered && Clock::now() < stop;)
  {
    ASSERT_TRUE(tf->PublishYAML(good));
    this->Logic->Spin();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    answered = buffer->can_transform("world", "tool", ros2vtk::tf2::kLatestTime);
  }
  ASSERT_TRUE(answered) << "the buffer of a node that never spun has no world <- tool";
  EXPECT_STREQ(lookup->GetLookupStatus(), "waiting"); // nodes change on the spin only
  EXPECT_EQ(receiverLogic->GetNumberOfSpins(), 0);

  // The first spin looks up and counts the transforms inserted since the last spin.
  EXPECT_GE(receiverLogic->Spin(), 2); // >= 1 transform inserted + the lookup node's update
  EXPECT_STREQ(lookup->GetLookupStatus(), "ok");
  // 0.25 m on the wire, millimetres in the scene.
  EXPECT_DOUBLE_EQ(lookup->GetMatrixTransformToParent()->GetElement(0, 3), 250.0);
}
