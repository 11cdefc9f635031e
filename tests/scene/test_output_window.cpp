// The pieces of /rosout logging that need no peer: how VTK's warning text is split into the
// fields of rcl_interfaces/msg/Log, and rcl's logger names. The wire side is proven with an
// rclpy /rosout subscriber in tests/interop/test_rosout.py.
#include "vtkROS2OutputWindow.h"

#include "ros2vtk/wire/Rosout.hpp"

#include <gtest/gtest.h>

#include <string>

TEST(OutputWindow, SplitsVTKWarningTextIntoFileLineClassAndMessage)
{
  std::string file, function, message;
  int line = -1;
  vtkROS2OutputWindow::ParseVTKMessage(
    "Warning: In /src/runtime/Scene/Module/vtkROS2SubscriberNode.cxx, line 117\n"
    "vtkROS2SubscriberStringNode (0x55d0c8e0a2b0): /bad: 2 malformed sample(s) rejected\n\n",
    file, line, function, message);
  EXPECT_EQ(file, "/src/runtime/Scene/Module/vtkROS2SubscriberNode.cxx");
  EXPECT_EQ(line, 117);
  EXPECT_EQ(function, "vtkROS2SubscriberStringNode");
  EXPECT_EQ(message, "/bad: 2 malformed sample(s) rejected");
}

TEST(OutputWindow, KeepsTextWithoutVTKFramingWhole)
{
  std::string file, function, message;
  int line = -1;
  vtkROS2OutputWindow::ParseVTKMessage(
    "plain text (not from a macro): here\n", file, line, function, message);
  EXPECT_EQ(file, "");
  EXPECT_EQ(line, 0);
  EXPECT_EQ(function, "");
  EXPECT_EQ(message, "plain text (not from a macro): here");
  vtkROS2OutputWindow::ParseVTKMessage(nullptr, file, line, function, message);
  EXPECT_EQ(message, "");
}

TEST(Rosout, LoggerNamesAreNamespaceAndNameJoinedByDots)
{
  EXPECT_EQ(ros2vtk::wire::Rosout::logger_name("/", "slicer"), "slicer");
  EXPECT_EQ(ros2vtk::wire::Rosout::logger_name("/robot1", "slicer"), "robot1.slicer");
  EXPECT_EQ(ros2vtk::wire::Rosout::logger_name("/lab/robot1", "sim"), "lab.robot1.sim");
}
