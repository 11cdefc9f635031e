// ros2vtk — mesh files into vtkPolyData (VTK's reader for STL, assimp for the rest).
//
// Why PLY goes through assimp and not VTK 9.1: vtkPLYReader crashes on malformed files (a null
// dereference in vtkPLY::find_element on a bad header, a free() of a non-heap address in
// RequestData on a truncated body; both found by mutating our test PLY under AddressSanitizer).
// Why OBJ goes through assimp and not VTK 9.1: vtkOBJReader reads no .mtl, and the MaterialNames
// it reports are not in the order of its MaterialIds (two_colours.obj comes out with the wrong
// colours); vtkOBJImporter needs a render window, and the parser behind it
// (vtkOBJPolyDataProcessor) crashed in our probe when a `usemtl` named a material the .mtl lacks.
// assimp reads OBJ + MTL as RViz 2 does (RViz loads every mesh through assimp).
#include "ros2vtk/robot/MeshLoader.hpp"

#include "ColladaFileCheck.hpp"
#include "PlyFileCheck.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSTLReader.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace ros2vtk {
namespace robot {
namespace {

std::string lower_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Collects what a VTK reader reports through vtkErrorMacro/vtkWarningMacro, so the messages go
// into our error string instead of VTK's output window (an observer on ErrorEvent replaces the
// default printing).
class VtkMessageCollector : public vtkCommand
{
public:
  static VtkMessageCollector* New() { return new VtkMessageCollector; }
  void Execute(vtkObject*, unsigned long event, void* call_data) override
  {
    const char* text = static_cast<const char*>(call_data);
    std::string message = text ? text : "";
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
      message.pop_back();
    (event == vtkCommand::ErrorEvent ? errors : warnings).push_back(message);
  }
  void watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  std::string summary() const
  {
    std::string out;
    for (const auto& message : errors)
      out += (out.empty() ? "" : "; ") + message;
    return out;
  }
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
};

unsigned char to_byte(double value)
{
  return static_cast<unsigned char>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

vtkSmartPointer<vtkUnsignedCharArray> make_color_array(vtkIdType points)
{
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName(kVertexColorArray);
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(points);
  return colors;
}

void fill_color(
  vtkUnsignedCharArray* colors, vtkIdType from, vtkIdType to, const std::array<double, 4>& rgba)
{
  const unsigned char bytes[4] = { to_byte(rgba[0]), to_byte(rgba[1]), to_byte(rgba[2]),
    to_byte(rgba[3]) };
  for (vtkIdType i = from; i < to; ++i)
    colors->SetTypedTuple(i, bytes);
}

// Triangles only, no stray vertices or lines: what the scene renders and the tests measure.
vtkSmartPointer<vtkPolyData> triangulated(vtkPolyData* input)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  return out;
}

bool finish(vtkPolyData* polydata, const std::string& path, MeshData* mesh, std::string* error)
{
  vtkSmartPointer<vtkPolyData> result = triangulated(polydata);
  if (result->GetNumberOfPoints() == 0 || result->GetNumberOfPolys() == 0)
  {
    if (error)
      *error = "mesh file '" + path + "' holds no triangles";
    return false;
  }
  if (mesh->has_vertex_colors)
    result->GetPointData()->SetActiveScalars(kVertexColorArray);
  mesh->polydata = result;
  return true;
}

template<typename Reader>
bool read_with_vtk(const std::string& path, const char* format, MeshData* mesh, std::string* error,
  vtkSmartPointer<vtkPolyData>* output)
{
  vtkNew<Reader> reader;
  vtkNew<VtkMessageCollector> messages;
  messages->watch(reader);
  if (reader->GetExecutive())
    messages->watch(reader->GetExecutive());
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!messages->errors.empty() || reader->GetErrorCode() != 0)
  {
    if (error)
      *error = std::string("VTK's ") + format + " reader failed on '" + path + "'" +
        (messages->errors.empty() ? std::string() : ": " + messages->summary());
    return false;
  }
  *output = reader->GetOutput();
  (void)mesh;
  return true;
}

// vtkSTLReader reads a truncated binary STL silently (it stops at the end of the file), so the
// header's triangle count is checked against the file size here: 80-byte header, uint32 count,
// 50 bytes per triangle. Files starting with "solid" may be ASCII and are left to VTK.
bool check_binary_stl_size(const std::string& path, std::string* error)
{
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, sizeof(head));
  const std::streamsize got = in.gcount();
  std::string start(head, static_cast<size_t>(std::min<std::streamsize>(got, 80)));
  start.erase(0, start.find_first_not_of(" \t\r\n"));
  // A file starting with "solid" may still be read as binary by vtkSTLReader (found by
  // tests/fuzz: such a file with NUL bytes, announcing 538 million triangles, made VTK allocate
  // 19 GB). Only a file that is all text skips the binary size check; the scan is linear, like
  // the ASCII parse that follows.
  bool all_text = true;
  std::ifstream scan(path, std::ios::binary);
  char chunk[65536];
  while (all_text && scan.read(chunk, sizeof(chunk)).gcount() > 0)
    all_text = std::all_of(chunk, chunk + scan.gcount(), [](char c) {
      const auto byte = static_cast<unsigned char>(c);
      return (byte >= 0x20 && byte < 0x7f) || (byte >= 0x09 && byte <= 0x0d);
    });
  const bool vtk_reads_binary = !all_text;
  if (start.compare(0, 5, "solid") == 0 && !vtk_reads_binary)
    return true;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (got < 84 || ec)
  {
    if (error)
      *error = "STL file '" + path + "' is too short for a binary STL (" + std::to_string(got) +
        " bytes) and is not ASCII STL";
    return false;
  }
  std::uint32_t count = 0;
  std::memcpy(&count, head + 80, 4);
  const std::uintmax_t needed = 84u + 50u * static_cast<std::uintmax_t>(count);
  if (size < needed)
  {
    if (error)
      *error = "STL file '" + path + "' is truncated: its header announces " +
        std::to_string(count) + " triangles (" + std::to_string(needed) +
        " bytes) but the file has " + std::to_string(size) + " bytes";
    return false;
  }
  return true;
}

