"""Remote sets of our node's parameters are bounded in size (issue 11 item 12): an rclpy
parameter client (its own process) sets oversized strings and arrays; our node refuses each with
a reason that names the sizes (SetParametersResult.reason), keeps its value and keeps serving. The
limit is configurable (vtkROS2NodeNode::SetParameterValueSizeLimit) and applies at its edge."""
from __future__ import annotations

import json

DEFAULT_LIMIT = 4 * 1024 * 1024


def serve_and_set(ros, *peer_args: str, limit: int | None = None) -> tuple[dict, dict, str]:
    args = ['--seconds', '40', 'serve'] + (['--value-limit', str(limit)] if limit is not None else [])
    ours = ros.scene(*args)
    ready = json.loads(ours.stdout.readline())
    assert ready.get('ready') is True, ours.stderr.read()
    peer = ros.peer('params', '/slicer', '--get', 'image_frame', 'frame_count', *peer_args)
    code, out, err = ros.finish(peer, timeout=90)
    assert code == 0, err
    ours.kill()
    _, _, our_err = ros.finish(ours)
    return ready, json.loads(out), our_err


def test_oversized_string_over_the_default_limit_is_refused_with_a_reason(ros):
    ready, result, _ = serve_and_set(ros, '--set-sized', f'image_frame=string:{DEFAULT_LIMIT + 1}',
                                     '--set', 'frame_count=43')
    assert ready['value_limit'] == DEFAULT_LIMIT
    accepted, refused = result['set']  # --set items go first, then --set-sized ones
    assert refused['successful'] is False
    assert refused['reason'] == (f"parameter 'image_frame' cannot be set: its string value holds "
                                 f"{DEFAULT_LIMIT + 1} bytes, more than this node accepts ({DEFAULT_LIMIT})")
    # Nothing kept, and the node still serves: the next parameter of the same request was set.
    assert accepted['successful'] is True
    assert result['get_after'] == {'image_frame': 'ct', 'frame_count': 43}


def test_configured_limit_applies_at_its_edge_to_strings_and_arrays(ros):
    limit = 1000
    ready, result, _ = serve_and_set(
        ros, '--set-sized', f'image_frame=string:{limit}', f'image_frame=string:{limit + 1}',
        'frame_count=integer_array:126', 'image_frame=string_array:200', limit=limit)
    assert ready['value_limit'] == limit
    at_limit, over, integers, strings = result['set']
    assert at_limit == {'successful': True, 'reason': ''}
    assert over['successful'] is False and f'holds {limit + 1} bytes' in over['reason'], over
    # Refused for their size before their type (both parameters are scalars): 126 * 8 bytes and
    # 200 * (2 + 4 length) bytes.
    assert integers['successful'] is False, integers
    assert integers['reason'] == (f"parameter 'frame_count' cannot be set: its integer_array value holds "
                                  f"1008 bytes, more than this node accepts ({limit})")
    assert strings['successful'] is False and 'string_array value holds 1200 bytes' in strings['reason'], strings
    assert result['get_after'] == {'image_frame': 'x' * limit, 'frame_count': 42}
