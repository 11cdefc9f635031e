// ros2vtk — turns the mesh URIs of a URDF into files on disk, the way RViz 2's
// resource_retriever does for `package://` and `file://`, but without libcurl and without a ROS
// installation: packages are found through the ament index layout (AMENT_PREFIX_PATH),
// ROS_PACKAGE_PATH and folders the user adds. Plain C++17 (std::filesystem).
#ifndef ros2vtk_robot_ResourceResolver_hpp
#define ros2vtk_robot_ResourceResolver_hpp

#include <cstdint>
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

/// Resolves `package://<pkg>/<path>`, `file://<abs path>`, absolute paths and paths relative to
/// a base folder (the URDF file's folder). Anything else (`http://`, `model://`, …) is refused
/// with a message listing what is supported.
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
  /// A folder the user adds; searched first. It may be a package, a folder holding packages
  /// (searched a few levels deep) or an install prefix (`<folder>/share/<pkg>`).
  void add_search_path(const std::string& folder);
  /// Adds, as a search path, the package holding `file` (a URDF read from a package's source or
  /// share folder): the first folder with a package.xml, up to three folders above the file. A
  /// URDF names its own meshes `package://<its package>/...`, so they then resolve with no
  /// AMENT_PREFIX_PATH set-up. Returns the package folder, or "" when none was found.
  std::string add_package_of(const std::string& file);

  /// When on (the default), a resolved file must lie inside one of the allowed roots after
  /// normalisation (`..` and symlinks resolved), and a `package://` file inside its package. The
  /// roots are the search folders, `<prefix>/share` of each ament prefix, the ROS_PACKAGE_PATH
  /// folders, the base folder of the resolve() call (the URDF file's folder) and those added with
  /// add_allowed_root(). A description received from the network must not make us read any file
  /// with a mesh extension (issue 11.10: `package://pkg/../../outside/x.stl`, `file:///...`);
  /// RViz has no such check. set_restrict_to_roots(false) is the explicit opt-out.
  void set_restrict_to_roots(bool on) { restrict_to_roots_ = on; }
  bool restrict_to_roots() const { return restrict_to_roots_; }
  void add_allowed_root(const std::string& folder);

  /// Files larger than this are refused (they are almost certainly not a mesh).
  void set_max_file_bytes(std::uint64_t bytes) { max_file_bytes_ = bytes; }
  std::uint64_t max_file_bytes() const { return max_file_bytes_; }

  /// Resolves `uri`; relative paths are taken from `base_folder` (empty: the current folder).
  /// The file must exist, be a regular file, and pass the root and size checks.
  ResolvedResource resolve(const std::string& uri, const std::string& base_folder) const;

  /// The folder of package `name`, or "" (then `tried` lists where it looked, when given).
  std::string find_package(const std::string& name, std::vector<std::string>* tried = nullptr) const;

  /// The schemes resolve() accepts, for messages and docs.
  static std::string supported_forms();

private:
  std::string find_in_search_folder(const std::string& folder, const std::string& name) const;
  const std::map<std::string, std::string>& packages_under(const std::string& folder) const;
  std::vector<std::string> allowed_roots(const std::string& base_folder) const;

  std::vector<std::string> ament_prefixes_;
  std::vector<std::string> ros_package_path_;
  std::vector<std::string> search_paths_;
  std::vector<std::string> extra_roots_;
  bool restrict_to_roots_ = true;
  std::uint64_t max_file_bytes_ = kDefaultMaxFileBytes;
  /// search folder -> (package name -> package folder), filled on first use.
  mutable std::map<std::string, std::map<std::string, std::string>> scanned_;
};

} // namespace robot
} // namespace ros2vtk

#endif
