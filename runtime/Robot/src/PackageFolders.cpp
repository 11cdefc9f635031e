// ros2vtk — package.xml, crawling folder trees for packages, walking up from a file.
#include "ros2vtk/robot/PackageFolders.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>
#include <utility>

namespace fs = std::filesystem;

namespace ros2vtk {
namespace robot {
namespace {

// How deep folder trees are crawled, and how many folders at most are looked at per crawl (so a
// search path of "/" cannot stall loading).
constexpr int kMaxCrawlDepth = 4;
constexpr int kMaxCrawledFolders = 20000;
constexpr std::uintmax_t kMaxPackageXmlBytes = 1u << 20;

bool has_ignore_marker(const fs::path& folder)
{
  for (const char* marker : { "COLCON_IGNORE", "CATKIN_IGNORE", "AMENT_IGNORE" })
    if (fs::exists(folder / marker))
      return true;
  return false;
}

std::vector<fs::path> sorted_child_folders(const fs::path& folder)
{
  std::vector<fs::path> children;
  std::error_code ec;
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  if (ec)
    return children;
  for (; it != fs::directory_iterator(); it.increment(ec))
  {
    if (ec)
      break;
    const std::string child_name = it->path().filename().string();
    std::error_code dir_ec;
    if (!child_name.empty() && child_name[0] != '.' && it->is_directory(dir_ec))
      children.push_back(it->path());
  }
  std::sort(children.begin(), children.end()); // deterministic choice between duplicates
  return children;
}

} // namespace

bool has_package_xml(const fs::path& folder)
{
  std::error_code ec;
  return fs::is_regular_file(folder / "package.xml", ec);
}

// A regular expression, not an XML parser: the file is small, the element is mandatory and flat
// (REP 149), and this keeps the resolver free of XML libraries.
std::string package_xml_name(const fs::path& folder)
{
  const fs::path package_xml = folder / "package.xml";
  std::error_code ec;
  if (!fs::is_regular_file(package_xml, ec) ||
    fs::file_size(package_xml, ec) > kMaxPackageXmlBytes || ec)
    return {};
  std::ifstream in(package_xml);
  std::stringstream text;
  text << in.rdbuf();
  static const std::regex name_element("<name>\\s*([^<\\s]+)\\s*</name>");
  std::smatch match;
  const std::string content = text.str();
  if (std::regex_search(content, match, name_element))
    return match[1].str();
  return {};
}

fs::path normalised(const fs::path& path)
{
  std::error_code ec;
  fs::path result = fs::weakly_canonical(path, ec);
  if (ec)
    return path.lexically_normal();
  return result;
}

PackageTree crawl_for_packages(const std::string& folder)
{
  PackageTree tree;
  std::map<std::string, std::string> by_folder_name;
  int visited = 0;
  // Breadth-first, like rospack's crawl: a folder with a package.xml is a package and is not
  // searched further (packages do not nest).
  std::vector<std::pair<fs::path, int>> queue{ { fs::path(folder), 0 } };
  for (size_t next = 0; next < queue.size() && visited < kMaxCrawledFolders; ++next)
  {
    const fs::path current = queue[next].first;
    const int depth = queue[next].second;
    ++visited;
    if (has_package_xml(current))
    {
      const std::string canonical = normalised(current).string();
      const std::string xml_name = package_xml_name(current);
      if (!xml_name.empty())
        tree.packages.emplace(xml_name, canonical);
      by_folder_name.emplace(current.filename().string(), canonical);
      continue;
    }
    if (depth > 0)
      tree.plain_folders.emplace(current.filename().string(), normalised(current).string());
    if (depth >= kMaxCrawlDepth || has_ignore_marker(current))
      continue;
    for (const auto& child : sorted_child_folders(current))
      queue.emplace_back(child, depth + 1);
  }
  for (const auto& entry : by_folder_name)
    tree.packages.emplace(entry.first, entry.second);
  return tree;
}

PackagesAboveFile::PackagesAboveFile(const std::string& file)
  : file_(file)
{
  std::error_code ec;
  fs::path folder = fs::absolute(fs::path(file), ec).parent_path();
  if (ec)
    return;
  while (!folder.empty())
  {
    if (has_package_xml(folder))
      packages_.push_back({ normalised(folder).string(), package_xml_name(folder) });
    if (folder == folder.root_path() || folder.parent_path() == folder)
      break;
    folder = folder.parent_path();
  }
}

std::string PackagesAboveFile::find(const std::string& name) const
{
  for (const auto& package : packages_)
    if (package.name == name)
      return package.folder;
  for (const auto& package : packages_)
    if (fs::path(package.folder).filename() == name)
      return package.folder;
  return {};
}

std::string PackagesAboveFile::nearest() const
{
  return packages_.empty() ? std::string() : packages_.front().folder;
}

std::vector<std::string> PackagesAboveFile::folders() const
{
  std::vector<std::string> out;
  for (const auto& package : packages_)
    out.push_back(package.folder);
  return out;
}

} // namespace robot
} // namespace ros2vtk
