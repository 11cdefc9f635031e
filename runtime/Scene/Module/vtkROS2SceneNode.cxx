#include "vtkROS2SceneNode.h"

#include "vtkROS2Scene.h"

#include "vtkXMLDataElement.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

//------------------------------------------------------------------------------
class vtkROS2SceneNode::vtkInternals
{
public:
  std::string ID;
  std::string Name;
  std::map<std::string, std::string> Attributes;
  std::map<std::string, std::vector<std::string>, std::less<>> References; // role -> IDs, in order
  std::string Scratch; // storage for the space-separated lists returned as const char*
  // The last first reference resolved (GetNodeReference runs at every spin for every child):
  // valid while the role pointer, this node's references, its scene and the scene's nodes are
  // unchanged.
  struct ResolvedReference
  {
    const char* Role = nullptr;
    unsigned long ReferencesVersion = 0;
    const vtkROS2Scene* Scene = nullptr;
    unsigned long NodesVersion = 0;
    vtkROS2SceneNode* Node = nullptr;
  };
  mutable ResolvedReference Resolved;
};

namespace {
std::string JoinKeys(const std::map<std::string, std::string>& values)
{
  std::string joined;
  for (const auto& entry : values)
  {
    joined += (joined.empty() ? "" : " ") + entry.first;
  }
  return joined;
}
} // namespace

const char* const vtkROS2SceneNode::ROS2NodeReferenceRole = "ros2Node";
const char* const vtkROS2SceneNode::LegacyROS2NodeReferenceRole = "ROS2Node";

