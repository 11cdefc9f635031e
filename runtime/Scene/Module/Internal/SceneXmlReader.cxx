// ros2vtk — bounded scene-file reading (see SceneXmlReader.hpp for why).
#include "SceneXmlReader.hpp"

#include "ros2vtk/wire/Utf8.hpp"

#include <vtkNew.h>
#include <vtkXMLDataElement.h>

#include <tinyxml2.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace ros2vtk {
namespace scene {

namespace {

bool Fail(std::string* error, const std::string& what)
{
  if (error)
  {
    *error = what;
  }
  return false;
}

/// Depth, element and attribute counts of the parsed document against the limits; iterative.
bool CheckLimits(const tinyxml2::XMLElement* root, const SceneXmlLimits& limits, std::string* error)
{
  std::vector<std::pair<const tinyxml2::XMLElement*, int>> pending{ { root, 1 } };
  std::size_t elements = 0;
  while (!pending.empty())
  {
    const auto [element, depth] = pending.back();
    pending.pop_back();
    if (++elements > limits.max_elements)
    {
      return Fail(error, "more than " + std::to_string(limits.max_elements) + " elements");
    }
    if (depth > limits.max_depth)
    {
      return Fail(error,
        "elements nested deeper than " + std::to_string(limits.max_depth) + " (line " +
          std::to_string(element->GetLineNum()) + ")");
    }
    std::size_t attributes = 0;
    for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a; a = a->Next())
    {
      if (++attributes > limits.max_attributes_per_element)
      {
        return Fail(error,
          "element <" + wire::clip_for_message(element->Name(), 80) + "> on line " +
            std::to_string(element->GetLineNum()) + " has more than " +
            std::to_string(limits.max_attributes_per_element) + " attributes");
      }
    }
    for (const tinyxml2::XMLElement* child = element->FirstChildElement(); child;
         child = child->NextSiblingElement())
    {
      pending.emplace_back(child, depth + 1);
    }
  }
  return true;
}

std::string Repaired(const char* text)
{
  std::string value = text ? text : "";
  wire::repair_utf8(value);
  return value;
}

} // namespace

vtkSmartPointer<vtkXMLDataElement> ReadSceneXml(
  const std::string& text, std::string* error, const SceneXmlLimits& limits)
{
  if (text.size() > limits.max_bytes)
  {
    Fail(error,
      "the document is " + std::to_string(text.size()) + " bytes, over the limit of " +
        std::to_string(limits.max_bytes));
    return nullptr;
  }
  tinyxml2::XMLDocument document(true, tinyxml2::PRESERVE_WHITESPACE);
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
  {
    Fail(error,
      "not a well-formed XML document (" +
        wire::clip_for_message(Repaired(document.ErrorStr()), 300) + ")");
    return nullptr;
  }
  const tinyxml2::XMLElement* root = document.RootElement();
  if (!root)
  {
    Fail(error, "the XML document has no root element");
    return nullptr;
  }
  if (!CheckLimits(root, limits, error))
  {
    return nullptr;
  }
  // Within the limits: the VTK tree, breadth of one explicit stack instead of recursion.
  auto result = vtkSmartPointer<vtkXMLDataElement>::New();
  std::vector<std::pair<const tinyxml2::XMLElement*, vtkXMLDataElement*>> pending{ { root,
    result } };
  while (!pending.empty())
  {
    const auto [source, target] = pending.back();
    pending.pop_back();
    target->SetName(Repaired(source->Name()).c_str());
    for (const tinyxml2::XMLAttribute* a = source->FirstAttribute(); a; a = a->Next())
    {
      target->SetAttribute(Repaired(a->Name()).c_str(), Repaired(a->Value()).c_str());
    }
    if (const char* characters = source->GetText())
    {
      const std::string data = Repaired(characters);
      target->SetCharacterData(data.c_str(), static_cast<int>(data.size()));
    }
    for (const tinyxml2::XMLElement* child = source->FirstChildElement(); child;
         child = child->NextSiblingElement())
    {
      vtkNew<vtkXMLDataElement> nested;
      target->AddNestedElement(nested); // the parent holds it; the pointer stays valid
      pending.emplace_back(child, nested.GetPointer());
    }
  }
  return result;
}

bool ReadSceneXmlFile(
  const char* path, std::string* text, std::string* error, const SceneXmlLimits& limits)
{
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path, ec))
  {
    return Fail(error, std::string("cannot open '") + path + "'");
  }
  if (bytes > limits.max_bytes)
  {
    return Fail(error,
      std::string("'") + path + "' is " + std::to_string(bytes) + " bytes, over the limit of " +
        std::to_string(limits.max_bytes));
  }
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  contents << file.rdbuf();
  if (!file && !file.eof())
  {
    return Fail(error, std::string("cannot read '") + path + "'");
  }
  *text = contents.str();
  return true;
}

} // namespace scene
} // namespace ros2vtk
