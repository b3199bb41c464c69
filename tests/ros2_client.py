"""The other side of the ROS 2 bridge in the tests: an rclpy node that starts ``sailmujoco ros2``,
answers it, and prints what it saw as one JSON line.

Run by tests/test_ros2_bridge.py with the Python of tests/ros2_support.py, inside a loopback
network namespace only::

    python tests/ros2_client.py SCENARIO OUT_DIR [bridge arguments ...]

Scenarios: ``answer`` (answer every step: the rudder 0 until ``--turn-at`` s, then
``--rudder``; the sail ``--sail``; stop answering for ``--pause`` s of wall time at
``--pause-at`` s of sim time), ``listen`` (subscribe, never answer), ``wrong_type`` (publish
std_msgs/Float32 on the rudder's topic).
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import time

import rclpy
from geometry_msgs.msg import TwistStamped, Vector3Stamped
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu, NavSatFix
from std_msgs.msg import Float32, Float64

SUBSCRIBED = {"/clock": Clock, "/gps/fix": NavSatFix, "/gps/vel": TwistStamped, "/imu/data": Imu,
              "/wind/apparent": Vector3Stamped, "/sim/odom": Odometry, "/sim/wind/true": Vector3Stamped}


def stamp_of(message) -> int:
    t = message.clock if isinstance(message, Clock) else message.header.stamp
    return t.sec * 10**9 + t.nanosec


def values_of(message) -> dict:
    """The few fields the tests check, per message type."""
    if isinstance(message, NavSatFix):
        return {"latitude": message.latitude, "longitude": message.longitude, "altitude": message.altitude,
                "frame_id": message.header.frame_id}
    if isinstance(message, Odometry):
        q = message.pose.pose.orientation
        return {"yaw": math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)),
                "yaw_rate": message.twist.twist.angular.z, "x": message.pose.pose.position.x,
                "y": message.pose.pose.position.y, "frame_id": message.header.frame_id,
                "child_frame_id": message.child_frame_id}
    if isinstance(message, Imu):
        return {"frame_id": message.header.frame_id,
                "acceleration_covariance_0": float(message.linear_acceleration_covariance[0])}
    return {}


class Client:
    """Subscribes to the bridge's topics (names remapped by ``names``) and answers each step."""

    def __init__(self, node, names: dict, args):
        self.node, self.args = node, args
        self.seen, self.pending, self.answered = [], {}, set()
        self.pause_until = None
        self.rudder = node.create_publisher(Float64, names.get("/rudder/command", "/rudder/command"), 10)
        self.sail = node.create_publisher(Float64, names.get("/sail/command", "/sail/command"), 10)
        for topic, kind in SUBSCRIBED.items():
            node.create_subscription(kind, names.get(topic, topic), self._take(topic), 10)

    def _take(self, topic):
        def take(message):
            stamp = stamp_of(message)
            self.seen.append({"topic": topic, "stamp": stamp, "wall": time.perf_counter(),
                              **values_of(message)})
            got = self.pending.setdefault(stamp, set())
            got.add(topic)
            if len(got) == len(SUBSCRIBED):
                self.answer(stamp)

        return take

    def answer(self, stamp: int) -> None:
        if self.args.scenario == "listen":
            return
        t = stamp * 1e-9
        if self.args.pause and self.pause_until is None and t >= self.args.pause_at:
            self.pause_until = time.perf_counter() + self.args.pause
        if self.pause_until is not None and time.perf_counter() < self.pause_until:
            return
        rudder = self.args.rudder if t >= self.args.turn_at else 0.0
        self.rudder.publish(Float64(data=rudder))
        self.sail.publish(Float64(data=self.args.sail))
        self.answered.add(stamp)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("scenario", choices=("answer", "listen", "wrong_type"))
    parser.add_argument("--names", default="{}", help="JSON: default topic -> its name")
    parser.add_argument("--rudder", type=float, default=0.0)
    parser.add_argument("--sail", type=float, default=0.6)
    parser.add_argument("--turn-at", type=float, default=0.0)
    parser.add_argument("--pause", type=float, default=0.0)
    parser.add_argument("--pause-at", type=float, default=0.0)
    parser.add_argument("--wall", type=float, default=60.0, help="give up after this many seconds")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    bridge_args = argv[split + 1:]  # after --: sailmujoco ros2's arguments
    rclpy.init()
    node = rclpy.create_node("bridge_test_client")
    bridge = subprocess.Popen([sys.executable, "-m", "sailmujoco", "ros2", *bridge_args],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    client = wrong = None
    if args.scenario in ("answer", "listen"):
        client = Client(node, json.loads(args.names), args)
    else:
        wrong = node.create_publisher(Float32, "/rudder/command", 10)
    start = time.perf_counter()
    types = {}
    while bridge.poll() is None and time.perf_counter() - start < args.wall:
        rclpy.spin_once(node, timeout_sec=0.05)
        if wrong is not None:
            wrong.publish(Float32(data=0.1))
        types.update({name: kinds for name, kinds in node.get_topic_names_and_types()})
    if bridge.poll() is None:
        bridge.terminate()
    out, err = bridge.communicate(timeout=30)
    node.destroy_node()
    rclpy.try_shutdown()
    print(json.dumps({"returncode": bridge.returncode, "stdout": out, "stderr": err, "types": types,
                      "seen": client.seen if client else [],
                      "answered": sorted(client.answered) if client else []}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
