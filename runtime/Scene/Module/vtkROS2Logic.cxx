#include "vtkROS2Logic.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2OutputWindow.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/wire/Participant.hpp"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkWeakPointer.h"

#include <sys/epoll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>
#include <utility>
#include <vector>

namespace {
const char* const DefaultNodeName = "slicer"; // as SlicerROS2
using Clock = std::chrono::steady_clock;
} // namespace

//------------------------------------------------------------------------------
class vtkROS2Logic::vtkInternals
{
public:
  vtkNew<vtkROS2Scene> Scene;
  int EpollFd = -1;
  std::vector<int> Watched; // descriptors registered in EpollFd
  std::vector<std::pair<int, std::vector<uint8_t>>>
    WatchedKeys; // (fd, participant GUID) of Watched

  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkCallbackCommand> TimerCallback;
  unsigned long TimerObserverTag = 0;
  int TimerId = -1;

  ~vtkInternals()
  {
    if (this->EpollFd >= 0)
    {
      ::close(this->EpollFd);
    }
  }

  // The scene's ROS nodes, found again only when nodes were added or removed: a spin must not
  // walk every link and model node of every robot to find the one or two ROS nodes.
  std::vector<vtkWeakPointer<vtkROS2NodeNode>> RosNodes;
  bool RosNodesStale = true;
  vtkNew<vtkCallbackCommand> SceneCallback;

  // The created ones among them, refilled in place: a spin allocates nothing to find them.
  std::vector<vtkROS2NodeNode*> Created;
  // Each ROS node of WatchedKeys with its modification time when the keys were last built:
  // Create and Destroy modify the node, so while none changed, the wake-up set is current and
  // a spin skips building the keys (an allocation per node, and the participant's GUID).
  std::vector<std::pair<vtkROS2NodeNode*, vtkMTimeType>> WatchedNodeTimes;

  const std::vector<vtkROS2NodeNode*>& CreatedNodes()
  {
    if (this->RosNodesStale)
    {
      this->RosNodes.clear();
      for (int i = 0; i < this->Scene->GetNumberOfNodes(); ++i)
      {
        if (auto* node = vtkROS2NodeNode::SafeDownCast(this->Scene->GetNthNode(i)))
        {
          this->RosNodes.emplace_back(node);
        }
      }
      this->RosNodesStale = false;
      this->WatchedNodeTimes.clear(); // nodes added or removed: check the keys again
    }
    this->Created.clear();
    for (vtkROS2NodeNode* node : this->RosNodes)
    {
      if (node && node->IsCreated())
      {
        this->Created.push_back(node);
      }
    }
    return this->Created;
  }

  bool WakeUpSetCurrent() const
  {
    if (this->WatchedNodeTimes.size() != this->Created.size())
    {
      return false;
    }
    for (size_t i = 0; i < this->Created.size(); ++i)
    {
      if (this->WatchedNodeTimes[i].first != this->Created[i] ||
        this->WatchedNodeTimes[i].second != this->Created[i]->GetMTime())
      {
        return false;
      }
    }
    return true;
  }
};

vtkStandardNewMacro(vtkROS2Logic);

//------------------------------------------------------------------------------
vtkROS2Logic::vtkROS2Logic()
  : Internals(new vtkInternals)
{
  // Warnings and errors of the scene's nodes go to /rosout too (and still to the console).
  vtkROS2OutputWindow::Install();
  this->Internals->SceneCallback->SetClientData(this->Internals.get());
  this->Internals->SceneCallback->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void*) {
      static_cast<vtkInternals*>(clientData)->RosNodesStale = true;
    });
  this->Internals->Scene->AddObserver(vtkROS2Scene::NodeAddedEvent, this->Internals->SceneCallback);
  this->Internals->Scene->AddObserver(
    vtkROS2Scene::NodeRemovedEvent, this->Internals->SceneCallback);
  this->Internals->TimerCallback->SetClientData(this);
  this->Internals->TimerCallback->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData) {
      auto* self = static_cast<vtkROS2Logic*>(clientData);
      const int timerId = callData ? *static_cast<int*>(callData) : -1;
      if (timerId == self->Internals->TimerId)
      {
        self->Spin();
      }
    });
}

