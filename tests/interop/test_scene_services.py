"""Services both ways through our VTK-wrapped Python API (vtkROS2ServiceClientNode /
vtkROS2ServiceServerNode) against rclpy servers and clients in their own processes."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from conftest import BUILD, HERE, VENV_PYTHON

PARAMETER_NAMES = ['flag', 'count', 'gain', 'frame', 'bytes', 'flags', 'counts', 'gains', 'frames', 'missing']


def ours(ros, *args: str):
    env = dict(ros.env, PYTHONPATH=str(BUILD / 'python'))
    return ros.start(['/usr/bin/python3', str(HERE / 'service_runner.py'), *args], env)


def rclpy_peer(ros, *args: str):
    return ros.start([str(VENV_PYTHON), str(HERE / 'service_peer.py'), *args])


def last_json(out: str) -> dict:
    return json.loads(out.strip().splitlines()[-1])


def run_pair(ros, server_args, client_args, server_first=True, timeout=60):
    """Starts a server and a client process; returns (client result, server result)."""
    server = server_args[0](ros, *server_args[1:])
    ros.wait_ready(server)
    client = client_args[0](ros, *client_args[1:])
    code, out, err = ros.finish(client, timeout=timeout)
    assert code == 0, err
    server_code, server_out, server_err = ros.finish(server, timeout=timeout)
    assert server_code == 0, server_err
    return last_json(out), last_json(server_out)


# -- rclpy server, our client ------------------------------------------------------------------

@pytest.mark.parametrize('request_yaml, success', [('{data: true}', True), ('{data: false}', False)])
def test_our_client_calls_rclpy_setbool(ros, request_yaml, success):
    result, served = run_pair(ros, (rclpy_peer, 'server', 'std_srvs/srv/SetBool', '/enable', '--count', '1'),
                              (ours, 'call', 'std_srvs/srv/SetBool', '/enable', request_yaml))
    assert result['ok'] == 1 and result['failed'] == 0, result
    assert result['first'] == {'success': success, 'message': f'rclpy set {success}'}
    assert result['status'] == 'succeeded' and result['events'] == {'response': 1, 'failed': 0}
    assert served['served'] == 1


def test_our_client_calls_rclpy_trigger_asynchronously(ros):
    result, served = run_pair(ros, (rclpy_peer, 'server', 'std_srvs/srv/Trigger', '/trigger', '--count', '5'),
                              (ours, 'call', 'std_srvs/srv/Trigger', '/trigger', '{}', '--count', '5',
                               '--asynchronous'))
    assert result['events'] == {'response': 5, 'failed': 0}, result
    assert result['pending'] == 0
    assert result['last']['success'] is True and result['last']['message'].startswith('rclpy triggered ')
    assert served['served'] == 5


def test_our_client_gets_every_field_kind_from_rclpy_get_parameters(ros):
    result, _ = run_pair(ros, (rclpy_peer, 'server', 'rcl_interfaces/srv/GetParameters', '/planner/get_parameters',
                               '--count', '1'),
                         (ours, 'call', 'rcl_interfaces/srv/GetParameters', '/planner/get_parameters',
                          json.dumps({'names': PARAMETER_NAMES})))
    values = result['first']['values']
    assert len(values) == len(PARAMETER_NAMES), result
    by_name = dict(zip(PARAMETER_NAMES, values))
    assert by_name['flag']['bool_value'] is True and by_name['flag']['type'] == 1
    assert by_name['count']['integer_value'] == -7
    assert by_name['gain']['double_value'] == 0.5
    assert by_name['frame']['string_value'] == 'ct_scanner'
    assert [ord(b) if isinstance(b, str) else b for b in by_name['bytes']['byte_array_value']] == [1, 255]
    assert by_name['flags']['bool_array_value'] == [True, False, True]
    assert by_name['counts']['integer_array_value'] == [1, -2, 3]
    assert by_name['gains']['double_array_value'] == [0.25, 1.5]
    assert by_name['frames']['string_array_value'] == ['base', 'tool']
    assert by_name['missing']['type'] == 0


def test_our_client_makes_1000_calls_to_rclpy_without_loss(ros):
    result, served = run_pair(ros, (rclpy_peer, 'server', 'std_srvs/srv/Trigger', '/trigger', '--count', '1000',
                                    '--seconds', '120'),
                              (ours, 'call', 'std_srvs/srv/Trigger', '/trigger', '{}', '--count', '1000'),
                              timeout=150)
    assert result['ok'] == 1000 and result['failed'] == 0, result['errors']
    # Every response is the answer to its own request (the server counts them).
    assert result['distinct'] == 1000
    assert result['last']['message'] == 'rclpy triggered 1000'
    assert served['served'] == 1000


def test_slow_rclpy_server_gives_our_client_a_clear_timeout(ros):
    result, _ = run_pair(ros, (rclpy_peer, 'server', 'std_srvs/srv/SetBool', '/slow', '--delay', '3',
                               '--seconds', '8'),
                         (ours, 'call', 'std_srvs/srv/SetBool', '/slow', '{data: true}', '--timeout', '1'))
    assert result['ok'] == 0 and result['failed'] == 1, result
    assert result['status'] == 'timed out'
    assert result['errors'] == ['timed out: /slow sent no response within 1 s']
    assert result['events'] == {'response': 0, 'failed': 1}


def test_missing_server_gives_our_client_a_clear_timeout(ros):
    client = ours(ros, 'call', 'std_srvs/srv/Trigger', '/nobody_serves_this', '{}', '--wait', '0',
                  '--timeout', '1.5')
    code, out, err = ros.finish(client)
    assert code == 0, err
    result = last_json(out)
    assert result['status'] == 'timed out' and result['failed'] == 1
    assert result['errors'] == ['timed out: no server for /nobody_serves_this (std_srvs/srv/Trigger) '
                                'appeared within 1.5 s']


# -- our server, rclpy client ------------------------------------------------------------------

@pytest.mark.parametrize('data', [True, False])
def test_rclpy_client_calls_our_setbool(ros, data):
    result, served = run_pair(ros, (ours, 'serve', 'std_srvs/srv/SetBool', '/enable', '--count', '1'),
                              (rclpy_peer, 'client', 'std_srvs/srv/SetBool', '/enable', json.dumps({'data': data})))
    assert result['received'] == 1, result
    assert result['first'] == {'success': data, 'message': f'ours set {"true" if data else "false"}'}
    assert served['requests'] == 1 and served['responses'] == 1
    assert served['first_request'] == {'data': data}


def test_rclpy_client_calls_our_trigger(ros):
    result, served = run_pair(ros, (ours, 'serve', 'std_srvs/srv/Trigger', '/trigger', '--count', '1'),
                              (rclpy_peer, 'client', 'std_srvs/srv/Trigger', '/trigger', '{}'))
    assert result['first'] == {'success': True, 'message': 'ours triggered 1'}, result


def test_rclpy_client_gets_every_field_kind_from_our_get_parameters(ros):
    result, _ = run_pair(ros, (ours, 'serve', 'rcl_interfaces/srv/GetParameters', '/planner/get_parameters',
                               '--count', '1'),
                         (rclpy_peer, 'client', 'rcl_interfaces/srv/GetParameters', '/planner/get_parameters',
                          json.dumps({'names': PARAMETER_NAMES})))
    values = dict(zip(PARAMETER_NAMES, result['first']['values']))
    assert values['flag']['bool_value'] is True and values['flag']['type'] == 1
    assert values['count']['integer_value'] == -7
    assert values['gain']['double_value'] == 0.5
    assert values['frame']['string_value'] == 'ct_scanner'
    # rclpy gives byte sequences as 1-byte bytes objects (the peer's JSON: [[1], [255]]).
    assert values['bytes']['byte_array_value'] == [[1], [255]]
    assert values['flags']['bool_array_value'] == [True, False, True]
    assert values['counts']['integer_array_value'] == [1, -2, 3]
    assert values['gains']['double_array_value'] == [0.25, 1.5]
    assert values['frames']['string_array_value'] == ['base', 'tool']
    assert values['missing']['type'] == 0


def test_rclpy_client_sets_parameters_through_our_set_parameters(ros):
    request = {'parameters': [{'name': 'gain', 'value': {'type': 3, 'double_value': 2.5}},
                              {'name': 'frames', 'value': {'type': 9, 'string_array_value': ['a', 'b']}},
                              {'name': 'unset', 'value': {'type': 0}}]}
    result, served = run_pair(ros, (ours, 'serve', 'rcl_interfaces/srv/SetParameters', '/planner/set_parameters',
                                    '--count', '1'),
                              (rclpy_peer, 'client', 'rcl_interfaces/srv/SetParameters', '/planner/set_parameters',
                               json.dumps(request)))
    assert result['first']['results'] == [{'successful': True, 'reason': 'gain:3'},
                                          {'successful': True, 'reason': 'frames:9'},
                                          {'successful': False, 'reason': 'unset:0'}], result
    assert served['first_request']['parameters'][1]['value']['string_array_value'] == ['a', 'b']


def test_rclpy_client_makes_1000_calls_to_our_server_without_loss(ros):
    result, served = run_pair(ros, (ours, 'serve', 'std_srvs/srv/Trigger', '/trigger', '--count', '1000',
                                    '--seconds', '120'),
                              (rclpy_peer, 'client', 'std_srvs/srv/Trigger', '/trigger', '{}', '--count', '1000'),
                              timeout=150)
    assert result['received'] == 1000 and result['failed'] == 0, result
    assert result['distinct'] == 1000 and result['last']['message'] == 'ours triggered 1000'
    assert served['responses'] == 1000 and served['unanswered'] == 0


@pytest.mark.parametrize('default', [True, False])
def test_unanswered_request_times_out_on_our_server(ros, default):
    server_args = ['serve', 'std_srvs/srv/Trigger', '/ignored', '--ignore', '--response-timeout', '1',
                   '--seconds', '6']
    if not default:
        server_args.append('--no-default')
    result, served = run_pair(ros, (ours, *server_args),
                              (rclpy_peer, 'client', 'std_srvs/srv/Trigger', '/ignored', '{}', '--timeout', '4'))
    assert served['requests'] == 1 and served['unanswered'] == 1 and served['pending'] == 0, served
    if default:
        # The default response went out: the rclpy client got it.
        assert result['received'] == 1 and result['first'] == {'success': False, 'message': ''}, result
    else:
        assert result['received'] == 0 and result['failed'] == 1, result


def test_empty_service_both_ways(ros):
    """std_srvs/Empty: a request and a response without fields (one dummy byte on the wire)."""
    result, served = run_pair(ros, (rclpy_peer, 'server', 'std_srvs/srv/Empty', '/reset', '--count', '1'),
                              (ours, 'call', 'std_srvs/srv/Empty', '/reset', '{}'))
    assert result['ok'] == 1 and result['first'] == {}, result
    assert served['served'] == 1
    result, served = run_pair(ros, (ours, 'serve', 'std_srvs/srv/Empty', '/reset', '--count', '1'),
                              (rclpy_peer, 'client', 'std_srvs/srv/Empty', '/reset', '{}'))
    assert result['received'] == 1 and result['first'] == {}, result
    assert served['responses'] == 1 and served['unanswered'] == 0
