// ros2vtk — a client of one ROS 2 action of any generated .action type (issue 13).
//
//   client = rosNode.CreateAndAddActionClientNode("test_msgs/action/Fibonacci", "/fibonacci")
//   result = client.SendGoalAndWait("{order: 5}", 10.0)   # scripts: spins until the result
//   client.SendGoalYAML("{order: 5}")                      # applications: events on later spins
//   # GoalResponseEvent (accepted or rejected), FeedbackReceivedEvent (GetLastFeedbackYAML),
//   # ResultReceivedEvent (GetResultYAML, GetGoalStatus), GoalFailedEvent (GetLastError)
//   client.CancelGoal()                                    # CancelResponseEvent
//
// On the wire it is what rcl_action makes (docs/actions.md): the services
// `<action>/_action/send_goal`, `get_result` and `cancel_goal`, the feedback topic and the
// transient-local status topic. Goals, results and feedback are YAML through the action's
// generated tables (wire::ActionTypeSupport), so one class serves every generated action type.
// Several goals may be in flight (as with rclpy's ActionClient): each is tracked by its goal id
// (GetNthGoalId, the ...ById accessors); the single-goal API (GetGoalStatus, GetResultYAML,
// CancelGoal...) reads the last goal sent. CancelAllGoals asks the server to cancel every goal.
#ifndef vtkROS2ActionClientNode_h
#define vtkROS2ActionClientNode_h

#include "ros2vtkSceneModule.h" // for export macro
#include "vtkROS2EndpointNode.h"

#include "vtkCommand.h" // for vtkCommand::UserEvent

#include <memory> // for std::unique_ptr (pimpl)
#include <string> // for std::string

class vtkROS2NodeNode;

class ROS2VTKSCENE_EXPORT vtkROS2ActionClientNode : public vtkROS2EndpointNode
{
public:
  static vtkROS2ActionClientNode* New();
  vtkTypeMacro(vtkROS2ActionClientNode, vtkROS2EndpointNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    /// The server answered the goal: GetGoalStatus() is Accepted or Rejected.
    GoalResponseEvent = vtkCommand::UserEvent + 80,
    /// Feedback for the current goal arrived (GetLastFeedbackYAML).
    FeedbackReceivedEvent = vtkCommand::UserEvent + 81,
    /// The result arrived (GetResultYAML; GetGoalStatus is Succeeded, Canceled or Aborted).
    ResultReceivedEvent = vtkCommand::UserEvent + 82,
    /// The goal could not be sent or was not answered in time; GetLastError says why.
    GoalFailedEvent = vtkCommand::UserEvent + 83,
    /// The server answered a CancelGoal (GetLastCancelReturnCode).
    CancelResponseEvent = vtkCommand::UserEvent + 84
  };

  /// Where the current goal stands. Accepted .. Aborted follow action_msgs/msg/GoalStatus as
  /// the server reports it on the status topic and in the result.
  enum GoalState
  {
    Idle = 0,
    WaitingForServer,
    WaitingForAcceptance,
    Rejected,
    Accepted,
    Executing,
    Canceling,
    Succeeded,
    Canceled,
    Aborted,
    TimedOut,
    Failed
  };

  /// "/fibonacci" (resolved) and "test_msgs/action/Fibonacci".
  const char* GetActionName() const { return this->GetEndpointName(); }
  const char* GetActionType() const { return this->GetEndpointType(); }
  /// True when the server's three services are matched and it publishes feedback and status
  /// (rcl_action_server_is_available).
  bool IsServerReady() const;

  ///@{
  /// The goal the next SendGoal sends (the action's X_Goal); blank until set. False with
  /// vtkErrorMacro naming the field on invalid YAML or a value that does not fit.
  bool SetGoalYAML(const char* yaml);
  std::string GetGoalYAML() const;
  bool SetGoalField(const char* path, const char* value);
  void ResetGoal();
  ///@}

  /// Seconds a goal may wait for a server and for its acceptance, and a cancel request for its
  /// answer (default 5). The result itself has no deadline (goals may run for long).
  void SetTimeout(double seconds) { this->SetEndpointTimeout("SetTimeout", seconds); }
  double GetTimeout() const { return this->EndpointTimeout; }

  /// Sends the goal set above with a new random goal id; the answer arrives on a later Spin.
  /// Returns the goal's number in this client (> 0), or -1 when not attached.
  vtkTypeInt64 SendGoal();
  /// SetGoalYAML then SendGoal (-1 on invalid YAML).
  vtkTypeInt64 SendGoalYAML(const char* yaml);
  /// Asks the server to cancel the current goal (action_msgs/srv/CancelGoal with its id). False
  /// when there is no accepted, unfinished goal.
  bool CancelGoal();
  /// The same for goal `goalId` (32 hex digits, GetNthGoalId).
  bool CancelGoalById(const char* goalId);
  /// Asks the server to cancel every goal it has (zero goal id and zero stamp, as rclcpp's
  /// async_cancel_all_goals): the goals of other clients of the action too. False when not
  /// attached.
  bool CancelAllGoals();
  /// Asks the server to cancel every goal it accepted at or before the time `sec`.`nanosec`
  /// on the server's clock (a zero goal id and this stamp, as rclcpp's async_cancel_goals_before):
  /// the goals of other clients of the action too. A goal's acceptance time, as the server
  /// stamped it: GetGoalAcceptedSecById / GetGoalAcceptedNanosecById. False when not attached.
  bool CancelGoalsBefore(int sec, unsigned int nanosec);

