// Test-only publisher/subscriber classes on std_msgs/msg/String, written the way the generated
// node classes are (subclasses of the runtime's bases), so the scene's contract is exercised
// without the generated node module. Registered as short name "TestString".
#ifndef ros2vtk_tests_TestStringNodes_h
#define ros2vtk_tests_TestStringNodes_h

#include "vtkROS2PublisherNode.h"
#include "vtkROS2SubscriberNode.h"

#include <string>
#include <vector>

class vtkROS2PublisherTestStringNode : public vtkROS2PublisherNode
{
public:
  static vtkROS2PublisherTestStringNode* New();
  vtkTypeMacro(vtkROS2PublisherTestStringNode, vtkROS2PublisherNode);

  bool Publish(const std::string& text);
  const char* GetSlicerType() const override { return "std::string"; }

protected:
  vtkROS2PublisherTestStringNode() = default;
  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
};

class vtkROS2SubscriberTestStringNode : public vtkROS2SubscriberNode
{
public:
  static vtkROS2SubscriberTestStringNode* New();
  vtkTypeMacro(vtkROS2SubscriberTestStringNode, vtkROS2SubscriberNode);

  /// The newest message's text ("" before the first).
  std::string GetLastMessage() const;
  const char* GetSlicerType() const override { return "std::string"; }

  /// What OnNewMessages saw, spin after spin: the texts of GetNewRawMessage(0..n-1).
  std::vector<std::vector<std::string>> Batches;

protected:
  vtkROS2SubscriberTestStringNode() = default;
  const ros2vtk::wire::MessageTypeSupport& GetMessageTypeSupport() const override;
  void OnNewMessages() override;
};

/// Registers both classes (idempotent).
void RegisterTestStringNodes();

#endif
