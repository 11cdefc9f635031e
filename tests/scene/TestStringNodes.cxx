#include "TestStringNodes.h"

#include "NodeClassRegistry.hpp"

#include "ros2vtk/std_msgs/msg/string.hpp"

#include "vtkObjectFactory.h"

#include <stdexcept>

using StringMessage = ros2vtk::std_msgs::msg::String;

vtkStandardNewMacro(vtkROS2PublisherTestStringNode);
vtkStandardNewMacro(vtkROS2SubscriberTestStringNode);

bool vtkROS2PublisherTestStringNode::Publish(const std::string& text)
{
  StringMessage message;
  message.data = text;
  return this->PublishMessage(&message);
}

const ros2vtk::wire::MessageTypeSupport& vtkROS2PublisherTestStringNode::GetMessageTypeSupport()
  const
{
  return StringMessage::type_support();
}

std::string vtkROS2SubscriberTestStringNode::GetLastMessage() const
{
  const auto* message = static_cast<const StringMessage*>(this->GetLastRawMessage());
  return message ? message->data : std::string();
}

const ros2vtk::wire::MessageTypeSupport& vtkROS2SubscriberTestStringNode::GetMessageTypeSupport()
  const
{
  return StringMessage::type_support();
}

void vtkROS2SubscriberTestStringNode::OnNewMessages()
{
  std::vector<std::string> batch;
  for (int i = 0; i < this->GetNumberOfNewMessages(); ++i)
  {
    batch.push_back(static_cast<const StringMessage*>(this->GetNewRawMessage(i))->data);
  }
  this->Batches.push_back(batch);
}

namespace {
template<typename T>
vtkROS2SceneNode* Create()
{
  return T::New();
}
} // namespace

void RegisterTestStringNodes()
{
  using namespace ros2vtk::scene;
  auto& registry = NodeClassRegistry::instance();
  std::string error;
  if (!registry.add({ "TestString", "vtkROS2PublisherTestStringNode", "std_msgs/msg/String",
                      NodeDirection::Publisher, &Create<vtkROS2PublisherTestStringNode> },
        &error) ||
    !registry.add({ "TestString", "vtkROS2SubscriberTestStringNode", "std_msgs/msg/String",
                    NodeDirection::Subscriber, &Create<vtkROS2SubscriberTestStringNode> },
      &error))
  {
    throw std::runtime_error(error);
  }
}
