"""The robot's computer and the imaging workstation as two network namespaces (see conftest.py):
ROS 2's default discovery (SUBNET, multicast) across a real interface, both ways, with rclpy on
the robot side and our VTK-wrapped API on the imaging side."""
from __future__ import annotations

import json
import os
import re
import time
from pathlib import Path

import pytest

from conftest import IMAGING_ADDRESS, ROBOT_ADDRESS, ip

SENT = 20


def test_rclpy_pose_on_the_robot_host_reaches_our_subscriber_on_the_imaging_host(lab):
    ours = lab.imaging.scene('--seconds', '25', 'sub', 'PoseStamped', '/needle', '--count', str(SENT), '--linger', '1')
    lab.imaging.wait_ready(ours)
    pose = {'header': {'frame_id': 'world'}, 'pose': {'position': {'x': 0.1, 'y': -0.2, 'z': 0.3},
                                                       'orientation': {'x': 0.0, 'y': 0.0, 'z': 0.0, 'w': 1.0}}}
    peer = lab.robot.peer('pub', '/needle', 'geometry_msgs/msg/PoseStamped', json.dumps(pose),
                          '--count', str(SENT), '--rate', '20', '--wait', '15')
    code, out, err = lab.imaging.finish(ours, timeout=40)
    lab.robot.finish(peer)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] == SENT and result['rejected'] == 0, result
    assert [round(result['value'][i][3], 9) for i in range(3)] == [100.0, -200.0, 300.0]  # mm


def test_our_publisher_on_the_imaging_host_reaches_rclpy_on_the_robot_host(lab):
    echo = lab.robot.peer('echo', '/target', 'std_msgs/msg/String', '--count', '3', '--timeout', '30')
    lab.robot.wait_ready(echo)
    ours = lab.imaging.scene('--seconds', '20', 'pub', 'String', '/target')
    code, out, err = lab.robot.finish(echo, timeout=40)
    lab.imaging.finish(ours)
    assert code == 0, err
    assert json.loads(out.splitlines()[-1])['data']


def announced_by_one_process(lab, start_process) -> dict[str, set]:
    """The UDPv4 locators the participant(s) of one process on the imaging host announce, as the
    robot host receives them by multicast (tests/network/spdp_listen.py): {list kind: {address}}
    (other locator kinds as 'kind N': rclpy's shared memory, which ours keeps off)."""
    listener = lab.robot.start(['/usr/bin/python3', str(Path(__file__).parent / 'spdp_listen.py'),
                                str(lab.robot.domain), ROBOT_ADDRESS, '4'])
    lab.robot.wait_ready(listener)
    process = start_process()
    code, out, err = lab.robot.finish(listener, timeout=30)
    lab.imaging.stop(process)
    assert code == 0, err
    announced = json.loads(out.splitlines()[-1])
    assert len(announced) >= 1, f'no announcement reached the other host: {out}'
    addresses: dict[str, set] = {}
    for listed in announced.values():
        for kind, locator_kind, address, _ in listed:
            addresses.setdefault(kind, set()).add(address if locator_kind == 1 else f'kind {locator_kind}')
    return addresses


