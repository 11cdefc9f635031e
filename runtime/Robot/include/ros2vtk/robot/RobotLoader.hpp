// ros2vtk — a robot's visuals from its URDF, as VTK geometry: every <visual> of every link,
// meshes (through ResourceResolver + MeshLoader, with the visual's scale) and primitives, the
// visual origins and the colours. Plain C++ on urdfdom + VTK (not wrapped); the scene's robot
// node calls it and puts each visual under the link's transform node.
//
// Units: everything stays in metres here (URDF units); the scene applies the m -> mm policy.
#ifndef ros2vtk_robot_RobotLoader_hpp
#define ros2vtk_robot_RobotLoader_hpp

#include "ros2vtk/robot/MeshCache.hpp"
#include "ros2vtk/robot/MeshLoader.hpp"
#include "ros2vtk/robot/ResourceResolver.hpp"
#include "ros2vtk/robot/XacroProcessor.hpp"

#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace urdf {
class ModelInterface; // urdfdom's parsed model (urdf_model/model.h)
}

namespace ros2vtk {
namespace robot {

/// What a visual's geometry came from. Placeholder: the mesh could not be loaded (see the
/// link's warnings) and a 1 cm cube stands in for it.
enum class VisualKind
{
  Mesh,
  Box,
  Cylinder,
  Sphere,
  Placeholder
};

/// One <visual> of a link.
struct LinkVisual
{
  std::string name; ///< the <visual name="…"> attribute (often empty)
  VisualKind kind = VisualKind::Placeholder;
  /// Geometry in the visual's own frame, scale applied, metres. Shared between visuals that use
  /// the same mesh file and scale (the loader's cache): treat it as read-only.
  vtkSmartPointer<vtkPolyData> geometry;
  /// Pose of the visual in its link's frame (the <origin>), metres.
  vtkSmartPointer<vtkMatrix4x4> origin;

  std::string mesh_uri;  ///< as written in the URDF (meshes and placeholders)
  std::string mesh_path; ///< the file it resolved to ("" when it did not)
  std::array<double, 3> mesh_scale{ { 1.0, 1.0, 1.0 } };

  /// The URDF material: its name (may be empty), and its rgba when it gives one (materials named
  /// at robot level are looked up).
  std::string material_name;
  bool has_material_color = false;
  std::array<double, 4> material_color{ { 1.0, 1.0, 1.0, 1.0 } };
  std::string material_texture; ///< <texture filename="…">, recorded, not loaded

  /// Colours from the mesh file itself (Collada/OBJ materials): one colour, or per-point colours
  /// in geometry's kVertexColorArray; and the texture files its materials name.
  bool has_mesh_color = false;
  std::array<double, 4> mesh_color{ { 1.0, 1.0, 1.0, 1.0 } };
  bool has_vertex_colors = false;
  std::vector<std::string> mesh_textures;

  /// The colour to show: the URDF material's when it has one (RViz's rule), else the mesh
  /// file's single colour, else a neutral grey. Per-point colours, when present, are meant to
  /// win over this unless the URDF gave a colour.
  std::array<double, 4> display_color() const;
};

/// All visuals of one link, in URDF order, and what went wrong while loading them.
struct LinkVisuals
{
  std::string link;
  std::vector<LinkVisual> visuals;
  std::vector<std::string> warnings; ///< "link 'x': could not load mesh 'uri': why"

  /// "ok", or "<k> of <n> visuals are placeholders: <first warning>" (the link's status for
  /// a panel or a script; every warning stays in `warnings`).
  std::string status() const;
};

/// A robot's visuals. Links come parents first (depth-first from the root), so the order is
/// stable and follows the tree.
struct RobotVisuals
{
  std::string robot_name;
  std::string root_link;
  std::vector<LinkVisuals> links;
  /// What urdfdom complained about while still accepting the URDF (it drops a visual whose
  /// geometry does not parse, for instance); the affected links also carry a warning.
  std::vector<std::string> urdf_warnings;

