"""Bad input from a real rclpy peer: malformed bytes, an image whose step does not fit its data,
a NaN pose. Our side counts and reports them, gives no value, and keeps running."""
from __future__ import annotations

import copy
import json

from samples import SAMPLES


def test_malformed_payloads_are_rejected_counted_and_we_keep_running(ros):
    ours = ros.scene('--seconds', '25', 'sub', 'String', '/bad/string')
    ros.wait_ready(ours)
    bad = ros.peer('pub_raw', '/bad/string', 'std_msgs/msg/String',
                   '00010000ffffffff41',          # string length 4 GiB in a 9-byte payload
                   '0001000008000000616263',      # truncated string
                   '0001',                        # shorter than the encapsulation header
                   '0200000001000000',            # unknown encapsulation
                   '--count', '2')
    ros.finish(bad)
    good = ros.peer('pub', '/bad/string', 'std_msgs/msg/String', json.dumps({'data': 'still alive'}),
                    '--count', '30', '--rate', '10')
    code, out, err = ros.finish(ours)
    ros.stop(good)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['value'] == 'still alive'
    assert result['rejected'] >= 6, result
    assert result['rejection'], 'the reason of the last rejection is kept'


def test_image_whose_step_does_not_fit_its_data_gives_no_image_and_a_reason(ros):
    image = copy.deepcopy(SAMPLES['sensor_msgs/msg/Image'])
    image['step'] = 100  # 2 rows of 100 bytes announced, 18 bytes of data
    ours = ros.scene('--seconds', '15', 'sub', 'Image', '/bad/image')
    ros.wait_ready(ours)
    peer = ros.peer('pub', '/bad/image', 'sensor_msgs/msg/Image', json.dumps(image), '--count', '30')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] >= 1 and result['value'] is None
    assert 'step' in result['conversion_error'], result


def test_nan_pose_is_refused_with_a_reason(ros):
    pose = copy.deepcopy(SAMPLES['geometry_msgs/msg/PoseStamped'])
    pose['pose']['position']['x'] = float('nan')
    ours = ros.scene('--seconds', '15', 'sub', 'PoseStamped', '/bad/pose')
    ros.wait_ready(ours)
    peer = ros.peer('pub', '/bad/pose', 'geometry_msgs/msg/PoseStamped', json.dumps(pose), '--count', '30')
    code, out, err = ros.finish(ours)
    ros.stop(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] >= 1 and result['value'] is None
    assert result['conversion_error'], result


HIGH_PARTICIPANT_ID = """<?xml version="1.0" encoding="UTF-8" ?>
<dds xmlns="http://www.eprosima.com"><profiles>
  <participant profile_name="high_id" is_default_profile="true"><rtps><participantID>60</participantID></rtps></participant>
</profiles></dds>
"""


def test_after_forty_reopened_scenes_a_peer_numbered_above_31_still_finds_our_node(ros, tmp_path):
    # Each reopened scene makes a new participant. Fast DDS 2.9 numbered ours on from 40, so it
    # listened outside the ports 0..31 that LOCALHOST discovery probes; a peer numbered above 31
    # too (here rclpy, set to 60 by a Fast DDS profile, as on a host running many nodes) and ours
    # never found each other. Ours now takes the lowest free number.
    profile = tmp_path / 'high_id.xml'
    profile.write_text(HIGH_PARTICIPANT_ID)
    ours = ros.scene('--reopen', '40', '--seconds', '20', 'sub', 'String', '/reopened')
    ros.wait_ready(ours)
    talker = ros.peer('pub', '/reopened', 'std_msgs/msg/String', json.dumps({'data': 'found you'}),
                      '--count', '40', '--rate', '10',
                      env=dict(ros.env, FASTDDS_DEFAULT_PROFILES_FILE=str(profile)))
    code, out, err = ros.finish(ours)
    ros.stop(talker)
    assert code == 0, err
    assert json.loads(out.splitlines()[-1])['value'] == 'found you'
