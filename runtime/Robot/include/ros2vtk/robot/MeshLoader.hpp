// ros2vtk — reads one mesh file into vtkPolyData: STL through VTK's reader; PLY (whole file
// checked against its header first), OBJ (+ MTL colours), Collada (arrays and counts checked
// first), glTF/GLB and every other format assimp knows through assimp (VTK 9.1's PLY reader crashes
// on malformed files and its OBJ readers get MTL colours wrong, see MeshLoader.cpp). Plain C++ on
// VTK (not wrapped); the robot loader calls it once per distinct mesh file.
#ifndef ros2vtk_robot_MeshLoader_hpp
#define ros2vtk_robot_MeshLoader_hpp

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// A loaded mesh, in the file's own units (metres for ROS meshes; a Collada <unit> is applied).
struct MeshData
{
  vtkSmartPointer<vtkPolyData> polydata; ///< triangles (and the reader's normals, if any)
  /// One colour for the whole mesh, from its file (a Collada/OBJ material, …), when it has one.
  bool has_color = false;
  std::array<double, 4> color{ { 1.0, 1.0, 1.0, 1.0 } }; ///< RGBA in [0, 1]
  /// Several colours: per-point RGBA (unsigned char) in the point-data array named
  /// kVertexColorArray, also set as the active scalars.
  bool has_vertex_colors = false;
  /// Texture image file names named by the file's materials (recorded, not loaded).
  std::vector<std::string> textures;
};

/// Name of the per-point colour array (RGBA, unsigned char) when MeshData::has_vertex_colors.
constexpr const char* kVertexColorArray = "Colors";

/// Loads mesh files. Chooses the reader by the lower-cased extension. Never throws; errors
/// come back as false + a message naming the file and the reason: a file that cannot be opened
/// (the system's reason), is empty, is a Git LFS pointer, has an unknown extension, or the
/// reader's complaint.
class MeshLoader
{
public:
  /// Reads `path` (an existing file; resolve URIs first with ResourceResolver).
  bool load(const std::string& path, MeshData* mesh, std::string* error) const;

  /// Lower-cased extensions read by VTK here (.stl); every other extension goes to assimp.
  static std::vector<std::string> vtk_extensions();
  /// True when assimp (as built on this machine) claims it can read the extension, e.g. ".dae".
  static bool assimp_reads(const std::string& extension);
};

} // namespace robot
} // namespace ros2vtk

#endif
