// ros2vtk (private) — urdfdom's parser with its diagnostics captured, so a broken URDF fails
// with urdfdom's own words ("Joint [j] is missing a parent…") instead of a console line.
#ifndef ros2vtk_robot_UrdfDiagnostics_hpp
#define ros2vtk_robot_UrdfDiagnostics_hpp

#include <urdf_model/model.h>
#include <urdf_world/types.h>

#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// urdf::parseURDF, with the messages urdfdom logs through console_bridge collected into
/// `error` when it fails, and into `messages` either way (urdfdom also logs what it drops while
/// accepting a URDF, e.g. a visual whose geometry does not parse). Kept off the console.
/// Serialised by a mutex because console_bridge's output handler is process-wide.
urdf::ModelInterfaceSharedPtr parse_urdf_with_diagnostics(
  const std::string& urdf_xml, std::string* error, std::vector<std::string>* messages = nullptr);

} // namespace robot
} // namespace ros2vtk

#endif
