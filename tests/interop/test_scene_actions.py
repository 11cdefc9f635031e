"""Actions through our VTK-wrapped Python API (vtkROS2ActionClientNode) against an rclpy
ActionServer for test_msgs/action/Fibonacci in its own process (action_peer.py). Expected
values are computed here from the definition of the sequence, not by our code."""
from __future__ import annotations

import json

from conftest import BUILD, HERE, VENV_PYTHON

# action_msgs/msg/GoalStatus
STATUS_UNKNOWN, STATUS_SUCCEEDED, STATUS_CANCELED = 0, 4, 5


def fibonacci_feedbacks(order: int) -> list[list[int]]:
    """The sequences rclpy's Fibonacci server publishes as feedback, one per step: it starts
    from [0, 1] and appends the sum of the last two numbers, order - 1 times."""
    sequence, feedbacks = [0, 1], []
    for _ in range(order - 1):
        sequence = sequence + [sequence[-1] + sequence[-2]]
        feedbacks.append(sequence)
    return feedbacks


def ours(ros, *args: str):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', str(HERE / 'action_runner.py'), *args], env)


def rclpy_server(ros, *args: str):
    server = ros.start([str(VENV_PYTHON), str(HERE / 'action_peer.py'), 'server', *args])
    ros.wait_ready(server)
    return server


def last_json(out: str) -> dict:
    return json.loads(out.strip().splitlines()[-1])


def run_client(ros, *args: str, timeout: float = 60) -> dict:
    client = ours(ros, *args)
    code, out, err = ros.finish(client, timeout=timeout)
    assert code == 0, err
    lines = out.strip().splitlines()
    assert json.loads(lines[0]) == {'ready': True} or '--wait' in args, out + err
    return last_json(out)


def test_our_client_gets_feedback_and_result_from_rclpy_fibonacci(ros):
    server = rclpy_server(ros, '/fibonacci', '--step', '0.05', '--seconds', '30')
    result = run_client(ros, 'goal', 'test_msgs/action/Fibonacci', '/fibonacci', '{order: 5}', '--timeout', '15')
    expected = fibonacci_feedbacks(5)
    assert expected[-1] == [0, 1, 1, 2, 3, 5]
    assert result['status'] == 'succeeded' and result['error'] == '', result
    assert result['result'] == {'sequence': expected[-1]}
    assert result['result_status'] == STATUS_SUCCEEDED
    # Feedback is reliable (KEEP_LAST 10): every step arrives, in order, the last one included.
    assert result['feedback_count'] == len(expected) >= 1
    assert [f['sequence'] for f in result['feedbacks']] == expected
    assert result['last_feedback'] == {'sequence': expected[-1]}
    assert result['events'] == {'GoalResponseEvent': 1, 'FeedbackReceivedEvent': len(expected),
                                'ResultReceivedEvent': 1, 'GoalFailedEvent': 0, 'CancelResponseEvent': 0}
    # (Accepted and executing are passing states: one spin may take them together with the result.)
    assert result['statuses'][-1] == 'succeeded', result['statuses']
    assert len(result['goal_id']) == 32 and result['goal_id'] != '0' * 32
    ros.stop(server)


def test_our_client_cancels_a_running_rclpy_goal(ros):
    # 0.3 s per step: the goal of order 20 would run for ~6 s; we cancel after two feedbacks.
    server = rclpy_server(ros, '/slow_fibonacci', '--step', '0.3', '--seconds', '30')
    result = run_client(ros, 'goal', 'test_msgs/action/Fibonacci', '/slow_fibonacci', '{order: 20}',
                        '--timeout', '15', '--cancel-after', '2')
    assert result['cancel_sent'] is True
    assert result['cancel_return_code'] == 0, result  # action_msgs/srv/CancelGoal ERROR_NONE
    assert result['status'] == 'canceled' and result['result_status'] == STATUS_CANCELED, result
    assert 'canceling' in result['statuses']
    # The server stops at its next step: the partial sequence is a prefix of the full one.
    full = fibonacci_feedbacks(20)[-1]
    partial = result['result']['sequence']
    assert 3 <= len(partial) < len(full) and partial == full[:len(partial)]
    assert result['feedback_count'] >= 2
    assert result['events']['CancelResponseEvent'] == 1 and result['events']['ResultReceivedEvent'] == 1
    ros.stop(server)


def test_rclpy_rejects_our_goal_and_we_say_so(ros):
    server = rclpy_server(ros, '/fibonacci', '--max-order', '10', '--seconds', '30')
    result = run_client(ros, 'goal', 'test_msgs/action/Fibonacci', '/fibonacci', '{order: 11}', '--timeout', '10')
    assert result['status'] == 'rejected' and result['done'] is True, result
    assert result['error'] == 'goal rejected by /fibonacci'
    assert result['result'] is None and result['accepted'] == 0 and result['feedback_count'] == 0
    assert result['events']['GoalResponseEvent'] == 1 and result['events']['ResultReceivedEvent'] == 0
    ros.stop(server)


