// ros2vtk — the display manager (see the header): scene and node observers that note changes,
// and Update() that hands them to the displayable managers.
#include "vtkROS2DisplayManager.h"

#include "vtkROS2DisplayableManager.h"
#include "vtkROS2ImageDisplayableManager.h"
#include "vtkROS2ModelDisplayableManager.h"
#include "vtkROS2PointCloudDisplayableManager.h"
#include "vtkROS2PoseArrayDisplayableManager.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SceneNode.h"
#include "vtkROS2TransformDisplayableManager.h"
#include "vtkROS2TransformNode.h"

#include "vtkActor.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <map>
#include <unordered_set>
#include <vector>

vtkStandardNewMacro(vtkROS2DisplayManager);

namespace {

template<class Manager>
vtkROS2DisplayableManager* MakeManager()
{
  return Manager::New();
}

// The registry of displayable manager kinds; the built-in ones first. Models come before
// transforms only for readability: no node is both.
std::vector<vtkROS2DisplayManager::DisplayableManagerFactory>& Factories()
{
  static std::vector<vtkROS2DisplayManager::DisplayableManagerFactory> factories = {
    &MakeManager<vtkROS2ModelDisplayableManager>,
    &MakeManager<vtkROS2TransformDisplayableManager>,
    &MakeManager<vtkROS2ImageDisplayableManager>,
    &MakeManager<vtkROS2PointCloudDisplayableManager>,
    &MakeManager<vtkROS2PoseArrayDisplayableManager>,
  };
  return factories;
}

}

class vtkROS2DisplayManager::vtkInternals
{
public:
  vtkWeakPointer<vtkROS2Scene> Scene;
  std::vector<unsigned long> SceneObservers;
  vtkWeakPointer<vtkRenderer> Renderer;
  std::vector<vtkSmartPointer<vtkROS2DisplayableManager>> Managers;
  // Observer tags per observed node (every node of the scene).
  std::map<vtkROS2SceneNode*, std::vector<unsigned long>> NodeObservers;
  // Which manager draws a node (absent: none can, yet).
  std::map<vtkROS2SceneNode*, vtkROS2DisplayableManager*> Owner;
  // Nodes added or modified since the last Update, in order, without repeats.
  std::vector<vtkROS2SceneNode*> Pending;
  std::unordered_set<vtkROS2SceneNode*> PendingSet;
  bool PosesChanged = false;
  bool SettingsChanged = false;
  bool Removed = false; // a prop left the renderer since the last Update

  void Queue(vtkROS2SceneNode* node)
  {
    if (this->PendingSet.insert(node).second)
    {
      this->Pending.push_back(node);
    }
  }
  void Unqueue(vtkROS2SceneNode* node)
  {
    if (this->PendingSet.erase(node))
    {
      this->Pending.erase(
        std::remove(this->Pending.begin(), this->Pending.end(), node), this->Pending.end());
    }
  }
};

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::RegisterDisplayableManagerClass(DisplayableManagerFactory factory)
{
  if (factory)
  {
    Factories().push_back(factory);
  }
}

//------------------------------------------------------------------------------
vtkROS2DisplayManager::vtkROS2DisplayManager()
  : Internals(new vtkInternals)
{
  for (DisplayableManagerFactory factory : Factories())
  {
    vtkSmartPointer<vtkROS2DisplayableManager> manager;
    manager.TakeReference(factory());
    if (manager)
    {
      manager->SetDisplayManager(this);
      this->Internals->Managers.push_back(manager);
    }
  }
}

