// ros2vtk — the module logic: owns a scene, the default ROS node and the spin loop
// (SlicerROS2's vtkSlicerROS2Logic, without Slicer).
//
//   logic = vtkROS2Logic::New();
//   node = logic->GetDefaultROS2Node();          // ROS node "slicer", created on first use
//   sub = node->CreateAndAddSubscriberNode("String", "/chatter");
//   logic->SpinFor(10.0);                        // plain program: spin at SpinRate for 10 s
//   logic->AttachToInteractor(interactor);       // VTK app: a repeating interactor timer
//   logic->SpinOnWakeUp(1.0);                    // event-driven: wait for data, then spin
//
// Every spin runs on the calling thread; observers of subscriber nodes fire there.
#ifndef vtkROS2Logic_h
#define vtkROS2Logic_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkObject.h"

#include <memory> // for std::unique_ptr (pimpl)

class vtkROS2NodeNode;
class vtkROS2Scene;
class vtkRenderWindowInteractor;
class vtkROS2RobotNode;

class ROS2VTKSCENE_EXPORT vtkROS2Logic : public vtkObject
{
public:
  static vtkROS2Logic* New();
  vtkTypeMacro(vtkROS2Logic, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The scene this logic owns (never null).
  vtkROS2Scene* GetScene();

  /// The ROS node named "slicer" (namespace "/") of the scene, added and created on first use.
  /// nullptr (vtkErrorMacro) when DDS cannot create it.
  vtkROS2NodeNode* GetDefaultROS2Node();

  ///@{
  /// SlicerROS2's logic shortcuts: a robot on the default ROS node, described by the parameter
  /// `parameterName` of `parameterNodeName` (CreateAndAddRobotNode), and its removal. The
  /// robot node, or nullptr / false with vtkErrorMacro as the ROS node's methods.
  vtkROS2RobotNode* AddRobot(const char* robotName, const char* parameterNodeName,
    const char* parameterName = "robot_description", const char* fixedFrame = "",
    const char* tfPrefix = "");
  bool RemoveRobot(const char* robotName);
  ///@}

  /// Spins every vtkROS2NodeNode of the scene once; returns the number of messages handled.
  int Spin();

  /// Timer mode: spins per second for SpinFor and AttachToInteractor (default 50, as SlicerROS2).
  /// Must be > 0; changing it re-arms an attached interactor timer.
  void SetSpinRate(double hz);
  double GetSpinRate() const { return this->SpinRate; }
  /// Spins at SpinRate for `seconds` (plain programs); returns the messages handled.
  int SpinFor(double seconds);
  /// Spins from a repeating timer of `interactor` at SpinRate, on the interactor's thread.
  /// Replaces a previous attachment. False for a null interactor.
  bool AttachToInteractor(vtkRenderWindowInteractor* interactor);
  void DetachFromInteractor();

  /// Event-driven mode: waits up to `timeoutSeconds` (< 0: forever) until any ROS node of the
  /// scene has queued data, then spins (also after a timeout, for periodic work such as
  /// parameter requests). Returns what the spin handled.
  int SpinOnWakeUp(double timeoutSeconds);
  /// One descriptor for a host loop (Qt QSocketNotifier, poll, …): readable while any ROS node
  /// of the scene has queued data; the host then calls Spin(). Nodes created later are included
  /// from the next call to Spin / SpinOnWakeUp / GetWakeUpFileDescriptor. -1 on failure.
  int GetWakeUpFileDescriptor();

  /// Spin timing, for status lines: duration of the last spin and mean over all spins (ms).
  double GetLastSpinDuration() const { return this->LastSpinDuration; }
  double GetMeanSpinDuration() const;
  vtkTypeInt64 GetNumberOfSpins() const { return this->NumberOfSpins; }

protected:
  vtkROS2Logic();
  ~vtkROS2Logic() override;

  double SpinRate = 50.0;
  double LastSpinDuration = 0.0;
  double TotalSpinDuration = 0.0;
  vtkTypeInt64 NumberOfSpins = 0;

private:
  vtkROS2Logic(const vtkROS2Logic&) = delete;
  void operator=(const vtkROS2Logic&) = delete;

  /// Watches every created ROS node's wake-up descriptor (no-op until event-driven mode).
  void SyncWakeUpSet();
  /// Event-driven mode from now on: creates the epoll set, then syncs it. False on failure.
  bool StartWakeUpSet();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
