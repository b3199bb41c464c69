"""The boat as a ROS 2 node (rclpy): its instruments published, its commands read, on sim time.

:class:`Bridge` runs one episode of an environment. At every control step it publishes the
topics of :data:`~sailmujoco.ros2.contract.TOPICS` (``/clock`` first, so a node on
``use_sim_time`` has the step's time when its data come), then takes the action from the last
``/rudder/command`` and ``/sail/command`` (std_msgs/Float64, rad, clipped to the servos' range).

Two ways to keep time:

* **lock-step** (the default): the step waits until a command has come on each command topic
  since the step was published; the simulation's clock stands still meanwhile. While it waits it
  publishes the step's messages again every :data:`RESEND` s of wall time (the same stamps), so a
  node that starts after the bridge is not left waiting for data that went before it subscribed.
  A node that answers one of those twice sends a stale pair the next step takes; only a node
  slower than :data:`RESEND` s does. With no command for ``timeout`` s the run ends (as
  ``sailmujoco sitl`` ends when ArduPilot stops).

* **free-running** (``rate``): the steps are paced at ``rate`` times real time and take the
  latest commands whenever they came (zero until the first).

Before it publishes, the bridge looks on its domain for :data:`DISCOVERY` s: another node that
already publishes the clock (a bridge still running) is refused in one line, as a taken port is.

rclpy is imported only here, when a bridge starts: ``pip install 'sailmujoco[ros2]'`` (the
PyPI build of Jazzy's rclpy) or a sourced ROS 2 install gives it.
"""

from __future__ import annotations

import importlib
import math
import time
from dataclasses import dataclass

import numpy as np

from .contract import COMMANDS, DEFAULT_ORIGIN, TOPICS, course_topics, step_row, topic_fields
from .geodesy import Origin

INSTALL = ("the ROS 2 bridge needs rclpy: pip install 'sailmujoco[ros2]' (Linux x86_64), or run it "
           "where a ROS 2 install is sourced (source /opt/ros/jazzy/setup.bash)")
RESEND = 0.5
"""Seconds of wall time between the lock-step's resends of a step's messages."""
GRAPH_CHECK = 1.0
"""Seconds of wall time between checks of the command topics' types on the ROS graph."""
DISCOVERY = 3.0
"""Seconds of wall time the bridge looks for another clock on its domain before it starts."""
PROGRESS = 60.0
"""Simulated seconds between progress lines."""


class RclpyMissing(RuntimeError):
    """rclpy cannot be imported; the message says what to install (:data:`INSTALL`)."""


class BridgeError(RuntimeError):
    """The bridge cannot go on: ROS 2 did not start, or a topic carries another type (one line)."""


def require_rclpy():
    """rclpy, its executor and its QoS profile; :class:`RclpyMissing` (one line) without it."""
    try:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.qos import QoSProfile
    except ImportError:
        raise RclpyMissing(INSTALL) from None
    return rclpy, SingleThreadedExecutor, QoSProfile


def message_class(kind: str):
    """rclpy's class of a message type named ``package/msg/Name``.

    Parameters
    ----------
    kind : str
        The type, e.g. ``"sensor_msgs/msg/Imu"``.
    """
    package, _, name = kind.split("/")
    return getattr(importlib.import_module(f"{package}.msg"), name)


def fill(message, fields: dict, stamp):
    """``message`` with ``fields`` set (nested mappings into nested messages); a ``frame_id``
    key is the header's, which is stamped ``stamp`` (builtin_interfaces/Time).

    Parameters
    ----------
    message : object
        An rclpy message.
    fields : dict
        Its fields (:func:`sailmujoco.ros2.contract.topic_fields`).
    stamp : builtin_interfaces.msg.Time
        The header's stamp.
    """
    for name, value in fields.items():
        if name == "frame_id":
            message.header.frame_id = value
            message.header.stamp = stamp
        elif isinstance(value, dict):
            fill(getattr(message, name), value, stamp)
        else:
            setattr(message, name, value)
    return message


