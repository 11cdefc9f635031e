// ros2vtk — URDF visuals into VTK geometry (every visual of every link, cached meshes).
#include "ros2vtk/robot/RobotLoader.hpp"

#include "UrdfDiagnostics.hpp"
#include "UrdfMaterials.hpp"

#include <urdf_model/model.h>

#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkNew.h>
#include <vtkReverseSense.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

namespace ros2vtk {
namespace robot {
namespace {

// Enough facets that a 6 cm sphere or a cylinder looks round in the viewer, few enough that a
// robot of primitives stays cheap.
constexpr int kRoundResolution = 32;

vtkSmartPointer<vtkPolyData> output_of(vtkPolyDataAlgorithm* algorithm)
{
  algorithm->Update();
  vtkSmartPointer<vtkPolyData> out = algorithm->GetOutput();
  return out;
}

vtkSmartPointer<vtkPolyData> make_box(double x, double y, double z)
{
  vtkNew<vtkCubeSource> box;
  box->SetXLength(x);
  box->SetYLength(y);
  box->SetZLength(z);
  return output_of(box);
}

// URDF cylinders lie along z and are centred on the origin; vtkCylinderSource's lie along y.
vtkSmartPointer<vtkPolyData> make_cylinder(double radius, double length)
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(radius);
  cylinder->SetHeight(length);
  cylinder->SetResolution(kRoundResolution);
  cylinder->CappingOn();
  vtkNew<vtkTransform> y_to_z;
  y_to_z->RotateX(90.0);
  vtkNew<vtkTransformPolyDataFilter> rotate;
  rotate->SetInputConnection(cylinder->GetOutputPort());
  rotate->SetTransform(y_to_z);
  return output_of(rotate);
}

vtkSmartPointer<vtkPolyData> make_sphere(double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(kRoundResolution);
  sphere->SetPhiResolution(kRoundResolution / 2);
  return output_of(sphere);
}

vtkSmartPointer<vtkPolyData> scaled(vtkPolyData* input, const std::array<double, 3>& scale)
{
  vtkNew<vtkTransform> transform;
  transform->Scale(scale[0], scale[1], scale[2]);
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetInputData(input);
  filter->SetTransform(transform);
  filter->Update();
  vtkSmartPointer<vtkPolyData> out = filter->GetOutput();
  // A mirroring scale (an odd number of negative factors) turns the triangles inside out;
  // reversing their order keeps the outside outside.
  if (scale[0] * scale[1] * scale[2] < 0)
  {
    vtkNew<vtkReverseSense> reverse;
    reverse->SetInputData(out);
    reverse->ReverseCellsOn();
    reverse->ReverseNormalsOff();
    reverse->Update();
    out = reverse->GetOutput();
  }
  return out;
}

vtkSmartPointer<vtkMatrix4x4> to_matrix(const urdf::Pose& pose)
{
  double x = pose.rotation.x, y = pose.rotation.y, z = pose.rotation.z, w = pose.rotation.w;
  const double norm = std::sqrt(x * x + y * y + z * z + w * w);
  if (norm > 0)
  {
    x /= norm, y /= norm, z /= norm, w /= norm;
  }
  else
  {
    x = y = z = 0, w = 1;
  }
  const double rotation[3][3] = { { 1 - 2 * (y * y + z * z), 2 * (x * y - z * w),
                                    2 * (x * z + y * w) },
    { 2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w) },
    { 2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y) } };
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      matrix->SetElement(r, c, rotation[r][c]);
  matrix->SetElement(0, 3, pose.position.x);
  matrix->SetElement(1, 3, pose.position.y);
  matrix->SetElement(2, 3, pose.position.z);
  return matrix;
}

vtkSmartPointer<vtkPolyData> shallow_copy(vtkPolyData* source)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(source);
  return copy;
}

std::string in_quotes(const std::string& text)
{
  return "'" + text + "'";
}

} // namespace