  const LinkVisuals* link(const std::string& name) const;
  size_t visual_count() const;
  /// Visuals whose mesh could not be loaded (each also has a warning).
  size_t placeholder_count() const;
  /// urdf_warnings, then every link's warnings in link order.
  std::vector<std::string> warnings() const;
  /// Visuals that are meshes in the URDF (loaded or not).
  size_t mesh_visual_count() const;
  /// The one line a load reports, whatever the number of visuals:
  ///   "7 visuals, all 5 meshes loaded"
  ///   "7 visuals, 5 of 5 meshes missing (2 causes); first: link 'a': could not load mesh '…': …"
  /// A description whose meshes all name an unknown package says so once, not once per visual.
  std::string summary() const;
};

/// Options of a load.
struct RobotLoadOptions
{
  /// Folder for relative mesh paths. load_file() sets it to the URDF file's folder when empty.
  std::string base_folder;
  /// Side of the placeholder cube for meshes that do not load (metres).
  double placeholder_size = 0.01;
  /// Mesh files read at the same time: 0 = one per core (at most 8), 1 = one after the other on
  /// the calling thread. A Collada robot spends most of its first load in assimp, file by file.
  unsigned mesh_threads = 0;
};

/// Builds RobotVisuals from URDF XML. Meshes are cached by resolved file, modification time, size
/// and scale (MeshCache: the loader's own by default, or one shared with other loaders), so
/// loading the same robot (or a second robot sharing meshes) again reads no mesh file.
/// Never throws. Not thread-safe (one loader per thread; a shared MeshCache is thread-safe).
class RobotLoader
{
public:
  /// Uses ResourceResolver::from_environment() for package lookups.
  RobotLoader();
  explicit RobotLoader(ResourceResolver resolver);

  ResourceResolver& resolver() { return resolver_; }
  const ResourceResolver& resolver() const { return resolver_; }

  /// Parses `urdf_xml` and loads every visual. Returns false (and a message naming the problem,
  /// from urdfdom's own diagnostics) only when the URDF itself is broken; a mesh that does not
  /// load is a warning on its link and a placeholder.
  bool load_xml(const std::string& urdf_xml, const RobotLoadOptions& options, RobotVisuals* robot,
    std::string* error);
  /// The text of a URDF file, or of a xacro file expanded by xacro(); false (and why) when it is
  /// missing, unreadable, larger than the resolver's file size limit or does not expand.
  bool read_urdf_file(const std::string& urdf_path, std::string* text, std::string* error) const;
  /// Reads the URDF file, then load_xml() with relative paths taken from its folder.
  bool load_file(const std::string& urdf_path, RobotVisuals* robot, std::string* error,
    RobotLoadOptions options = RobotLoadOptions());

  /// Expands `.xacro` files for read_urdf_file() and load_file(): its command and arguments.
  XacroProcessor& xacro() { return xacro_; }
  const XacroProcessor& xacro() const { return xacro_; }

  /// Mesh files read (not served from the cache) since construction; for tests and benchmarks.
  size_t mesh_files_read() const { return mesh_files_read_; }
  /// Shares `cache` (e.g. MeshCache::shared(), as the scene's robot nodes do) instead of the
  /// loader's own.
  void set_mesh_cache(std::shared_ptr<MeshCache> cache) { cache_ = std::move(cache); }
  const std::shared_ptr<MeshCache>& mesh_cache() const { return cache_; }
  void clear_cache() { cache_->clear(); }

private:
  /// One distinct (mesh URI, scale) of a description: resolved, then served from the cache or read.
  struct MeshRead
  {
    bool ok = false;
    std::string path; ///< resolved file
    std::string key;  ///< MeshCache key
    MeshData mesh;    ///< already scaled
    std::string why;  ///< when !ok
    bool needs_file = false;
  };
  using MeshReads = std::map<std::string, MeshRead>; // by mesh_read_id()

  static std::string mesh_read_id(const std::string& uri, const std::array<double, 3>& scale);
  /// Every distinct mesh of the model resolved, and the files the cache lacks read, several at a
  /// time (options.mesh_threads), before the visuals are built in document order.
  MeshReads read_meshes(const urdf::ModelInterface& model, const RobotLoadOptions& options);
  MeshRead resolve_mesh(const std::string& uri, const std::array<double, 3>& scale,
    const std::string& base_folder) const;
  /// Reads, scales and caches one file; runs on several threads at once (MeshLoader keeps no
  /// state, MeshCache locks).
  void read_mesh_file(MeshRead* read, const std::array<double, 3>& scale) const;
  static bool fill_mesh_visual(const MeshRead& read, LinkVisual* visual, std::string* why);

  ResourceResolver resolver_;
  XacroProcessor xacro_;
  MeshLoader mesh_loader_;
  std::shared_ptr<MeshCache> cache_ = std::make_shared<MeshCache>(); // meshes already scaled
  size_t mesh_files_read_ = 0;
};

/// "link 'x': could not load mesh 'uri': why" — the one wording of a mesh warning.
std::string mesh_warning(const std::string& link, const std::string& uri, const std::string& why);

} // namespace robot
} // namespace ros2vtk

#endif
