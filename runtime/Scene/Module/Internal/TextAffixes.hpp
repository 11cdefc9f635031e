// ros2vtk — whether a text starts or ends with another (C++20's std::string::starts_with /
// ends_with, which C++17 lacks), for the Scene module's name parsing (class names, type names).
#ifndef ros2vtk_scene_TextAffixes_hpp
#define ros2vtk_scene_TextAffixes_hpp

#include <string>

namespace ros2vtk {
namespace scene {

inline bool starts_with(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

inline bool ends_with(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace scene
} // namespace ros2vtk

#endif