def test_missing_action_server_gives_our_client_a_clear_timeout(ros):
    result = run_client(ros, 'goal', 'test_msgs/action/Fibonacci', '/nobody_serves_this', '{order: 3}',
                        '--wait', '0', '--timeout', '1.5')
    assert result['status'] == 'timed out' and result['done'] is True, result
    assert result['error'] == ('timed out: no server for /nobody_serves_this (test_msgs/action/Fibonacci) '
                               'appeared within 1.5 s')
    assert result['events']['GoalFailedEvent'] == 1 and result['events']['GoalResponseEvent'] == 0


def test_our_client_has_two_goals_in_flight_and_both_results(ros):
    """One client, two goals sent back to back (rclpy's server runs them side by side on its
    multi-threaded executor): each is followed by its goal id, each gets its own feedback and
    result; the single-goal API reads the last goal sent."""
    server = rclpy_server(ros, '/fibonacci_pair', '--step', '0.1', '--seconds', '40')
    result = run_client(ros, 'goals', 'test_msgs/action/Fibonacci', '/fibonacci_pair', '{order: 5}', '{order: 8}',
                        '--timeout', '20')
    assert result['all_done'] is True, result
    first, second = result['goals']
    assert first['id'] != second['id'] and len(first['id']) == len(second['id']) == 32
    assert result['number_of_goals'] == 2 and result['nth_ids'] == [first['id'], second['id']]
    for goal, order in ((first, 5), (second, 8)):
        expected = fibonacci_feedbacks(order)
        assert goal['status'] == 'succeeded' and goal['result_status'] == STATUS_SUCCEEDED, goal
        assert goal['result'] == {'sequence': expected[-1]} and goal['error'] == ''
        # Feedback of each goal only (the topic carries both): an in-order suffix ending with the
        # last step (an early one may be sent before our reader matched, as with rclpy clients).
        sequences = [f['sequence'] for f in goal['feedbacks']]
        assert 1 <= len(sequences) == goal['feedback_count'] and sequences == expected[-len(sequences):], goal
        assert goal['last_feedback'] == {'sequence': expected[-1]}
        assert goal['events']['GoalResponseEvent'] == 1 and goal['events']['ResultReceivedEvent'] == 1, goal
        assert goal['events']['GoalFailedEvent'] == 0
    assert result['accepted'] == 2 and result['results'] == 2
    # The single-goal API: the last goal sent.
    assert result['current']['id'] == second['id'] and result['current']['status'] == 'succeeded'
    assert result['current']['result'] == {'sequence': fibonacci_feedbacks(8)[-1]}
    ros.stop(server)


def test_our_client_cancels_all_goals_at_once(ros):
    """CancelAllGoals sends one CancelGoal request with a zero goal id and a zero stamp (rclcpp's
    async_cancel_all_goals): rclpy's server cancels both running goals."""
    server = rclpy_server(ros, '/slow_pair', '--step', '0.3', '--seconds', '40')
    result = run_client(ros, 'goals', 'test_msgs/action/Fibonacci', '/slow_pair', '{order: 20}', '{order: 25}',
                        '--timeout', '20', '--cancel-all-after', '2')
    assert result['cancel_sent'] is True and result['cancel_return_code'] == 0, result  # ERROR_NONE
    assert result['cancel_events'] == 1
    assert result['all_done'] is True
    for goal, order in zip(result['goals'], (20, 25)):
        assert goal['status'] == 'canceled' and goal['result_status'] == STATUS_CANCELED, goal
        full = fibonacci_feedbacks(order)[-1]
        partial = goal['result']['sequence']
        assert 3 <= len(partial) < len(full) and partial == full[:len(partial)], goal
        assert goal['feedback_count'] >= 2
    ros.stop(server)


