// ros2vtk (private) — the <material> of every URDF visual, read with tinyxml2.
//
// Why not urdfdom's urdf::Material: it cannot tell "no colour given" from an explicit opaque
// black (both are r=g=b=0, a=1), and the loader must know whether the URDF or the mesh file
// decides a visual's colour.
#ifndef ros2vtk_robot_UrdfMaterials_hpp
#define ros2vtk_robot_UrdfMaterials_hpp

#include <array>
#include <map>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// A material as the URDF states it, after looking up robot-level (or earlier) named materials.
struct MaterialSpec
{
  std::string name;
  bool has_color = false;
  std::array<double, 4> rgba{ { 1.0, 1.0, 1.0, 1.0 } };
  std::string texture;
};

class UrdfMaterials
{
public:
  /// Reads the materials of `urdf_xml` (already accepted by urdfdom). False + message when the
  /// XML does not parse.
  bool read(const std::string& urdf_xml, std::string* error);

  /// The material of the `index`-th <visual> of `link` (in document order, as urdfdom keeps
  /// them); an empty spec when it has none.
  MaterialSpec visual_material(const std::string& link, size_t index) const;

  /// Number of <visual> elements of `link` in the document.
  size_t visual_count(const std::string& link) const;

private:
  std::map<std::string, std::vector<MaterialSpec>> visuals_;
};

} // namespace robot
} // namespace ros2vtk

#endif
