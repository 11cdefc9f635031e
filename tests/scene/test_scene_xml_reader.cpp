// SceneXmlReader: scene-file text into a VTK element tree within bounds (issue 11.4). Each limit
// is checked by counts: the largest document inside a limit reads, one more element, level or
// attribute is refused with a reason, before any VTK element exists. Times are in
// bench_scene_xml (a benchmark, not a test).
#include "Internal/SceneXmlReader.hpp"

#include <vtkXMLDataElement.h>

#include <gtest/gtest.h>

#include <string>

using ros2vtk::scene::ReadSceneXml;
using ros2vtk::scene::SceneXmlLimits;

namespace {

std::string nested(int depth)
{
  std::string text;
  for (int i = 0; i < depth; ++i)
    text += "<e>";
  for (int i = 0; i < depth; ++i)
    text += "</e>";
  return text;
}

std::string flat(int children)
{
  std::string text = "<root>";
  for (int i = 0; i < children; ++i)
    text += "<c/>";
  return text + "</root>";
}

std::string with_attributes(int count)
{
  std::string text = "<root";
  for (int i = 0; i < count; ++i)
    text += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
  return text + "/>";
}

TEST(SceneXmlReader, BuildsTheTreeInDocumentOrderWithDecodedAttributes)
{
  std::string error;
  auto root = ReadSceneXml(
    "<ROS2Scene version=\"1\"><a id=\"x\" note=\"&lt;&amp;&quot;\"><b/></a><c id=\"y\"/>"
    "</ROS2Scene>",
    &error);
  ASSERT_TRUE(root) << error;
  EXPECT_STREQ(root->GetName(), "ROS2Scene");
  EXPECT_STREQ(root->GetAttribute("version"), "1");
  ASSERT_EQ(root->GetNumberOfNestedElements(), 2);
  EXPECT_STREQ(root->GetNestedElement(0)->GetAttribute("note"), "<&\"");
  EXPECT_STREQ(root->GetNestedElement(0)->GetNestedElement(0)->GetName(), "b");
  EXPECT_STREQ(root->GetNestedElement(1)->GetAttribute("id"), "y");
}

TEST(SceneXmlReader, DepthIsBoundedByCount)
{
  SceneXmlLimits limits;
  std::string error;
  EXPECT_TRUE(ReadSceneXml(nested(limits.max_depth), &error)) << error;
  EXPECT_FALSE(ReadSceneXml(nested(limits.max_depth + 1), &error));
  EXPECT_NE(error.find("nested deeper than 16"), std::string::npos) << error;
  // 150 000 levels crashed VTK's recursive element destructor; tinyxml2 stops at 100 levels.
  error.clear();
  EXPECT_FALSE(ReadSceneXml(nested(150000), &error));
  EXPECT_NE(error.find("DEPTH"), std::string::npos) << error;
}

TEST(SceneXmlReader, ElementAndAttributeCountsAreBounded)
{
  SceneXmlLimits limits;
  limits.max_elements = 1000;
  std::string error;
  EXPECT_TRUE(ReadSceneXml(flat(999), &error, limits)) << error; // + the root
  EXPECT_FALSE(ReadSceneXml(flat(1000), &error, limits));
  EXPECT_NE(error.find("more than 1000 elements"), std::string::npos) << error;
  EXPECT_TRUE(ReadSceneXml(with_attributes(256), &error)) << error;
  EXPECT_FALSE(ReadSceneXml(with_attributes(257), &error));
  EXPECT_NE(error.find("more than 256 attributes"), std::string::npos) << error;
}

TEST(SceneXmlReader, SizeIsBoundedBeforeParsing)
{
  SceneXmlLimits limits;
  limits.max_bytes = 1 << 20;
  const std::string big(2 << 20, 'x');
  std::string error;
  auto root = ReadSceneXml("<r a=\"" + big + "\"/>", &error, limits);
  EXPECT_FALSE(root);
  EXPECT_NE(error.find("over the limit of 1048576"), std::string::npos) << error;
  // Within the default limit a 2 MB attribute is read whole.
  root = ReadSceneXml("<r a=\"" + big + "\"/>", &error);
  ASSERT_TRUE(root) << error;
  EXPECT_EQ(std::string(root->GetAttribute("a")).size(), big.size());
}

TEST(SceneXmlReader, MalformedTextAndInvalidUtf8)
{
  std::string error;
  EXPECT_FALSE(ReadSceneXml("<a><b></a>", &error));
  EXPECT_NE(error.find("not a well-formed XML document"), std::string::npos) << error;
  EXPECT_FALSE(ReadSceneXml("", &error));
  auto root = ReadSceneXml("<a n=\"x\xff"
                           "y\"/>",
    &error);
  ASSERT_TRUE(root) << error;
  EXPECT_STREQ(root->GetAttribute("n"), "x\xEF\xBF\xBDy"); // U+FFFD, the project's policy
}

} // namespace