def test_our_client_cancels_the_goals_accepted_before_a_time(ros):
    """CancelGoalsBefore sends a zero goal id and a stamp (rclcpp's async_cancel_goals_before):
    rclpy's server cancels the goals it accepted at or before it. The stamp lies halfway between
    the two goals' acceptance stamps (0.3 s apart): the first goal is canceled, the second runs
    to the end. Not the first goal's stamp itself: rclpy answers SendGoal with a stamp taken just
    before rcl_action_accept_new_goal stamps the goal again (a few µs later), so a cancel at the
    answered stamp misses the goal on rclpy's own server too (checked with an rclpy client)."""
    server = rclpy_server(ros, '/slow_before', '--step', '0.3', '--seconds', '40')
    result = run_client(ros, 'goals', 'test_msgs/action/Fibonacci', '/slow_before', '{order: 20}', '{order: 9}',
                        '--timeout', '20', '--stagger', '0.3', '--cancel-before-first-after', '2')
    assert result['cancel_sent'] is True and result['cancel_return_code'] == 0, result  # ERROR_NONE
    assert result['all_done'] is True
    first, second = result['goals']
    assert first['accepted_stamp'] < second['accepted_stamp'] and first['accepted_stamp'][0] > 0, result
    assert first['status'] == 'canceled' and first['result_status'] == STATUS_CANCELED, first
    partial = first['result']['sequence']
    assert 3 <= len(partial) < 21 and partial == fibonacci_feedbacks(20)[-1][:len(partial)], first
    assert second['status'] == 'succeeded' and second['result_status'] == STATUS_SUCCEEDED, second
    assert second['result'] == {'sequence': fibonacci_feedbacks(9)[-1]}
    ros.stop(server)


# -- our server, rclpy ActionClient ------------------------------------------------------------

def our_server(ros, *args: str):
    server = ours(ros, 'serve', *args)
    ros.wait_ready(server)
    return server


def rclpy_client(ros, *args: str, timeout: float = 60) -> dict:
    client = ros.start([str(VENV_PYTHON), str(HERE / 'action_peer.py'), 'client', *args])
    code, out, err = ros.finish(client, timeout=timeout)
    assert code == 0, err
    assert json.loads(out.strip().splitlines()[0]) == {'ready': True}, out + err
    return last_json(out)


def test_rclpy_client_gets_feedback_and_result_from_our_server(ros):
    server = our_server(ros, '/fibonacci', '--step', '0.05', '--count', '1', '--seconds', '30')
    result = rclpy_client(ros, '/fibonacci', '5')
    expected = fibonacci_feedbacks(5)
    assert result['accepted'] is True, result
    assert result['status'] == STATUS_SUCCEEDED and result['sequence'] == expected[-1]
    # Feedback sent before our feedback writer has discovered the client's reader is not
    # delivered (volatile, as with an rclpy server: wait_for_server only proves the client's side
    # of discovery). What arrives is in order, ends with the last feedback, and skips only a
    # prefix (the Jazzy client under CI load missed the first one).
    feedbacks = result['feedbacks']
    assert feedbacks and feedbacks == expected[len(expected) - len(feedbacks):], feedbacks
    code, out, err = ros.finish(server, timeout=40)
    assert code == 0, err
    served = last_json(out)
    assert served['orders'] == [5] and served['outcomes'] == ['succeeded'] and served['results_sent'] == 1


def test_finished_goal_expires_after_the_result_timeout_as_rcl_action(ros):
    """rcl_action_expire_goals: once the result timeout has passed, our server forgets the goal and
    a result request for it is answered STATUS_UNKNOWN, which is what rclpy's client reads."""
    server = our_server(ros, '/expiring_fibonacci', '--step', '0.05', '--count', '1', '--seconds', '30',
                        '--result-timeout', '0.5', '--linger', '4')
    result = rclpy_client(ros, '/expiring_fibonacci', '3', '--result-again-after', '2')
    assert result['status'] == STATUS_SUCCEEDED and result['sequence'] == fibonacci_feedbacks(3)[-1], result
    assert result['status_asked_again'] == STATUS_UNKNOWN, result
    code, out, err = ros.finish(server, timeout=40)
    assert code == 0, err
    served = last_json(out)
    assert served['expired'] == 1 and served['goals_kept'] == 0, served


def test_rclpy_client_cancels_a_goal_on_our_server(ros):
    server = our_server(ros, '/slow_fibonacci', '--step', '0.3', '--count', '1', '--seconds', '30')
    result = rclpy_client(ros, '/slow_fibonacci', '20', '--cancel-after', '2', '--timeout', '15')
    assert result['cancel_return_code'] == 0, result  # ERROR_NONE
    assert result['status'] == STATUS_CANCELED, result
    full = fibonacci_feedbacks(20)[-1]
    assert 3 <= len(result['sequence']) < len(full) and result['sequence'] == full[:len(result['sequence'])]
    code, out, err = ros.finish(server, timeout=40)
    assert code == 0, err
    served = last_json(out)
    assert served['cancels'] == 1 and served['cancel_events'] == 1 and served['outcomes'] == ['canceled']


def test_our_server_rejects_a_goal_of_the_rclpy_client(ros):
    server = our_server(ros, '/fibonacci', '--max-order', '10', '--seconds', '10')
    result = rclpy_client(ros, '/fibonacci', '11')
    assert result == {'accepted': False}
    ros.stop(server)