def test_our_participant_announces_the_addresses_rclpy_announces_on_the_same_host(lab):
    """What our participant tells the other host (its SPDP locators, read by an independent RTPS
    parser on the robot host): the imaging host's link address, not only 127.0.0.1, and the same
    unicast addresses as an rclpy node on that host (so an interface rclpy leaves out, here a
    second link that is down with an address of its own, is left out by ours too)."""
    down_a, down_b = f'{lab.imaging_if}x', f'{lab.imaging_if}y'
    ip('-n', lab.imaging_ns, 'link', 'add', down_a, 'type', 'veth', 'peer', 'name', down_b)
    ip('-n', lab.imaging_ns, 'addr', 'add', '198.19.0.2/24', 'dev', down_a)  # left down
    ours = announced_by_one_process(lab, lambda: lab.imaging.scene('--seconds', '10', 'pub', 'String', '/chatter'))
    rclpy = announced_by_one_process(lab, lambda: lab.imaging.peer(
        'pub', '/chatter', 'std_msgs/msg/String', json.dumps({'data': 'x'}), '--count', '-1', '--wait', '0'))
    print(f'announced by ours: {ours}; by rclpy: {rclpy}')
    for kind in ('metatraffic_unicast', 'default_unicast'):
        assert IMAGING_ADDRESS in ours.get(kind, set()), ours
        udp = {address for address in rclpy.get(kind, set()) if not address.startswith('kind ')}
        assert ours[kind] == udp, (kind, ours, rclpy)
    assert '198.19.0.2' not in set().union(*ours.values()), ours
    assert '127.0.0.1' not in set().union(*ours.values()), ours


def test_our_localhost_node_is_invisible_to_a_subnet_peer_on_the_other_host(lab):
    """Our node in LOCALHOST mode beside an rclpy node on the other host that discovers by
    multicast (SUBNET): the peer sees neither our node nor our topic, and we get none of its data."""
    lab.imaging.env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    ours = lab.imaging.scene('--seconds', '12', 'sub', 'String', '/needle',
                             '--count', '1')
    lab.imaging.wait_ready(ours)
    peer = lab.robot.peer('pub', '/needle', 'std_msgs/msg/String', json.dumps({'data': 'x'}),
                          '--count', '100', '--rate', '20', '--wait', '0')
    graph = lab.robot.peer('graph', '--wait', '6', '--expect-node', 'slicer')
    code, out, err = lab.robot.finish(graph, timeout=30)
    assert code == 0, err
    seen = json.loads(out.splitlines()[-1])
    assert ['slicer', '/'] not in seen['nodes'], seen['nodes']
    assert not any(sub[0] == 'slicer' for sub in seen['subscribers'].get('/needle', [])), seen
    code, out, err = lab.imaging.finish(ours, timeout=30)
    lab.robot.finish(peer)
    assert code == 0, err
    assert json.loads(out.splitlines()[-1])['count'] == 0, 'LOCALHOST discovery crossed to the other host'


def test_a_subnet_peer_on_another_domain_sees_nothing_of_ours(lab):
    lab.robot.env['ROS_DOMAIN_ID'] = str(lab.imaging.domain + 100)
    ours = lab.imaging.scene('--seconds', '10', 'pub', 'String', '/chatter')
    lab.imaging.wait_ready(ours)
    graph = lab.robot.peer('graph', '--wait', '5', '--expect-node', 'slicer')
    code, out, err = lab.robot.finish(graph, timeout=30)
    lab.imaging.finish(ours)
    assert code == 0, err
    seen = json.loads(out.splitlines()[-1])
    assert ['slicer', '/'] not in seen['nodes'] and '/chatter' not in seen['topics'], seen


def test_the_same_graph_query_across_the_link_finds_our_node(lab):
    """The control of the two tests above: same domain, SUBNET on both sides."""
    ours = lab.imaging.scene('--seconds', '15', 'pub', 'String', '/chatter')
    lab.imaging.wait_ready(ours)
    graph = lab.robot.peer('graph', '--wait', '10', '--expect-node', 'slicer')
    code, out, err = lab.robot.finish(graph, timeout=30)
    lab.imaging.finish(ours)
    assert code == 0, err
    seen = json.loads(out.splitlines()[-1])
    assert ['slicer', '/'] in seen['nodes'], seen['nodes']
    assert seen['topics'].get('/chatter') == ['std_msgs/msg/String'], seen['topics']