std::string mesh_warning(const std::string& link, const std::string& uri, const std::string& why)
{
  // The resolver's messages start by naming the URI too; say it once.
  const std::string repeated = "could not resolve " + in_quotes(uri) + ": ";
  const std::string reason =
    why.compare(0, repeated.size(), repeated) == 0 ? why.substr(repeated.size()) : why;
  return "link " + in_quotes(link) + ": could not load mesh " + in_quotes(uri) + ": " + reason;
}

std::array<double, 4> LinkVisual::display_color() const
{
  if (has_material_color)
    return material_color;
  if (has_mesh_color)
    return mesh_color;
  return { { 0.7, 0.7, 0.7, 1.0 } };
}

const LinkVisuals* RobotVisuals::link(const std::string& name) const
{
  for (const auto& entry : links)
    if (entry.link == name)
      return &entry;
  return nullptr;
}

size_t RobotVisuals::visual_count() const
{
  size_t count = 0;
  for (const auto& entry : links)
    count += entry.visuals.size();
  return count;
}

size_t RobotVisuals::placeholder_count() const
{
  size_t count = 0;
  for (const auto& entry : links)
    for (const auto& visual : entry.visuals)
      count += visual.kind == VisualKind::Placeholder ? 1 : 0;
  return count;
}

std::vector<std::string> RobotVisuals::warnings() const
{
  std::vector<std::string> all = urdf_warnings;
  for (const auto& entry : links)
    all.insert(all.end(), entry.warnings.begin(), entry.warnings.end());
  return all;
}

size_t RobotVisuals::mesh_visual_count() const
{
  size_t count = 0;
  for (const auto& entry : links)
    for (const auto& visual : entry.visuals)
      count += visual.mesh_uri.empty() ? 0 : 1;
  return count;
}

namespace {

// The cause of a mesh warning without its link and URI ("link 'a': could not load mesh 'u': why"
// -> "why"), so that ten visuals failing for one reason count as one cause. A path in the reason
// (no such file '/x/a.stl') still makes causes differ per file; that is information, not noise.
std::string cause_of(const std::string& warning)
{
  const std::string marker = "': ";
  const size_t mesh = warning.find(": could not load mesh '");
  if (mesh == std::string::npos)
    return warning;
  const size_t after_uri = warning.find(marker, mesh + 23);
  return after_uri == std::string::npos ? warning : warning.substr(after_uri + marker.size());
}

} // namespace

std::string LinkVisuals::status() const
{
  if (warnings.empty())
    return "ok";
  size_t placeholders = 0;
  for (const auto& visual : visuals)
    placeholders += visual.kind == VisualKind::Placeholder ? 1 : 0;
  return std::to_string(placeholders) + " of " + std::to_string(visuals.size()) +
    " visuals are placeholders: " + warnings.front();
}

std::string RobotVisuals::summary() const
{
  const size_t visuals = visual_count();
  const size_t meshes = mesh_visual_count();
  size_t missing_meshes = 0;
  for (const auto& entry : links)
    for (const auto& visual : entry.visuals)
      missing_meshes += !visual.mesh_uri.empty() && visual.kind == VisualKind::Placeholder ? 1 : 0;
  std::string line = std::to_string(visuals) + (visuals == 1 ? " visual, " : " visuals, ");
  if (missing_meshes == 0)
    line += meshes == 0
      ? "no meshes"
      : "all " + std::to_string(meshes) + (meshes == 1 ? " mesh" : " meshes") + " loaded";
  else
    line += std::to_string(missing_meshes) + " of " + std::to_string(meshes) +
      (meshes == 1 ? " mesh" : " meshes") + " missing";
  const std::vector<std::string> all = warnings();
  if (all.empty())
    return line;
  std::set<std::string> causes;
  for (const auto& warning : all)
    causes.insert(cause_of(warning));
  line += " (" + std::to_string(all.size()) + (all.size() == 1 ? " warning" : " warnings") + ", " +
    std::to_string(causes.size()) + (causes.size() == 1 ? " cause" : " causes") +
    "); first: " + all.front();
  return line;
}

RobotLoader::RobotLoader()
  : resolver_(ResourceResolver::from_environment())
{
}