  ///@{
  /// Finished goals (rejected, succeeded, canceled, aborted, timed out, failed) are kept, by id,
  /// until forgotten: ForgetGoalById drops one (false when the id is unknown or the goal is not
  /// finished), ForgetFinishedGoals drops every finished goal and returns how many. At most
  /// MaximumFinishedGoals (default 100, 0: none) are kept at all: on each spin the oldest finished
  /// goals beyond it are dropped, after their events were invoked (rclpy's client forgets a goal
  /// as soon as its result arrived). Forgetting the last goal sent leaves the single-goal API idle.
  bool ForgetGoalById(const char* goalId);
  int ForgetFinishedGoals();
  void SetMaximumFinishedGoals(int maximum);
  int GetMaximumFinishedGoals() const;
  ///@}

  /// For scripts: sends `goalYAML` and spins every ROS node of the scene until the result
  /// arrives, the goal is rejected or `timeoutSeconds` (<= 0: GetTimeout()) pass. Returns the
  /// result YAML, or "" with GetLastError saying why (rejected, timeout, no server). A goal
  /// still running at the timeout keeps running and is still tracked.
  std::string SendGoalAndWait(const char* goalYAML, double timeoutSeconds = -1.0);
  /// Spins the scene until the current goal is finished (result, rejection, failure) or
  /// `timeoutSeconds` pass; true when it is finished.
  bool WaitForGoal(double timeoutSeconds);
  /// The same for every goal sent; true when all are finished.
  bool WaitForAllGoals(double timeoutSeconds);
  bool AreAllGoalsDone() const;

  int GetGoalStatus() const;
  /// "idle", "waiting for server", "waiting for acceptance", "rejected", "accepted",
  /// "executing", "canceling", "succeeded", "canceled", "aborted", "timed out", "failed".
  const char* GetStatusAsString() const;
  /// True once the current goal is rejected, finished, timed out or failed.
  bool IsGoalDone() const;
  const char* GetLastError() const;
  /// The current goal's id as 32 hex digits ("" before the first goal).
  std::string GetGoalIdAsString() const;

  ///@{
  /// Feedback of the current goal: how many arrived, and the newest (blank before the first)
  /// as YAML or one field.
  vtkTypeInt64 GetNumberOfFeedbacks() const;
  std::string GetLastFeedbackYAML() const;
  std::string GetFeedbackField(const char* path) const;
  ///@}

  ///@{
  /// The current goal's result (blank before it arrives) as YAML or one field, and the status
  /// the server sent with it (action_msgs/msg/GoalStatus: 4 succeeded, 5 canceled, 6 aborted).
  std::string GetResultYAML() const;
  std::string GetResultField(const char* path) const;
  int GetResultStatus() const;
  ///@}

  /// return_code of the newest cancel response (action_msgs/srv/CancelGoal: 0 none, 1
  /// rejected, 2 unknown goal id, 3 goal terminated); -1 before one.
  int GetLastCancelReturnCode() const;
  ///@{
  /// Every goal sent and not forgotten, in order (ForgetGoalById, MaximumFinishedGoals), and each
  /// one's state by id
  /// ("" or an unknown id: idle, blank YAML, 0). GetLastEventGoalId: inside an observer, the goal
  /// the event is about ("" for CancelResponseEvent).
  int GetNumberOfGoals() const;
  std::string GetNthGoalId(int i) const;
  std::string GetLastEventGoalId() const;
  int GetGoalStatusById(const char* goalId) const;
  const char* GetStatusAsStringById(const char* goalId) const;
  bool IsGoalDoneById(const char* goalId) const;
  std::string GetGoalErrorById(const char* goalId) const;
  vtkTypeInt64 GetNumberOfFeedbacksById(const char* goalId) const;
  std::string GetLastFeedbackYAMLById(const char* goalId) const;
  std::string GetResultYAMLById(const char* goalId) const;
  std::string GetResultFieldById(const char* goalId, const char* path) const;
  int GetResultStatusById(const char* goalId) const;
  /// The time the server stamped on the goal when it accepted it (the SendGoal response's
  /// stamp; 0 before acceptance): CancelGoalsBefore takes it.
  int GetGoalAcceptedSecById(const char* goalId) const;
  unsigned int GetGoalAcceptedNanosecById(const char* goalId) const;
  ///@}

  /// Goals sent, goals accepted, results received.
  vtkTypeInt64 GetNumberOfGoalsSent() const;
  vtkTypeInt64 GetNumberOfGoalsAccepted() const;
  vtkTypeInt64 GetNumberOfResults() const;

#ifndef __VTK_WRAP__
  /// Used by vtkROS2NodeNode: chooses the type ("pkg/action/X" or "pkg/X"), creates the wire
  /// endpoints on `rosNode`. False with vtkErrorMacro otherwise.
  bool Attach(
    vtkROS2NodeNode* rosNode, const std::string& type, const std::string& action) override;
  /// Releases the wire endpoints (the ROS node is being destroyed); the node stays in the scene.
  void Detach() override;
  /// Per Spin: sends a waiting goal once the server is there, takes answers, feedback, status.
  int ProcessAction();
#endif

  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    return this->ProcessAction();
  }

protected:
  vtkROS2ActionClientNode();
  ~vtkROS2ActionClientNode() override;
  bool IsEndpointAttached() const override;

private:
  vtkROS2ActionClientNode(const vtkROS2ActionClientNode&) = delete;
  void operator=(const vtkROS2ActionClientNode&) = delete;

  bool SpinSceneUntil(double timeoutSeconds, bool (*done)(const vtkROS2ActionClientNode*));
  bool SendCancelRequest(const void* request);
  const char* CurrentGoalId() const;
  void DropFinishedGoalsBeyondMaximum();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
