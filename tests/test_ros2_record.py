"""A run's MCAP log read back with ROS 2's own MCAP decoder and with rosbags equals the run's table."""

import math
import sys

import numpy as np
import pytest
from mcap import reader as mcap_reader  # the test extra installs mcap and mcap-ros2-support
from mcap_ros2 import decoder as mcap_ros2_decoder
from sailmujoco.controllers.factories import fixed_sail

from sailmujoco import suite
from sailmujoco.frames import apparent_wind_angle
from sailmujoco.ros2 import geodesy
from sailmujoco.ros2.record import DEFAULT_ORIGIN, INSTALL, TOPICS, McapLog


@pytest.fixture(scope="module")
def logged(tmp_path_factory):
    path = tmp_path_factory.mktemp("mcap") / "run.mcap"
    env = suite.load("eleven_metre", "heading_hold", seed=2, sensors="typical", time_limit=8.0)
    with McapLog(env, path) as log:
        table = suite.rollout(env, fixed_sail(env, sail_deg=25.0), record=log)
    decoded = {}
    with open(path, "rb") as f:
        reader = mcap_reader.make_reader(f, decoder_factories=[mcap_ros2_decoder.DecoderFactory()])
        for schema, channel, message, value in reader.iter_decoded_messages():
            assert schema.encoding == "ros2msg" and schema.name == TOPICS[channel.topic]
            decoded.setdefault(channel.topic, []).append((message.log_time, value))
    return path, table, decoded, log.messages


def test_every_topic_has_one_message_per_control_step(logged):
    _, table, decoded, count = logged
    assert set(decoded) == set(TOPICS)
    assert all(len(messages) == len(table) for messages in decoded.values())
    assert count == len(TOPICS) * len(table)
    stamps = [m.clock.sec * 10**9 + m.clock.nanosec for _, m in decoded["/clock"]]
    assert stamps == [round(t * 1e9) for t in table["t"]]


def test_the_messages_carry_the_tables_values_to_the_bit(logged):
    _, table, decoded, _ = logged
    imu = [m for _, m in decoded["/imu/data"]]
    assert [m.angular_velocity.x for m in imu] == table["roll_rate"].tolist()
    assert [m.angular_velocity.z for m in imu] == table["yaw_rate"].tolist()
    assert all(m.linear_acceleration_covariance[0] == -1.0 for m in imu)  # not measured
    vel = [m.twist.linear for _, m in decoded["/gps/vel"]]
    assert [v.x for v in vel] == table["vel_e"].tolist() and [v.y for v in vel] == table["vel_n"].tolist()
    odom = [m for _, m in decoded["/sim/odom"]]
    assert [o.pose.pose.position.x for o in odom] == table["true_x"].tolist()
    assert [o.twist.twist.linear.x for o in odom] == table["u"].tolist()
    assert {o.header.frame_id for o in odom} == {"map"} and {o.child_frame_id for o in odom} == {"base_link"}


def test_the_fix_and_the_wind_read_back_as_the_instruments_measured(logged):
    _, table, decoded, _ = logged
    for (_, fix), (_, wind), (_, r) in zip(decoded["/gps/fix"], decoded["/wind/apparent"], table.iterrows(),
                                           strict=True):
        enu = geodesy.enu_from_geodetic(fix.latitude, fix.longitude, fix.altitude, DEFAULT_ORIGIN)
        assert enu == pytest.approx((r["x"], r["y"], 0.0), abs=1e-6)
        vector = (wind.vector.x, wind.vector.y, wind.vector.z)
        assert math.hypot(*vector) == pytest.approx(r["aws"], rel=1e-12)
        assert apparent_wind_angle(vector) == pytest.approx(r["awa"], abs=1e-12)
    # typical instruments: the fix is the receiver's, not the truth
    assert not np.allclose(table["x"], table["true_x"], atol=1e-3)


def test_rosbags_reads_the_same_messages(logged):
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    path, table, decoded, _ = logged
    store = get_typestore(Stores.ROS2_JAZZY)
    with Reader(path) as reader:
        imu = [store.deserialize_cdr(raw, connection.msgtype) for connection, _, raw in reader.messages()
               if connection.topic == "/imu/data"]
    assert [m.orientation.w for m in imu] == [m.orientation.w for _, m in decoded["/imu/data"]]
    assert len(imu) == len(table)


