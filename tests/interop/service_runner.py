"""Our service client or server (the VTK-wrapped Python API, Debian's python3 with
<build>/python on PYTHONPATH) in its own process, for test_scene_services.py. Prints JSON lines:
{"ready": ...} first, then one result object.

    service_runner.py call std_srvs/srv/SetBool /enable 'data: true' --count 1000
    service_runner.py serve std_srvs/srv/SetBool /enable --seconds 20
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import yaml

import ros2vtk

# Our server's answers for GetParameters (the same kinds the rclpy peer serves, byte arrays aside).
PARAMETER_VALUES = {
    'flag': {'type': 1, 'bool_value': True},
    'count': {'type': 2, 'integer_value': -7},
    'gain': {'type': 3, 'double_value': 0.5},
    'frame': {'type': 4, 'string_value': 'ct_scanner'},
    'bytes': {'type': 5, 'byte_array_value': [1, 255]},
    'flags': {'type': 6, 'bool_array_value': [True, False, True]},
    'counts': {'type': 7, 'integer_array_value': [1, -2, 3]},
    'gains': {'type': 8, 'double_array_value': [0.25, 1.5]},
    'frames': {'type': 9, 'string_array_value': ['base', 'tool']},
}


def cmd_call(args, logic, node) -> int:
    client = node.CreateAndAddServiceClientNode(args.type, args.name)
    if client is None:
        print(json.dumps({'ready': False, 'error': 'client not created'}), flush=True)
        return 1
    events = {'response': 0, 'failed': 0}
    client.AddObserver(ros2vtk.vtkROS2ServiceClientNode.ResponseReceivedEvent,
                       lambda *_: events.__setitem__('response', events['response'] + 1))
    client.AddObserver(ros2vtk.vtkROS2ServiceClientNode.RequestFailedEvent,
                       lambda *_: events.__setitem__('failed', events['failed'] + 1))
    ready = ros2vtk.spin_until(logic, client.IsServiceReady, seconds=args.wait) if args.wait > 0 else False
    print(json.dumps({'ready': bool(ready)}), flush=True)
    responses, errors, latencies = [], [], []
    if args.asynchronous:
        for _ in range(args.count):
            client.SendAsyncRequestYAML(args.yaml)
        ros2vtk.spin_until(logic, lambda: client.GetNumberOfPendingRequests() == 0, seconds=args.timeout + 5)
        responses = [client.GetLastResponseYAML()] if events['response'] else []
        errors = [client.GetLastError()] if client.GetLastError() else []
    else:
        for _ in range(args.count):
            start = time.perf_counter()
            response = client.Call(args.yaml, args.timeout)
            if response:
                latencies.append((time.perf_counter() - start) * 1e3)
                responses.append(response)
            else:
                errors.append(client.GetLastError())
    print(json.dumps({'ok': len(responses), 'failed': len(errors),
                      'first': yaml.safe_load(responses[0]) if responses else None,
                      'last': yaml.safe_load(responses[-1]) if responses else None,
                      'distinct': len(set(responses)), 'errors': sorted(set(errors)),
                      'status': client.GetStatusAsString(), 'events': events,
                      'pending': client.GetNumberOfPendingRequests(), 'latency_ms': latencies}), flush=True)
    return 0


def cmd_serve(args, logic, node) -> int:
    server = node.CreateAndAddServiceServerNode(args.type, args.name)
    if server is None:
        print(json.dumps({'ready': False}), flush=True)
        return 1
    server.SetResponseTimeout(args.response_timeout)
    server.SetAnswerUnansweredWithDefault(not args.no_default)
    seen = []

    def on_request(caller, _event):
        seen.append(caller.GetRequestYAML())
        if args.ignore:
            return  # left unanswered: the response timeout decides
        if args.type == 'std_srvs/srv/SetBool':
            data = caller.GetRequestField('data')
            caller.SetResponseField('success', data)
            caller.SetResponseField('message', f'ours set {data}')
        elif args.type == 'std_srvs/srv/Trigger':
            caller.SetResponseYAML(f"{{success: true, message: 'ours triggered {len(seen)}'}}")
        elif args.type == 'rcl_interfaces/srv/GetParameters':
            names = yaml.safe_load(caller.GetRequestYAML())['names']
            values = [PARAMETER_VALUES.get(name, {'type': 0}) for name in names]
            caller.SetResponseYAML(yaml.safe_dump({'values': values}))
        elif args.type == 'rcl_interfaces/srv/SetParameters':
            request = yaml.safe_load(caller.GetRequestYAML())
            results = [{'successful': p['value']['type'] != 0, 'reason': f"{p['name']}:{p['value']['type']}"}
                       for p in request['parameters']]
            caller.SetResponseYAML(yaml.safe_dump({'results': results}))
        else:
            caller.SendResponse()  # the default response

    server.AddObserver(ros2vtk.vtkROS2ServiceServerNode.RequestReceivedEvent, on_request)
    print(json.dumps({'ready': True}), flush=True)
    end = time.monotonic() + args.seconds
    while time.monotonic() < end and (not args.count or server.GetNumberOfResponses() < args.count):
        logic.SpinOnWakeUp(0.05)
    ros2vtk.spin_until(logic, lambda: False, seconds=0.3)  # the last replies leave
    print(json.dumps({'requests': server.GetNumberOfRequests(), 'responses': server.GetNumberOfResponses(),
                      'unanswered': server.GetNumberOfUnansweredRequests(),
                      'rejected': server.GetNumberOfRejectedRequests(), 'rejection': server.GetLastRejection(),
                      'first_request': yaml.safe_load(seen[0]) if seen else None,
                      'pending': server.GetNumberOfPendingRequests()}), flush=True)
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--node-name', default='slicer')
    sub = parser.add_subparsers(dest='command', required=True)
    call = sub.add_parser('call')
    call.add_argument('type')
    call.add_argument('name')
    call.add_argument('yaml')
    call.add_argument('--count', type=int, default=1)
    call.add_argument('--timeout', type=float, default=5.0)
    call.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the server (0: do not)')
    call.add_argument('--asynchronous', action='store_true', help='SendAsyncRequest all, then spin')
    serve = sub.add_parser('serve')
    serve.add_argument('type')
    serve.add_argument('name')
    serve.add_argument('--seconds', type=float, default=20.0)
    serve.add_argument('--count', type=int, default=0, help='stop after this many responses')
    serve.add_argument('--ignore', action='store_true', help='leave every request unanswered')
    serve.add_argument('--response-timeout', type=float, default=5.0)
    serve.add_argument('--no-default', action='store_true', help='drop unanswered requests')
    args = parser.parse_args()
    logic = ros2vtk.vtkROS2Logic()
    node = logic.GetDefaultROS2Node()
    return {'call': cmd_call, 'serve': cmd_serve}[args.command](args, logic, node)


if __name__ == '__main__':
    sys.exit(main())
