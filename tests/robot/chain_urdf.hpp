// ros2vtk tests — a long URDF chain, written here so both the VTK-free kinematics tests and the
// visual loader tests can check that nothing walks a description by recursion (issue 11.2).
#ifndef ros2vtk_tests_robot_chain_urdf_hpp
#define ros2vtk_tests_robot_chain_urdf_hpp

#include <string>

namespace ros2vtk_test {

/// A URDF chain of `links` links joined by fixed joints 1 mm apart along z. The root is
/// named last in sort order (link_<links-1> ... link_0), so urdfdom's name-sorted map holds the
/// deepest link first.
inline std::string chain_urdf(int links)
{
  std::string text = "<robot name=\"chain\">\n";
  for (int i = 0; i < links; ++i)
    text += "<link name=\"link_" + std::to_string(links - 1 - i) + "\"/>\n";
  for (int i = 1; i < links; ++i)
    text += "<joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"link_" +
      std::to_string(links - i) + "\"/><child link=\"link_" + std::to_string(links - 1 - i) +
      "\"/><origin xyz=\"0 0 0.001\"/></joint>\n";
  return text + "</robot>\n";
}

} // namespace ros2vtk_test

#endif
