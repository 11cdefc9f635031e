// Installs the loader of display markers' mesh resources (ros2vtk::convert::
// set_mesh_resource_loader) when the Scene library loads: a marker's `mesh_resource` URI is
// resolved as a robot's mesh URIs are (ros2vtk::robot::ResourceResolver from AMENT_PREFIX_PATH
// and ROS_PACKAGE_PATH, read when the URI is resolved; package://, file://, absolute paths), with
// the same safety rules (issue 11.10: the file must lie inside one of those roots, no larger than
// the resolver's size limit), read by the robot's MeshLoader and kept in the process's shared
// MeshCache. A marker arrives from the network, so nothing outside the roots is ever read.
#include "ros2vtk/convert/Marker.hpp"
#include "ros2vtk/robot/MeshCache.hpp"
#include "ros2vtk/robot/MeshLoader.hpp"
#include "ros2vtk/robot/ResourceResolver.hpp"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

namespace {

bool LoadMarkerMesh(const std::string& uri, vtkPolyData* mesh, std::string* error)
{
  using namespace ros2vtk::robot;
  const ResourceResolver resolver = ResourceResolver::from_environment();
  const ResolvedResource resolved = resolver.resolve(uri, "");
  if (!resolved.ok)
  {
    *error = resolved.error;
    return false;
  }
  const std::shared_ptr<MeshCache> cache = MeshCache::shared();
  const std::string key = MeshCache::key_of(resolved.path, { { 1.0, 1.0, 1.0 } });
  MeshData data;
  if (!cache->find(key, &data))
  {
    if (!MeshLoader().load(resolved.path, &data, error))
    {
      return false;
    }
    cache->insert(key, data);
  }
  mesh->ShallowCopy(data.polydata); // the cache's polydata stays read-only: arrays replaced below
  mesh->GetPointData()->SetScalars(nullptr);
  if (data.has_vertex_colors)
  {
    mesh->GetPointData()->SetScalars(data.polydata->GetPointData()->GetArray(kVertexColorArray));
  }
  else if (data.has_color)
  {
    vtkNew<vtkUnsignedCharArray> color;
    color->SetNumberOfComponents(4);
    color->SetNumberOfTuples(mesh->GetNumberOfPoints());
    unsigned char rgba[4];
    for (int c = 0; c < 4; ++c)
    {
      rgba[c] = static_cast<unsigned char>(std::lround(255.0 * data.color[c]));
    }
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      color->SetTypedTuple(i, rgba);
    }
    mesh->GetPointData()->SetScalars(color);
  }
  return true;
}

struct InstallMarkerMeshLoader
{
  InstallMarkerMeshLoader() { ros2vtk::convert::set_mesh_resource_loader(&LoadMarkerMesh); }
};
const InstallMarkerMeshLoader installMarkerMeshLoader;

} // namespace
