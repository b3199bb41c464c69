"""A ROS 2 heading-hold node that sails a course of legs against ``sailmujoco ros2``.

It reads the bridge's ``/imu/data`` (the heading, from the compass and heel sensor as fitted,
and the yaw rate) and ``/wind/apparent`` (the masthead unit), and publishes
``/rudder/command`` and ``/sail/command`` (std_msgs/Float64, rad) once per step: a PD law on
the heading error for the rudder, and the sail at half the apparent wind angle to leeward. It
runs on sim time (``use_sim_time``): each leg of the course is held for its simulated seconds.

    python examples/ros2/heading_hold.py --legs 0:60,300:60,210:60,150:60

The signs are the bridge's (docs/ros2.md): a positive rudder turns the boat to port, a positive
sail angle is the boom to port, the leeward side with the wind from starboard. When the course
is sailed it prints each leg's heading error over the leg's second half, and exits.
"""

from __future__ import annotations

import argparse
import json
import math
import sys

import rclpy
from geometry_msgs.msg import Vector3Stamped
from rclpy.node import Node
from rclpy.parameter import Parameter
from sensor_msgs.msg import Imu
from std_msgs.msg import Float64


def wrap(angle: float) -> float:
    """The angle in [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def heading_of(q) -> float:
    """Compass heading (rad, clockwise from north) of an ENU orientation (REP-103)."""
    yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
    return (math.pi / 2.0 - yaw) % (2.0 * math.pi)


class HeadingHold(Node):
    """Steer each leg's heading for its seconds; the sail to leeward at half the wind's angle."""

    def __init__(self, legs, kp: float, kd: float, max_rudder: float):
        super().__init__("heading_hold", parameter_overrides=[Parameter("use_sim_time", value=True)])
        self.legs, self.kp, self.kd, self.max_rudder = legs, kp, kd, max_rudder
        self.ends = [sum(seconds for _, seconds in legs[:i + 1]) for i in range(len(legs))]
        self.rudder = self.create_publisher(Float64, "/rudder/command", 10)
        self.sail = self.create_publisher(Float64, "/sail/command", 10)
        self.create_subscription(Imu, "/imu/data", self.on_imu, 10)
        self.create_subscription(Vector3Stamped, "/wind/apparent", self.on_wind, 10)
        self.imu = None
        self.errors = [[] for _ in legs]
        self.done = False

    def on_imu(self, message: Imu) -> None:
        self.imu = message

    def on_wind(self, message: Vector3Stamped) -> None:
        """The step's data are in (the bridge publishes the IMU before the wind): answer."""
        if self.imu is None or self.imu.header.stamp != message.header.stamp:
            return
        t = message.header.stamp.sec + 1e-9 * message.header.stamp.nanosec
        leg = next((i for i, end in enumerate(self.ends) if t < end), None)
        if leg is None:
            self.done = True
            return
        start = self.ends[leg] - self.legs[leg][1]
        desired = math.radians(self.legs[leg][0])
        error = wrap(heading_of(self.imu.orientation) - desired)
        if t >= start + self.legs[leg][1] / 2.0:
            self.errors[leg].append(error)
        heading_rate = -self.imu.angular_velocity.z  # FLU's z turns counter-clockwise, the heading clockwise
        rudder = max(-self.max_rudder, min(self.max_rudder, self.kp * error + self.kd * heading_rate))
        awa = math.atan2(message.vector.y, -message.vector.x)  # from starboard positive
        sail = math.copysign(min(max(abs(awa) / 2.0, 0.1), 1.3), awa)
        self.rudder.publish(Float64(data=rudder))
        self.sail.publish(Float64(data=sail))

    def summary(self) -> list[dict]:
        """Each leg's heading and its error over the leg's second half, deg."""
        return [{"heading_deg": heading, "steps": len(errors),
                 "mean_abs_error_deg": (math.degrees(sum(map(abs, errors)) / len(errors))
                                        if errors else math.nan)}
                for (heading, _), errors in zip(self.legs, self.errors, strict=True)]


def legs_of(text: str) -> list[tuple[float, float]]:
    """``HEADING:SECONDS,...`` as [(heading_deg, seconds)]."""
    try:
        legs = [(float(h), float(s)) for h, s in (part.split(":") for part in text.split(","))]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected HEADING:SECONDS,..., e.g. 60:60,120:60, "
                                         f"got {text!r}") from None
    if any(not (seconds > 0) for _, seconds in legs):
        raise argparse.ArgumentTypeError(f"each leg's seconds must be positive, got {text!r}")
    return legs


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--legs", type=legs_of, default=legs_of("0:60,300:60,210:60,150:60"),
                        help="HEADING:SECONDS,... compass degrees and simulated seconds")
    parser.add_argument("--kp", type=float, default=1.0, help="rudder per radian of heading error")
    parser.add_argument("--kd", type=float, default=2.0, help="rudder per rad/s of heading rate")
    parser.add_argument("--max-rudder", type=float, default=0.5, help="rudder limit, rad")
    parser.add_argument("--json", action="store_true", help="print the summary as one JSON line")
    args = parser.parse_args(argv)
    rclpy.init()
    node = HeadingHold(args.legs, args.kp, args.kd, args.max_rudder)
    try:
        while rclpy.ok() and not node.done:
            rclpy.spin_once(node, timeout_sec=1.0)
    except KeyboardInterrupt:
        return 130
    finally:
        summary = node.summary()
        node.destroy_node()
        rclpy.try_shutdown()
    for i, leg in enumerate(summary):
        print(f"leg {i + 1}: heading {leg['heading_deg']:g} deg, mean |error| over its second half "
              f"{leg['mean_abs_error_deg']:.1f} deg ({leg['steps']} steps)")
    if args.json:
        print(json.dumps(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