bool load_stl(const std::string& path, MeshData* mesh, std::string* error)
{
  if (!check_binary_stl_size(path, error))
    return false;
  vtkSmartPointer<vtkPolyData> output;
  if (!read_with_vtk<vtkSTLReader>(path, "STL", mesh, error, &output))
    return false;
  return finish(output, path, mesh, error);
}

// ---- assimp -------------------------------------------------------------------------------

bool material_diffuse(const aiScene* scene, unsigned index, std::array<double, 4>* rgba,
  std::vector<std::string>* textures)
{
  if (index >= scene->mNumMaterials || !scene->mMaterials[index])
    return false;
  const aiMaterial* material = scene->mMaterials[index];
  aiString name;
  // assimp invents "DefaultMaterial" for meshes without one: that is not a colour of the file.
  if (material->Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
    std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME)
    return false;
  aiString texture;
  if (material->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS && textures &&
    std::find(textures->begin(), textures->end(), texture.C_Str()) == textures->end())
    textures->push_back(texture.C_Str());
  aiColor4D diffuse;
  if (material->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) != AI_SUCCESS)
    return false;
  float opacity = 1.0f;
  if (material->Get(AI_MATKEY_OPACITY, opacity) != AI_SUCCESS)
    opacity = 1.0f;
  *rgba = { { diffuse.r, diffuse.g, diffuse.b,
    std::clamp(static_cast<double>(diffuse.a * opacity), 0.0, 1.0) } };
  return true;
}