//------------------------------------------------------------------------------
vtkROS2Logic::~vtkROS2Logic()
{
  this->DetachFromInteractor();
  // Endpoints and participants go while the logic is intact. A script that kept a node but not
  // its logic (`node = ros2vtk.vtkROS2Logic().GetDefaultROS2Node()`) hears why from the node.
  this->Internals->Scene->ClearBecause(
    "the vtkROS2Logic that owned its scene was deleted (in Python: keep a reference to the logic, "
    "logic = ros2vtk.vtkROS2Logic(), for as long as its nodes are used)");
}

//------------------------------------------------------------------------------
vtkROS2Scene* vtkROS2Logic::GetScene()
{
  return this->Internals->Scene;
}

//------------------------------------------------------------------------------
vtkROS2RobotNode* vtkROS2Logic::AddRobot(const char* robotName, const char* parameterNodeName,
  const char* parameterName, const char* fixedFrame, const char* tfPrefix)
{
  vtkROS2NodeNode* node = this->GetDefaultROS2Node();
  return node
    ? node->CreateAndAddRobotNode(robotName, parameterNodeName, parameterName, fixedFrame, tfPrefix)
    : nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2Logic::RemoveRobot(const char* robotName)
{
  vtkROS2NodeNode* node = this->GetDefaultROS2Node();
  return node && node->RemoveAndDeleteRobotNode(robotName);
}

//------------------------------------------------------------------------------
vtkROS2NodeNode* vtkROS2Logic::GetDefaultROS2Node()
{
  vtkROS2Scene* scene = this->Internals->Scene;
  for (int i = 0; i < scene->GetNumberOfNodes(); ++i)
  {
    auto* node = vtkROS2NodeNode::SafeDownCast(scene->GetNthNode(i));
    if (node && node->IsCreated() && std::string(node->GetROS2NodeName()) == DefaultNodeName &&
      std::string(node->GetROS2NodeNamespace()) == "/")
    {
      return node;
    }
  }
  vtkNew<vtkROS2NodeNode> node;
  scene->AddNode(node);
  if (!node->Create(DefaultNodeName))
  {
    scene->RemoveNode(node);
    vtkErrorMacro("GetDefaultROS2Node: cannot create the ROS node '" << DefaultNodeName << "'");
    return nullptr;
  }
  this->SyncWakeUpSet();
  return node;
}

//------------------------------------------------------------------------------
int vtkROS2Logic::Spin()
{
  const auto start = Clock::now();
  int handled = 0;
  // By index: a node's callback may spin again, which refills the list.
  const std::vector<vtkROS2NodeNode*>& nodes = this->Internals->CreatedNodes();
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    handled += nodes[i]->Spin();
  }
  this->LastSpinDuration = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  this->TotalSpinDuration += this->LastSpinDuration;
  ++this->NumberOfSpins;
  this->SyncWakeUpSet();
  return handled;
}

//------------------------------------------------------------------------------
double vtkROS2Logic::GetMeanSpinDuration() const
{
  return this->NumberOfSpins > 0
    ? this->TotalSpinDuration / static_cast<double>(this->NumberOfSpins)
    : 0.0;
}

//------------------------------------------------------------------------------
void vtkROS2Logic::SetSpinRate(double hz)
{
  if (!(hz > 0.0) || !std::isfinite(hz))
  {
    vtkErrorMacro(
      "SetSpinRate: the rate must be a positive number of spins per second, got " << hz);
    return;
  }
  if (hz == this->SpinRate)
  {
    return;
  }
  this->SpinRate = hz;
  this->Modified();
  if (vtkRenderWindowInteractor* interactor = this->Internals->Interactor)
  {
    this->AttachToInteractor(interactor); // re-arm with the new period
  }
}

//------------------------------------------------------------------------------
int vtkROS2Logic::SpinFor(double seconds)
{
  const auto period = std::chrono::duration_cast<Clock::duration>(
    std::chrono::duration<double>(1.0 / this->SpinRate));
  const auto start = Clock::now();
  const auto end = start +
    std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::max(0.0, seconds)));
  int handled = 0;
  auto next = start;
  do
  {
    handled += this->Spin();
    next += period;
    if (next > end)
    {
      break;
    }
    std::this_thread::sleep_until(next);
  } while (Clock::now() < end);
  return handled;
}

