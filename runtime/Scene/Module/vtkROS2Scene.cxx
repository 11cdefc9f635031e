#include "vtkROS2Scene.h"

#include "NodeClassRegistry.hpp"
#include "Internal/SceneXmlReader.hpp"
#include "vtkROS2SceneNode.h"

#include "vtkCollection.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLUtilities.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace {
// Root element and format version of scene files.
const char* const SceneTag = "ROS2Scene";
const int SceneFormatVersion = 1;
} // namespace

//------------------------------------------------------------------------------
class vtkROS2Scene::vtkInternals
{
public:
  std::vector<vtkSmartPointer<vtkROS2SceneNode>> Nodes; // in the order they were added
  std::map<std::string, vtkROS2SceneNode*, std::less<>>
    ByID;                                      // less<>: find(const char*) copies nothing
  std::map<std::string, int> NextIndexByClass; // for `<ClassName><n>` IDs
  std::string RemovalReason;                   // while ClearBecause runs: why the nodes leave
  std::string FixedFrame;                      // SetFixedFrame ("" none)
  // referenced ID -> nodes of this scene that gained a reference to it (a superset: a node that
  // dropped the reference since is visited for nothing, never missed).
  std::unordered_map<std::string, std::unordered_set<vtkROS2SceneNode*>> Referrers;
  // The same pairs the other way round, so a node that leaves the scene is taken out of every
  // Referrers entry it is in, including those of references it has dropped since (otherwise a
  // freed node would be visited when the node it once referred to is removed).
  std::unordered_map<vtkROS2SceneNode*, std::unordered_set<std::string>> ReferencedBy;
  unsigned long NodesVersion = 0; // see GetNodesVersion

  std::string UniqueID(const std::string& className)
  {
    int& next = this->NextIndexByClass[className];
    std::string id;
    do
    {
      id = className + std::to_string(++next);
    } while (this->ByID.count(id) > 0);
    return id;
  }
};

vtkStandardNewMacro(vtkROS2Scene);