RobotLoader::RobotLoader(ResourceResolver resolver)
  : resolver_(std::move(resolver))
{
}

std::string RobotLoader::mesh_read_id(const std::string& uri, const std::array<double, 3>& scale)
{
  char text[80];
  std::snprintf(text, sizeof(text), "|%.17g,%.17g,%.17g", scale[0], scale[1], scale[2]);
  return uri + text;
}

RobotLoader::MeshRead RobotLoader::resolve_mesh(
  const std::string& uri, const std::array<double, 3>& scale, const std::string& base_folder) const
{
  MeshRead read;
  for (double factor : scale)
  {
    if (!std::isfinite(factor) || factor == 0.0)
    {
      char text[160];
      std::snprintf(text, sizeof(text), "the scale (%g %g %g) has a zero or non-finite factor",
        scale[0], scale[1], scale[2]);
      read.why = text;
      return read;
    }
  }
  const ResolvedResource resolved = resolver_.resolve(uri, base_folder);
  if (!resolved.ok)
  {
    read.why = resolved.error;
    return read;
  }
  read.path = resolved.path;
  read.key = MeshCache::key_of(resolved.path, scale);
  read.ok = cache_->find(read.key, &read.mesh);
  read.needs_file = !read.ok;
  return read;
}

void RobotLoader::read_mesh_file(MeshRead* read, const std::array<double, 3>& scale) const
{
  if (!mesh_loader_.load(read->path, &read->mesh, &read->why))
    return;
  if (scale[0] != 1.0 || scale[1] != 1.0 || scale[2] != 1.0)
    read->mesh.polydata = scaled(read->mesh.polydata, scale);
  cache_->insert(read->key, read->mesh);
  read->ok = true;
}

bool RobotLoader::fill_mesh_visual(const MeshRead& read, LinkVisual* visual, std::string* why)
{
  visual->mesh_path = read.path;
  if (!read.ok)
  {
    *why = read.why;
    return false;
  }
  visual->geometry = shallow_copy(read.mesh.polydata);
  visual->has_mesh_color = read.mesh.has_color;
  visual->mesh_color = read.mesh.color;
  visual->has_vertex_colors = read.mesh.has_vertex_colors;
  visual->mesh_textures = read.mesh.textures;
  return true;
}

RobotLoader::MeshReads RobotLoader::read_meshes(
  const urdf::ModelInterface& model, const RobotLoadOptions& options)
{
  MeshReads reads;
  std::vector<std::pair<MeshRead*, std::array<double, 3>>> files;
  for (const auto& named : model.links_)
  {
    if (!named.second)
      continue;
    for (const urdf::VisualSharedPtr& visual : named.second->visual_array)
    {
      if (!visual || !visual->geometry || visual->geometry->type != urdf::Geometry::MESH)
        continue;
      const auto* mesh = static_cast<const urdf::Mesh*>(visual->geometry.get());
      const std::array<double, 3> scale{ { mesh->scale.x, mesh->scale.y, mesh->scale.z } };
      const std::string id = mesh_read_id(mesh->filename, scale);
      if (reads.count(id))
        continue;
      MeshRead& read = reads[id] = resolve_mesh(mesh->filename, scale, options.base_folder);
      if (read.needs_file)
        files.emplace_back(&read, scale);
    }
  }
  // Largest files first, so that no thread is left with a large file after the others are done.
  std::vector<std::uintmax_t> sizes(files.size());
  for (size_t i = 0; i < files.size(); ++i)
  {
    std::error_code ec;
    sizes[i] = std::filesystem::file_size(files[i].first->path, ec);
  }
  std::vector<size_t> order(files.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a] > sizes[b]; });

  unsigned threads = options.mesh_threads;
  if (threads == 0)
    threads = std::min(8u, std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<unsigned>(std::min<size_t>(threads, files.size()));
  std::atomic<size_t> next{ 0 };
  auto work = [&] {
    for (size_t i = next++; i < order.size(); i = next++)
      read_mesh_file(files[order[i]].first, files[order[i]].second);
  };
  // Written here because no library we use runs a few independent jobs on a few threads and
  // waits for them (vtkSMPTools' backend in Debian's VTK may be the sequential one).
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < threads; ++t)
    helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers)
    helper.join();
  for (const auto& file : files)
    mesh_files_read_ += file.first->ok ? 1 : 0;
  return reads;
}

