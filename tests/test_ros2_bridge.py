"""``sailmujoco ros2`` against a ROS 2 stack's own clients: rclpy, and an independent Cyclone DDS reader.

Every DDS participant runs inside a loopback-only network namespace (tests/ros2_support.py).
The expected types are the standard messages the contract names (REP-103 frames, sim time on
/clock), not read from the bridge's code.
"""

import json
import math
import re
import subprocess
import sys
from collections import defaultdict

import pytest
from ros2_support import ROOT, in_namespace, need_namespace, ros_python

STEP_NS = 100_000_000  # the tasks' control step, 0.1 s
EXPECTED_TYPES = {
    "/clock": "rosgraph_msgs/msg/Clock", "/gps/fix": "sensor_msgs/msg/NavSatFix",
    "/gps/vel": "geometry_msgs/msg/TwistStamped", "/imu/data": "sensor_msgs/msg/Imu",
    "/wind/apparent": "geometry_msgs/msg/Vector3Stamped", "/sim/odom": "nav_msgs/msg/Odometry",
    "/sim/wind/true": "geometry_msgs/msg/Vector3Stamped",
    "/rudder/command": "std_msgs/msg/Float64", "/sail/command": "std_msgs/msg/Float64"}


@pytest.fixture(scope="module")
def python():
    need_namespace()
    return ros_python()


def client(python, *args, timeout=240):
    """Run tests/ros2_client.py in the namespace; its JSON report."""
    done = in_namespace([python, ROOT / "tests" / "ros2_client.py", *args], timeout=timeout)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def answered(python, tmp_path_factory):
    """Six seconds on a beam reach: the rudder 0, then -0.4 from 2 s; no answer for 1.6 s at 3 s."""
    log = tmp_path_factory.mktemp("ros2") / "run.mcap"
    report = client(python, "answer", "--rudder", "-0.4", "--turn-at", "2", "--pause", "1.6",
                    "--pause-at", "3", "--", "eleven_metre", "--set", "wind_from_deg=90", "--seconds", "6",
                    "--record", log)
    return report, log


def by_topic(report):
    seen = defaultdict(list)
    for message in report["seen"]:
        seen[message["topic"]].append(message)
    return seen


def test_the_bridge_speaks_the_standard_types_in_rep103_frames(answered):
    report, _ = answered
    assert report["returncode"] == 0, report["stderr"]
    for topic, kind in EXPECTED_TYPES.items():
        assert report["types"].get(topic) == [kind], topic
    seen = by_topic(report)
    assert {m["frame_id"] for m in seen["/gps/fix"]} == {"gps"}
    assert {m["frame_id"] for m in seen["/imu/data"]} == {"base_link"}
    assert {(m["frame_id"], m["child_frame_id"]) for m in seen["/sim/odom"]} == {("map", "base_link")}
    # no accelerometer among the instruments: sensor_msgs/Imu's "not given"
    assert {m["acceleration_covariance_0"] for m in seen["/imu/data"]} == {-1.0}
    # at 59.9 N a degree of latitude is 111.4 km: the boat's 6 s stay within a few metres of the origin
    assert all(abs(m["latitude"] - 59.9) < 1e-3 and abs(m["longitude"] - 10.7) < 2e-3
               for m in seen["/gps/fix"])


def test_every_stamp_is_a_clock_tick_and_the_clock_steps_once_per_control_step(answered):
    report, _ = answered
    seen = by_topic(report)
    clocks = sorted({m["stamp"] for m in seen["/clock"]})
    assert clocks == [k * STEP_NS for k in range(61)]  # 0 .. 6 s in 0.1 s, none missing
    for topic in EXPECTED_TYPES:
        if topic in seen:
            assert {m["stamp"] for m in seen[topic]} == set(clocks), topic


def test_lock_step_holds_the_clock_while_no_command_comes_and_resumes_when_one_does(answered):
    report, _ = answered
    clocks = [m for m in report["seen"] if m["topic"] == "/clock"]
    paused = [m for m in clocks if m["stamp"] == 30 * STEP_NS]  # the client went quiet at 3.0 s
    held = paused[-1]["wall"] - paused[0]["wall"]
    assert len(paused) >= 3 and held > 1.0  # resent every 0.5 s while the clock stood at 3.0 s
    later = [m["stamp"] for m in clocks if m["wall"] > paused[-1]["wall"]]
    assert later and min(later) == 31 * STEP_NS and max(later) == 60 * STEP_NS
    assert "60 steps (6.0 s simulated)" in report["stdout"]