def test_robot_from_robot_state_publisher_on_the_robot_host_follows_tf_on_the_imaging_host(lab):
    """The paper's set-up split over two computers: robot_state_publisher (rclpy) and its tf on the
    robot's host, our robot node on the imaging host; every link matches yourdfpy to 1e-6 m."""
    from test_scene_robot import ARM, ARM_PACKAGE, TOLERANCE_MM, matches, run_robot
    ready, state, snapshots, expected = run_robot(lab.imaging, ARM, 'parameter', configs=2,
                                                  mesh_paths=[ARM_PACKAGE], rsp_host=lab.robot)
    assert state['state'] == 'loaded', state
    assert sorted(state['links']) == sorted(ready['links'])
    for config in expected:
        best = min(matches(snapshot['links'], config['links']) for snapshot in snapshots)
        assert best < TOLERANCE_MM, f"configuration {config['config']} never matched (best {best})"


# The long outage costs over two minutes; CI runs the 5 s and 30 s cuts (the second is beyond
# Fast DDS's 20 s lease, so both sides drop and must rediscover each other) and
# scripts/test-network-long.sh (ROS2VTK_LONG_NETWORK_TESTS=1) runs all three, and the loss
# comparisons with rclpy below.
OUTAGES = [5, 30] + ([120] if os.environ.get('ROS2VTK_LONG_NETWORK_TESTS') == '1' else [])


@pytest.mark.parametrize('outage', OUTAGES)
def test_a_cut_link_heals_and_the_stream_resumes_without_restarting_either_side(lab, outage):
    rate, before, after = 10, 4.0, 8.0
    total = int(rate * (before + outage + after))
    ours = lab.imaging.scene('--seconds', str(before + outage + after + 20), 'sub', 'String', '/stream',
                             '--count', str(total), '--status-every', '0.5')
    lab.imaging.wait_ready(ours)
    peer = lab.robot.peer('pub', '/stream', 'std_msgs/msg/String', json.dumps({'data': ''}), '--count', str(total),
                          '--rate', str(rate), '--wait', '15', '--sequence-field', 'data', '--linger', '10')
    time.sleep(2.0 + before)  # discovery, then the stream runs for `before` seconds
    cut_at = time.time()
    lab.cut()
    time.sleep(outage)
    healed_at = time.time()
    lab.heal()
    code, out, err = lab.imaging.finish(ours, timeout=before + outage + after + 60)
    peer_code, _, peer_err = lab.robot.finish(peer, timeout=60)
    assert code == 0, err
    assert peer_code == 0, peer_err
    result = json.loads(out.splitlines()[-1])
    # The last message, sent after the link healed, arrived: the subscription resumed by itself.
    assert result['value'] == str(total - 1), result
    # Lost: what was sent during the outage, and after a cut beyond the lease also what was sent
    # until the two sides rediscovered each other (a new match of a volatile reader gets no
    # history, as with rclpy). Measured: a 5 s cut lost 41 of 170 (the history of 10 came through),
    # a 30 s cut 306 of 420 (rediscovery took ~0.6 s). Allow 5 s for rediscovery.
    lost = total - result['count']
    print(f'link cut for {outage} s: {result["count"]} of {total} arrived, the last one included')
    assert lost <= int(rate * (outage + 5)), result
    assert result['rejected'] == 0, result

    # The link status our node showed (every 0.5 s) while it lasted.
    status = [json.loads(line)['status'] for line in out.splitlines() if line.startswith('{"status"')]
    before_cut = [s for s in status if s['t'] < cut_at and s['count'] > 0]
    during = [s for s in status if cut_at + 2.0 < s['t'] < healed_at]
    after_heal = [s for s in status if s['t'] > healed_at]
    assert before_cut and during and after_heal, status
    assert before_cut[-1]['link'] == 'peers' and before_cut[-1]['matched'] >= 1, before_cut[-1]
    assert before_cut[-1]['since_last'] < 1.0, before_cut[-1]
    # The stream fell silent: the age of the last message grows through the outage (10 Hz normally).
    assert all(s['since_last'] > 1.5 for s in during), during
    if outage > 25:  # beyond the 20 s lease: the robot's participants are dropped and shown gone
        gone = [s for s in during if s['link'] == 'no peers']
        assert gone and all(s['participants'] == 0 and s['matched'] == 0 for s in gone), during
        assert gone[-1]['dropped'] >= 1, gone[-1]
    else:  # within the lease: DDS still counts the peer; only the silence shows
        assert all(s['link'] == 'peers' for s in during), during
    # Healed: peers, a match and a fresh message again (the robot's publisher leaves later).
    assert any(s['link'] == 'peers' and s['matched'] >= 1 and 0 <= s['since_last'] < 1.0 for s in after_heal), \
        after_heal
    # The same changes as events (LinkStateChangedEvent), on the spinning thread: beyond the
    # lease the robot's participant is dropped ("no peers") during the outage and found again
    # ("peers") after the heal; within it nothing changes, so nothing fires while it lasts.
    events = [json.loads(line)['link_event'] for line in out.splitlines() if line.startswith('{"link_event"')]
    assert events and all(e['spinning_thread'] for e in events), events
    assert events[0]['state'] == 'peers' and events[0]['t'] < cut_at, events  # found at the start
    in_outage = [e for e in events if cut_at < e['t'] < healed_at]
    after = [e for e in events if e['t'] > healed_at]
    if outage > 25:
        assert [e['state'] for e in in_outage][-1:] == ['no peers'] and in_outage[-1]['participants'] == 0, events
        assert after and after[0]['state'] == 'peers' and after[0]['participants'] >= 1, events
        # 5 s after the drop the node said so (stderr), with what to check.
        assert 'ROS node /slicer has seen no other ROS 2 participant for 5 s (nothing can arrive on /stream)' in err
    else:
        assert in_outage == [], events
    print(f'link events around the {outage} s cut: ' + ', '.join(
        f"{e['t'] - cut_at:+.1f}s {e['state']}/{e['participants']}p" for e in events))
    print(f'link status during the {outage} s cut: ' + ', '.join(
        f"{s['t'] - cut_at:.1f}s {s['link']}/{s['participants']}p/{s['matched']}m/{s['since_last']:.1f}s"
        for s in during[::4]))