//------------------------------------------------------------------------------
vtkROS2SceneNode::vtkROS2SceneNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2SceneNode::~vtkROS2SceneNode() = default;

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetID() const
{
  return this->Internals->ID.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::SetName(const char* name)
{
  const std::string value = name ? name : "";
  if (value == this->Internals->Name)
  {
    return;
  }
  this->Internals->Name = value;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetName() const
{
  return this->Internals->Name.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::SetAttribute(const char* name, const char* value)
{
  if (!name || !*name)
  {
    vtkErrorMacro("SetAttribute: an attribute needs a non-empty name");
    return;
  }
  if (!value)
  {
    this->RemoveAttribute(name);
    return;
  }
  auto it = this->Internals->Attributes.find(name);
  if (it != this->Internals->Attributes.end() && it->second == value)
  {
    return;
  }
  this->Internals->Attributes[name] = value;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetAttribute(const char* name) const
{
  if (!name)
  {
    return nullptr;
  }
  auto it = this->Internals->Attributes.find(name);
  return it == this->Internals->Attributes.end() ? nullptr : it->second.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::RemoveAttribute(const char* name)
{
  if (name && this->Internals->Attributes.erase(name) > 0)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetAttributeNames()
{
  this->Internals->Scratch = JoinKeys(this->Internals->Attributes);
  return this->Internals->Scratch.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::SetNodeReferenceID(const char* role, const char* referencedNodeID)
{
  if (!role || !*role)
  {
    vtkErrorMacro("SetNodeReferenceID: a reference needs a non-empty role");
    return;
  }
  std::vector<std::string> wanted;
  if (referencedNodeID && *referencedNodeID)
  {
    wanted.emplace_back(referencedNodeID);
  }
  auto it = this->Internals->References.find(role);
  const bool had = it != this->Internals->References.end();
  if ((had && it->second == wanted) || (!had && wanted.empty()))
  {
    return;
  }
  if (wanted.empty())
  {
    this->Internals->References.erase(it);
  }
  else
  {
    this->Internals->References[role] = wanted;
    this->NoteReferenceInScene(wanted.front());
  }
  ++this->ReferencesVersion;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::AddNodeReferenceID(const char* role, const char* referencedNodeID)
{
  if (!role || !*role || !referencedNodeID || !*referencedNodeID)
  {
    vtkErrorMacro("AddNodeReferenceID: role and referenced node ID must be non-empty");
    return;
  }
  this->Internals->References[role].emplace_back(referencedNodeID);
  this->NoteReferenceInScene(referencedNodeID);
  ++this->ReferencesVersion;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::RemoveNodeReferenceID(const char* role, const char* referencedNodeID)
{
  if (!role || !referencedNodeID)
  {
    return;
  }
  auto it = this->Internals->References.find(role);
  if (it == this->Internals->References.end())
  {
    return;
  }
  auto& ids = it->second;
  auto found = std::find(ids.begin(), ids.end(), referencedNodeID);
  if (found == ids.end())
  {
    return;
  }
  ids.erase(found);
  if (ids.empty())
  {
    this->Internals->References.erase(it);
  }
  ++this->ReferencesVersion;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::RemoveNodeReferenceIDs(const char* role)
{
  if (role && this->Internals->References.erase(role) > 0)
  {
    ++this->ReferencesVersion;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkROS2SceneNode::GetNumberOfNodeReferences(const char* role) const
{
  if (!role)
  {
    return 0;
  }
  auto it = this->Internals->References.find(role);
  return it == this->Internals->References.end() ? 0 : static_cast<int>(it->second.size());
}

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetNthNodeReferenceID(const char* role, int n) const
{
  if (!role || n < 0)
  {
    return nullptr;
  }
  auto it = this->Internals->References.find(role);
  if (it == this->Internals->References.end() || n >= static_cast<int>(it->second.size()))
  {
    return nullptr;
  }
  return it->second[static_cast<size_t>(n)].c_str();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2SceneNode::GetNthNodeReference(const char* role, int n) const
{
  if (!this->Scene)
  {
    return nullptr;
  }
  auto& cached = this->Internals->Resolved;
  const unsigned long nodesVersion = this->Scene->GetNodesVersion();
  if (n == 0 && role && cached.Role == role &&
    cached.ReferencesVersion == this->ReferencesVersion && cached.Scene == this->Scene &&
    cached.NodesVersion == nodesVersion)
  {
    return cached.Node;
  }
  const char* id = this->GetNthNodeReferenceID(role, n);
  vtkROS2SceneNode* node = id ? this->Scene->GetNodeByID(id) : nullptr;
  if (n == 0 && role)
  {
    cached = { role, this->ReferencesVersion, this->Scene, nodesVersion, node };
  }
  return node;
}

//------------------------------------------------------------------------------
const char* vtkROS2SceneNode::GetNodeReferenceRoles()
{
  std::string roles;
  for (const auto& entry : this->Internals->References)
  {
    roles += (roles.empty() ? "" : " ") + entry.first;
  }
  this->Internals->Scratch = roles;
  return this->Internals->Scratch.c_str();
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::GetNodeReferenceRoleList(std::vector<std::string>& roles) const
{
  roles.clear();
  for (const auto& entry : this->Internals->References)
  {
    roles.push_back(entry.first);
  }
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::SetSceneAndID(
  vtkROS2Scene* scene, const char* id, const std::string& leftBecause)
{
  if (!scene && this->Scene)
  {
    this->LeftSceneBecause = leftBecause;
    this->OnRemovedFromScene();
  }
  else if (scene)
  {
    this->LeftSceneBecause.clear();
  }
  this->Scene = scene;
  this->Internals->ID = id ? id : "";
  for (const auto& role : this->Internals->References)
  {
    for (const std::string& referenced : role.second)
    {
      this->NoteReferenceInScene(referenced);
    }
  }
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::NoteReferenceInScene(const std::string& referencedNodeID)
{
  if (this->Scene)
  {
    this->Scene->NoteReferrer(referencedNodeID, this);
  }
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::ForgetReferencesTo(const char* referencedNodeID)
{
  if (!referencedNodeID)
  {
    return;
  }
  bool changed = false;
  for (auto it = this->Internals->References.begin(); it != this->Internals->References.end();)
  {
    auto& ids = it->second;
    const size_t before = ids.size();
    ids.erase(std::remove(ids.begin(), ids.end(), referencedNodeID), ids.end());
    changed = changed || ids.size() != before;
    it = ids.empty() ? this->Internals->References.erase(it) : std::next(it);
  }
  if (changed)
  {
    ++this->ReferencesVersion;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::WriteXML(vtkXMLDataElement* element)
{
  if (!element)
  {
    return;
  }
  element->SetAttribute("id", this->Internals->ID.c_str());
  element->SetAttribute("name", this->Internals->Name.c_str());
  for (const auto& attribute : this->Internals->Attributes)
  {
    vtkXMLDataElement* child = vtkXMLDataElement::New();
    child->SetName("Attribute");
    child->SetAttribute("name", attribute.first.c_str());
    child->SetAttribute("value", attribute.second.c_str());
    element->AddNestedElement(child);
    child->Delete();
  }
  for (const auto& reference : this->Internals->References)
  {
    for (const auto& id : reference.second)
    {
      const vtkROS2SceneNode* referenced =
        this->Scene ? this->Scene->GetNodeByID(id.c_str()) : nullptr;
      if (referenced && !referenced->GetSaveWithScene())
      {
        continue; // not in the file: the reference would dangle when restored
      }
      vtkXMLDataElement* child = vtkXMLDataElement::New();
      child->SetName("Reference");
      child->SetAttribute("role", reference.first.c_str());
      child->SetAttribute("id", id.c_str());
      element->AddNestedElement(child);
      child->Delete();
    }
  }
}

//------------------------------------------------------------------------------
bool vtkROS2SceneNode::ReadXML(vtkXMLDataElement* element)
{
  if (!element)
  {
    vtkErrorMacro("ReadXML: no element");
    return false;
  }
  const char* name = element->GetAttribute("name");
  this->Internals->Name = name ? name : "";
  this->Internals->Attributes.clear();
  this->Internals->References.clear();
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* child = element->GetNestedElement(i);
    const std::string tag = child->GetName() ? child->GetName() : "";
    if (tag == "Attribute")
    {
      const char* key = child->GetAttribute("name");
      const char* value = child->GetAttribute("value");
      if (!key || !*key || !value)
      {
        vtkErrorMacro(
          "ReadXML: <Attribute> of node '" << this->Internals->ID << "' needs 'name' and 'value'");
        return false;
      }
      this->Internals->Attributes[key] = value;
    }
    else if (tag == "Reference")
    {
      const char* role = child->GetAttribute("role");
      const char* id = child->GetAttribute("id");
      if (!role || !*role || !id || !*id)
      {
        vtkErrorMacro(
          "ReadXML: <Reference> of node '" << this->Internals->ID << "' needs 'role' and 'id'");
        return false;
      }
      // One role, two spellings in files of earlier versions.
      const bool legacy = std::string(role) == LegacyROS2NodeReferenceRole;
      this->Internals->References[legacy ? ROS2NodeReferenceRole : role].emplace_back(id);
      this->NoteReferenceInScene(id);
    }
  }
  ++this->ReferencesVersion;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
int vtkROS2SceneNode::OnROS2NodeSpin(vtkROS2NodeNode*)
{
  return 0;
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::OnROS2NodeDestroyed(vtkROS2NodeNode*) {}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::ROS2NodeChildKeyChanged()
{
  if (vtkROS2SceneNode* owner = this->GetNodeReference(ROS2NodeReferenceRole))
  {
    ++owner->ReferencesVersion;
  }
}

//------------------------------------------------------------------------------
void vtkROS2SceneNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ID: " << this->Internals->ID << "\n";
  os << indent << "Name: " << this->Internals->Name << "\n";
  for (const auto& attribute : this->Internals->Attributes)
  {
    os << indent << "Attribute " << attribute.first << ": " << attribute.second << "\n";
  }
  for (const auto& reference : this->Internals->References)
  {
    os << indent << "References " << reference.first << ":";
    for (const auto& id : reference.second)
    {
      os << " " << id;
    }
    os << "\n";
  }
}

//------------------------------------------------------------------------------
bool vtkROS2SceneNode::CopyContentFrom(vtkObject* data, std::string* error)
{
  if (error)
  {
    *error = std::string(this->GetClassName()) + " cannot take the content of a " +
      (data ? data->GetClassName() : "null object") +
      " (a model node takes vtkPolyData, a transform node vtkMatrix4x4)";
  }
  return false;
}
