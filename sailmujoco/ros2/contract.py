"""The bridge's contract with a ROS 2 stack: its topics, their types, and what each carries.

Published once per control step, stamped with the simulation's time (the fields from
:mod:`sailmujoco.ros2.messages`; the MCAP log writes the same):

* ``/clock`` (rosgraph_msgs/Clock): the simulation's time; a node with ``use_sim_time`` runs on it.
* ``/gps/fix`` (sensor_msgs/NavSatFix, frame ``gps``): the GNSS position as fitted, WGS84 about
  the stated origin.
* ``/gps/vel`` (geometry_msgs/TwistStamped, frame ``map``, ENU): its velocity over ground.
* ``/imu/data`` (sensor_msgs/Imu, frame ``base_link``): the orientation from the compass and the
  heel sensor as fitted (the pitch is the true one: the instruments have no pitch sensor), the
  gyro's roll and yaw rates (the pitch rate the true one); no linear acceleration (its
  covariance's first element -1, sensor_msgs/Imu's "not given").
* ``/wind/apparent`` (geometry_msgs/Vector3Stamped, frame ``base_link``): the masthead unit's
  reading, the air's velocity past the boat.
* ``/sim/odom`` (nav_msgs/Odometry, frame ``map``, child ``base_link``): the true pose (ENU) and
  the true velocity in the body frame (REP-105's convention for a twist). Ground truth: under
  ``/sim``, apart from what the instruments give.
* ``/sim/wind/true`` (geometry_msgs/Vector3Stamped, frame ``map``): the true wind at the sail
  (east, north), where it blows to.

A course task (:mod:`sailmujoco.tasks.course`) adds its references (:data:`REFERENCES`), each
as ``/course/<key>`` (geometry_msgs/PointStamped, frame ``map``, ENU, m): the leg's
``last_mark`` and ``next_mark``, station keeping's ``box_center``, area scanning's
``area_center`` (:func:`course_topics`).

Subscribed (:data:`COMMANDS`): ``/rudder/command`` and ``/sail/command`` (std_msgs/Float64),
radians, the package's signs: a positive angle swings the trailing edge to port (a positive
rudder turns the boat to port; a positive sail angle is the boom to port, the leeward side with
the wind from starboard).

A team whose topics differ renames them in a remap file (:func:`read_remap`)::

    [topics]
    "/gps/fix" = "/sensors/gnss/fix"
    "/rudder/command" = "/actuators/rudder"
"""

from __future__ import annotations

import re

from ..frames import quat_from_euler, yaw_from_heading
from ..tomlfile import read_toml
from . import messages
from .geodesy import Origin

TOPICS = {
    "/clock": "rosgraph_msgs/msg/Clock",
    "/gps/fix": "sensor_msgs/msg/NavSatFix",
    "/gps/vel": "geometry_msgs/msg/TwistStamped",
    "/imu/data": "sensor_msgs/msg/Imu",
    "/wind/apparent": "geometry_msgs/msg/Vector3Stamped",
    "/sim/odom": "nav_msgs/msg/Odometry",
    "/sim/wind/true": "geometry_msgs/msg/Vector3Stamped",
}
"""Published topic -> its ROS 2 message type."""
REFERENCES = ("last_mark", "next_mark", "box_center", "area_center")
"""A course task's references (observation keys, (east, north) m), published as ``/course/<key>``."""
POINT = "geometry_msgs/msg/PointStamped"
COMMANDS = {"/rudder/command": "std_msgs/msg/Float64", "/sail/command": "std_msgs/msg/Float64"}
"""Subscribed topic -> its ROS 2 message type: the action's rudder and sail angles, rad, in order."""
DEFAULT_ORIGIN = Origin(latitude=59.9, longitude=10.7)  # the Oslo fjord, where the 11:Metre class sails

# ROS 2's rules for a fully qualified topic name (design.ros2.org, "Topic and Service name
# mapping to DDS"): tokens of letters, digits and underscores, not starting with a digit, joined
# by single slashes, no trailing slash, no double underscore.
_TOKEN = r"[A-Za-z_][A-Za-z0-9_]*"
_NAME = re.compile(rf"^/{_TOKEN}(/{_TOKEN})*$")


def check_topic_name(name, what: str) -> str:
    """``name``, refused in one line unless it is a fully qualified ROS 2 topic name.

    Parameters
    ----------
    name : object
        The name.
    what : str
        Where it was given, for the message.
    """
    if not isinstance(name, str) or not _NAME.match(name) or "__" in name:
        raise ValueError(f"{what} must be a ROS 2 topic name such as '/gps/fix' (a leading slash, "
                         f"letters, digits and underscores between single slashes), got {name!r}")
    return name


