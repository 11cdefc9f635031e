// ros2vtk — base class of the displayable managers (see the header): the node -> prop map and
// the renderer bookkeeping shared by every kind.
#include "vtkROS2DisplayableManager.h"

#include "vtkROS2SceneNode.h"
#include "vtkROS2TransformNode.h"

#include "vtkMatrix4x4.h"
#include "vtkProp.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <map>

class vtkROS2DisplayableManager::vtkInternals
{
public:
  vtkWeakPointer<vtkRenderer> Renderer;
  // Keyed by the node pointer: the display manager removes a node here before the scene lets go.
  std::map<vtkROS2SceneNode*, vtkSmartPointer<vtkProp>> Props;
};

//------------------------------------------------------------------------------
vtkROS2DisplayableManager::vtkROS2DisplayableManager()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2DisplayableManager::~vtkROS2DisplayableManager()
{
  this->RemoveAllNodes();
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::SetRenderer(vtkRenderer* renderer)
{
  vtkRenderer* old = this->Internals->Renderer;
  if (old == renderer)
  {
    return;
  }
  for (auto& entry : this->Internals->Props)
  {
    if (old)
    {
      old->RemoveViewProp(entry.second);
    }
    if (renderer)
    {
      renderer->AddViewProp(entry.second);
    }
  }
  this->Internals->Renderer = renderer;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkRenderer* vtkROS2DisplayableManager::GetRenderer() const
{
  return this->Internals->Renderer;
}

//------------------------------------------------------------------------------
bool vtkROS2DisplayableManager::AddNode(vtkROS2SceneNode* node)
{
  if (!node || this->HasNode(node))
  {
    return false;
  }
  vtkSmartPointer<vtkProp> prop;
  prop.TakeReference(this->CreateProp(node));
  if (!prop)
  {
    return false;
  }
  this->Internals->Props[node] = prop;
  if (vtkRenderer* renderer = this->Internals->Renderer)
  {
    renderer->AddViewProp(prop);
  }
  this->UpdateProp(node, prop);
  this->UpdatePose(node, prop);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::RemoveNode(vtkROS2SceneNode* node)
{
  auto it = this->Internals->Props.find(node);
  if (it == this->Internals->Props.end())
  {
    return;
  }
  if (vtkRenderer* renderer = this->Internals->Renderer)
  {
    renderer->RemoveViewProp(it->second);
  }
  this->Internals->Props.erase(it);
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::RemoveAllNodes()
{
  while (!this->Internals->Props.empty())
  {
    this->RemoveNode(this->Internals->Props.begin()->first);
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::UpdateNode(vtkROS2SceneNode* node)
{
  auto it = this->Internals->Props.find(node);
  if (it != this->Internals->Props.end())
  {
    this->UpdateProp(node, it->second);
    this->UpdatePose(node, it->second);
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::UpdatePoses()
{
  for (auto& entry : this->Internals->Props)
  {
    this->UpdatePose(entry.first, entry.second);
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::UpdateAll()
{
  for (auto& entry : this->Internals->Props)
  {
    this->UpdateProp(entry.first, entry.second);
    this->UpdatePose(entry.first, entry.second);
  }
}

//------------------------------------------------------------------------------
bool vtkROS2DisplayableManager::HasNode(vtkROS2SceneNode* node) const
{
  return this->Internals->Props.count(node) > 0;
}

//------------------------------------------------------------------------------
int vtkROS2DisplayableManager::GetNumberOfNodes() const
{
  return static_cast<int>(this->Internals->Props.size());
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2DisplayableManager::GetPropForNode(vtkROS2SceneNode* node) const
{
  auto it = this->Internals->Props.find(node);
  return it == this->Internals->Props.end() ? nullptr : it->second.GetPointer();
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2DisplayableManager::GetNodeForProp(vtkProp* prop) const
{
  if (!prop)
  {
    return nullptr;
  }
  for (const auto& entry : this->Internals->Props)
  {
    if (entry.second == prop)
    {
      return entry.first;
    }
    if (auto* assembly = vtkPropAssembly::SafeDownCast(entry.second))
    {
      if (assembly->GetParts()->IsItemPresent(prop))
      {
        return entry.first;
      }
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::GetParentTransformToWorld(
  vtkROS2SceneNode* node, vtkMatrix4x4* matrix)
{
  matrix->Identity();
  if (!node)
  {
    return;
  }
  // "transform" is the reference role of models and transforms (vtkROS2ModelNode and
  // vtkROS2TransformNode::SetParentTransformNodeID); any node may use it to be placed.
  if (auto* parent = vtkROS2TransformNode::SafeDownCast(node->GetNodeReference("transform")))
  {
    parent->GetMatrixTransformToWorld(matrix);
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayableManager::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNodes: " << this->GetNumberOfNodes() << "\n";
}