def test_a_rudder_command_turns_the_boat_to_its_side(answered):
    """A negative rudder (trailing edge to starboard) turns the bow to starboard: yaw, counted
    counter-clockwise in ENU, decreases."""
    report, _ = answered
    odom = {m["stamp"]: m for m in by_topic(report)["/sim/odom"]}
    at = {t: odom[int(round(t / 0.1)) * STEP_NS] for t in (2.0, 6.0)}
    assert at[6.0]["yaw_rate"] < -0.05
    assert at[6.0]["yaw"] - at[2.0]["yaw"] < -0.1


def test_the_bridges_mcap_log_holds_what_the_topics_carried(answered):
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    report, log = answered
    fixes = {m["stamp"]: m for m in by_topic(report)["/gps/fix"]}
    counts = defaultdict(int)
    with open(log, "rb") as f:
        for _, channel, message, decoded in make_reader(f, decoder_factories=[DecoderFactory()]) \
                .iter_decoded_messages():
            counts[channel.topic] += 1
            if channel.topic == "/gps/fix":
                live = fixes[message.log_time]
                assert (decoded.latitude, decoded.longitude) == (live["latitude"], live["longitude"])
    assert counts == {topic: 61 for topic in EXPECTED_TYPES if "command" not in topic}
    store = get_typestore(Stores.ROS2_JAZZY)
    with Reader(log) as reader:
        odom = [store.deserialize_cdr(raw, c.msgtype) for c, _, raw in reader.messages()
                if c.topic == "/sim/odom"]
    assert len(odom) == 61 and all(math.isfinite(o.pose.pose.position.x) for o in odom)


def test_a_command_topic_of_another_type_is_one_line(python):
    report = client(python, "wrong_type", "--", "eleven_metre", "--seconds", "5", "--timeout", "20")
    assert report["returncode"] == 2
    assert report["stderr"].strip() == ("sailmujoco ros2: topic /rudder/command carries "
                                        "std_msgs/msg/Float32; the bridge's is std_msgs/msg/Float64")


def test_a_remap_file_renames_the_topics(python, tmp_path):
    remap = tmp_path / "topics.toml"
    remap.write_text('[topics]\n"/gps/fix" = "/sensors/gnss/fix"\n"/rudder/command" = "/actuators/rudder"\n')
    names = json.dumps({"/gps/fix": "/sensors/gnss/fix", "/rudder/command": "/actuators/rudder"})
    report = client(python, "answer", "--names", names, "--", "eleven_metre", "--seconds", "1",
                    "--remap", remap)
    assert report["returncode"] == 0, report["stderr"]
    assert report["types"]["/sensors/gnss/fix"] == ["sensor_msgs/msg/NavSatFix"]
    assert report["types"]["/actuators/rudder"] == ["std_msgs/msg/Float64"]
    assert "/gps/fix" not in report["types"] and "/rudder/command" not in report["types"]
    assert "10 steps (1.0 s simulated)" in report["stdout"]


def test_without_rclpy_the_bridge_says_what_to_install_in_one_line():
    """rclpy hidden from the import (None in sys.modules), so no DDS starts even where it is installed."""
    code = ("import sys; sys.modules['rclpy'] = None; from sailmujoco.cli.main import main; "
            "sys.exit(main(['ros2', 'eleven_metre', '--seconds', '1']))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        "sailmujoco ros2: the ROS 2 bridge needs rclpy: pip install 'sailmujoco[ros2]' (Linux x86_64), or "
        "run it where a ROS 2 install is sourced (source /opt/ros/jazzy/setup.bash)"]