def read_remap(path) -> dict:
    """The topic names of a remap file: each default topic -> the name it goes by.

    The file is TOML with one table, ``[topics]``, keyed by the default names
    (:data:`TOPICS`, :data:`COMMANDS`); topics it leaves out keep their names. Anything else is
    refused in one line: a key that is no topic of the contract, a name that is no ROS 2 topic
    name, two topics given one name.

    Parameters
    ----------
    path : str or os.PathLike
        The remap file.

    Returns
    -------
    dict
        Every topic of the contract -> its name.
    """
    data = read_toml(path, "remap file")
    where = f"remap file {str(path)!r}"
    extra = sorted(set(data) - {"topics"})
    if extra:
        raise ValueError(f"{where}: unknown table or key {extra[0]!r}; the file has one table, [topics]")
    table = data.get("topics", {})
    if not isinstance(table, dict):
        raise ValueError(f"{where}: topics must be a table, [topics], of default name = new name")
    known = {**TOPICS, **COMMANDS}
    for key in table:
        if key not in known:
            raise ValueError(f"{where}: {key!r} is not a topic of the bridge; the topics are "
                             f"{', '.join(known)}")
    names = {topic: check_topic_name(table.get(topic, topic), f"{where}: the name of {topic!r}")
             for topic in known}
    seen = {}
    for topic, name in names.items():
        if name in seen:
            raise ValueError(f"{where}: {seen[name]!r} and {topic!r} are both named {name!r}")
        seen[name] = topic
    return names


def course_topics(keys) -> dict:
    """``/course/<key>`` -> geometry_msgs/PointStamped for each of :data:`REFERENCES` in ``keys``.

    Parameters
    ----------
    keys : iterable of str
        A task's observation keys (its observation spec's, or an observation's).
    """
    keys = set(keys)
    return {f"/course/{key}": POINT for key in REFERENCES if key in keys}


def step_row(observation: dict, position) -> dict:
    """The values a step's messages carry: the instruments' and the truth's, SI, ENU, and under
    ``course`` a course task's references (:data:`REFERENCES`, [east, north] m).

    Parameters
    ----------
    observation : dict
        A TimeStep's observation (with its ``true_state``).
    position : array_like, shape (3,)
        The true position of CO in the world (east, north, up), m.
    """
    ts = observation["true_state"]
    course = {key: [float(observation[key][0]), float(observation[key][1])]
              for key in REFERENCES if key in observation}
    return {**({"course": course} if course else {}), "t": float(ts["time"]), "true_x": float(position[0]),
            "true_y": float(position[1]), "true_z": float(position[2]),
            "x": float(observation["position"][0]), "y": float(observation["position"][1]),
            "vel_e": float(observation["velocity"][0]), "vel_n": float(observation["velocity"][1]),
            "heading": float(observation["heading"]), "heel": float(observation["heel"]),
            "roll_rate": float(observation["roll_rate"]), "yaw_rate": float(observation["yaw_rate"]),
            "awa": float(observation["apparent_wind_angle"]),
            "aws": float(observation["apparent_wind_speed"]),
            "true_yaw": float(ts["yaw"]), "true_heel": float(ts["heel"]), "true_pitch": float(ts["pitch"]),
            "true_pitch_rate": float(ts["pitch_rate"]), "true_roll_rate": float(ts["roll_rate"]),
            "true_yaw_rate": float(ts["yaw_rate"]), "u": float(ts["u"]), "v": float(ts["v"]),
            "w": float(ts["w"]), "true_wind_e": float(ts["true_wind"][0]),
            "true_wind_n": float(ts["true_wind"][1])}


def topic_fields(row: dict, origin: Origin, stamp: int) -> dict:
    """Each topic's fields for one step (the headers' frame under ``frame_id``).

    Parameters
    ----------
    row : dict
        The step's values (:func:`step_row`).
    origin : Origin
        Where the world's origin lies on the WGS84 ellipsoid.
    stamp : int
        The simulation's time, ns (the ``/clock`` message's).

    Returns
    -------
    dict
        Topic (:data:`TOPICS`, and a course's :func:`course_topics`) -> its message's fields.
    """
    measured = quat_from_euler(row["heel"], row["true_pitch"], yaw_from_heading(row["heading"]))
    true = quat_from_euler(row["true_heel"], row["true_pitch"], row["true_yaw"])
    imu = messages.imu(measured, (row["roll_rate"], row["true_pitch_rate"], row["yaw_rate"]), None)
    fix = messages.nav_sat_fix((row["x"], row["y"], 0.0), origin)
    odom = messages.odometry((row["true_x"], row["true_y"], row["true_z"]), true,
                             (row["u"], row["v"], row["w"]),
                             (row["true_roll_rate"], row["true_pitch_rate"], row["true_yaw_rate"]))
    course = {f"/course/{key}": {"frame_id": "map", "point": messages.vector3((x, y, 0.0))}
              for key, (x, y) in row.get("course", {}).items()}
    return {"/clock": {"clock": messages.time(stamp)}, "/gps/fix": {"frame_id": "gps", **fix},
            "/gps/vel": {"frame_id": "map", "twist": messages.twist_enu((row["vel_e"], row["vel_n"], 0.0))},
            "/imu/data": {"frame_id": "base_link", **imu},
            "/wind/apparent": {"frame_id": "base_link",
                               "vector": messages.apparent_wind(row["awa"], row["aws"])},
            "/sim/odom": {"frame_id": "map", "child_frame_id": "base_link", **odom},
            "/sim/wind/true": {"frame_id": "map",
                               "vector": messages.vector3((row["true_wind_e"], row["true_wind_n"], 0.0))},
            **course}