//------------------------------------------------------------------------------
vtkROS2Scene::vtkROS2Scene()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2Scene::~vtkROS2Scene()
{
  this->Clear();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::AddNode(vtkROS2SceneNode* node)
{
  if (!node)
  {
    vtkErrorMacro("AddNode: node is null");
    return nullptr;
  }
  if (!this->AddNodeWithID(node, this->Internals->UniqueID(node->GetClassName())))
  {
    return nullptr;
  }
  return node;
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::AddNodeWithID(vtkROS2SceneNode* node, const std::string& id)
{
  if (node->GetScene())
  {
    vtkErrorMacro("AddNode: node '" << node->GetID() << "' is already in a scene");
    return false;
  }
  if (id.empty() || this->Internals->ByID.count(id) > 0)
  {
    vtkErrorMacro("AddNode: node ID '" << id << "' is empty or already used");
    return false;
  }
  this->Internals->Nodes.emplace_back(node);
  this->Internals->ByID[id] = node;
  ++this->Internals->NodesVersion;
  node->SetSceneAndID(this, id.c_str());
  this->Modified();
  this->InvokeEvent(NodeAddedEvent, node);
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::RemoveNode(vtkROS2SceneNode* node)
{
  if (!node || node->GetScene() != this)
  {
    vtkErrorMacro("RemoveNode: node is not in this scene");
    return false;
  }
  auto& nodes = this->Internals->Nodes;
  // From the back: Clear removes the newest node first.
  auto last = [&nodes](vtkROS2SceneNode* wanted) {
    return std::find(nodes.rbegin(), nodes.rend(), wanted);
  };
  if (last(node) == nodes.rend())
  {
    vtkErrorMacro("RemoveNode: node is not in this scene");
    return false;
  }
  // Keep the node alive until observers have seen it go.
  vtkSmartPointer<vtkROS2SceneNode> keep = node;
  const std::string id = node->GetID();
  // Lets it release ROS resources while the scene is intact.
  node->SetSceneAndID(nullptr, id.c_str(), this->Internals->RemovalReason);
  nodes.erase(std::next(last(node)).base());
  this->Internals->ByID.erase(id);
  ++this->Internals->NodesVersion;
  auto& referrers = this->Internals->Referrers;
  auto& referencedBy = this->Internals->ReferencedBy;
  auto noted = referencedBy.find(node);
  if (noted != referencedBy.end())
  {
    for (const std::string& referenced : noted->second)
    {
      auto entry = referrers.find(referenced);
      if (entry != referrers.end())
      {
        entry->second.erase(node);
        if (entry->second.empty())
        {
          referrers.erase(entry);
        }
      }
    }
    referencedBy.erase(noted);
  }
  auto entry = referrers.find(id);
  if (entry != referrers.end())
  {
    const std::unordered_set<vtkROS2SceneNode*> visit = std::move(entry->second);
    referrers.erase(entry);
    for (vtkROS2SceneNode* other : visit)
    {
      referencedBy[other].erase(id);
      if (other->GetScene() == this)
      {
        other->ForgetReferencesTo(id.c_str());
      }
    }
  }
  this->Modified();
  this->InvokeEvent(NodeRemovedEvent, node);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2Scene::NoteReferrer(const std::string& referencedNodeID, vtkROS2SceneNode* referrer)
{
  if (referrer && referrer->GetScene() == this)
  {
    this->Internals->Referrers[referencedNodeID].insert(referrer);
    this->Internals->ReferencedBy[referrer].insert(referencedNodeID);
  }
}

//------------------------------------------------------------------------------
void vtkROS2Scene::Clear()
{
  this->ClearBecause(std::string());
}

//------------------------------------------------------------------------------
void vtkROS2Scene::ClearBecause(const std::string& reason)
{
  this->Internals->RemovalReason = reason;
  while (!this->Internals->Nodes.empty())
  {
    this->RemoveNode(this->Internals->Nodes.back());
  }
  this->Internals->RemovalReason.clear();
  this->Internals->NextIndexByClass.clear();
}

//------------------------------------------------------------------------------
int vtkROS2Scene::GetNumberOfNodes() const
{
  return static_cast<int>(this->Internals->Nodes.size());
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::GetNthNode(int n) const
{
  if (n < 0 || n >= this->GetNumberOfNodes())
  {
    return nullptr;
  }
  return this->Internals->Nodes[static_cast<size_t>(n)];
}

//------------------------------------------------------------------------------
unsigned long vtkROS2Scene::GetNodesVersion() const
{
  return this->Internals->NodesVersion;
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::GetNodeByID(const char* id) const
{
  if (!id)
  {
    return nullptr;
  }
  auto it = this->Internals->ByID.find(id);
  return it == this->Internals->ByID.end() ? nullptr : it->second;
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::GetFirstNodeByName(const char* name) const
{
  if (!name)
  {
    return nullptr;
  }
  for (const auto& node : this->Internals->Nodes)
  {
    if (std::string(node->GetName()) == name)
    {
      return node;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkROS2Scene::GetNodesByClass(const char* className, vtkCollection* nodes) const
{
  if (!className || !nodes)
  {
    return;
  }
  for (const auto& node : this->Internals->Nodes)
  {
    if (node->IsA(className))
    {
      nodes->AddItem(node);
    }
  }
}

//------------------------------------------------------------------------------
int vtkROS2Scene::GetNumberOfNodesByClass(const char* className) const
{
  if (!className)
  {
    return 0;
  }
  return static_cast<int>(std::count_if(this->Internals->Nodes.begin(),
    this->Internals->Nodes.end(), [className](const auto& node) { return node->IsA(className); }));
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::GetNthNodeByClass(int n, const char* className) const
{
  if (!className || n < 0)
  {
    return nullptr;
  }
  for (const auto& node : this->Internals->Nodes)
  {
    if (node->IsA(className) && n-- == 0)
    {
      return node;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::CreateNodeByClass(const char* className)
{
  auto& registry = ros2vtk::scene::NodeClassRegistry::instance();
  const auto* info = className ? registry.find_class(className) : nullptr;
  if (!info)
  {
    std::ostringstream known;
    for (auto direction : { ros2vtk::scene::NodeDirection::Other,
           ros2vtk::scene::NodeDirection::Publisher, ros2vtk::scene::NodeDirection::Subscriber })
    {
      for (const auto* entry : registry.classes(direction))
      {
        known << " " << entry->class_name;
      }
    }
    vtkErrorMacro("CreateNodeByClass: unknown class '" << (className ? className : "(null)")
                                                       << "'. Known classes:" << known.str());
    return nullptr;
  }
  return info->create();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2Scene::AddNewNodeByClass(const char* className, const char* name)
{
  // The registry accepts SlicerROS2's class names and Slicer's core classes' names too.
  vtkSmartPointer<vtkROS2SceneNode> node;
  node.TakeReference(this->CreateNodeByClass(className));
  if (!node)
  {
    return nullptr;
  }
  if (name && *name)
  {
    node->SetName(name);
  }
  return this->AddNode(node);
}

//------------------------------------------------------------------------------
std::string vtkROS2Scene::WriteToXMLString()
{
  vtkNew<vtkXMLDataElement> root;
  root->SetName(SceneTag);
  root->SetIntAttribute("version", SceneFormatVersion);
  if (!this->Internals->FixedFrame
         .empty()) // only when set: files of earlier versions stay as they were
  {
    root->SetAttribute("fixedFrame", this->Internals->FixedFrame.c_str());
  }
  for (const auto& node : this->Internals->Nodes)
  {
    if (!node->GetSaveWithScene())
    {
      continue;
    }
    vtkNew<vtkXMLDataElement> element;
    element->SetName(node->GetXMLTagName());
    node->WriteXML(element);
    root->AddNestedElement(element);
  }
  std::ostringstream stream;
  vtkIndent indent; // one element per line: scene files are read and diffed by people
  vtkXMLUtilities::FlattenElement(root, stream, &indent, 1);
  return stream.str();
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::WriteToXMLFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("WriteToXMLFile: no file name");
    return false;
  }
  std::ofstream file(fileName);
  file << this->WriteToXMLString();
  file.close();
  if (!file)
  {
    vtkErrorMacro("WriteToXMLFile: cannot write '" << fileName << "'");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::ReadFromXMLFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("ReadFromXMLFile: no file name");
    return false;
  }
  std::string text;
  std::string error;
  if (!ros2vtk::scene::ReadSceneXmlFile(fileName, &text, &error))
  {
    vtkErrorMacro("ReadFromXMLFile: " << error);
    return false;
  }
  vtkSmartPointer<vtkXMLDataElement> root = ros2vtk::scene::ReadSceneXml(text, &error);
  if (!root)
  {
    vtkErrorMacro("ReadFromXMLFile: '" << fileName << "': " << error);
    return false;
  }
  return this->ReadFromXMLElement(root);
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::ReadFromXMLString(const char* xml)
{
  std::string error = "no text";
  vtkSmartPointer<vtkXMLDataElement> root =
    xml ? ros2vtk::scene::ReadSceneXml(xml, &error) : nullptr;
  if (!root)
  {
    vtkErrorMacro("ReadFromXMLString: " << error);
    return false;
  }
  return this->ReadFromXMLElement(root);
}

//------------------------------------------------------------------------------
bool vtkROS2Scene::ReadFromXMLElement(vtkXMLDataElement* root)
{
  if (!root || !root->GetName() || std::string(root->GetName()) != SceneTag)
  {
    vtkErrorMacro("ReadFromXML: root element is <"
      << (root && root->GetName() ? root->GetName() : "") << ">, expected <" << SceneTag << ">");
    return false;
  }
  int version = 0;
  if (!root->GetScalarAttribute("version", version) || version != SceneFormatVersion)
  {
    vtkErrorMacro(
      "ReadFromXML: unsupported scene format version (expected " << SceneFormatVersion << ")");
    return false;
  }
  // Atomic (issue 11.6): every node is created and read first; the current scene is replaced
  // only when all of them are valid, and is left exactly as it was otherwise.
  std::vector<std::pair<vtkSmartPointer<vtkROS2SceneNode>, std::string>> incoming;
  std::map<std::string, int> seen;
  for (int i = 0; i < root->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = root->GetNestedElement(i);
    const char* className = element->GetName();
    const char* id = element->GetAttribute("id");
    if (!id || !*id)
    {
      vtkErrorMacro("ReadFromXML: element " << i << " <" << (className ? className : "")
                                            << "> has no id; the scene was not changed");
      return false;
    }
    if (!seen.emplace(id, i).second)
    {
      vtkErrorMacro("ReadFromXML: elements " << seen[id] << " and " << i << " share the id '" << id
                                             << "'; the scene was not changed");
      return false;
    }
    vtkSmartPointer<vtkROS2SceneNode> node;
    node.TakeReference(this->CreateNodeByClass(className));
    if (!node)
    {
      vtkErrorMacro("ReadFromXML: cannot create node '" << id << "'; the scene was not changed");
      return false;
    }
    if (!node->ReadXML(element))
    {
      vtkErrorMacro(
        "ReadFromXML: invalid properties for node '" << id << "'; the scene was not changed");
      return false;
    }
    incoming.emplace_back(node, id);
  }
  this->Clear();
  const char* fixedFrame = root->GetAttribute("fixedFrame");
  this->SetFixedFrame(fixedFrame ? fixedFrame : "");
  std::vector<vtkROS2SceneNode*> restored;
  for (const auto& [node, id] : incoming)
  {
    if (!this->AddNodeWithID(node, id)) // cannot fail: ids were checked above
    {
      return false;
    }
    restored.push_back(node);
  }
  for (vtkROS2SceneNode* node : restored)
  {
    if (node->GetScene() == this)
    {
      node->OnSceneRestored();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2Scene::SetFixedFrame(const char* frame)
{
  const std::string value = frame ? frame : "";
  if (value == this->Internals->FixedFrame)
  {
    return;
  }
  this->Internals->FixedFrame = value;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkROS2Scene::GetFixedFrame() const
{
  return this->Internals->FixedFrame.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2Scene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FixedFrame: " << this->Internals->FixedFrame << "\n";
  os << indent << "NumberOfNodes: " << this->Internals->Nodes.size() << "\n";
  for (const auto& node : this->Internals->Nodes)
  {
    os << indent.GetNextIndent() << node->GetID() << " (" << node->GetClassName() << ") '"
       << node->GetName() << "'\n";
  }
}
