// Our side of tests/extending/test_lab_exchange.py: a ROS node using a package generated from
// its .msg files (lab_msgs/NeedleTarget, mapping rule of kind point), by its short name, as a
// user of docs/extending.md would.
//   extending_lab_peer echo TOPIC SECONDS   prints "point_mm x y z", "frame F" and the YAML of
//                                           the first message, then exits (1 on timeout)
//   extending_lab_peer pub TOPIC SECONDS    waits for a subscriber, publishes a vtkPoints
//                                           (mapped publisher: unmapped fields stay zero/empty)
//                                           and a full message by YAML (generic publisher)
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2PublisherNeedleTargetNode.h"
#include "vtkROS2SubscriberNeedleTargetNode.h"

#include "vtkNew.h"
#include "vtkPoints.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <thread>

#include "ros2vtkLabTestRegister.hpp" // ros2vtk_register_ros2vtkLabTest_nodes()

namespace {
bool SpinUntil(vtkROS2Logic* logic, const std::function<bool()>& done, double seconds)
{
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end)
  {
    logic->Spin();
    if (done())
    {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return done();
}

int Echo(vtkROS2Logic* logic, const char* topic, double seconds)
{
  auto* sub = vtkROS2SubscriberNeedleTargetNode::SafeDownCast(
    logic->GetDefaultROS2Node()->CreateAndAddSubscriberNode("NeedleTarget", topic));
  if (!sub)
  {
    std::cerr << "no NeedleTarget subscriber class" << std::endl;
    return 2;
  }
  std::cout << "ready" << std::endl;
  if (!SpinUntil(
        logic, [&] { return sub->GetNumberOfMessages() > 0; }, seconds))
  {
    std::cerr << "timeout: no message on " << topic << std::endl;
    return 1;
  }
  vtkPoints* points = sub->GetLastMessage();
  if (!points || points->GetNumberOfPoints() != 1)
  {
    std::cerr << "conversion failed: " << sub->GetLastConversionError() << std::endl;
    return 1;
  }
  double p[3];
  points->GetPoint(0, p);
  std::printf("point_mm %.3f %.3f %.3f\n", p[0], p[1], p[2]);
  std::printf("frame %s\n", sub->GetLastMessageFrameID().c_str());
  std::cout << "yaml\n" << sub->GetLastMessageYAML() << std::flush;
  return 0;
}

int Publish(vtkROS2Logic* logic, const char* topic, double seconds)
{
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  auto* pub = vtkROS2PublisherNeedleTargetNode::SafeDownCast(
    node->CreateAndAddPublisherNode("NeedleTarget", topic));
  // The generic node sends every field (depth, label) the mapping rule does not carry.
  vtkNew<vtkROS2PublisherGenericNode> generic;
  logic->GetScene()->AddNode(generic);
  if (!pub || !generic->SetROSType("lab_msgs/msg/NeedleTarget") ||
    !generic->AddToROS2Node(node->GetID(), topic))
  {
    std::cerr << "cannot create the publishers" << std::endl;
    return 2;
  }
  if (!SpinUntil(
        logic,
        [&] {
          return pub->GetNumberOfMatchedSubscriptions() > 0 &&
            generic->GetNumberOfMatchedSubscriptions() > 0;
        },
        seconds))
  {
    std::cerr << "timeout: no subscriber on " << topic << std::endl;
    return 1;
  }
  pub->SetFrameID("needle_base");
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(10.0, -20.0, 125.0); // mm
  if (pub->Publish(points) != 1)
  {
    std::cerr << "Publish failed: " << pub->GetLastConversionError() << std::endl;
    return 1;
  }
  logic->Spin();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  if (!generic->PublishYAML("{header: {frame_id: tip}, target: {x: 0.5, y: 0.25, z: -1.0}, "
                            "depth: 0.045, label: entry A}"))
  {
    std::cerr << "PublishYAML failed" << std::endl;
    return 1;
  }
  SpinUntil(
    logic, [] { return false; }, 1.0); // let both messages leave
  std::cout << "published 2" << std::endl;
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 4)
  {
    std::cerr << "usage: extending_lab_peer echo|pub TOPIC SECONDS" << std::endl;
    return 2;
  }
  ros2vtk_register_ros2vtkLabTest_nodes();
  vtkNew<vtkROS2Logic> logic;
  const std::string mode = argv[1];
  const double seconds = std::atof(argv[3]);
  if (mode == "echo")
  {
    return Echo(logic, argv[2], seconds);
  }
  if (mode == "pub")
  {
    return Publish(logic, argv[2], seconds);
  }
  std::cerr << "unknown mode " << mode << std::endl;
  return 2;
}