//------------------------------------------------------------------------------
bool vtkROS2Logic::AttachToInteractor(vtkRenderWindowInteractor* interactor)
{
  if (!interactor)
  {
    vtkErrorMacro("AttachToInteractor: interactor is null");
    return false;
  }
  this->DetachFromInteractor();
  const auto periodMs =
    static_cast<unsigned long>(std::max(1.0, std::round(1000.0 / this->SpinRate)));
  this->Internals->Interactor = interactor;
  this->Internals->TimerObserverTag =
    interactor->AddObserver(vtkCommand::TimerEvent, this->Internals->TimerCallback);
  this->Internals->TimerId = interactor->CreateRepeatingTimer(periodMs);
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2Logic::DetachFromInteractor()
{
  vtkRenderWindowInteractor* interactor = this->Internals->Interactor;
  if (interactor)
  {
    interactor->RemoveObserver(this->Internals->TimerObserverTag);
    if (this->Internals->TimerId >= 0)
    {
      interactor->DestroyTimer(this->Internals->TimerId);
    }
  }
  this->Internals->Interactor = nullptr;
  this->Internals->TimerObserverTag = 0;
  this->Internals->TimerId = -1;
}

//------------------------------------------------------------------------------
void vtkROS2Logic::SyncWakeUpSet()
{
  vtkInternals& internals = *this->Internals;
  if (internals.EpollFd < 0)
  {
    // Not event-driven (yet): a timer-driven spinner never asks for a descriptor, and its nodes'
    // wake-ups stay unarmed (no eventfd write per message, no read per spin).
    return;
  }
  // Each watched descriptor with the GUID of the participant that owns it: a destroyed
  // participant's descriptor number can be reused by a new one, which comparing numbers alone
  // would miss. Registrations change only when this list does (epoll_ctl is a syscall).
  internals.CreatedNodes();
  if (internals.WakeUpSetCurrent())
  {
    return; // the usual spin
  }
  internals.WatchedNodeTimes.clear();
  std::vector<std::pair<int, std::vector<uint8_t>>> current;
  for (vtkROS2NodeNode* node : internals.Created)
  {
    internals.WatchedNodeTimes.emplace_back(node, node->GetMTime());
    const int fd = node->GetWakeUpFileDescriptor();
    if (fd >= 0)
    {
      current.emplace_back(fd, node->GetParticipant()->gid());
    }
  }
  if (current == internals.WatchedKeys)
  {
    return;
  }
  for (int fd : internals.Watched)
  {
    ::epoll_ctl(internals.EpollFd, EPOLL_CTL_DEL, fd, nullptr); // may already be gone: ignored
  }
  internals.Watched.clear();
  for (const auto& key : current)
  {
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.fd = key.first;
    if (::epoll_ctl(internals.EpollFd, EPOLL_CTL_ADD, key.first, &event) == 0)
    {
      internals.Watched.push_back(key.first);
    }
  }
  internals.WatchedKeys = std::move(current);
}

//------------------------------------------------------------------------------
bool vtkROS2Logic::StartWakeUpSet()
{
  vtkInternals& internals = *this->Internals;
  if (internals.EpollFd < 0)
  {
    internals.EpollFd = ::epoll_create1(EPOLL_CLOEXEC);
    if (internals.EpollFd < 0)
    {
      vtkErrorMacro("cannot create the wake-up descriptor: " << std::strerror(errno));
      return false;
    }
  }
  this->SyncWakeUpSet();
  return true;
}

//------------------------------------------------------------------------------
int vtkROS2Logic::GetWakeUpFileDescriptor()
{
  this->StartWakeUpSet();
  return this->Internals->EpollFd;
}

//------------------------------------------------------------------------------
int vtkROS2Logic::SpinOnWakeUp(double timeoutSeconds)
{
  if (!this->StartWakeUpSet())
  {
    return 0;
  }
  const int timeoutMs =
    timeoutSeconds < 0 ? -1 : static_cast<int>(std::ceil(timeoutSeconds * 1000.0));
  epoll_event events[8];
  int ready = -1;
  do
  {
    ready = ::epoll_wait(this->Internals->EpollFd, events, 8, timeoutMs);
  } while (ready < 0 && errno == EINTR);
  // Spin on a timeout too: besides queued data there is periodic work (parameter requests to
  // send or repeat, tf lookups whose frames arrived through another node, robots to update).
  return this->Spin();
}

//------------------------------------------------------------------------------
void vtkROS2Logic::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SpinRate: " << this->SpinRate << "\n";
  os << indent << "NumberOfSpins: " << this->NumberOfSpins << "\n";
  os << indent << "LastSpinDuration (ms): " << this->LastSpinDuration << "\n";
  os << indent << "MeanSpinDuration (ms): " << this->GetMeanSpinDuration() << "\n";
  os << indent << "Scene:\n";
  this->Internals->Scene->PrintSelf(os, indent.GetNextIndent());
}
