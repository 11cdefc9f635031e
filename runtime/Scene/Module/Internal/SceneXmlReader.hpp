// ros2vtk — reads scene-file text into a VTK XML element tree within fixed bounds (private to
// the Scene module). VTK's own reader (vtkXMLUtilities) is unsafe on a hostile file: 150 000
// nested elements crash its recursive element destructor and a 50 MB attribute parses in
// quadratic time (issue 11.4). Here tinyxml2 parses (linear, its depth capped at 100), the
// limits below are checked on its tree, and only then is the vtkXMLDataElement tree built,
// iteratively. Attribute text follows the project's invalid-UTF-8 policy (U+FFFD, counted).
#ifndef ros2vtk_scene_SceneXmlReader_hpp
#define ros2vtk_scene_SceneXmlReader_hpp

#include <vtkSmartPointer.h>

#include <cstddef>
#include <string>

class vtkXMLDataElement;

namespace ros2vtk {
namespace scene {

/// Far above any scene a person saves (a few hundred nodes, depth 3), far below what hurts.
struct SceneXmlLimits
{
  std::size_t max_bytes = 64u * 1024u * 1024u;
  int max_depth = 16;
  std::size_t max_elements = 100000;
  std::size_t max_attributes_per_element = 256;
};

/// The element tree of `text`, or nullptr with `error` naming the first limit or syntax error.
vtkSmartPointer<vtkXMLDataElement> ReadSceneXml(
  const std::string& text, std::string* error, const SceneXmlLimits& limits = SceneXmlLimits());

/// The contents of `path`, refused before reading when larger than limits.max_bytes.
bool ReadSceneXmlFile(const char* path, std::string* text, std::string* error,
  const SceneXmlLimits& limits = SceneXmlLimits());

} // namespace scene
} // namespace ros2vtk

#endif