//------------------------------------------------------------------------------
vtkROS2DisplayManager::~vtkROS2DisplayManager()
{
  this->SetScene(nullptr);
  for (auto& manager : this->Internals->Managers)
  {
    manager->RemoveAllNodes();
    manager->SetDisplayManager(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetScene(vtkROS2Scene* scene)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Scene == scene)
  {
    return;
  }
  if (vtkROS2Scene* old = internals.Scene)
  {
    for (unsigned long tag : internals.SceneObservers)
    {
      old->RemoveObserver(tag);
    }
  }
  internals.SceneObservers.clear();
  while (!internals.NodeObservers.empty())
  {
    this->ForgetNode(internals.NodeObservers.begin()->first);
  }
  internals.Scene = scene;
  if (scene)
  {
    internals.SceneObservers.push_back(
      scene->AddObserver(vtkROS2Scene::NodeAddedEvent, this, &vtkROS2DisplayManager::OnSceneEvent));
    internals.SceneObservers.push_back(scene->AddObserver(
      vtkROS2Scene::NodeRemovedEvent, this, &vtkROS2DisplayManager::OnSceneEvent));
    // A scene deleted first removes its observers before it clears its nodes (vtkObject does),
    // so NodeRemovedEvent never comes: let go of every node while they still exist.
    internals.SceneObservers.push_back(
      scene->AddObserver(vtkCommand::DeleteEvent, this, &vtkROS2DisplayManager::OnSceneEvent));
    for (int i = 0; i < scene->GetNumberOfNodes(); ++i)
    {
      this->ObserveNode(scene->GetNthNode(i));
    }
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkROS2Scene* vtkROS2DisplayManager::GetScene() const
{
  return this->Internals->Scene;
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetRenderer(vtkRenderer* renderer)
{
  if (this->Internals->Renderer == renderer)
  {
    return;
  }
  this->Internals->Renderer = renderer;
  for (auto& manager : this->Internals->Managers)
  {
    manager->SetRenderer(renderer);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkRenderer* vtkROS2DisplayManager::GetRenderer() const
{
  return this->Internals->Renderer;
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::ObserveNode(vtkROS2SceneNode* node)
{
  vtkInternals& internals = *this->Internals;
  if (!node || internals.NodeObservers.count(node))
  {
    return;
  }
  std::vector<unsigned long>& tags = internals.NodeObservers[node];
  tags.push_back(
    node->AddObserver(vtkCommand::ModifiedEvent, this, &vtkROS2DisplayManager::OnNodeEvent));
  if (vtkROS2TransformNode::SafeDownCast(node))
  {
    tags.push_back(node->AddObserver(
      vtkROS2TransformNode::TransformModifiedEvent, this, &vtkROS2DisplayManager::OnNodeEvent));
  }
  // Drawn on the next Update: a node is often configured right after it is added.
  internals.Queue(node);
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::ForgetNode(vtkROS2SceneNode* node)
{
  vtkInternals& internals = *this->Internals;
  auto observed = internals.NodeObservers.find(node);
  if (observed != internals.NodeObservers.end())
  {
    for (unsigned long tag : observed->second)
    {
      node->RemoveObserver(tag);
    }
    internals.NodeObservers.erase(observed);
  }
  internals.Unqueue(node);
  auto owner = internals.Owner.find(node);
  if (owner != internals.Owner.end())
  {
    owner->second->RemoveNode(node);
    internals.Owner.erase(owner);
    internals.Removed = true;
    // What hung under a removed transform now sits in the world.
    internals.PosesChanged = true;
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::OnSceneEvent(vtkObject*, unsigned long event, void* callData)
{
  auto* node = static_cast<vtkROS2SceneNode*>(callData);
  if (event == vtkROS2Scene::NodeAddedEvent)
  {
    this->ObserveNode(node);
  }
  else if (event == vtkROS2Scene::NodeRemovedEvent)
  {
    // Now, not on the next Update: the scene is about to release the node.
    this->ForgetNode(node);
  }
  else if (event == vtkCommand::DeleteEvent)
  {
    while (!this->Internals->NodeObservers.empty())
    {
      this->ForgetNode(this->Internals->NodeObservers.begin()->first);
    }
    this->Internals->SceneObservers.clear(); // vtkObject removes them itself
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::OnNodeEvent(vtkObject* caller, unsigned long, void*)
{
  auto* node = static_cast<vtkROS2SceneNode*>(caller);
  this->Internals->Queue(node);
  if (vtkROS2TransformNode::SafeDownCast(node))
  {
    // A transform (or its lookup status) changed: everything under it moves or recolours.
    this->Internals->PosesChanged = true;
  }
}

//------------------------------------------------------------------------------
bool vtkROS2DisplayManager::IsUpdatePending() const
{
  const vtkInternals& internals = *this->Internals;
  return !internals.Pending.empty() || internals.PosesChanged || internals.SettingsChanged ||
    internals.Removed;
}

//------------------------------------------------------------------------------
bool vtkROS2DisplayManager::Update()
{
  vtkInternals& internals = *this->Internals;
  if (!this->IsUpdatePending())
  {
    return false;
  }
  bool changed = internals.Removed;
  internals.Removed = false;
  std::vector<vtkROS2SceneNode*> pending;
  pending.swap(internals.Pending);
  internals.PendingSet.clear();
  for (vtkROS2SceneNode* node : pending)
  {
    auto owner = internals.Owner.find(node);
    if (owner != internals.Owner.end())
    {
      owner->second->UpdateNode(node);
      changed = true;
      continue;
    }
    for (auto& manager : internals.Managers)
    {
      if (manager->CanDisplay(node))
      {
        if (manager->AddNode(node))
        {
          internals.Owner[node] = manager;
          changed = true;
        }
        break;
      }
    }
  }
  if (internals.SettingsChanged)
  {
    for (auto& manager : internals.Managers)
    {
      manager->UpdateAll();
    }
    changed = true;
  }
  else if (internals.PosesChanged)
  {
    for (auto& manager : internals.Managers)
    {
      manager->UpdatePoses();
    }
    changed = true;
  }
  internals.SettingsChanged = false;
  internals.PosesChanged = false;
  return changed;
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SettingsChanged()
{
  this->Internals->SettingsChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetAxesVisible(bool visible)
{
  if (this->AxesVisible != visible)
  {
    this->AxesVisible = visible;
    this->SettingsChanged();
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetAxesLength(double length)
{
  if (length > 0 && this->AxesLength != length)
  {
    this->AxesLength = length;
    this->SettingsChanged();
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetArrowLength(double length)
{
  if (length > 0 && this->ArrowLength != length)
  {
    this->ArrowLength = length;
    this->SettingsChanged();
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetPointSize(double size)
{
  if (size > 0 && this->PointSize != size)
  {
    this->PointSize = size;
    this->SettingsChanged();
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetUntrackedColor(double r, double g, double b)
{
  this->UntrackedColor[0] = r;
  this->UntrackedColor[1] = g;
  this->UntrackedColor[2] = b;
  this->SettingsChanged();
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::SetPlaceholderColor(double r, double g, double b)
{
  this->PlaceholderColor[0] = r;
  this->PlaceholderColor[1] = g;
  this->PlaceholderColor[2] = b;
  this->SettingsChanged();
}

//------------------------------------------------------------------------------
int vtkROS2DisplayManager::GetNumberOfDisplayedNodes() const
{
  return static_cast<int>(this->Internals->Owner.size());
}

//------------------------------------------------------------------------------
vtkROS2DisplayableManager* vtkROS2DisplayManager::GetDisplayableManagerForNode(
  vtkROS2SceneNode* node) const
{
  auto owner = this->Internals->Owner.find(node);
  return owner == this->Internals->Owner.end() ? nullptr : owner->second;
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2DisplayManager::GetPropForNode(vtkROS2SceneNode* node) const
{
  vtkROS2DisplayableManager* manager = this->GetDisplayableManagerForNode(node);
  return manager ? manager->GetPropForNode(node) : nullptr;
}

//------------------------------------------------------------------------------
vtkROS2SceneNode* vtkROS2DisplayManager::GetNodeForProp(vtkProp* prop) const
{
  for (const auto& manager : this->Internals->Managers)
  {
    if (vtkROS2SceneNode* node = manager->GetNodeForProp(prop))
    {
      return node;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
vtkActor* vtkROS2DisplayManager::GetActorForNode(vtkROS2SceneNode* node) const
{
  vtkProp* prop = this->GetPropForNode(node);
  if (auto* assembly = vtkPropAssembly::SafeDownCast(prop))
  {
    // A node drawn by several props (shapes and their labels) has its actor first.
    return assembly->GetParts()->GetNumberOfItems() > 0
      ? vtkActor::SafeDownCast(assembly->GetParts()->GetItemAsObject(0))
      : nullptr;
  }
  return vtkActor::SafeDownCast(prop);
}

//------------------------------------------------------------------------------
int vtkROS2DisplayManager::GetNumberOfDisplayableManagers() const
{
  return static_cast<int>(this->Internals->Managers.size());
}

//------------------------------------------------------------------------------
vtkROS2DisplayableManager* vtkROS2DisplayManager::GetNthDisplayableManager(int n) const
{
  if (n < 0 || n >= this->GetNumberOfDisplayableManagers())
  {
    return nullptr;
  }
  return this->Internals->Managers[n];
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::AddDisplayableManager(vtkROS2DisplayableManager* manager)
{
  if (!manager)
  {
    return;
  }
  manager->SetDisplayManager(this);
  manager->SetRenderer(this->Internals->Renderer);
  this->Internals->Managers.emplace_back(manager);
  // Nodes nobody drew yet get a chance with the new manager.
  for (auto& entry : this->Internals->NodeObservers)
  {
    if (!this->Internals->Owner.count(entry.first))
    {
      this->Internals->Queue(entry.first);
    }
  }
}

//------------------------------------------------------------------------------
void vtkROS2DisplayManager::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDisplayedNodes: " << this->GetNumberOfDisplayedNodes() << "\n";
  os << indent << "AxesVisible: " << this->AxesVisible << "\n";
}
