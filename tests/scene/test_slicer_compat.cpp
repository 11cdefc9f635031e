// What Slicer scripts call on the scene's plain nodes (issue 14): Slicer's model and transform
// class names, the display-node spelling, a subscriber's target node taking content, and
// SlicerROS2's QoS enums. No DDS: the exchange with rclpy is in
// tests/slicerros2_compat/test_published_examples.py.
#include "vtkROS2ModelNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2TransformNode.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <string>

namespace {
vtkNew<vtkPolyData> ThreePoints()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(1, 2, 3);
  points->InsertNextPoint(4, 5, 6);
  points->InsertNextPoint(7, 8, 9);
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  return polyData;
}
} // namespace

TEST(SlicerCompat, SlicersModelAndTransformClassNamesGiveOurNodes)
{
  vtkNew<vtkROS2Scene> scene;
  EXPECT_STREQ(
    scene->AddNewNodeByClass("vtkMRMLModelNode", "model")->GetClassName(), "vtkROS2ModelNode");
  EXPECT_STREQ(scene->AddNewNodeByClass("vtkMRMLLinearTransformNode", "t")->GetClassName(),
    "vtkROS2TransformNode");
  EXPECT_STREQ(
    scene->AddNewNodeByClass("vtkMRMLTransformNode", "u")->GetClassName(), "vtkROS2TransformNode");
  EXPECT_STREQ(scene->GetNodeByID("vtkROS2ModelNode1")->GetName(), "model");
  EXPECT_EQ(scene->AddNewNodeByClass("vtkMRMLVolumeNode"), nullptr); // not one of ours
}

TEST(SlicerCompat, AModelNodeCopiesPolyDataAndIsItsOwnDisplayNode)
{
  vtkNew<vtkROS2ModelNode> model;
  auto source = ThreePoints();
  std::string error;
  ASSERT_TRUE(model->CopyContentFrom(source, &error)) << error;
  ASSERT_NE(model->GetPolyData(), nullptr);
  EXPECT_NE(model->GetPolyData(), source.GetPointer()); // a copy: the subscriber reuses its object
  source->GetPoints()->SetPoint(0, -1, -1, -1);
  double point[3];
  model->GetPolyData()->GetPoint(0, point);
  EXPECT_EQ(point[0], 1.0);
  EXPECT_EQ(model->GetPolyData()->GetNumberOfPoints(), 3);

  vtkNew<vtkMatrix4x4> matrix;
  EXPECT_FALSE(model->CopyContentFrom(matrix, &error));
  EXPECT_NE(
    error.find("vtkROS2ModelNode cannot take the content of a vtkMatrix4x4"), std::string::npos)
    << error;
  EXPECT_EQ(model->GetPolyData()->GetNumberOfPoints(), 3); // unchanged by the refusal

  model->CreateDefaultDisplayNodes();
  EXPECT_EQ(model->GetDisplayNode(), model.GetPointer());
  model->GetDisplayNode()->SetPointSize(5.0);
  model->GetDisplayNode()->SetColor(0.2, 0.6, 1.0);
  EXPECT_EQ(model->GetPointSize(), 5.0);
  EXPECT_EQ(model->GetColor()[2], 1.0);
}

TEST(SlicerCompat, ATransformNodeTakesAMatrixAndRefusesPolyData)
{
  vtkNew<vtkROS2TransformNode> transform;
  vtkNew<vtkMatrix4x4> matrix;
  matrix->SetElement(1, 3, 42.0);
  std::string error;
  ASSERT_TRUE(transform->CopyContentFrom(matrix, &error)) << error;
  EXPECT_EQ(transform->GetMatrixTransformToParent()->GetElement(1, 3), 42.0);
  auto polyData = ThreePoints();
  EXPECT_FALSE(transform->CopyContentFrom(polyData, &error));
  EXPECT_NE(error.find("a transform node vtkMatrix4x4"), std::string::npos) << error;
  EXPECT_EQ(transform->GetMatrixTransformToParent()->GetElement(1, 3), 42.0);
}

TEST(SlicerCompat, PointSizeIsSavedAndABadOneRefused)
{
  vtkNew<vtkROS2Scene> scene;
  auto* model = vtkROS2ModelNode::SafeDownCast(scene->AddNewNodeByClass("vtkROS2ModelNode", "m"));
  ASSERT_NE(model, nullptr);
  model->SetPointSize(7.5);
  const std::string xml = scene->WriteToXMLString();
  vtkNew<vtkROS2Scene> restored;
  ASSERT_TRUE(restored->ReadFromXMLString(xml.c_str())) << xml;
  EXPECT_EQ(
    vtkROS2ModelNode::SafeDownCast(restored->GetNodeByID(model->GetID()))->GetPointSize(), 7.5);

  std::string bad = xml;
  const auto at = bad.find("pointSize=\"7.5\"");
  ASSERT_NE(at, std::string::npos) << xml;
  bad.replace(at, 15, "pointSize=\"0\"");
  vtkNew<vtkROS2Scene> refused;
  EXPECT_FALSE(refused->ReadFromXMLString(bad.c_str()));
}

TEST(SlicerCompat, QoSEnumsSetThePoliciesAndRefuseUnknownValues)
{
  vtkNew<vtkROS2PublisherGenericNode> pub;
  EXPECT_TRUE(pub->SetQoSHistoryDepth(15));
  EXPECT_TRUE(pub->SetQoSReliability(vtkROS2TopicNode::BestEffort));
  EXPECT_TRUE(pub->SetQoSDurability(vtkROS2TopicNode::TransientLocal));
  EXPECT_EQ(pub->GetHistoryDepth(), 15);
  EXPECT_STREQ(pub->GetReliability(), "best_effort");
  EXPECT_STREQ(pub->GetDurability(), "transient_local");
  EXPECT_EQ(pub->GetQoSReliability(), vtkROS2TopicNode::BestEffort);
  EXPECT_EQ(pub->GetQoSDurability(), vtkROS2TopicNode::TransientLocal);

  // SlicerROS2's values: 0 system default, 1 reliable / transient local, 2 best effort / volatile.
  EXPECT_EQ(static_cast<int>(vtkROS2TopicNode::Reliable), 1);
  EXPECT_EQ(static_cast<int>(vtkROS2TopicNode::Volatile), 2);
  EXPECT_TRUE(pub->SetQoSReliability(vtkROS2TopicNode::ReliabilitySystemDefault));
  EXPECT_TRUE(pub->SetQoSDurability(vtkROS2TopicNode::DurabilitySystemDefault));
  EXPECT_STREQ(pub->GetReliability(), "reliable"); // rmw's default profile
  EXPECT_STREQ(pub->GetDurability(), "volatile");

  EXPECT_FALSE(pub->SetQoSReliability(3));
  EXPECT_FALSE(pub->SetQoSDurability(-1));
  EXPECT_STREQ(pub->GetReliability(), "reliable");
  EXPECT_STREQ(pub->GetDurability(), "volatile");
}