def test_without_rosbags_the_log_says_what_to_install(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "rosbags.typesys", None)
    env = suite.load("eleven_metre", "heading_hold", seed=0)
    with pytest.raises(RuntimeError, match=r"^the MCAP log needs rosbags: pip install 'sailmujoco\[ros2\]'$"):
        McapLog(env, tmp_path / "run.mcap")
    assert INSTALL.startswith("the MCAP log needs rosbags")


def test_a_log_path_that_is_not_mcap_is_one_line(tmp_path):
    env = suite.load("eleven_metre", "heading_hold", seed=0)
    with pytest.raises(ValueError, match=r"^the MCAP log's path must end in \.mcap, got '.*run\.bag'$"):
        McapLog(env, tmp_path / "run.bag")


def test_a_sitl_runs_log_holds_its_trajectory_table_stamped_with_sitls_clock(tmp_path):
    """``sailmujoco sitl --record``: the backend's rows, 10 a simulated second, as messages; the
    apparent wind is the vane's reading, the pose the truth."""
    from sailmujoco.sitl.backend import JsonBackend
    from sailmujoco.sitl.protocol import servo_packet

    path = tmp_path / "sitl.mcap"
    log = McapLog(None, path)
    backend = JsonBackend("saoud_robot", wind_speed=5.0, wind_from_deg=90.0, sensors="typical", mcap=log)
    for k in range(200):  # 200 frames of the robot's 2.5 ms: 0.5 s
        backend.handle(servo_packet([1500] * 16, 400, k))
    log.close()
    table = backend.trajectory()
    decoded = {}
    with open(path, "rb") as f:
        reader = mcap_reader.make_reader(f, decoder_factories=[mcap_ros2_decoder.DecoderFactory()])
        for _, channel, message, value in reader.iter_decoded_messages():
            decoded.setdefault(channel.topic, []).append((message.log_time, value))
    assert set(decoded) == set(TOPICS)
    assert [t for t, _ in decoded["/clock"]] == [round(t * 1e9) for t in table["t"]]
    odom = [m for _, m in decoded["/sim/odom"]]
    assert [o.pose.pose.position.x for o in odom] == table["x"].tolist()
    wind = [m.vector for _, m in decoded["/wind/apparent"]]
    assert [math.degrees(apparent_wind_angle((v.x, v.y, v.z))) for v in wind] == \
        pytest.approx(table["vane_deg"].tolist(), abs=1e-9)


def test_a_course_tasks_marks_are_logged_and_published_as_points_in_the_map_frame(tmp_path):
    """The race's legs on /course/last_mark and /course/next_mark: the start (0, 0) and the
    windward mark 100 m up a wind from 90 deg, i.e. (100, 0) east, as laid by hand."""
    from sailmujoco.controllers.factories import line_following

    from sailmujoco.ros2.node import Bridge

    path = tmp_path / "race.mcap"
    env = suite.load("viel_boat", "upwind_downwind", seed=0, time_limit=2.0, wind_from_deg=90.0)
    point = "geometry_msgs/msg/PointStamped"
    assert {k: v for k, v in Bridge(env).topics.items() if k.startswith("/course")} == {
        "/course/last_mark": point, "/course/next_mark": point}
    with McapLog(env, path) as log:
        table = suite.rollout(env, line_following(env), record=log)
    points = {}
    with open(path, "rb") as f:
        reader = mcap_reader.make_reader(f, decoder_factories=[mcap_ros2_decoder.DecoderFactory()])
        for schema, channel, _, value in reader.iter_decoded_messages(topics=["/course/last_mark",
                                                                             "/course/next_mark"]):
            assert schema.name == "geometry_msgs/msg/PointStamped" and value.header.frame_id == "map"
            points.setdefault(channel.topic, set()).add((value.point.x, value.point.y, value.point.z))
    assert len(table) == 21
    assert points["/course/last_mark"] == {(0.0, 0.0, 0.0)}
    next_mark = points["/course/next_mark"].pop()
    assert next_mark == pytest.approx((100.0, 0.0, 0.0), abs=1e-9) and not points["/course/next_mark"]
