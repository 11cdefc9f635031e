// ros2vtk — finding a service type by any of the names scripts give it (see the header).
#include "Internal/ServiceTypeName.hpp"
#include "Internal/TextAffixes.hpp"

#include <vector>

namespace ros2vtk {
namespace scene {

namespace {

/// "vtkMRMLROS2ServiceClientSetBoolNode" (SlicerROS2's classes, and ours spelled the same way)
/// -> "SetBool"; anything else unchanged.
std::string without_class_name(const std::string& name)
{
  static const char* const prefixes[] = { "vtkMRMLROS2ServiceClient", "vtkMRMLROS2ServiceServer",
    "vtkROS2ServiceClient", "vtkROS2ServiceServer" };
  for (const char* prefix : prefixes)
  {
    const std::string p = prefix;
    if (starts_with(name, p) && ends_with(name, "Node") && name.size() > p.size() + 4)
    {
      return name.substr(p.size(), name.size() - p.size() - 4);
    }
  }
  return name;
}

} // namespace

const wire::ServiceTypeSupport* find_service_type_by_any_name(
  const std::string& name, std::string* error)
{
  const std::string bare = without_class_name(name);
  if (bare.find('/') != std::string::npos || bare == name)
  {
    if (const wire::ServiceTypeSupport* type = wire::find_service_type(bare))
    {
      return type;
    }
  }
  if (bare.find('/') == std::string::npos)
  {
    std::vector<std::string> matches;
    for (const std::string& known : wire::registered_service_types())
    {
      const auto slash = known.rfind('/');
      if (slash != std::string::npos && known.compare(slash + 1, std::string::npos, bare) == 0)
      {
        matches.push_back(known);
      }
    }
    if (matches.size() == 1)
    {
      return wire::find_service_type(matches.front());
    }
    if (matches.size() > 1)
    {
      if (error)
      {
        *error = "service type '" + name + "' is ambiguous: it could be";
        for (const std::string& match : matches)
        {
          *error += ' ' + match;
        }
        *error += " (give the package, e.g. '" + matches.front() + "')";
      }
      return nullptr;
    }
  }
  return wire::find_service_type(name, error); // unknown: says so and lists the known types
}

} // namespace scene
} // namespace ros2vtk