def stream_through_loss(lab, qos: str, rate: int, ours: bool) -> tuple[int, int]:
    """An rclpy publisher on the robot host sends `rate`·4 numbered strings to our subscriber (or,
    as the baseline, an rclpy one) on the imaging host; returns (arrived, sent)."""
    total = rate * 4
    if ours:
        receiver = lab.imaging.scene('--seconds', '40', 'sub', 'String', '/stream', '--count', str(total),
                                     '--linger', '2', '--qos', qos)
    else:
        receiver = lab.imaging.peer('echo', '/stream', 'std_msgs/msg/String', '--count', str(total),
                                    '--timeout', '25', '--qos', qos)
    lab.imaging.wait_ready(receiver)
    peer = lab.robot.peer('pub', '/stream', 'std_msgs/msg/String', json.dumps({'data': ''}), '--count', str(total),
                          '--rate', str(rate), '--wait', '20', '--sequence-field', 'data', '--linger', '15',
                          '--qos', qos)
    # The publisher stays (--linger) so that its writer can still repair losses by retransmission
    # (a reliable reader delivers in order: one late repair holds back everything after it; with
    # 5 s one run under load saw 292 of 400); once the receiver has what it waited for, it goes.
    code, out, err = lab.imaging.finish(receiver, timeout=60)
    lab.robot.stop(peer)
    if ours:
        assert code == 0, err
        result = json.loads(out.splitlines()[-1])
        assert result['rejected'] == 0, result
        return result['count'], total
    return len(out.splitlines()), total  # one line per message (no ready line on stdout left)