struct AssimpCollector
{
  const aiScene* scene = nullptr;
  vtkSmartPointer<vtkPoints> points = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkCellArray> triangles = vtkSmartPointer<vtkCellArray>::New();
  std::vector<std::array<double, 4>> point_colors; ///< one per point
  std::vector<bool> point_colored;
  std::vector<std::string> textures;
  int depth_guard = 0;

  void add_node(const aiNode* node, const aiMatrix4x4& parent)
  {
    // A malformed file could describe a very deep (or, through assimp's bugs, cyclic) tree.
    if (!node || ++depth_guard > 100000)
      return;
    const aiMatrix4x4 transform = parent * node->mTransformation;
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      if (node->mMeshes[i] < scene->mNumMeshes)
        add_mesh(scene->mMeshes[node->mMeshes[i]], transform);
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      add_node(node->mChildren[c], transform);
  }

  void add_mesh(const aiMesh* mesh, const aiMatrix4x4& transform)
  {
    if (!mesh || !mesh->mVertices)
      return;
    const vtkIdType first = points->GetNumberOfPoints();
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh->mVertices[v];
      points->InsertNextPoint(p.x, p.y, p.z);
    }
    std::array<double, 4> rgba{ { 1.0, 1.0, 1.0, 1.0 } };
    const bool has_material_color = material_diffuse(scene, mesh->mMaterialIndex, &rgba, &textures);
    if (mesh->HasVertexColors(0))
    {
      for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      {
        const aiColor4D& c = mesh->mColors[0][v];
        point_colors.push_back({ { c.r, c.g, c.b, c.a } });
      }
      point_colored.insert(point_colored.end(), mesh->mNumVertices, true);
    }
    else
    {
      point_colors.insert(point_colors.end(), mesh->mNumVertices, rgba);
      point_colored.insert(point_colored.end(), mesh->mNumVertices, has_material_color);
    }
    // Polygons go in as they are and vtkTriangleFilter triangulates them (finish()): assimp
    // 5.2's own aiProcess_Triangulate aborts the process on some malformed files (an ai_assert
    // in TriangulateProcess.cpp, met with a truncated PLY).
    std::vector<vtkIdType> ids;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
    {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices < 3 || !face.mIndices)
        continue; // points and lines (removed by SortByPType already) or a broken face
      ids.clear();
      bool valid = true;
      for (unsigned k = 0; k < face.mNumIndices && valid; ++k)
      {
        valid = face.mIndices[k] < mesh->mNumVertices;
        ids.push_back(first + static_cast<vtkIdType>(face.mIndices[k]));
      }
      if (valid)
        triangles->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
  }
};

bool load_with_assimp(const std::string& path, MeshData* mesh, std::string* error)
{
  Assimp::Importer importer;
  // A Collada file's <up_axis> is not applied: ROS tools (RViz, DART, Gazebo) take the authored
  // coordinates as the link frame. Its <unit meter="…"> is applied (assimp scales the root node),
  // so a DAE in centimetres comes out in metres like RViz shows it.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(
    AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path,
    aiProcess_ValidateDataStructure | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode)
  {
    if (error)
      *error = "assimp could not read '" + path + "': " + importer.GetErrorString();
    return false;
  }
  AssimpCollector collector;
  collector.scene = scene;
  collector.add_node(scene->mRootNode, aiMatrix4x4());
  mesh->textures = collector.textures;

  vtkNew<vtkPolyData> polydata;
  polydata->SetPoints(collector.points);
  polydata->SetPolys(collector.triangles);
  const auto& colors = collector.point_colors;
  const bool one_color = !colors.empty() &&
    std::all_of(colors.begin(), colors.end(), [&](const auto& c) { return c == colors.front(); });
  const bool all_colored = std::all_of(
    collector.point_colored.begin(), collector.point_colored.end(), [](bool b) { return b; });
  const bool any_colored = std::any_of(
    collector.point_colored.begin(), collector.point_colored.end(), [](bool b) { return b; });
  if (any_colored && all_colored && one_color)
  {
    mesh->has_color = true;
    mesh->color = colors.front();
  }
  else if (any_colored)
  {
    auto array = make_color_array(static_cast<vtkIdType>(colors.size()));
    // Points come in runs of one colour (a mesh's material): one conversion per run.
    for (size_t run = 0, i = 1; run < colors.size(); run = i++)
    {
      while (i < colors.size() && colors[i] == colors[run])
        ++i;
      fill_color(array, static_cast<vtkIdType>(run), static_cast<vtkIdType>(i), colors[run]);
    }
    polydata->GetPointData()->AddArray(array);
    mesh->has_vertex_colors = true;
  }
  return finish(polydata, path, mesh, error);
}

