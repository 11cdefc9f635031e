"""Our action client or server (the VTK-wrapped Python API, Debian's python3 with
<build>/python on PYTHONPATH) in its own process, for test_scene_actions.py. Prints JSON lines:
{"ready": ...} first, then one result object.

    action_runner.py goal test_msgs/action/Fibonacci /fibonacci '{order: 5}' --timeout 10
    action_runner.py goal ... --cancel-after 2      # asynchronous: SendGoal, cancel, WaitForGoal
    action_runner.py goals test_msgs/action/Fibonacci /fibonacci '{order: 5}' '{order: 8}' [--cancel-all-after 2]
    action_runner.py goals ... --stagger 0.3 --cancel-before-first-after 2  # CancelGoalsBefore
                                                     # several goals in flight on one client, by goal id
    action_runner.py serve /fibonacci --step 0.1 --max-order 20 --count 1

The server computes Fibonacci as rclpy's example server does (start from [0, 1], append one
number per step, feedback after each), in this script, through the server node's API.
"""
from __future__ import annotations

import argparse
import json
import sys

import yaml

import ros2vtk

EVENTS = ('GoalResponseEvent', 'FeedbackReceivedEvent', 'ResultReceivedEvent', 'GoalFailedEvent',
          'CancelResponseEvent')


def cmd_goal(args, logic, node) -> int:
    client = node.CreateAndAddActionClientNode(args.type, args.name)
    if client is None:
        print(json.dumps({'ready': False, 'error': 'client not created'}), flush=True)
        return 1
    events = {name: 0 for name in EVENTS}
    statuses = []
    feedbacks = []
    for name in EVENTS:
        client.AddObserver(getattr(ros2vtk.vtkROS2ActionClientNode, name),
                           lambda caller, _e, name=name: events.__setitem__(name, events[name] + 1))
    client.AddObserver(ros2vtk.vtkROS2ActionClientNode.FeedbackReceivedEvent,
                       lambda caller, _e: feedbacks.append(yaml.safe_load(caller.GetLastFeedbackYAML())))
    client.AddObserver('ModifiedEvent', lambda caller, _e: statuses.append(caller.GetStatusAsString())
                       if not statuses or statuses[-1] != caller.GetStatusAsString() else None)
    ready = ros2vtk.spin_until(logic, client.IsServerReady, seconds=args.wait) if args.wait > 0 else False
    print(json.dumps({'ready': bool(ready)}), flush=True)
    cancel_sent = None
    if args.cancel_after:
        client.SetTimeout(args.timeout)
        client.SendGoalYAML(args.yaml)
        ros2vtk.spin_until(logic, lambda: client.GetNumberOfFeedbacks() >= args.cancel_after or client.IsGoalDone(),
                           seconds=args.timeout)
        cancel_sent = bool(client.CancelGoal())
        client.WaitForGoal(args.timeout)
        result_yaml = client.GetResultYAML() if client.GetNumberOfResults() else ''
    else:
        result_yaml = client.SendGoalAndWait(args.yaml, args.timeout)
    print(json.dumps({'status': client.GetStatusAsString(), 'done': bool(client.IsGoalDone()),
                      'result': yaml.safe_load(result_yaml) if result_yaml else None,
                      'result_status': client.GetResultStatus(), 'error': client.GetLastError(),
                      'feedback_count': client.GetNumberOfFeedbacks(),
                      'last_feedback': yaml.safe_load(client.GetLastFeedbackYAML()),
                      'feedbacks': feedbacks, 'events': events, 'statuses': statuses,
                      'cancel_sent': cancel_sent, 'cancel_return_code': client.GetLastCancelReturnCode(),
                      'goal_id': client.GetGoalIdAsString(),
                      'accepted': client.GetNumberOfGoalsAccepted()}), flush=True)
    return 0