bool RobotLoader::load_xml(const std::string& urdf_xml, const RobotLoadOptions& options,
  RobotVisuals* robot, std::string* error)
{
  if (!robot)
    return false;
  *robot = RobotVisuals();
  std::string parse_error;
  // tinyxml2 first: for malformed XML it names the line and the problem, urdfdom only the latter.
  UrdfMaterials materials;
  if (urdf_xml.find_first_not_of(" \t\r\n") != std::string::npos &&
    !materials.read(urdf_xml, &parse_error))
  {
    if (error)
      *error = parse_error;
    return false;
  }
  std::vector<std::string> urdf_messages;
  urdf::ModelInterfaceSharedPtr model =
    parse_urdf_with_diagnostics(urdf_xml, &parse_error, &urdf_messages);
  if (!model)
  {
    if (error)
      *error = parse_error;
    return false;
  }
  robot->urdf_warnings = urdf_messages;
  robot->robot_name = model->getName();
  urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root)
  {
    if (error)
      *error = "URDF has no root link";
    return false;
  }
  robot->root_link = root->name;
  MeshReads meshes = read_meshes(*model, options);

  // Depth-first from the root, parents before children (urdfdom keeps links in a name-sorted map).
  // An explicit stack, not recursion: a description from the network may be a chain of 10 000+
  // links (issue 11.2: ~7000 overflowed the stack).
  std::set<std::string> visited;
  std::vector<urdf::LinkConstSharedPtr> pending{ root };
  while (!pending.empty())
  {
    const urdf::LinkConstSharedPtr link = std::move(pending.back());
    pending.pop_back();
    if (!link || !visited.insert(link->name).second)
      continue;
    LinkVisuals entry;
    entry.link = link->name;
    // urdfdom drops visuals it cannot parse; then the document's visuals no longer line up with
    // urdfdom's, and the colours come from urdfdom's own material instead.
    const size_t in_document = materials.visual_count(link->name);
    const bool lined_up = in_document == link->visual_array.size();
    if (!lined_up)
      entry.warnings.push_back("link " + in_quotes(link->name) + ": urdfdom dropped " +
        std::to_string(in_document - std::min(in_document, link->visual_array.size())) +
        " of its " + std::to_string(in_document) + " visuals" +
        (urdf_messages.empty() ? std::string() : " (urdfdom: " + urdf_messages.back() + ")"));
    for (size_t index = 0; index < link->visual_array.size(); ++index)
    {
      const urdf::VisualSharedPtr& source = link->visual_array[index];
      if (!source)
        continue;
      LinkVisual visual;
      visual.name = source->name;
      visual.origin = to_matrix(source->origin);
      MaterialSpec material = materials.visual_material(link->name, index);
      if (!lined_up)
      {
        material = MaterialSpec();
        if (source->material)
        {
          material.name = source->material->name;
          material.has_color = source->material->texture_filename.empty();
          const urdf::Color& c = source->material->color;
          material.rgba = { { c.r, c.g, c.b, c.a } };
          material.texture = source->material->texture_filename;
        }
      }
      visual.material_name = material.name;
      visual.has_material_color = material.has_color;
      visual.material_color = material.rgba;
      visual.material_texture = material.texture;

      std::string why;
      const urdf::Geometry* geometry = source->geometry.get();
      if (!geometry)
      {
        why = "has no geometry";
      }
      else if (geometry->type == urdf::Geometry::MESH)
      {
        const auto* mesh = static_cast<const urdf::Mesh*>(geometry);
        visual.kind = VisualKind::Mesh;
        visual.mesh_uri = mesh->filename;
        visual.mesh_scale = { { mesh->scale.x, mesh->scale.y, mesh->scale.z } };
        if (!fill_mesh_visual(
              meshes[mesh_read_id(mesh->filename, visual.mesh_scale)], &visual, &why))
          entry.warnings.push_back(mesh_warning(link->name, mesh->filename, why));
        else
          why.clear();
      }
      else if (geometry->type == urdf::Geometry::BOX)
      {
        const auto* box = static_cast<const urdf::Box*>(geometry);
        visual.kind = VisualKind::Box;
        if (box->dim.x > 0 && box->dim.y > 0 && box->dim.z > 0)
          visual.geometry = make_box(box->dim.x, box->dim.y, box->dim.z);
        else
          why = "box size must be positive";
      }
      else if (geometry->type == urdf::Geometry::CYLINDER)
      {
        const auto* cylinder = static_cast<const urdf::Cylinder*>(geometry);
        visual.kind = VisualKind::Cylinder;
        if (cylinder->radius > 0 && cylinder->length > 0)
          visual.geometry = make_cylinder(cylinder->radius, cylinder->length);
        else
          why = "cylinder radius and length must be positive";
      }
      else if (geometry->type == urdf::Geometry::SPHERE)
      {
        const auto* sphere = static_cast<const urdf::Sphere*>(geometry);
        visual.kind = VisualKind::Sphere;
        if (sphere->radius > 0)
          visual.geometry = make_sphere(sphere->radius);
        else
          why = "sphere radius must be positive";
      }
      else
      {
        why = "has a geometry type ros2vtk does not know";
      }
      if (!visual.geometry)
      {
        // Primitive problems are not reported by mesh_warning above.
        if (visual.kind != VisualKind::Mesh)
          entry.warnings.push_back("link " + in_quotes(link->name) + ": visual " +
            std::to_string(index) + " " + why + "; a placeholder is shown");
        visual.kind = VisualKind::Placeholder;
        visual.geometry =
          make_box(options.placeholder_size, options.placeholder_size, options.placeholder_size);
      }
      entry.visuals.push_back(std::move(visual));
    }
    robot->links.push_back(std::move(entry));
    // Reversed, so the first child is visited first (the order the recursive walk had).
    for (auto child = link->child_links.rbegin(); child != link->child_links.rend(); ++child)
      pending.push_back(*child);
  }
  return true;
}