@dataclass
class Counters:
    """What a bridge's run did.

    Parameters
    ----------
    steps : int
        Control steps taken.
    simulated : float
        Simulated seconds.
    wall : float
        Wall seconds from the first publication to the end.
    resent : int
        Times a step's messages were published again while the lock-step waited.
    refused : int
        Commands refused (not a finite number); the last good one held.
    ended : str
        Why the run ended.
    """

    steps: int = 0
    simulated: float = 0.0
    wall: float = 0.0
    resent: int = 0
    refused: int = 0
    ended: str = ""

    @property
    def speed(self) -> float:
        """Simulated seconds per wall second."""
        return self.simulated / self.wall if self.wall > 0 else math.nan


class Bridge:
    """One episode of ``env`` as a ROS 2 node.

    Parameters
    ----------
    env : SailEnvironment
        The environment (:func:`sailmujoco.suite.load`): its boat, task, sea and instruments.
    origin : Origin
        Where the world's origin lies on the WGS84 ellipsoid.
    names : dict, optional
        Each topic of the contract -> the name it goes by (:func:`~sailmujoco.ros2.contract.
        read_remap`); default the contract's own names.
    rate : float, optional
        Free-running at ``rate`` times real time; None: lock-step.
    timeout : float
        Lock-step: wall seconds without a command that end the run.
    record : callable, optional
        A rollout ``record`` (:class:`~sailmujoco.ros2.record.McapLog`) called with each step;
        the row it returns is published.
    say : callable
        Where the progress lines go (``print``).
    """

    def __init__(self, env, *, origin: Origin = DEFAULT_ORIGIN, names: dict | None = None,
                 rate: float | None = None, timeout: float = 30.0, record=None, say=print):
        self.env, self.origin, self.rate, self.timeout = env, origin, rate, timeout
        self.names = {topic: topic for topic in {**TOPICS, **COMMANDS}} if names is None else dict(names)
        self.topics = {**TOPICS, **course_topics(env.observation_spec())}  # published: name -> type
        for topic in self.topics:
            self.names.setdefault(topic, topic)
        self.record, self.say = record, say
        self.counters = Counters()
        spec = env.action_spec()
        self._low, self._high = np.asarray(spec.minimum, float), np.asarray(spec.maximum, float)
        self.command = np.zeros(len(COMMANDS))
        self._fresh: set = set()

    def run(self) -> Counters:
        """Sail the episode; what it did (also :attr:`counters` if it is interrupted).

        Raises
        ------
        RclpyMissing
            rclpy cannot be imported.
        BridgeError
            ROS 2 did not start, or a topic of the contract carries another type.
        """
        rclpy, executor_class, qos = require_rclpy()
        context = rclpy.Context()
        try:
            rclpy.init(context=context)
            self.node = rclpy.create_node("sailmujoco", context=context)
        except Exception as err:  # rclpy's own errors (an RCLError, a bad ROS_DOMAIN_ID) say what is wrong
            raise BridgeError(f"ROS 2 did not start: {str(err).splitlines()[0]}") from None
        try:
            self.executor = executor_class(context=context)
            self.executor.add_node(self.node)
            self._check_alone()
            self._publishers = {topic: self.node.create_publisher(message_class(kind), self.names[topic],
                                                                  qos(depth=10))
                                for topic, kind in self.topics.items()}
            for index, (topic, kind) in enumerate(COMMANDS.items()):
                self.node.create_subscription(message_class(kind), self.names[topic],
                                              self._on_command(topic, index), qos(depth=10))
            names = self.names
            self.say(f"ros2: on ROS_DOMAIN_ID {self.node.context.get_domain_id()}, publishing "
                     f"{names['/clock']}, {names['/imu/data']}, {names['/gps/fix']}, ...; reading "
                     f"{names['/rudder/command']} and {names['/sail/command']}")
            self._sail()
        finally:
            self.node.destroy_node()
            rclpy.try_shutdown(context=context)
        return self.counters

    def _on_command(self, topic: str, index: int):
        def take(message):
            value = float(message.data)
            if not math.isfinite(value):
                self.counters.refused += 1
                return
            self.command[index] = value
            self._fresh.add(topic)

        return take

    def _sail(self) -> None:
        env, counters = self.env, self.counters
        self._check_graph()
        self._checked = time.perf_counter()
        timestep = env.reset()
        self._start = time.perf_counter()
        self._publish(0, timestep, None)
        next_progress = PROGRESS
        while not timestep.last():
            if self.rate is None:
                if not self._await_commands():
                    counters.ended = f"no command for {self.timeout:g} s"
                    break
            else:
                self._pace()
            action = np.clip(self.command, self._low, self._high)
            timestep = env.step(action)
            counters.steps += 1
            self._publish(counters.steps, timestep, action)
            if counters.simulated >= next_progress:
                self.say(f"ros2: t = {counters.simulated:.0f} s, {counters.speed:.1f} times real time")
                next_progress += PROGRESS
        counters.ended = counters.ended or "the episode's end"

    def _publish(self, step: int, timestep, action) -> None:
        observation = timestep.observation
        row = (self.record(step, timestep, action) if self.record is not None
               else step_row(observation, self.env.physics.position()))
        stamp = int(round(row["t"] * 1e9))
        self._messages = [(self._publishers[topic], fill(message_class(self.topics[topic])(), fields,
                                                         self._stamp(stamp)))
                          for topic, fields in topic_fields(row, self.origin, stamp).items()]
        self._send()
        self.counters.simulated = row["t"]
        self.counters.wall = time.perf_counter() - self._start

    def _stamp(self, stamp: int):
        from builtin_interfaces.msg import Time

        return Time(sec=stamp // 10**9, nanosec=stamp % 10**9)

    def _send(self) -> None:
        self._fresh.clear()
        for publisher, message in self._messages:
            publisher.publish(message)

    def _await_commands(self) -> bool:
        """Wait for a command on each command topic; False after ``timeout`` s without one."""
        start = last = checked = time.perf_counter()
        while len(self._fresh) < len(COMMANDS):
            self.executor.spin_once(timeout_sec=RESEND / 5)
            now = time.perf_counter()
            if now - start > self.timeout:
                return False
            if now - checked > GRAPH_CHECK:
                self._check_graph()
                checked = now
            if now - last > RESEND and len(self._fresh) < len(COMMANDS):
                self._send_again()
                last = now
        return True

    def _send_again(self) -> None:
        fresh = set(self._fresh)
        self._send()
        self._fresh |= fresh
        self.counters.resent += 1

    def _pace(self) -> None:
        """Free-running: hold the step until the time it reaches is due at ``rate`` times real time,
        reading commands meanwhile."""
        due = self._start + (self.counters.simulated + self.env.control_timestep()) / self.rate
        while True:
            self.executor.spin_once(timeout_sec=max(0.0, min(due - time.perf_counter(), GRAPH_CHECK)))
            now = time.perf_counter()
            if now - self._checked > GRAPH_CHECK:
                self._check_graph()
                self._checked = now
            if now >= due:
                return

    def _check_graph(self) -> None:
        """A topic of the contract that someone publishes or reads with another type: one line."""
        wanted = {self.names[topic]: kind for topic, kind in {**self.topics, **COMMANDS}.items()}
        for name, kinds in self.node.get_topic_names_and_types():
            other = [kind for kind in kinds if name in wanted and kind != wanted[name]]
            if other:
                raise BridgeError(f"topic {name} carries {other[0]}; the bridge's is {wanted[name]}")

    def _check_alone(self) -> None:
        """Another node that already publishes the clock on this domain (a bridge left running, the
        ROS analogue of a port in use): one line, before this one publishes anything."""
        clock = self.names["/clock"]
        end = time.perf_counter() + DISCOVERY
        while time.perf_counter() < end:
            self.executor.spin_once(timeout_sec=0.1)
            if self.node.count_publishers(clock):
                domain = self.node.context.get_domain_id()
                raise BridgeError(f"another node already publishes {clock} on ROS_DOMAIN_ID {domain} "
                                  f"(a bridge still running?): stop it, or give this one another "
                                  f"ROS_DOMAIN_ID")