def cmd_goals(args, logic, node) -> int:
    """Sends every YAML goal at once on one client, follows each by its goal id (events name it:
    GetLastEventGoalId), optionally CancelAllGoals once every goal had N feedbacks, then waits
    for all (WaitForAllGoals)."""
    client = node.CreateAndAddActionClientNode(args.type, args.name)
    if client is None:
        print(json.dumps({'ready': False, 'error': 'client not created'}), flush=True)
        return 1
    per_goal = {}  # goal id -> {'events': {...}, 'feedbacks': [...]}

    def on_event(caller, _e, name):
        goal = caller.GetLastEventGoalId()
        entry = per_goal.setdefault(goal, {'events': {n: 0 for n in EVENTS}, 'feedbacks': []})
        entry['events'][name] += 1
        if name == 'FeedbackReceivedEvent':
            entry['feedbacks'].append(yaml.safe_load(caller.GetLastFeedbackYAMLById(goal)))
    for name in EVENTS:
        client.AddObserver(getattr(ros2vtk.vtkROS2ActionClientNode, name),
                           lambda caller, e, name=name: on_event(caller, e, name))
    ready = ros2vtk.spin_until(logic, client.IsServerReady, seconds=args.wait)
    print(json.dumps({'ready': bool(ready)}), flush=True)
    client.SetTimeout(args.timeout)
    sent = []
    for goal_yaml in args.yaml:
        client.SendGoalYAML(goal_yaml)
        sent.append(client.GetGoalIdAsString())
        if args.stagger:  # the next goal is sent once this one is accepted, and later by this much
            ros2vtk.spin_until(logic, lambda: client.GetStatusAsString() not in ('waiting for server',
                                                                                  'waiting for acceptance'),
                               seconds=args.timeout)
            ros2vtk.spin_until(logic, lambda: False, seconds=args.stagger)
    cancel_sent = None
    if args.cancel_all_after or args.cancel_before_first_after:
        after = args.cancel_all_after or args.cancel_before_first_after
        ros2vtk.spin_until(logic, lambda: all(client.GetNumberOfFeedbacksById(g) >= after or
                                              client.IsGoalDoneById(g) for g in sent), seconds=args.timeout)
        if args.cancel_all_after:
            cancel_sent = bool(client.CancelAllGoals())
        else:  # every goal accepted at or before the time halfway between the first two stamps
            ns = [client.GetGoalAcceptedSecById(g) * 10**9 + client.GetGoalAcceptedNanosecById(g) for g in sent[:2]]
            cancel_sent = bool(client.CancelGoalsBefore(sum(ns) // 2 // 10**9, sum(ns) // 2 % 10**9))
    all_done = bool(client.WaitForAllGoals(args.timeout))
    goals = []
    for goal in sent:
        result_yaml = client.GetResultYAMLById(goal)
        goals.append({'id': goal, 'status': client.GetStatusAsStringById(goal), 'done': bool(client.IsGoalDoneById(goal)),
                      'result': yaml.safe_load(result_yaml) if client.GetResultStatusById(goal) else None,
                      'result_status': client.GetResultStatusById(goal), 'error': client.GetGoalErrorById(goal),
                      'feedback_count': client.GetNumberOfFeedbacksById(goal),
                      'last_feedback': yaml.safe_load(client.GetLastFeedbackYAMLById(goal)),
                      'accepted_stamp': [client.GetGoalAcceptedSecById(goal), client.GetGoalAcceptedNanosecById(goal)],
                      **per_goal.get(goal, {'events': {}, 'feedbacks': []})})
    print(json.dumps({'goals': goals, 'all_done': all_done, 'cancel_sent': cancel_sent,
                      'cancel_return_code': client.GetLastCancelReturnCode(),
                      'cancel_events': per_goal.get('', {}).get('events', {}).get('CancelResponseEvent', 0),
                      'number_of_goals': client.GetNumberOfGoals(),
                      'nth_ids': [client.GetNthGoalId(i) for i in range(client.GetNumberOfGoals())],
                      'current': {'id': client.GetGoalIdAsString(), 'status': client.GetStatusAsString(),
                                  'result': yaml.safe_load(client.GetResultYAML())},
                      'accepted': client.GetNumberOfGoalsAccepted(), 'results': client.GetNumberOfResults()}),
          flush=True)
    return 0


def cmd_serve(args, logic, node) -> int:
    server = node.CreateAndAddActionServerNode('test_msgs/action/Fibonacci', args.name)
    if server is None:
        print(json.dumps({'ready': False}), flush=True)
        return 1
    if args.result_timeout is not None:
        server.SetResultTimeout(args.result_timeout)
    decided = []

    def on_goal(caller, _event):
        order = int(caller.GetGoalField('order'))
        decided.append(order)
        if order > args.max_order:
            caller.RejectGoal()

    cancels = []
    server.AddObserver(ros2vtk.vtkROS2ActionServerNode.GoalReceivedEvent, on_goal)
    server.AddObserver(ros2vtk.vtkROS2ActionServerNode.CancelRequestedEvent, lambda *_: cancels.append(1))
    print(json.dumps({'ready': True}), flush=True)
    import time
    end = time.monotonic() + args.seconds
    current, sequence, order, due, finished, outcomes = None, [], 0, 0.0, 0, []
    while time.monotonic() < end and (not args.count or finished < args.count):
        logic.SpinOnWakeUp(0.02)
        if not server.HasActiveGoal():
            continue
        if server.GetGoalIdAsString() != current:
            current, sequence, order, due = server.GetGoalIdAsString(), [0, 1], int(server.GetGoalField('order')), 0.0
        if server.IsCancelRequested():
            server.ConfirmGoalCanceled(yaml.safe_dump({'sequence': sequence}))
            finished += 1
            outcomes.append('canceled')
        elif time.monotonic() >= due:
            if len(sequence) <= order:
                sequence = sequence + [sequence[-1] + sequence[-2]]
                server.PublishFeedbackYAML(yaml.safe_dump({'sequence': sequence}))
                due = time.monotonic() + args.step
            else:
                server.SucceedGoal(yaml.safe_dump({'sequence': sequence}))
                finished += 1
                outcomes.append('succeeded')
    ros2vtk.spin_until(logic, lambda: False, seconds=args.linger)  # result requests still on their way
    print(json.dumps({'received': server.GetNumberOfGoalsReceived(), 'accepted': server.GetNumberOfGoalsAccepted(),
                      'rejected': server.GetNumberOfGoalsRejected(), 'cancels': server.GetNumberOfCancelRequests(),
                      'cancel_events': len(cancels), 'results_sent': server.GetNumberOfResultsSent(),
                      'orders': decided, 'outcomes': outcomes,
                      'expired': server.GetNumberOfExpiredGoals(), 'goals_kept': server.GetNumberOfGoals()}), flush=True)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node-name', default='slicer')
    sub = parser.add_subparsers(dest='command', required=True)
    goal = sub.add_parser('goal')
    goal.add_argument('type')
    goal.add_argument('name')
    goal.add_argument('yaml')
    goal.add_argument('--timeout', type=float, default=10.0)
    goal.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the server (0: do not)')
    goal.add_argument('--cancel-after', type=int, default=0, help='cancel after this many feedbacks')
    goals = sub.add_parser('goals')
    goals.add_argument('type')
    goals.add_argument('name')
    goals.add_argument('yaml', nargs='+')
    goals.add_argument('--timeout', type=float, default=10.0)
    goals.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the server')
    goals.add_argument('--cancel-all-after', type=int, default=0,
                       help='CancelAllGoals once every goal had this many feedbacks')
    goals.add_argument('--cancel-before-first-after', type=int, default=0,
                       help='after this many feedbacks of every goal, CancelGoalsBefore(halfway between the '
                            'first two acceptance stamps)')
    goals.add_argument('--stagger', type=float, default=0.0,
                       help='send each goal once the previous one is accepted, this many seconds later')
    serve = sub.add_parser('serve')
    serve.add_argument('name')
    serve.add_argument('--seconds', type=float, default=20.0)
    serve.add_argument('--step', type=float, default=0.05, help='seconds per Fibonacci step')
    serve.add_argument('--max-order', type=int, default=40, help='goals above are rejected')
    serve.add_argument('--count', type=int, default=0, help='stop after this many finished goals')
    serve.add_argument('--linger', type=float, default=0.5, help='seconds served after the last goal')
    serve.add_argument('--result-timeout', type=float, default=None, help="the server's result timeout (s)")
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    return {'goal': cmd_goal, 'goals': cmd_goals, 'serve': cmd_serve}[args.command](args, logic, node)


if __name__ == '__main__':
    sys.exit(main())
