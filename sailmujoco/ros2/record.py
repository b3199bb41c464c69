"""Every run as an MCAP log: what the boat's instruments measure and its truth, as ROS 2 messages.

:class:`McapLog` is a ``record`` of :func:`sailmujoco.suite.rollout`: at every control step it
writes the topics of :data:`TOPICS` in ROS 2's CDR encoding, each with its message definition
embedded (so ``ros2 bag play``, Foxglove, PlotJuggler and Rerun open the file, and
``mcap-ros2-support`` and ``rosbags`` read it back), and hands the rollout its row: the values it
wrote. The messages' fields come from :mod:`sailmujoco.ros2.messages`; the writer is rosbags'
(its typestore for the ROS 2 distribution, its MCAP storage), installed by
``pip install 'sailmujoco[ros2]'``.

What each topic carries, its frame and its signs: :mod:`sailmujoco.ros2.contract`.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import numpy as np

from . import messages
from .contract import DEFAULT_ORIGIN, TOPICS, course_topics, step_row, topic_fields
from .geodesy import Origin

__all__ = ["DEFAULT_ORIGIN", "DISTROS", "INSTALL", "TOPICS", "McapLog", "RosbagsMissing", "check_log_path"]

DISTROS = ("humble", "jazzy")
INSTALL = "the MCAP log needs rosbags: pip install 'sailmujoco[ros2]'"


def check_log_path(path, what: str = "the MCAP log's path") -> Path:
    """``path`` as a Path, refused in one line unless its name ends in ``.mcap``.

    Parameters
    ----------
    path : str or os.PathLike
        The log's file.
    what : str
        What the message calls it (a CLI option's name, for one).
    """
    if Path(path).suffix != ".mcap":
        raise ValueError(f"{what} must end in .mcap, got {str(path)!r}")
    return Path(path)


class RosbagsMissing(RuntimeError):
    """rosbags is not installed; the message says what to install (:data:`INSTALL`)."""


def _typestore(distro: str):
    """rosbags' typestore of a ROS 2 distribution; one line where rosbags is missing."""
    if distro not in DISTROS:
        raise ValueError(f"distro must be one of {', '.join(map(repr, DISTROS))}, got {distro!r}")
    try:
        from rosbags.typesys import Stores, get_typestore
    except ImportError:
        raise RosbagsMissing(INSTALL) from None
    return get_typestore(Stores.ROS2_HUMBLE if distro == "humble" else Stores.ROS2_JAZZY)


class McapLog:
    """A rollout's ``record`` that writes every control step to an MCAP file.

    Use it as a context manager (the file is complete when it closes)::

        with McapLog(env, "run.mcap") as log:
            table = suite.rollout(env, controller, record=log)

    Parameters
    ----------
    env : SailEnvironment or None
        The environment the rollout runs (its physics gives the true position); None where the
        rows come from elsewhere, handed to :meth:`write` (``sailmujoco sitl --record``).
    path : str or os.PathLike
        The MCAP file written (replaced if it exists).
    origin : Origin
        Where the world's origin lies on the WGS84 ellipsoid (:data:`DEFAULT_ORIGIN`).
    distro : {"humble", "jazzy"}
        The ROS 2 distribution whose message definitions are embedded.
    """

    def __init__(self, env, path, origin: Origin = DEFAULT_ORIGIN, distro: str = "jazzy"):
        self.env = env
        self.path = check_log_path(path)
        self.origin = origin
        self._store = _typestore(distro)
        from rosbags.rosbag2 import StoragePlugin, Writer

        self._folder = Path(tempfile.mkdtemp(prefix="sailmujoco-mcap-"))
        self._writer = Writer(self._folder / self.path.stem, version=9, storage_plugin=StoragePlugin.MCAP)
        self._writer.open()
        self.topics = {**TOPICS, **(course_topics(env.observation_spec()) if env is not None else {})}
        self._connections = {topic: self._writer.add_connection(topic, kind, typestore=self._store)
                             for topic, kind in self.topics.items()}
        self.messages = 0

    def __enter__(self) -> McapLog:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        """Finish the file and move it to ``path``."""
        if self._writer is None:
            return
        self._writer.close()
        self._writer = None
        self.path.parent.mkdir(parents=True, exist_ok=True)
        shutil.move(str(next(self._folder.rglob("*.mcap"))), self.path)
        shutil.rmtree(self._folder, ignore_errors=True)

    def __call__(self, step, timestep, action) -> dict:
        """Write this step's messages; the row of the values written.

        Parameters
        ----------
        step : int
            The rollout's step (0: the reset).
        timestep : dm_env.TimeStep
            Its TimeStep (the observation with its ``true_state``).
        action : numpy.ndarray or None
            The action that led to it (None at the reset).
        """
        row = step_row(timestep.observation, self.env.physics.position())
        self.write(row)
        return row

    def write(self, row: dict) -> None:
        """Write one step's messages, stamped with its time ``row["t"]``.

        Parameters
        ----------
        row : dict
            The step's values (:func:`sailmujoco.ros2.contract.step_row`).
        """
        stamp = int(round(row["t"] * 1e9))
        for topic, fields in topic_fields(row, self.origin, stamp).items():
            kind = self.topics[topic]
            raw = self._store.serialize_cdr(self._message(kind, fields, stamp), kind)
            self._writer.write(self._connections[topic], stamp, raw)
            self.messages += 1

    def _message(self, kind: str, fields: dict, stamp: int):
        """rosbags' message of type ``kind`` filled from ``fields`` (a header stamped ``stamp``)."""
        types = self._store.types
        cls = types[kind]
        values = {}
        for name, field in cls.__dataclass_fields__.items():
            if name.startswith("__") or name.isupper():
                continue  # rosbags' class attributes and the message's constants
            if name == "header":
                time = types["builtin_interfaces/msg/Time"](**messages.time(stamp))
                values[name] = types["std_msgs/msg/Header"](stamp=time, frame_id=fields["frame_id"])
                continue
            value = fields[name]
            if isinstance(value, dict):
                values[name] = self._message(field.type.replace("__msg__", "/msg/"), value, stamp)
            elif isinstance(value, list):
                values[name] = np.array(value, dtype=np.float64)
            else:
                values[name] = value
        return cls(**values)