def test_random_packet_loss_reliable_keep_all_loses_nothing(lab):
    """5 % of the packets dropped each way (nftables): a reliable keep-all stream at 100 Hz (above
    the paper's 50 Hz) arrives whole: retransmission repairs every loss."""
    lab.drop(5)
    arrived, total = stream_through_loss(lab, 'keep_all', 100, ours=True)
    print(f'5 % loss, reliable keep_all at 100 Hz: {arrived} of {total} arrived')
    assert arrived == total


@pytest.mark.skipif(os.environ.get('ROS2VTK_LONG_NETWORK_TESTS') != '1',
                    reason='2 min of streams beside an rclpy baseline: run by scripts/test-network-long.sh, not CI')
@pytest.mark.parametrize('qos', ['default', 'sensor_data'])
def test_random_packet_loss_degrades_keep_last_and_best_effort_streams_gracefully(lab, qos):
    """With ROS's default keep-last-10 history (or best effort), 5 % loss at 100 Hz costs samples
    that a retransmission no longer finds in the writer's history; rclpy's own subscriber loses
    them too. Ours keeps receiving; both counts are printed (measured over 6 s at 100 Hz: default ours
    589 vs rclpy 505 of 600, best effort 451 vs 440; another run 402 vs 499: runs spread widely)."""
    lab.drop(5)
    arrived, total = stream_through_loss(lab, qos, 100, ours=True)
    baseline, _ = stream_through_loss(lab, qos, 100, ours=False)
    print(f'5 % loss, {qos} at 100 Hz: ours {arrived}, rclpy {baseline} of {total} arrived')
    assert total // 2 < arrived <= total


@pytest.mark.parametrize('static_peers', [False, True], ids=['no_static_peers', 'ROS_STATIC_PEERS'])
def test_without_multicast_static_peers_find_the_other_host(lab, static_peers):
    """Multicast dropped on the link: SUBNET discovery alone finds nobody (the control); with
    ROS_STATIC_PEERS naming the other host on both sides (ROS 2 Jazzy and later), rclpy and our
    node discover each other by unicast and the data flows."""
    lab.block_multicast()
    if static_peers:
        lab.robot.env['ROS_STATIC_PEERS'] = IMAGING_ADDRESS
        lab.imaging.env['ROS_STATIC_PEERS'] = ROBOT_ADDRESS
    ours = lab.imaging.scene('--seconds', '15' if static_peers else '8', 'sub', 'String', '/needle', '--count', '5')
    lab.imaging.wait_ready(ours)
    peer = lab.robot.peer('pub', '/needle', 'std_msgs/msg/String', json.dumps({'data': 'target'}),
                          '--count', '5', '--rate', '10', '--wait', '12' if static_peers else '6')
    code, out, err = lab.imaging.finish(ours, timeout=40)
    lab.robot.finish(peer, timeout=30)
    assert code == 0, err
    result = json.loads(out.splitlines()[-1])
    assert result['count'] == (5 if static_peers else 0), result
    if not static_peers:  # alone for 8 s: our node says so once, with its settings and what to check
        assert len(re.findall(r'Warning: In \S*vtkROS2NodeNode\.cxx', err)) == 1, err  # said once
        warning = [line for line in err.splitlines() if 'has seen no other ROS 2 participant' in line]
        assert 'ROS node /slicer has seen no other ROS 2 participant for 5 s (nothing can arrive on /needle)' in warning[0]
        assert (f'it uses ROS_DOMAIN_ID={lab.imaging.domain} and ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET (multicast); '
                'check that the other side uses the same domain and range, that multicast reaches it (if the network '
                'drops multicast: ROS_STATIC_PEERS or ROS_DISCOVERY_SERVER), and that no firewall drops UDP ports '
                f'{7400 + 250 * lab.imaging.domain}-{7649 + 250 * lab.imaging.domain} (docs/networking.md)') in warning[0], warning
    else:
        assert 'has seen no other ROS 2 participant' not in err, err
