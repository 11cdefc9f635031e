// ros2vtk — what makes a folder a ROS package, and the two ways the resolver finds
// packages on disk besides the ament index: crawling a folder tree (rospack's way), and walking
// up from a URDF file to the package that holds it. Plain C++17 (std::filesystem).
#ifndef ros2vtk_robot_PackageFolders_hpp
#define ros2vtk_robot_PackageFolders_hpp

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

/// True when `folder` holds a package.xml file.
bool has_package_xml(const std::filesystem::path& folder);

/// The <name> in `folder`/package.xml, or "" (no file, no name, or a file over 1 MB).
std::string package_xml_name(const std::filesystem::path& folder);

/// `path` with `..` and symlinks resolved as far as it exists (std::filesystem::weakly_canonical),
/// or lexically normalised when that fails.
std::filesystem::path normalised(const std::filesystem::path& path);

/// What a breadth-first crawl of a folder tree found: packages (folders with a package.xml, not
/// searched further since packages do not nest), and the other folders by name, so that "not
/// found" can say a folder of the wanted name exists but is no package.
struct PackageTree
{
  /// Package name -> folder (normalised). The <name> of package.xml wins; the folder's own name
  /// is a fallback for trees where the two differ and the URDF used the folder name.
  std::map<std::string, std::string> packages;
  /// Folder name -> first folder of that name without a package.xml (crawl order).
  std::map<std::string, std::string> plain_folders;
};

/// Crawls `folder` up to a few levels deep (skipping hidden folders and COLCON_IGNORE /
/// CATKIN_IGNORE / AMENT_IGNORE trees), bounded in folders visited so that "/" cannot stall.
PackageTree crawl_for_packages(const std::string& folder);

/// The packages above a file (a URDF read from disk), nearest first: every folder from the file's
/// own up to the filesystem root that holds a package.xml. Description packages often keep the
/// package.xml several folders above the URDF (`pkg/robots/x_description/urdf/x.urdf`), so the
/// walk has no depth limit; it reads one package.xml per folder that has one.
class PackagesAboveFile
{
public:
  explicit PackagesAboveFile(const std::string& file);

  const std::string& file() const { return file_; }
  /// The nearest folder whose package.xml names `name`; failing that, the nearest package folder
  /// whose folder name is `name`; else "".
  std::string find(const std::string& name) const;
  /// The nearest package folder, whatever its name ("" when none): the package the file is in.
  std::string nearest() const;
  /// Every package folder met on the way up (normalised), nearest first.
  std::vector<std::string> folders() const;

private:
  struct Package
  {
    std::string folder;
    std::string name;
  };
  std::string file_;
  std::vector<Package> packages_;
};

} // namespace robot
} // namespace ros2vtk

#endif