def test_an_independent_cyclone_dds_reader_decodes_the_fix_rclpy_sees(python, tmp_path):
    """Cyclone DDS, knowing only the wire names ROS 2 gives the type and the topic, reads the same
    NavSatFix, field for field, that the rclpy client received."""
    script = (f'"$1" {ROOT}/tests/ros2_cyclone_reader.py 12 > {tmp_path}/cyclone.json & '
              f'"$1" {ROOT}/tests/ros2_client.py answer -- eleven_metre --seconds 40 '
              f'> {tmp_path}/rclpy.json; wait')
    done = in_namespace(["sh", "-c", script, "sh", python], timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    cyclone = json.loads((tmp_path / "cyclone.json").read_text())
    report = json.loads((tmp_path / "rclpy.json").read_text().strip().splitlines()[-1])
    assert report["returncode"] == 0, report["stderr"]
    live = {m["stamp"]: m for m in by_topic(report)["/gps/fix"]}
    assert len(cyclone) >= 50  # of the 401 steps, at least 5 s of them
    for sample in cyclone:
        fix = live[sample["stamp"]]
        assert (sample["latitude"], sample["longitude"], sample["frame_id"]) == \
            (fix["latitude"], fix["longitude"], "gps")
        # STATUS_FIX and SERVICE_GPS; the covariance unknown (no receiver error given)
        assert sample["status"] == [0, 1] and sample["covariance_type"] == 0


def test_the_recipes_heading_hold_node_sails_its_course(python):
    """docs/ros2.md's node, lock-step on sim time, in a wind from the east: four legs (a beam
    reach, a broad reach, a gybe onto the other broad reach, a close reach) each held within
    10 deg over its second half, every step answered (125 of the 0.1 s steps in each 12.5 s)."""
    script = ('"$1" -m sailmujoco ros2 eleven_metre --set wind_from_deg=90 --seconds 100 > /dev/null & '
              '"$1" examples/ros2/heading_hold.py --legs 0:25,300:25,210:25,150:25 --json; wait $!')
    done = in_namespace(["sh", "-c", script, "sh", python], timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    legs = json.loads(done.stdout.strip().splitlines()[-1])
    assert [leg["heading_deg"] for leg in legs] == [0, 300, 210, 150]
    for leg in legs:
        assert leg["steps"] == 125 and leg["mean_abs_error_deg"] < 10.0, leg


def test_lock_step_with_no_command_ends_after_its_timeout_and_free_running_needs_none(python):
    waited = client(python, "listen", "--", "eleven_metre", "--seconds", "2", "--timeout", "1")
    assert waited["returncode"] == 0, waited["stderr"]
    assert "0 steps (0.0 s simulated)" in waited["stdout"] and "ended: no command for 1 s" in waited["stdout"]
    # free-running at real time: it starts as it comes up (a node that joins later sees the clock
    # from then on), and runs without a command
    free = client(python, "listen", "--", "eleven_metre", "--seconds", "4", "--rate", "1")
    assert free["returncode"] == 0, free["stderr"]
    assert "40 steps (4.0 s simulated)" in free["stdout"] and "ended: the episode's end" in free["stdout"]
    clocks = [m for m in free["seen"] if m["topic"] == "/clock"]
    assert len(clocks) >= 10 and clocks[-1]["stamp"] == 40 * STEP_NS
    # paced, not faster than real time: the bridge's own wall time at least the 4 s it simulated
    wall = float(re.search(r"simulated\) in ([0-9.]+) s", free["stdout"]).group(1))
    assert wall >= 4.0


def test_a_second_bridge_on_the_same_domain_is_one_line_and_the_first_sails_on(python, tmp_path):
    """The ROS analogue of a port in use: a clock already published on the domain. The first
    bridge waits (lock-step, no commands) until the second has been refused, then is stopped."""
    script = (f'"$1" -m sailmujoco ros2 eleven_metre --seconds 5 --timeout 120 > {tmp_path}/first.txt & '
              f'first=$!; until grep -q publishing {tmp_path}/first.txt; do sleep 0.2; done; '
              f'"$1" -m sailmujoco ros2 eleven_metre --seconds 5 2> {tmp_path}/second.err; '
              f'echo $? > {tmp_path}/second.rc; kill -TERM $first; wait $first; '
              f'echo $? > {tmp_path}/first.rc')
    done = in_namespace(["sh", "-c", script, "sh", python], timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert (tmp_path / "second.rc").read_text().strip() == "2"
    assert (tmp_path / "second.err").read_text().strip().splitlines() == [
        "sailmujoco ros2: another node already publishes /clock on ROS_DOMAIN_ID 42 "
        "(a bridge still running?): stop it, or give this one another ROS_DOMAIN_ID"]
    assert (tmp_path / "first.rc").read_text().strip() == "0"
    assert "ended: terminated" in (tmp_path / "first.txt").read_text()
