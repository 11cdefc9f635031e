// ros2vtk (private) — URDF materials with tinyxml2 (see the header for why).
#include "UrdfMaterials.hpp"

#include <tinyxml2.h>

#include <sstream>

namespace ros2vtk {
namespace robot {
namespace {

MaterialSpec parse_material(const tinyxml2::XMLElement* element)
{
  MaterialSpec spec;
  if (const char* name = element->Attribute("name"))
    spec.name = name;
  if (const tinyxml2::XMLElement* color = element->FirstChildElement("color"))
  {
    if (const char* rgba = color->Attribute("rgba"))
    {
      std::istringstream values(rgba);
      std::array<double, 4> parsed{};
      size_t count = 0;
      while (count < 4 && values >> parsed[count])
        ++count;
      if (count == 4)
      {
        spec.has_color = true;
        spec.rgba = parsed;
      }
    }
  }
  if (const tinyxml2::XMLElement* texture = element->FirstChildElement("texture"))
    if (const char* filename = texture->Attribute("filename"))
      spec.texture = filename;
  return spec;
}

// A named material without colour or texture refers to one defined elsewhere (urdfdom's rule).
MaterialSpec resolve(MaterialSpec spec, const std::map<std::string, MaterialSpec>& named)
{
  if (spec.name.empty())
    return spec;
  auto found = named.find(spec.name);
  if (found == named.end())
    return spec;
  if (!spec.has_color && found->second.has_color)
  {
    spec.has_color = true;
    spec.rgba = found->second.rgba;
  }
  if (spec.texture.empty())
    spec.texture = found->second.texture;
  return spec;
}

} // namespace

bool UrdfMaterials::read(const std::string& urdf_xml, std::string* error)
{
  visuals_.clear();
  tinyxml2::XMLDocument document;
  if (document.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS)
  {
    if (error)
      *error = std::string("URDF is not well-formed XML: ") + document.ErrorStr();
    return false;
  }
  const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
  if (!robot)
  {
    if (error)
      *error = "URDF has no <robot> element";
    return false;
  }
  std::map<std::string, MaterialSpec> named;
  for (const auto* material = robot->FirstChildElement("material"); material;
       material = material->NextSiblingElement("material"))
  {
    MaterialSpec spec = parse_material(material);
    if (!spec.name.empty())
      named[spec.name] = spec;
  }
  for (const auto* link = robot->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link"))
  {
    const char* link_name = link->Attribute("name");
    if (!link_name)
      continue;
    std::vector<MaterialSpec>& specs = visuals_[link_name];
    for (const auto* visual = link->FirstChildElement("visual"); visual;
         visual = visual->NextSiblingElement("visual"))
    {
      const tinyxml2::XMLElement* material = visual->FirstChildElement("material");
      MaterialSpec spec = material ? resolve(parse_material(material), named) : MaterialSpec();
      // A link-level material with a colour becomes known by name to later links, as in urdfdom.
      if (material && !spec.name.empty() && (spec.has_color || !spec.texture.empty()) &&
        !named.count(spec.name))
        named[spec.name] = spec;
      specs.push_back(spec);
    }
  }
  return true;
}

MaterialSpec UrdfMaterials::visual_material(const std::string& link, size_t index) const
{
  auto found = visuals_.find(link);
  if (found == visuals_.end() || index >= found->second.size())
    return {};
  return found->second[index];
}

} // namespace robot
} // namespace ros2vtk

namespace ros2vtk {
namespace robot {

size_t UrdfMaterials::visual_count(const std::string& link) const
{
  auto found = visuals_.find(link);
  return found == visuals_.end() ? 0 : found->second.size();
}

} // namespace robot
} // namespace ros2vtk