bool RobotLoader::read_urdf_file(
  const std::string& urdf_path, std::string* text, std::string* error) const
{
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(urdf_path, ec);
  if (ec || !std::filesystem::is_regular_file(urdf_path, ec))
  {
    if (error)
      *error = "cannot read the URDF file " + in_quotes(urdf_path) + ": no such file";
    return false;
  }
  if (XacroProcessor::is_xacro_file(urdf_path))
    return xacro_.expand(urdf_path, resolver_.max_file_bytes(), text, error);
  if (bytes > resolver_.max_file_bytes())
  {
    if (error)
      *error = "URDF file " + in_quotes(urdf_path) + " is " + std::to_string(bytes) +
        " bytes, over the limit of " + std::to_string(resolver_.max_file_bytes()) + " bytes";
    return false;
  }
  std::ifstream in(urdf_path, std::ios::binary);
  std::stringstream contents;
  contents << in.rdbuf();
  if (!in && !in.eof())
  {
    if (error)
      *error = "cannot read the URDF file " + in_quotes(urdf_path);
    return false;
  }
  *text = contents.str();
  return true;
}

bool RobotLoader::load_file(
  const std::string& urdf_path, RobotVisuals* robot, std::string* error, RobotLoadOptions options)
{
  std::string text;
  if (!read_urdf_file(urdf_path, &text, error))
    return false;
  // Its own meshes are `package://<the package holding the file>/...`: found by walking up.
  resolver_.add_package_of(urdf_path);
  std::error_code ec;
  if (options.base_folder.empty())
    options.base_folder = std::filesystem::absolute(urdf_path, ec).parent_path().string();
  std::string why;
  if (!load_xml(text, options, robot, &why))
  {
    if (error)
      *error = "URDF file " + in_quotes(urdf_path) + ": " + why;
    return false;
  }
  return true;
}

} // namespace robot
} // namespace ros2vtk
