// ros2vtk — mesh URI resolution (package://, file://, absolute, relative).
#include "ros2vtk/robot/ResourceResolver.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace ros2vtk {
namespace robot {
namespace {

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
    if (text[i] == '%' && i + 2 < text.size() &&
      std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
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

std::string in_quotes(const std::string& text)
{
  return "'" + text + "'";
}

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

void ResourceResolver::set_ament_prefixes(std::vector<std::string> prefixes)
{
  ament_prefixes_ = std::move(prefixes);
}

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
  // A robot reloading its file asks again: walk up once per file.
  for (const auto& above : urdf_files_)
    if (above.file() == file)
      return above.nearest();
  urdf_files_.emplace_back(file);
  return urdf_files_.back().nearest();
}

void ResourceResolver::add_allowed_root(const std::string& folder)
{
  if (!folder.empty())
    extra_roots_.push_back(folder);
}

std::string ResourceResolver::supported_forms()
{
  return "package://<package>/<path>, package:///<path> (relative to the description), "
         "file:///<absolute path>, an absolute path, or a path relative to the URDF file's folder";
}

const PackageTree& ResourceResolver::crawled(const std::string& folder) const
{
  auto cached = crawled_.find(folder);
  if (cached == crawled_.end())
    cached = crawled_.emplace(folder, crawl_for_packages(folder)).first;
  return cached->second;
}

// The order: a package.xml (its name or the folder's), an install prefix, a package crawled
// below; then the folder-name rule for data shipped without package.xml (yourdfpy and pybullet
// take a folder named like the package): the search path itself, or a folder directly inside it.
// Only direct children count: a folder of that name deeper down is more likely a sub-folder
// (meshes/arm/) than the package, and is reported as rejected instead.
std::string ResourceResolver::find_in_search_folder(
  const std::string& folder, const std::string& name, PackageSearchReport* report) const
{
  const fs::path base(folder);
  std::error_code ec;
  if (has_package_xml(base) &&
    (package_xml_name(base) == name || normalised(base).filename() == name))
    return normalised(base).string();
  if (has_package_xml(base / "share" / name))
    return normalised(base / "share" / name).string();
  const PackageTree& tree = crawled(folder);
  auto found = tree.packages.find(name);
  if (found != tree.packages.end())
    return found->second;
  if (!has_package_xml(base) && normalised(base).filename() == name && fs::is_directory(base, ec))
    return normalised(base).string();
  if (fs::is_directory(base / name, ec))
    return normalised(base / name).string();
  auto plain = tree.plain_folders.find(name);
  if (report && plain != tree.plain_folders.end())
    report->rejected.push_back(in_quotes(plain->second) +
      " is named like the package but has no package.xml and is neither a mesh search path "
      "nor directly inside one (add it, or the folder holding it, with AddMeshSearchPath)");
  return {};
}

std::string ResourceResolver::find_package(
  const std::string& name, PackageSearchReport* report) const
{
  for (const auto& folder : search_paths_)
  {
    std::string found = find_in_search_folder(folder, name, report);
    if (!found.empty())
      return found;
    if (report)
      report->looked_in.push_back("mesh search path " + in_quotes(folder));
  }
  for (const auto& above : urdf_files_)
  {
    std::string found = above.find(name);
    if (!found.empty())
      return found;
    if (report)
    {
      std::vector<std::string> met = above.folders();
      for (auto& folder : met)
        folder = in_quotes(folder);
      report->looked_in.push_back("the folders above " + in_quotes(above.file()) +
        " up to the filesystem root (" +
        (met.empty() ? std::string("no package.xml there")
                     : "package.xml in " + join(met, ", ") + " names another package") +
        ")");
    }
  }
  for (const auto& prefix : ament_prefixes_)
  {
    const fs::path candidate = fs::path(prefix) / "share" / name;
    if (has_package_xml(candidate))
      return normalised(candidate).string();
    std::error_code ec;
    if (report && fs::is_directory(candidate, ec))
      report->rejected.push_back(
        in_quotes(candidate.string()) + " has no package.xml, so it is not an installed package");
    if (report)
      report->looked_in.push_back("AMENT_PREFIX_PATH " + in_quotes(candidate.string()));
  }
  for (const auto& folder : ros_package_path_)
  {
    const PackageTree& tree = crawled(folder);
    auto found = tree.packages.find(name);
    if (found != tree.packages.end())
      return found->second;
    auto plain = tree.plain_folders.find(name);
    if (report && plain != tree.plain_folders.end())
      report->rejected.push_back(in_quotes(plain->second) +
        " is named like the package but has no package.xml (ROS_PACKAGE_PATH takes only "
        "folders with a package.xml; add it with AddMeshSearchPath)");
    if (report)
      report->looked_in.push_back("ROS_PACKAGE_PATH " + in_quotes(folder));
  }
  return {};
}

std::string ResourceResolver::package_not_found(
  const std::string& name, const PackageSearchReport& report) const
{
  std::string text = "package " + in_quotes(name) + " not found";
  if (report.looked_in.empty())
    text +=
      ": no package locations are set (no URDF file, AMENT_PREFIX_PATH and ROS_PACKAGE_PATH are "
      "empty and "
      "no mesh search path was added; add the folder holding the package with AddMeshSearchPath)";
  else
    text += " (looked in " + join(report.looked_in, "; ") + ")";
  // Each rejected folder once: the same crawl can be reported by more than one location.
  std::set<std::string> said;
  for (const auto& rejected : report.rejected)
    if (said.insert(rejected).second)
      text += "; " + rejected;
  return text;
}

std::vector<std::string> ResourceResolver::allowed_roots(const std::string& base_folder) const
{
  std::vector<std::string> roots = search_paths_;
  if (!base_folder.empty())
    roots.push_back(base_folder);
  for (const auto& above : urdf_files_)
  {
    const auto folders = above.folders();
    roots.insert(roots.end(), folders.begin(), folders.end());
  }
  for (const auto& prefix : ament_prefixes_) // packages live in <prefix>/share, not all of /usr
    roots.push_back((fs::path(prefix) / "share").string());
  roots.insert(roots.end(), ros_package_path_.begin(), ros_package_path_.end());
  roots.insert(roots.end(), extra_roots_.begin(), extra_roots_.end());
  return roots;
}

ResolvedResource ResourceResolver::check_file(const fs::path& candidate,
  const std::string& base_folder, const std::string& package_folder) const
{
  ResolvedResource result;
  const fs::path resolved = normalised(candidate);
  const std::string shown = in_quotes(candidate.lexically_normal().string());
  std::error_code ec;
  if (!fs::exists(resolved, ec))
  {
    result.error = "no such file " + shown;
    return result;
  }
  if (!fs::is_regular_file(resolved, ec))
  {
    result.error = shown + " is not a regular file";
    return result;
  }
  if (restrict_to_roots_)
  {
    if (!package_folder.empty() && !is_inside(resolved, fs::path(package_folder)))
    {
      result.error = in_quotes(resolved.string()) + " lies outside its package folder " +
        in_quotes(package_folder) + " (root check is on)";
      return result;
    }
    const auto roots = allowed_roots(base_folder);
    const bool inside = std::any_of(roots.begin(), roots.end(),
      [&](const std::string& root) { return is_inside(resolved, normalised(root)); });
    if (!inside)
    {
      result.error = in_quotes(resolved.string()) + " lies outside the allowed roots (" +
        (roots.empty() ? std::string("none are set") : join(roots, ", ")) +
        "; root check is on: add the folder as a mesh search path, or switch the check off)";
      return result;
    }
  }
  const std::uintmax_t bytes = fs::file_size(resolved, ec);
  if (ec)
  {
    result.error = "cannot read the size of " + in_quotes(resolved.string()) + ": " + ec.message();
    return result;
  }
  if (bytes > max_file_bytes_)
  {
    result.error = in_quotes(resolved.string()) + " is " + std::to_string(bytes) +
      " bytes, over the limit of " + std::to_string(max_file_bytes_) + " bytes";
    return result;
  }
  result.ok = true;
  result.path = resolved.string();
  return result;
}

// A relative path has no folder of its own when the description came over the network, so the
// candidates are, in order: the base folder (the URDF file's, or the user's SetMeshBaseFolder),
// each search path, and with no base folder the current folder last. A leading `../` climbs out
// of the URDF's folder, which a search path is not, so `../meshes/x.STL` is also tried as
// `<search path>/meshes/x.STL`. Every candidate passes the same root check.
ResolvedResource ResourceResolver::resolve_relative(
  const std::string& uri, const std::string& base_folder) const
{
  const fs::path relative(uri);
  fs::path below_parents;
  bool climbs = false;
  for (const auto& part : relative.lexically_normal())
  {
    if (part == ".." && below_parents.empty())
      climbs = true;
    else
      below_parents /= part;
  }
  std::vector<fs::path> candidates;
  if (!base_folder.empty())
    candidates.push_back(fs::path(base_folder) / relative);
  for (const auto& folder : search_paths_)
  {
    candidates.push_back(fs::path(folder) / relative);
    if (climbs && !below_parents.empty())
      candidates.push_back(fs::path(folder) / below_parents);
  }
  std::error_code ec;
  if (base_folder.empty())
    candidates.push_back(fs::current_path(ec) / relative);

  std::vector<std::string> missing;
  ResolvedResource first_refusal;
  for (const auto& candidate : candidates)
  {
    ResolvedResource checked = check_file(candidate, base_folder, "");
    if (checked.ok)
      return checked;
    if (checked.error.compare(0, 13, "no such file ") == 0)
      missing.push_back(in_quotes(candidate.lexically_normal().string()));
    else if (first_refusal.error.empty())
      first_refusal = checked; // a file is there but refused: that is the news, not the misses
  }
  ResolvedResource result;
  if (!first_refusal.error.empty())
  {
    result.error = first_refusal.error;
    return result;
  }
  result.error = "no such file (looked for " + join(missing, ", ") + ")";
  if (base_folder.empty())
    result.error +=
      "; the description has no folder of its own (it came from a parameter or a topic): give the "
      "folder relative mesh paths start from with SetMeshBaseFolder, or add the folder holding the "
      "meshes with AddMeshSearchPath";
  return result;
}

// `package:///meshes/x.stl` names no package (exporters write it when their package name is
// left empty). resource_retriever refuses it; yourdfpy and the other Python loaders take the path
// relative to the description. So do we: inside the package holding the URDF file, then as a
// relative mesh path (the base folder, the search paths), with the same root check.
ResolvedResource ResourceResolver::resolve_without_package(
  const std::string& uri, const std::string& relative, const std::string& base_folder) const
{
  ResolvedResource result;
  const std::string why =
    "no package name after package://, so '" + relative + "' was taken relative to the description";
  if (relative.empty())
  {
    result.error =
      "could not resolve " + in_quotes(uri) + ": no package name and no file path after package://";
    return result;
  }
  std::vector<std::string> missing;
  for (auto above = urdf_files_.rbegin(); above != urdf_files_.rend();
       ++above) // the latest file first
  {
    const std::string package_folder = above->nearest();
    if (package_folder.empty())
      continue;
    const ResolvedResource checked =
      check_file(fs::path(package_folder) / relative, base_folder, package_folder);
    if (checked.ok)
      return checked;
    if (checked.error.compare(0, 13, "no such file ") != 0)
    {
      result.error = "could not resolve " + in_quotes(uri) + ": " + why + ": " + checked.error;
      return result;
    }
    missing.push_back("the package of " + in_quotes(above->file()) + " (" +
      in_quotes((fs::path(package_folder) / relative).lexically_normal().string()) + ")");
  }
  const ResolvedResource plain = resolve_relative(relative, base_folder);
  if (plain.ok)
    return plain;
  result.error = "could not resolve " + in_quotes(uri) + ": " + why + ": " +
    (missing.empty() ? std::string() : "not in " + join(missing, ", ") + "; ") + plain.error;
  return result;
}

ResolvedResource ResourceResolver::resolve(
  const std::string& uri, const std::string& base_folder) const
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
    const std::string relative =
      slash == std::string::npos ? std::string() : rest.substr(slash + 1);
    if (package.empty())
      return resolve_without_package(uri, relative, base_folder);
    // The folder-name rule below takes <search path>/<package>: "." and ".." would name the
    // search path itself or its parent.
    if (package == "." || package == "..")
      return fail(in_quotes(package) + " is not a package name");
    if (relative.empty())
      return fail("no file path after package://" + package + "/");
    PackageSearchReport report;
    package_folder = find_package(package, &report);
    if (package_folder.empty())
      return fail(package_not_found(package, report));
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
    return fail("the scheme " + in_quotes(scheme[1].str() + "://") + " is not supported; use " +
      supported_forms());
  }
  else if (fs::path(uri).is_absolute())
  {
    candidate = uri;
  }
  else
  {
    const ResolvedResource relative = resolve_relative(uri, base_folder);
    return relative.ok ? relative : fail(relative.error);
  }

  const ResolvedResource checked = check_file(candidate, base_folder, package_folder);
  return checked.ok ? checked : fail(checked.error);
}

} // namespace robot
} // namespace ros2vtk