// Why the file is checked before a reader sees it: a reader's complaint about a file it could not
// use ("Unable to open file", "malformed XML", "too short for a binary STL") hides the cause a
// user can act on — no permission, an empty file, a Git LFS pointer checked out instead of the
// mesh (common in robot repositories cloned without git-lfs).
bool check_mesh_file(const std::string& path, const std::string& extension, std::string* error)
{
  auto fail = [&](const std::string& why) {
    if (error)
      *error = "mesh file '" + path + "' " + why;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail("does not exist or is not a regular file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return fail(
      "cannot be opened: " + std::string(errno ? std::strerror(errno) : "unknown reason"));
  char head[64] = {};
  in.read(head, sizeof(head));
  const std::streamsize got = in.gcount();
  if (in.bad())
    return fail("cannot be read: " + std::string(errno ? std::strerror(errno) : "read error"));
  std::string format = extension.empty() ? std::string("mesh") : extension.substr(1);
  std::transform(format.begin(), format.end(), format.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (got == 0)
    return fail("is empty (0 bytes), so it holds no " + format + " mesh");
  const std::string lfs_pointer = "version https://git-lfs.github.com/spec/";
  if (std::string(head, static_cast<size_t>(got)).compare(0, lfs_pointer.size(), lfs_pointer) == 0)
    return fail("is a Git LFS pointer, not the " + format +
      " mesh itself: the repository was cloned without git-lfs (run `git lfs pull` in it)");
  return true;
}

} // namespace

std::vector<std::string> MeshLoader::vtk_extensions()
{
  return { ".stl" };
}

bool MeshLoader::assimp_reads(const std::string& extension)
{
  Assimp::Importer importer;
  return importer.IsExtensionSupported(extension);
}

bool MeshLoader::load(const std::string& path, MeshData* mesh, std::string* error) const
{
  if (!mesh)
    return false;
  *mesh = MeshData();
  const std::string extension = lower_extension(path);
  if (extension.empty())
  {
    if (error)
      *error = "mesh file '" + path +
        "' has no file extension, so its format is unknown (STL, PLY, OBJ, Collada "
        ".dae, glTF/GLB and the other formats assimp reads are chosen by extension)";
    return false;
  }
  if (!check_mesh_file(path, extension, error))
    return false;
  try
  {
    if (extension == ".stl")
      return load_stl(path, mesh, error);
    if (extension == ".ply")
      return PlyFileCheck::check(path, error) && load_with_assimp(path, mesh, error);
    if (!assimp_reads(extension))
    {
      if (error)
        *error = "mesh file '" + path + "': the format '" + extension +
          "' is not supported (STL through VTK; PLY, OBJ, Collada .dae, glTF/GLB and the other "
          "formats "
          "assimp reads)";
      return false;
    }
    if (extension == ".dae" && !ColladaFileCheck::check(path, error))
      return false;
    return load_with_assimp(path, mesh, error);
  }
  catch (const std::exception& exception)
  {
    if (error)
      *error = "reading mesh file '" + path + "' failed: " + exception.what();
  }
  catch (...)
  {
    if (error)
      *error = "reading mesh file '" + path + "' failed with an unknown exception";
  }
  *mesh = MeshData();
  return false;
}

} // namespace robot
} // namespace ros2vtk
