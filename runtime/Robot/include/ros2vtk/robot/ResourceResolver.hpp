// ros2vtk — turns the mesh URIs of a URDF into files on disk, the way RViz 2's
// resource_retriever does for `package://` and `file://`, but without libcurl and without a ROS
// installation: packages are found through the ament index layout (AMENT_PREFIX_PATH),
// ROS_PACKAGE_PATH and folders the user adds. Plain C++17 (std::filesystem).
#ifndef ros2vtk_robot_ResourceResolver_hpp
#define ros2vtk_robot_ResourceResolver_hpp

#include "ros2vtk/robot/PackageFolders.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// Where a URI led. `path` is absolute and normalised (symlinks resolved) when `ok`.
struct ResolvedResource
{
  bool ok = false;
  std::string path;
  std::string error; ///< names the URI and what was tried, when !ok
};

/// What a package lookup looked at, for "not found" messages.
struct PackageSearchReport
{
  /// Each place searched, as the user would name it ("mesh search path '/data/robots'").
  std::vector<std::string> looked_in;
  /// Folders named like the package that were seen but not taken, each with the reason
  /// ("'/data/x/arm' is named like the package but has no package.xml and is neither a mesh
  /// search path nor directly inside one (…)").
  std::vector<std::string> rejected;
};

/// Resolves `package://<pkg>/<path>`, `file://<abs path>`, absolute paths and relative paths
/// (from a base folder, the URDF file's folder, then from the search paths). Anything else
/// (`http://`, `model://`, …) is refused with a message listing what is supported.
///
/// Packages are found, in this order: in the search paths the user added; above the URDF files
/// given to add_package_of(); in the ament index (AMENT_PREFIX_PATH); in ROS_PACKAGE_PATH.
/// A package is a folder with a package.xml whose <name> (or folder name) is the package; in a
/// search path, a folder named like the package with no package.xml is taken too (robot data
/// shipped outside ament: pip packages, simulator assets), as URDF loaders outside ROS do
/// (pybullet, yourdfpy).
///
/// Why a class and not a function: the package lookup scans folders, and a robot asks for the
/// same packages many times, so the package -> folder map is cached here. Not thread-safe (one
/// resolver per loading thread).
class ResourceResolver
{
public:
  /// 200 MB: far above any robot mesh, low enough that a wrong path to a disk image is refused.
  static constexpr std::uint64_t kDefaultMaxFileBytes = 200ull * 1024ull * 1024ull;

  /// A resolver that knows no packages yet (add folders, or use from_environment()).
  ResourceResolver() = default;

  /// A resolver reading AMENT_PREFIX_PATH and ROS_PACKAGE_PATH (colon-separated) now.
  static ResourceResolver from_environment();

  /// Prefixes of the ament index layout: package `p` is `<prefix>/share/p/` with a package.xml.
  void set_ament_prefixes(std::vector<std::string> prefixes);
  /// ROS_PACKAGE_PATH-style folders, searched a few levels deep for package.xml files.
  void set_ros_package_path(std::vector<std::string> folders);
  /// A folder the user adds (the robot node's AddMeshSearchPath). For `package://` it is searched
  /// first; it may be a package, a folder holding packages (searched a few levels deep), an
  /// install prefix (`<folder>/share/<pkg>`), or a folder named like the package / holding a
  /// folder named like it (no package.xml needed). For relative mesh paths it is searched after
  /// the base folder: `meshes/x.stl` as `<folder>/meshes/x.stl`, and `../meshes/x.STL` also as
  /// `<folder>/meshes/x.STL` (the description's folder is unknown, so its leading `..` cannot be
  /// followed). It is an allowed root.
  void add_search_path(const std::string& folder);
  /// Tells the resolver that the description was read from `file`: `package://<name>/` then also
  /// finds the nearest folder above the file, up to the filesystem root, whose package.xml names
  /// `<name>` (a URDF names its own meshes `package://<its package>/...`, so they resolve with no
  /// AMENT_PREFIX_PATH set-up). Every package folder above the file becomes an allowed root, so
  /// `../meshes/x.stl` from the package's urdf/ folder loads. Returns the nearest package folder
  /// above the file, or "" when there is none.
  std::string add_package_of(const std::string& file);

  /// When on (the default), a resolved file must lie inside one of the allowed roots after
  /// normalisation (`..` and symlinks resolved), and a `package://` file inside its package. The
  /// roots are the search folders, `<prefix>/share` of each ament prefix, the ROS_PACKAGE_PATH
  /// folders, the package folders above the files given to add_package_of(), the base folder of
  /// the resolve() call (the URDF file's folder) and those added with add_allowed_root(). A
  /// description received from the network must not make us read any file with a mesh
  /// extension (issue 11.10: `package://pkg/../../outside/x.stl`, `file:///...`); RViz has no
  /// such check. set_restrict_to_roots(false) is the explicit opt-out.
  void set_restrict_to_roots(bool on) { restrict_to_roots_ = on; }
  bool restrict_to_roots() const { return restrict_to_roots_; }
  void add_allowed_root(const std::string& folder);

  /// Files larger than this are refused (they are almost certainly not a mesh).
  void set_max_file_bytes(std::uint64_t bytes) { max_file_bytes_ = bytes; }
  std::uint64_t max_file_bytes() const { return max_file_bytes_; }

  /// Resolves `uri`; relative paths are taken from `base_folder`, then from the search paths
  /// (with no base folder: from the search paths, then the current folder). `package:///<path>`
  /// (no package name) is `<path>` in the package holding the URDF file, else a relative path.
  /// The file must exist, be a regular file, and pass the root and size checks.
  ResolvedResource resolve(const std::string& uri, const std::string& base_folder) const;

  /// The folder of package `name`, or "" (then `report`, when given, says where it looked).
  std::string find_package(const std::string& name, PackageSearchReport* report = nullptr) const;

  /// The schemes resolve() accepts, for messages and docs.
  static std::string supported_forms();

private:
  std::string find_in_search_folder(
    const std::string& folder, const std::string& name, PackageSearchReport* report) const;
  const PackageTree& crawled(const std::string& folder) const;
  std::vector<std::string> allowed_roots(const std::string& base_folder) const;
  ResolvedResource resolve_relative(const std::string& uri, const std::string& base_folder) const;
  ResolvedResource resolve_without_package(
    const std::string& uri, const std::string& relative, const std::string& base_folder) const;
  /// The checks every candidate file goes through: exists, regular, inside the roots (and inside
  /// `package_folder` when given), not over the size limit.
  ResolvedResource check_file(const std::filesystem::path& candidate,
    const std::string& base_folder, const std::string& package_folder) const;
  std::string package_not_found(const std::string& name, const PackageSearchReport& report) const;

  std::vector<std::string> ament_prefixes_;
  std::vector<std::string> ros_package_path_;
  std::vector<std::string> search_paths_;
  std::vector<std::string> extra_roots_;
  std::vector<PackagesAboveFile> urdf_files_;
  bool restrict_to_roots_ = true;
  std::uint64_t max_file_bytes_ = kDefaultMaxFileBytes;
  /// search folder -> what a crawl of it found, filled on first use.
  mutable std::map<std::string, PackageTree> crawled_;
};

} // namespace robot
} // namespace ros2vtk

#endif
