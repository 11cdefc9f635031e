// ros2vtk tests — fuzz targets for every parser of untrusted input that is not CDR (CDR decode
// per type is tests/message/test_cdr_fuzz): multi-array layouts, URDF text, mesh files (STL,
// OBJ, PLY, DAE), scene XML, message YAML, and runtime type descriptions (REP 2011, as a node's
// ~/get_type_description answers) with a payload decoded by the type built from them. Run by CTest
// under ASan + UBSan through the seeded driver (FuzzDriver.hpp), one test per target, a fixed
// number of inputs each:
//
//     fuzz_inputs TARGET CORPUS_FOLDER ITERATIONS [SEED]
//
// Exit code 0 when every input was handled (accepted or refused with a reason); a sanitizer
// report or a broken invariant aborts.
#include "FuzzDriver.hpp"

#include "SampleType.hpp"
#include "Internal/SceneXmlReader.hpp"

#include "ros2vtk/convert/MultiArray.hpp"
#include "ros2vtk/robot/KinematicTree.hpp"
#include "ros2vtk/robot/MeshLoader.hpp"
#include "ros2vtk/robot/RobotLoader.hpp"
#include "ros2vtk/wire/DynamicType.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkTable.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLDataElement.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <unistd.h>

using namespace ros2vtk_fuzz;

