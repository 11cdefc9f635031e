// ros2vtk — mesh URI resolution (package://, file://, absolute, relative).
#include "ros2vtk/robot/ResourceResolver.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace ros2vtk {
namespace robot {
namespace {

// How deep ROS_PACKAGE_PATH-style folders are searched, and how many folders at most are
// looked at per search folder (so a search path of "/" cannot stall loading).
constexpr int kMaxScanDepth = 4;
constexpr int kMaxScannedFolders = 20000;
constexpr std::uintmax_t kMaxPackageXmlBytes = 1u << 20;

std::vector<std::string> split_path_list(const char* value)
{
  std::vector<std::string> parts;
  if (!value)
    return parts;
  std::stringstream stream(value);
  std::string part;
  while (std::getline(stream, part, ':'))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

bool starts_with(const std::string& text, const std::string& prefix)
{
  return text.size() >= prefix.size() && text.compare(0, prefix.size(), prefix) == 0;
}

// file:// URIs may carry %XX escapes (spaces in folder names); nothing else is decoded.
std::string percent_decode(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i)
  {
    if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2])))
    {
      out.push_back(static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    }
    else
    {
      out.push_back(text[i]);
    }
  }
  return out;
}

bool is_file(const fs::path& path)
{
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// The <name> of a package.xml. A regular expression, not an XML parser: the file is small, the
// element is mandatory and flat (REP 149), and this keeps the resolver free of XML libraries.
std::string package_xml_name(const fs::path& package_xml)
{
  std::error_code ec;
  if (fs::file_size(package_xml, ec) > kMaxPackageXmlBytes || ec)
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

bool has_ignore_marker(const fs::path& folder)
{
  for (const char* marker : {"COLCON_IGNORE", "CATKIN_IGNORE", "AMENT_IGNORE"})
    if (fs::exists(folder / marker))
      return true;
  return false;
}

fs::path normalised(const fs::path& path)
{
  std::error_code ec;
  fs::path result = fs::weakly_canonical(path, ec);
  if (ec)
    return path.lexically_normal();
  return result;
}

// True when `path` is `root` or lies inside it (both normalised), compared part by part so that
// /data/robots2 is not inside /data/robots.
bool is_inside(const fs::path& path, const fs::path& root)
{
  auto root_end = root.end();
  // A trailing separator gives an empty last element; ignore it.
  if (!root.empty() && root.filename().empty())
    --root_end;
  auto mismatch = std::mismatch(root.begin(), root_end, path.begin(), path.end());
  return mismatch.first == root_end;
}

std::string in_quotes(const std::string& text) { return "'" + text + "'"; }

std::string join(const std::vector<std::string>& items, const std::string& separator)
{
  std::string out;
  for (size_t i = 0; i < items.size(); ++i)
    out += (i ? separator : std::string()) + items[i];
  return out;
}

} // namespace

ResourceResolver ResourceResolver::from_environment()
{
  ResourceResolver resolver;
  resolver.set_ament_prefixes(split_path_list(std::getenv("AMENT_PREFIX_PATH")));
  resolver.set_ros_package_path(split_path_list(std::getenv("ROS_PACKAGE_PATH")));
  return resolver;
}

void ResourceResolver::set_ament_prefixes(std::vector<std::string> prefixes) { ament_prefixes_ = std::move(prefixes); }

void ResourceResolver::set_ros_package_path(std::vector<std::string> folders)
{
  ros_package_path_ = std::move(folders);
}

void ResourceResolver::add_search_path(const std::string& folder)
{
  if (!folder.empty())
    search_paths_.push_back(folder);
}

std::string ResourceResolver::add_package_of(const std::string& file)
{
  fs::path folder = fs::path(file).parent_path();
  for (int level = 0; level < 3 && !folder.empty(); ++level, folder = folder.parent_path())
  {
    if (is_file(folder / "package.xml"))
    {
      add_search_path(folder.string());
      return folder.string();
    }
    if (folder == folder.root_path())
      break;
  }
  return "";
}

void ResourceResolver::add_allowed_root(const std::string& folder)
{
  if (!folder.empty())
    extra_roots_.push_back(folder);
}

std::string ResourceResolver::supported_forms()
{
  return "package://<package>/<path>, file:///<absolute path>, an absolute path, or a path relative "
         "to the URDF file's folder";
}

const std::map<std::string, std::string>& ResourceResolver::packages_under(const std::string& folder) const
{
  auto cached = scanned_.find(folder);
  if (cached != scanned_.end())
    return cached->second;
  std::map<std::string, std::string> by_xml_name;
  std::map<std::string, std::string> by_folder_name;
  int visited = 0;
  // Breadth-first, like rospack's crawl: a folder with a package.xml is a package and is not
  // searched further (packages do not nest).
  std::vector<std::pair<fs::path, int>> queue{{fs::path(folder), 0}};
  for (size_t next = 0; next < queue.size() && visited < kMaxScannedFolders; ++next)
  {
    const fs::path current = queue[next].first;
    const int depth = queue[next].second;
    ++visited;
    if (is_file(current / "package.xml"))
    {
      const std::string canonical = normalised(current).string();
      const std::string xml_name = package_xml_name(current / "package.xml");
      if (!xml_name.empty())
        by_xml_name.emplace(xml_name, canonical);
      by_folder_name.emplace(current.filename().string(), canonical);
      continue;
    }
    if (depth >= kMaxScanDepth || has_ignore_marker(current))
      continue;
    std::error_code ec;
    fs::directory_iterator it(current, fs::directory_options::skip_permission_denied, ec);
    if (ec)
      continue;
    std::vector<fs::path> children;
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
    for (const auto& child : children)
      queue.emplace_back(child, depth + 1);
  }
  // The <name> in package.xml is the package's name; the folder name is a fallback for trees
  // where the two differ and the URDF used the folder name.
  for (const auto& entry : by_folder_name)
    by_xml_name.emplace(entry.first, entry.second);
  return scanned_.emplace(folder, std::move(by_xml_name)).first->second;
}

std::string ResourceResolver::find_in_search_folder(const std::string& folder, const std::string& name) const
{
  const fs::path base(folder);
  if (is_file(base / "package.xml") &&
      (package_xml_name(base / "package.xml") == name || normalised(base).filename() == name))
    return normalised(base).string();
  if (is_file(base / "share" / name / "package.xml"))
    return normalised(base / "share" / name).string();
  const auto& packages = packages_under(folder);
  auto found = packages.find(name);
  return found == packages.end() ? std::string() : found->second;
}

std::string ResourceResolver::find_package(const std::string& name, std::vector<std::string>* tried) const
{
  for (const auto& folder : search_paths_)
  {
    std::string found = find_in_search_folder(folder, name);
    if (!found.empty())
      return found;
    if (tried)
      tried->push_back("search path " + in_quotes(folder));
  }
  for (const auto& prefix : ament_prefixes_)
  {
    const fs::path candidate = fs::path(prefix) / "share" / name;
    if (is_file(candidate / "package.xml"))
      return normalised(candidate).string();
    if (tried)
      tried->push_back("AMENT_PREFIX_PATH " + in_quotes(candidate.string()));
  }
  for (const auto& folder : ros_package_path_)
  {
    const auto& packages = packages_under(folder);
    auto found = packages.find(name);
    if (found != packages.end())
      return found->second;
    if (tried)
      tried->push_back("ROS_PACKAGE_PATH " + in_quotes(folder));
  }
  return {};
}

std::vector<std::string> ResourceResolver::allowed_roots(const std::string& base_folder) const
{
  std::vector<std::string> roots = search_paths_;
  if (!base_folder.empty())
    roots.push_back(base_folder);
  for (const auto& prefix : ament_prefixes_) // packages live in <prefix>/share, not all of /usr
    roots.push_back((fs::path(prefix) / "share").string());
  roots.insert(roots.end(), ros_package_path_.begin(), ros_package_path_.end());
  roots.insert(roots.end(), extra_roots_.begin(), extra_roots_.end());
  return roots;
}

ResolvedResource ResourceResolver::resolve(const std::string& uri, const std::string& base_folder) const
{
  ResolvedResource result;
  auto fail = [&](const std::string& why) {
    result.ok = false;
    result.path.clear();
    result.error = "could not resolve " + in_quotes(uri) + ": " + why;
    return result;
  };
  if (uri.empty())
    return fail("the URI is empty");

  fs::path candidate;
  std::string package_folder;
  static const std::regex scheme_pattern("^([A-Za-z][A-Za-z0-9+.\\-]*)://");
  std::smatch scheme;
  if (starts_with(uri, "package://"))
  {
    const std::string rest = uri.substr(std::string("package://").size());
    const size_t slash = rest.find('/');
    const std::string package = rest.substr(0, slash);
    const std::string relative = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
    if (package.empty())
      return fail("no package name after package://");
    if (relative.empty())
      return fail("no file path after package://" + package + "/");
    std::vector<std::string> tried;
    package_folder = find_package(package, &tried);
    if (package_folder.empty())
    {
      if (tried.empty())
        return fail("package " + in_quotes(package) +
                    " not found: no package locations are set (AMENT_PREFIX_PATH and ROS_PACKAGE_PATH "
                    "are empty and no search path was added)");
      return fail("package " + in_quotes(package) + " not found (looked in " + join(tried, ", ") + ")");
    }
    candidate = fs::path(package_folder) / relative;
  }
  else if (starts_with(uri, "file://"))
  {
    std::string rest = percent_decode(uri.substr(std::string("file://").size()));
    if (starts_with(rest, "localhost/"))
      rest = rest.substr(std::string("localhost").size());
    if (rest.empty() || rest[0] != '/')
      return fail("a file:// URI needs an absolute path (file:///folder/mesh.stl)");
    candidate = rest;
  }
  else if (std::regex_search(uri, scheme, scheme_pattern))
  {
    return fail("the scheme " + in_quotes(scheme[1].str() + "://") + " is not supported; use " + supported_forms());
  }
  else if (fs::path(uri).is_absolute())
  {
    candidate = uri;
  }
  else
  {
    std::error_code ec;
    const fs::path base = base_folder.empty() ? fs::current_path(ec) : fs::path(base_folder);
    candidate = base / uri;
  }

  const fs::path resolved = normalised(candidate);
  const std::string shown = in_quotes(candidate.lexically_normal().string());
  std::error_code ec;
  if (!fs::exists(resolved, ec))
    return fail("no such file " + shown);
  if (!fs::is_regular_file(resolved, ec))
    return fail(shown + " is not a regular file");

  if (restrict_to_roots_)
  {
    if (!package_folder.empty() && !is_inside(resolved, fs::path(package_folder)))
      return fail(in_quotes(resolved.string()) + " lies outside its package folder " + in_quotes(package_folder) +
                  " (root check is on)");
    const auto roots = allowed_roots(base_folder);
    const bool inside = std::any_of(roots.begin(), roots.end(),
                                    [&](const std::string& root) { return is_inside(resolved, normalised(root)); });
    if (!inside)
      return fail(in_quotes(resolved.string()) + " lies outside the allowed roots (" +
                  (roots.empty() ? std::string("none are set") : join(roots, ", ")) +
                  "; root check is on: add the folder as a mesh search path, or switch the check off)");
  }

  const std::uintmax_t bytes = fs::file_size(resolved, ec);
  if (ec)
    return fail("cannot read the size of " + in_quotes(resolved.string()) + ": " + ec.message());
  if (bytes > max_file_bytes_)
    return fail(in_quotes(resolved.string()) + " is " + std::to_string(bytes) + " bytes, over the limit of " +
                std::to_string(max_file_bytes_) + " bytes");

  result.ok = true;
  result.path = resolved.string();
  return result;
}

} // namespace robot
} // namespace ros2vtk
