// ros2vtk — a server of one ROS 2 action of any generated .action type (issue 13).
//
//   server = rosNode.CreateAndAddActionServerNode("test_msgs/action/Fibonacci", "/fibonacci")
//   server.AddObserver(server.GoalReceivedEvent, decide)   # may call RejectGoal()
//   # later spins, from the script: the current goal (the oldest one still running)
//   server.GetGoalYAML(); server.PublishFeedbackYAML("{sequence: [0, 1]}")
//   if server.IsCancelRequested(): server.ConfirmGoalCanceled("{sequence: [0, 1]}")
//   else: server.SucceedGoal("{sequence: [0, 1, 1]}")       # or AbortGoal(...)
//
// On the wire it is what rcl_action makes (docs/actions.md): it answers
// `<action>/_action/send_goal`, `get_result` and `cancel_goal` and publishes feedback and the
// transient-local status (the full array of goals it tracks, on every change). Accepted goals go
// straight to executing (as rclpy's server does); cancel requests for running goals are
// accepted (they become canceling; the script decides when the goal ends). Result requests for a
// running goal are answered when it ends. Finished goals are kept (listed in the status, their
// results served) for the result timeout, 900 s of node time by default as rclpy's server, then
// expire as rcl_action_expire_goals makes them.
#ifndef vtkROS2ActionServerNode_h
#define vtkROS2ActionServerNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2EndpointNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2NodeNode;

class ROS2VTKSCENE_EXPORT vtkROS2ActionServerNode : public vtkROS2EndpointNode
{
public:
  static vtkROS2ActionServerNode* New();
  vtkTypeMacro(vtkROS2ActionServerNode, vtkROS2EndpointNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    /// A goal arrived; GetGoalYAML / GetGoalField show it and RejectGoal() refuses it (else it is
    /// accepted when the observer returns).
    GoalReceivedEvent = vtkCommand::UserEvent + 90,
    /// A client asked to cancel a running goal (IsCancelRequested is now true for it).
    CancelRequestedEvent = vtkCommand::UserEvent + 91
  };

  const char* GetActionName() const { return this->GetEndpointName(); }
  const char* GetActionType() const { return this->GetEndpointType(); }

  /// While GoalReceivedEvent runs: refuse the goal being decided. False outside the event.
  bool RejectGoal();

  ///@{
  /// The current goal: inside GoalReceivedEvent the goal being decided, else the oldest goal
  /// still running ("" / false when there is none).
  bool HasActiveGoal() const;
  std::string GetGoalYAML() const;
  std::string GetGoalField(const char* path) const;
  std::string GetGoalIdAsString() const;
  /// A client asked to cancel the current goal.
  bool IsCancelRequested() const;
  /// action_msgs/msg/GoalStatus of the current goal (0 when there is none).
  int GetGoalStatus() const;
  ///@}

  ///@{
  /// For the current goal: publish a feedback message (the action's X_Feedback as YAML), or end
  /// it with a result (X_Result as YAML, "" for the blank one). Succeed and abort need a running
  /// goal, ConfirmGoalCanceled a goal whose cancel was requested (rcl's goal state machine).
  /// False with vtkErrorMacro on invalid YAML or when there is no such goal.
  bool PublishFeedbackYAML(const char* yaml);
  bool SucceedGoal(const char* resultYAML);
  bool AbortGoal(const char* resultYAML);
  bool ConfirmGoalCanceled(const char* resultYAML);
  ///@}

  /// Goals received, accepted and rejected, cancel requests accepted, results sent.
  vtkTypeInt64 GetNumberOfGoalsReceived() const;
  vtkTypeInt64 GetNumberOfGoalsAccepted() const;
  vtkTypeInt64 GetNumberOfGoalsRejected() const;
  vtkTypeInt64 GetNumberOfCancelRequests() const;
  vtkTypeInt64 GetNumberOfResultsSent() const;
  /// Goals tracked (running and finished), and those still running.
  int GetNumberOfGoals() const;
  int GetNumberOfActiveGoals() const;

  ///@{
  /// How long a finished goal stays tracked, in seconds of the node's clock (simulated time
  /// when use_sim_time is on): rcl_action's result_timeout, 900 s by default as rclpy's
  /// ActionServer. A result request for an expired goal is answered STATUS_UNKNOWN, as rcl's.
  /// The setter refuses a negative or non-finite value (vtkErrorMacro); saved with the scene.
  void SetResultTimeout(double seconds);
  double GetResultTimeout() const;
  /// Finished goals dropped after the result timeout so far.
  vtkTypeInt64 GetNumberOfExpiredGoals() const;
  ///@}

  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: chooses the type, creates the wire endpoints on `rosNode`.
  bool Attach(
    vtkROS2NodeNode* rosNode, const std::string& type, const std::string& action) override;
  void Detach() override;
  /// Per Spin: takes goal, result and cancel requests and answers them.
  int ProcessRequests();
#endif

  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    return this->ProcessRequests();
  }

protected:
  vtkROS2ActionServerNode();
  ~vtkROS2ActionServerNode() override;
  bool IsEndpointAttached() const override;

private:
  vtkROS2ActionServerNode(const vtkROS2ActionServerNode&) = delete;
  void operator=(const vtkROS2ActionServerNode&) = delete;

  bool Finish(int status, const char* resultYAML, const char* what);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