namespace {

void require(bool condition, const char* what)
{
  if (!condition)
  {
    std::cerr << "fuzz invariant broken: " << what << std::endl;
    std::abort();
  }
}

/// Bytes -> a multi-array: [dims (low 2 bits)] then per dim [size u32][stride u32][label 2
/// chars], [data_offset u32], then the data (doubles, and the same bytes as int64).
bool multi_array(const std::string& input)
{
  size_t at = 0;
  auto take = [&](void* out, size_t n) {
    std::memset(out, 0, n);
    const size_t have = at < input.size() ? std::min(n, input.size() - at) : 0;
    if (have)
      std::memcpy(out, input.data() + at, have);
    at += n;
  };
  uint8_t dims = 0;
  take(&dims, 1);
  ros2vtk::convert::MultiArrayLayout layout;
  for (int d = 0; d < (dims & 3); ++d)
  {
    ros2vtk::convert::MultiArrayDimension dim;
    take(&dim.size, 4);
    take(&dim.stride, 4);
    char label[2];
    take(label, 2);
    dim.label.assign(label, 2);
    layout.dim.push_back(dim);
  }
  take(&layout.data_offset, 4);
  std::vector<double> doubles;
  std::vector<int64_t> ints;
  while (at + 8 <= input.size())
  {
    double d;
    int64_t i;
    std::memcpy(&d, input.data() + at, 8);
    std::memcpy(&i, input.data() + at, 8);
    doubles.push_back(d);
    ints.push_back(i);
    at += 8;
  }
  std::string error;
  vtkNew<vtkDoubleArray> array;
  vtkNew<vtkTypeInt64Array> int_array;
  vtkNew<vtkTable> table;
  const bool a = ros2vtk::convert::multi_array_to_array(layout, doubles, array, &error);
  require(a || !error.empty(), "a refused multi-array has a reason");
  ros2vtk::convert::multi_array_to_array(layout, ints, int_array, &error);
  const bool t = ros2vtk::convert::multi_array_to_table(layout, doubles, table, &error);
  ros2vtk::convert::multi_array_to_table(layout, ints, table, &error);
  require(!a || array->GetNumberOfValues() <= static_cast<vtkIdType>(doubles.size()),
    "an array never holds more values than the message");
  return a || t;
}

bool urdf(const std::string& input)
{
  ros2vtk::robot::RobotLoader loader{ ros2vtk::robot::ResourceResolver() };
  ros2vtk::robot::RobotVisuals robot;
  std::string error;
  const bool loaded = loader.load_xml(input, ros2vtk::robot::RobotLoadOptions(), &robot, &error);
  require(loaded || !error.empty(), "a refused URDF has a reason");
  std::string tree_error;
  auto tree = ros2vtk::robot::KinematicTree::from_urdf(input, &tree_error);
  return loaded && tree;
}

/// A mesh target for one extension: the input is written to a file of that extension.
std::function<bool(const std::string&)> mesh(const std::string& extension)
{
  return [extension](const std::string& input) {
    static const std::string path = (std::filesystem::temp_directory_path() /
      ("ros2vtk_fuzz_" + std::to_string(::getpid()) + extension))
                                      .string();
    std::ofstream(path, std::ios::binary | std::ios::trunc) << input;
    ros2vtk::robot::MeshData mesh;
    std::string error;
    const bool ok = ros2vtk::robot::MeshLoader().load(path, &mesh, &error);
    require(ok || !error.empty(), "a refused mesh has a reason");
    require(!ok || mesh.polydata, "a loaded mesh has geometry");
    return ok;
  };
}

bool scene_xml(const std::string& input)
{
  std::string error;
  auto root = ros2vtk::scene::ReadSceneXml(input, &error);
  require(root || !error.empty(), "a refused scene file has a reason");
  return root != nullptr;
}

/// Accepted YAML must write back to YAML that reads to the same message.
bool yaml(const std::string& input)
{
  Sample first;
  std::string error;
  if (!ros2vtk::wire::from_yaml(sample_type(), input, &first, &error))
  {
    require(!error.empty(), "refused YAML has a reason");
    return false;
  }
  const std::string written = ros2vtk::wire::to_yaml(sample_type(), &first);
  Sample second;
  require(
    ros2vtk::wire::from_yaml(sample_type(), written, &second, &error), "written YAML reads back");
  require(first == second, "written YAML reads back to the same message");
  return true;
}

/// The text form of a type description and a payload (tests/fuzz/make_type_description_corpus.py
/// writes the seeds from rclpy's answers): "T name" starts a type (the main one first), "F name
/// type_id capacity string_capacity nested default..." adds a field, "P hex" is the payload;
/// other lines are skipped.
bool read_description(const std::string& input, ros2vtk::wire::TypeDescriptionData& description,
  std::vector<uint8_t>& payload)
{
  std::istringstream lines(input);
  std::string line;
  bool have_main = false;
  ros2vtk::wire::IndividualDescription* current = nullptr;
  while (std::getline(lines, line))
  {
    if (line.size() < 2 || line[1] != ' ')
      continue; // a broken line is skipped: the rest still reaches the type builder
    const std::string rest = line.substr(2);
    if (line[0] == 'T')
    {
      if (!have_main)
      {
        description.type.type_name = rest;
        current = &description.type;
        have_main = true;
      }
      else
      {
        description.referenced.push_back({ rest, {}, {} });
        current = &description.referenced.back();
      }
    }
    else if (line[0] == 'F' && current)
    {
      std::istringstream words(rest);
      ros2vtk::wire::DescriptionField field;
      unsigned type_id = 0;
      if (!(words >> field.name >> type_id >> field.capacity >> field.string_capacity >>
            field.nested_type_name))
        continue;
      field.type_id = static_cast<uint8_t>(type_id);
      if (field.nested_type_name == "-")
        field.nested_type_name.clear();
      std::getline(words >> std::ws, field.default_value);
      current->fields.push_back(std::move(field));
    }
    else if (line[0] == 'P')
    {
      for (size_t i = 0; i + 1 < rest.size(); i += 2)
        payload.push_back(
          static_cast<uint8_t>(std::strtoul(rest.substr(i, 2).c_str(), nullptr, 16)));
    }
  }
  return have_main;
}

/// A description is built or refused with a reason; a built type decodes the payload or refuses
/// it with a reason, and what it decoded writes back to bytes that decode to the same bytes.
/// Each accepted description takes one of the process's kMaxDynamicTypes slots: keep the input
/// count below that (CMakeLists.txt).
bool type_description(const std::string& input)
{
  ros2vtk::wire::TypeDescriptionData description;
  std::vector<uint8_t> payload;
  if (!read_description(input, description, payload))
    return false;
  std::string error;
  const std::string hash = ros2vtk::wire::type_description_hash(description, &error);
  require(!hash.empty() || !error.empty(), "an unhashable description has a reason");
  error.clear();
  const ros2vtk::wire::MessageTypeSupport* type =
    ros2vtk::wire::build_dynamic_message_type(description, "", &error);
  if (!type)
  {
    require(!error.empty(), "a refused description has a reason");
    return false;
  }
  std::unique_ptr<void, void (*)(void*)> message(type->create(), type->destroy);
  const std::string yaml_of_default = ros2vtk::wire::to_yaml(*type, message.get());
  (void)yaml_of_default;
  if (payload.empty())
    return true;
  if (!ros2vtk::wire::deserialize_message(
        *type, payload.data(), payload.size(), message.get(), &error))
  {
    require(!error.empty(), "a refused payload has a reason");
    return true; // the description was accepted
  }
  const std::string yaml = ros2vtk::wire::to_yaml(*type, message.get());
  (void)yaml;
  std::vector<uint8_t> written;
  ros2vtk::wire::serialize_message(*type, message.get(), written);
  std::unique_ptr<void, void (*)(void*)> again(type->create(), type->destroy);
  require(
    ros2vtk::wire::deserialize_message(*type, written.data(), written.size(), again.get(), &error),
    "what a runtime type wrote reads back");
  std::vector<uint8_t> rewritten;
  ros2vtk::wire::serialize_message(*type, again.get(), rewritten);
  require(written == rewritten, "a runtime type writes what it read back byte for byte");
  return true;
}

/// The constants of a .msg text (a learnt type's type_source): read or refused with a reason.
bool msg_constants(const std::string& input)
{
  std::vector<ros2vtk::wire::DescriptionConstant> constants;
  std::string error;
  if (!ros2vtk::wire::parse_msg_constants(input, &constants, &error))
  {
    require(!error.empty(), "refused constants have a reason");
    return false;
  }
  for (const auto& constant : constants)
    require(!constant.name.empty(), "a constant has a name");
  return true;
}

std::map<std::string, FuzzTarget> targets()
{
  std::map<std::string, FuzzTarget> all;
  auto add = [&](FuzzTarget target) {
    all[target.name] = std::move(target);
  };
  add({ "multi_array", {}, multi_array });
  add({ "urdf",
    { "<link name=\"l\"/>",
      "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>",
      "<visual><geometry><mesh filename=\"package://p/../../x.stl\"/></geometry></visual>",
      "<robot>", "</robot>", "<!ENTITY e \"&e;&e;\">", "&e;",
      "<material name=\"m\"><color rgba=\"1 0 0 1\"/></material>" },
    urdf });
  add({ "mesh_stl",
    { "solid ", "facet normal 0 0 1\n outer loop\n", "vertex 1e308 -1e308 nan\n",
      "endloop\n endfacet\n", std::string("\xff\xff\xff\x7f", 4) },
    mesh(".stl") });
  add({ "mesh_obj",
    { "v 1 2 3\n", "f 1 2 3\n", "f -1 -2 -99999\n", "vt 0 0\n", "mtllib x.mtl\n", "usemtl m\n" },
    mesh(".obj") });
  add({ "mesh_ply",
    { "element vertex 4294967295\n", "property float x\n",
      "property list uchar int vertex_indices\n", "end_header\n",
      "format binary_little_endian 1.0\n" },
    mesh(".ply") });
  add({ "mesh_dae",
    { "<node>", "</node>", "<instance_geometry url=\"#g\"/>", "<float_array count=\"99999999\">",
      "<p>0 1 2</p>", "<library_geometries>" },
    mesh(".dae") });
  add({ "scene_xml",
    { "<x>", "</x>", "<vtkROS2NodeNode id=\"a\" name=\"n\"/>", " attr=\"v\"", "&amp;", "<![CDATA[",
      "<!--" },
    scene_xml });
  add({ "yaml",
    { "inners: ", "[", "]", "{", "}", "- ", "&a ", "*a", "s: ", "text: ", "bytes: [1, 2]", "'",
      "\"\\x", "!!binary " },
    yaml });
  add({ "type_description",
    { "F v 1 0 0 test_msgs/msg/BasicTypes\n", "F s 17 0 0 - 'x'\n", "F a 49 4 0 -\n",
      "F q 145 0 0 -\n", "F b 97 3 8 -\n", "T test_msgs/msg/BasicTypes\n", " 4294967295 ", " 255 ",
      "P 00010000ffffffff\n" },
    type_description });
  add({ "msg_constants",
    { "uint8 A=1\n", "string S='#x'\n", "float32 F=1e38\n", "int64 N=-0x8000000000000000\n",
      "bool B=True\n", " = ", "<=", "#", "\"", "\\", "[", "string<=3 S=abcd\n" },
    msg_constants });
  return all;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 4)
  {
    std::cerr << "usage: fuzz_inputs TARGET CORPUS_FOLDER ITERATIONS [SEED]" << std::endl;
    return 2;
  }
  vtkObject::GlobalWarningDisplayOff(); // refused inputs make VTK readers complain on stderr
  const auto all = targets();
  const auto found = all.find(argv[1]);
  if (found == all.end())
  {
    std::cerr << "unknown target '" << argv[1] << "'; known:";
    for (const auto& entry : all)
      std::cerr << " " << entry.first;
    std::cerr << std::endl;
    return 2;
  }
  const auto corpus = read_corpus(argv[2]);
  if (corpus.empty())
  {
    std::cerr << "empty corpus folder '" << argv[2] << "'" << std::endl;
    return 2;
  }
  const FuzzReport report = fuzz(found->second, corpus, std::strtoull(argv[3], nullptr, 10),
    argc > 4 ? static_cast<uint32_t>(std::strtoul(argv[4], nullptr, 10)) : 1u);
  std::cout << argv[1] << ": " << report.inputs << " inputs (" << corpus.size()
            << " from the corpus), " << report.accepted << " accepted" << std::endl;
  // The unmodified corpus must be accepted: otherwise the target tests nothing but refusals.
  return report.accepted >= 1 ? 0 : 1;
}
