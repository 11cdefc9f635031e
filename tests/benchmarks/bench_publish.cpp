// bench_publish — the C++ sender of the throughput benchmarks (issue 17): our own scene publisher
// node, beside tests/benchmarks/ros_publisher.py (rclpy), so a receiver's latency can be measured
// without the rclpy publisher's own conversion and serialization in it.
//
// The VTK value is built once; every Publish() converts it to the ROS message, writes
// header.stamp = now (system clock, as the rclpy sender's time.time()) and sends it. Per publish it
// records the duration of the Publish() call: the sender's share (VTK → message, serialization,
// the Fast DDS write). Reliable, volatile, keep last 1000 (as the subscribers). Paced by an
// absolute schedule with sleeps only (two cores: the receiver needs one).
//
//   bench_publish --type PoseStamped|Image|PointCloud2|PoseArray --topic T [--rate HZ] [--seconds
//   S]
//                 [--width W --height H --encoding rgb8|mono16] [--points N] [--poses N] [--wait S]
//
// Prints {"sent": N, "seconds": S, "rate": achieved, "publish_ms": [...]} on stdout.
#include "BenchCommon.hpp"

#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2PublisherImageNode.h"
#include "vtkROS2PublisherPointCloud2Node.h"
#include "vtkROS2PublisherPoseArrayNode.h"
#include "vtkROS2PublisherPoseStampedNode.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkTransformCollection.h>

#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "ros2vtkNodesRegister.hpp" // ros2vtk_register_ros2vtkNodes_nodes()

namespace {

struct Options
{
  std::string type;
  std::string topic;
  double rate = 30.0;
  double seconds = 5.0;
  double wait = 20.0;
  int width = 640;
  int height = 480;
  std::string encoding = "rgb8";
  int points = 100000;
  int poses = 1000;
};

vtkSmartPointer<vtkImageData> make_image(const Options& o)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(o.width, o.height, 1);
  const bool mono16 = o.encoding == "mono16";
  image->AllocateScalars(mono16 ? VTK_UNSIGNED_SHORT : VTK_UNSIGNED_CHAR, mono16 ? 1 : 3);
  auto* bytes = static_cast<unsigned char*>(image->GetScalarPointer());
  const size_t size = static_cast<size_t>(o.width) * o.height * (mono16 ? 2 : 3);
  std::mt19937 random(17);
  for (size_t i = 0; i < size; ++i)
    bytes[i] = static_cast<unsigned char>(random());
  return image;
}

vtkSmartPointer<vtkPolyData> make_cloud(const Options& o)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(o.points);
  for (int i = 0; i < o.points; ++i) // a ramp of finite floats, as ros_publisher.py
    points->SetPoint(
      i, (3 * i % 1000) * 0.001, ((3 * i + 1) % 1000) * 0.001, ((3 * i + 2) % 1000) * 0.001);
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

vtkSmartPointer<vtkTransformCollection> make_poses(const Options& o)
{
  auto poses = vtkSmartPointer<vtkTransformCollection>::New();
  for (int i = 0; i < o.poses; ++i)
  {
    vtkNew<vtkTransform> pose;
    pose->Translate(0.001 * i, 0.0, 0.0);
    poses->AddItem(pose);
  }
  return poses;
}

template<typename Node, typename Value>
int run(const Options& options, Value* value)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  vtkNew<Node> publisher;
  publisher->SetReliability("reliable");
  publisher->SetHistory("keep_last");
  publisher->SetHistoryDepth(1000);
  logic->GetScene()->AddNode(publisher);
  if (!node || !publisher->AddToROS2Node(node->GetID(), options.topic.c_str()))
  {
    std::fprintf(stderr, "bench_publish: cannot publish on %s\n", options.topic.c_str());
    return 1;
  }
  const auto wait_end = bench::Clock::now() + std::chrono::duration<double>(options.wait);
  while (publisher->GetNumberOfMatchedSubscriptions() < 1 && bench::Clock::now() < wait_end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(
    std::chrono::milliseconds(500)); // as ros_publisher.py: let matching settle
  bench::publish_paced(
    options.rate, options.seconds, [&] { return publisher->Publish(value) != 0; },
    [] { return true; });
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  ros2vtk_register_ros2vtkNodes_nodes();
  Options o;
  const bool parsed = bench::OptionParser()
                        .add("--type", &o.type)
                        .add("--topic", &o.topic)
                        .add("--rate", &o.rate)
                        .add("--seconds", &o.seconds)
                        .add("--wait", &o.wait)
                        .add("--width", &o.width)
                        .add("--height", &o.height)
                        .add("--encoding", &o.encoding)
                        .add("--points", &o.points)
                        .add("--poses", &o.poses)
                        .parse(argc, argv);
  if (!parsed)
    return 2;
  if (o.rate <= 0 || o.seconds <= 0 || o.topic.empty())
  {
    std::fprintf(stderr, "bench_publish: --topic, --rate > 0 and --seconds > 0 are required\n");
    return 2;
  }
  if (o.type == "PoseStamped")
  {
    vtkNew<vtkMatrix4x4> pose;
    pose->SetElement(0, 3, 0.1);
    return run<vtkROS2PublisherPoseStampedNode>(o, pose.Get());
  }
  if (o.type == "Image")
    return run<vtkROS2PublisherImageNode>(o, make_image(o).Get());
  if (o.type == "PointCloud2")
    return run<vtkROS2PublisherPointCloud2Node>(o, make_cloud(o).Get());
  if (o.type == "PoseArray")
    return run<vtkROS2PublisherPoseArrayNode>(o, make_poses(o).Get());
  std::fprintf(
    stderr, "usage: bench_publish --type PoseStamped|Image|PointCloud2|PoseArray --topic T\n");
  return 2;
}
