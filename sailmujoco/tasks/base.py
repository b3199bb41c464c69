"""The task layer: dm_control-style tasks that run on any world (MuJoCo 6-DOF or a paper world).

A *world* meets :class:`sailmujoco.tasks.world.World`: ``step``, ``time``, ``timestep``,
``set_control``, ``place``, ``action_bounds``, ``stop_reason``, and ``truth``, its true state,
which :mod:`sailmujoco.measurement.observation` turns into the observation and the task's
record (:func:`~sailmujoco.measurement.observation.observation_and_record`).
MuJoCo boats are :class:`sailmujoco.physics.BoatPhysics`; the papers' reduced models are
wrapped by :class:`~sailmujoco.tasks.world.PaperPhysics` and
:class:`~sailmujoco.tasks.world.VielPhysics` so that ``dm_control.rl.control.Environment`` can
drive them.

Every task here documents its observation and action (unit, frame), splits its reward into
named terms (``reward_terms``; the reward is their sum) and keeps metrics over the episode.

Ending early never pays
    An episode that ends before its time limit (capsize, non-finite state; in the Gymnasium
    adapter also leaving the sailing area or the observation's bounds) earns, on its last step,
    the single term ``stopped`` = ``steps * (floor - 1)``: ``steps`` is that step and every
    step the episode had left, ``floor`` the task's :meth:`SailTask.reward_floor`, the least
    reward one step can earn while the episode runs. Sailing on would have earned at least
    ``steps * floor`` over the same steps, so a stop, however late, is worth less than any way
    of sailing on: an agent cannot learn to capsize its way out of a bad episode.

Observation
    The world's measurement (:mod:`sailmujoco.measurement.observation`) plus the task's
    references; its ``true_state`` is a :class:`sailmujoco.measurement.observation.TrueState`
    (a dict that flattens as one array, so ``dm_control.rl.control.flatten_observation`` and
    ``flat_observation=True`` work), or left out with ``include_true_state=False``. The reward
    reads the whole measurement either way.
"""

from __future__ import annotations

import math
from collections import OrderedDict

import numpy as np
from dm_control.rl import control
from dm_env import specs

from .. import frames
from ..actuation.servo import fitted_servos
from ..boat.fitted import actuator_options, sensor_options
from ..errors import check_number
from ..measurement.instruments import Instruments
from ..measurement.observation import TrueState, observation_and_record, observe, record
from .world import World


class SailTask(control.Task):
    """Base task. Subclasses set ``name``, ``duration`` and override the hooks below.

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-state randomisation (and, through :meth:`wind`, the gusts).
    heading_jitter_deg : float
        Half-width of the uniform random perturbation of the initial heading.
    include_true_state : bool
        Hand out the privileged ``true_state`` (force wrenches, the true wind, ...) in the
        observation. The full-state controllers of the papers read it, so the suite keeps it
        by default; the Gymnasium adapter leaves it out by default.
    sensors : str, dict or SensorOptions, optional
        The boat's instruments (:mod:`sailmujoco.boat.fitted`): ``"perfect"`` (the default,
        unless the boat has its own: every reading the true value), ``"typical"``, or a dict of figures over a
        preset. With any but perfect, the observation's measured keys are the instruments'
        readings, and ``speed_through_water`` and ``true_wind_estimate`` join them; the truth
        stays in ``true_state``.
    actuators : str, dict or ActuatorOptions, optional
        The boat's actuators (:mod:`sailmujoco.boat.fitted`): ``"perfect"`` (the default, unless
        the boat has its own: the command reaches the world's servo unchanged), ``"typical"``
        (rate limit, deadband, backlash and resolution in front of it), or a dict of figures over
        a preset.
    """

    name = "task"
    duration = 60.0  # s, default episode length

    def __init__(self, seed: int | None = None, heading_jitter_deg: float = 5.0,
                 include_true_state: bool = True, sensors=None, actuators=None):
        if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer))
                                 or seed < 0):
            raise ValueError(f"seed must be None or an integer >= 0, got {seed!r}")
        check_number("heading_jitter_deg", heading_jitter_deg, 0.0, 180.0)
        if not isinstance(include_true_state, bool):
            raise ValueError(f"include_true_state must be True or False, got {include_true_state!r}")
        self.include_true_state = include_true_state
        self.last_reward_terms: dict = {}
        self.seed = seed
        self.random = np.random.default_rng(seed)
        self.heading_jitter = math.radians(heading_jitter_deg)
        self.stopped = None
        self.last_observation = None  # the last observation handed out (the instruments' readings)
        self.last_true_observation = None  # ... and the same state's true observation
        self._measured = None  # (time, observation, record, true observation) of the state: measurement()
        self._records: list[dict] = []
        self.sensors = sensor_options(sensors)
        self.control_period = 0.1  # s, set by the environment (suite.load): the instruments' sample period
        self._episodes = 0
        self._instruments = None
        self.actuators = actuator_options(actuators)
        self._servos = None

    # ---- hooks for subclasses
    def wind(self):
        """The WindConfig this task sails in (seeded from the task's seed)."""
        raise NotImplementedError

    def initial_heading(self) -> float:
        """Compass heading (rad) the boat starts on, before the random jitter."""
        return 0.0

    def initial_speed(self) -> float:
        return 0.0

    def references(self, physics) -> dict:
        """Task references added to the observation (e.g. ``desired_heading``).

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        return {}

    def reward_terms(self, physics, observation) -> dict:
        """The reward's named terms; the reward is their sum.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        observation : dict
            The observation of this state (the world's measurement plus the task's references).
        """
        raise NotImplementedError

    def reward_floor(self, physics) -> float | None:
        """The least reward one step can earn while the episode runs (the sum of each term's
        least value), or None if the task does not know it (a stop then earns 0).

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        return None

    def summarise(self, records: list[dict]) -> dict:
        """Metrics from the per-step records.

        Parameters
        ----------
        records : list of dict
            The per-step records of the episode (:meth:`record`), in time order.
        """
        return {}

    # ---- control.Task API
    def initialize_episode(self, physics):
        """Place the boat at the origin on the initial heading (jittered) and speed; clear the records.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        heading = self.initial_heading() + self.random.uniform(-self.heading_jitter, self.heading_jitter)
        physics.place((0.0, 0.0), float(frames.yaw_from_heading(heading)), self.initial_speed())
        self.stopped = None
        self._records = []
        self.last_observation = self.last_true_observation = None
        self.last_reward_terms = {}
        self._measured = None
        self._floor = self.reward_floor(physics)
        self._instruments = self._new_instruments()  # each episode its own noise
        if not self.actuators.perfect:
            self._servos = fitted_servos(self.actuators, *action_bounds(physics), self.control_period,
                                         sheeted=getattr(physics, "sail_mode", "actuated") == "sheeted")
        self._episodes += 1

    def _new_instruments(self) -> Instruments | None:
        """The instruments of the episode about to start, on streams of their own (the task's
        other streams untouched); None for perfect sensors."""
        if self.sensors.perfect:
            return None
        return Instruments(self.sensors, self.control_period, self.seed, self._episodes)

    def before_step(self, action, physics):
        """Check the action and set it on the world's actuators.

        Parameters
        ----------
        action : array_like, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)]; both finite.
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        self._measured = None
        action = np.asarray(action, dtype=float)
        if action.shape != (2,) or not (math.isfinite(action[0]) and math.isfinite(action[1])):
            raise ValueError(f"{self.name}: action must be 2 finite numbers [rudder, sail], got {action}")
        if self._servos is not None:  # the fitted servos between the command and the world's
            rudder, sail, winch = self._servos
            command = sail.step(float(action[1]))
            if winch is not None:  # the sheet hauled in only as fast as the winch's torque allows
                command = winch.step(command, physics.sheet_tension())
            action = np.array([rudder.step(float(action[0])), command])
        physics.set_control(action)

    def measures_truth(self) -> bool:
        """Whether the observation is the world's truth through the built-in measurement, with
        nothing between a command and the world: perfect instruments and actuators, the
        ``true_state`` handed out, no measurement added at run time. A compiled closed loop
        (:mod:`sailmujoco.loop`) writes out only that path."""
        from ..measurement.observation import builtin_tables

        return (self.sensors.perfect and self.actuators.perfect and self._servos is None
                and self._instruments is None and self.include_true_state and builtin_tables())

    def add_records(self, records) -> None:
        """Append the per-step records of steps a compiled closed loop took (:meth:`record`'s).

        Parameters
        ----------
        records : iterable of dict
            The records, in step order.
        """
        self._records.extend(records)
        self._measured = None

    def after_step(self, physics):
        """Append this step's :meth:`record`.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        self._records.append(self.record(physics))

    def record(self, physics) -> dict:
        """What ``summarise`` needs from one step (our frames, SI).

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        return dict(self.measurement(physics)[1])

    def action_spec(self, physics):
        """Two commands: the rudder angle [rad], then the sail angle [rad] (actuated sail) or,
        with ``sail_mode="sheeted"``, the sheet length [m]; the spec's name says which.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        low, high = action_bounds(physics)
        return specs.BoundedArray((2,), np.float64, low, high, name=action_name(physics))

    def measurement(self, physics: World) -> tuple[dict, dict]:
        """(observation with the task's references, record) of the current state:
        :func:`~sailmujoco.measurement.observation.observation_and_record` of the world.

        dm_control asks for the record (after_step), the reward and the observation of one
        state in turn: it is measured once and handed to all three; get_observation hands it
        out, and the next request (or a step) measures afresh.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        measured = self._measured
        if measured is not None and measured[0] == physics.time():
            return measured[1], measured[2]  # nothing moved since
        if self._instruments is None:  # asked before any episode (a spec): this episode's set
            self._instruments = self._new_instruments()
        if self._instruments is None:
            obs, row = observation_and_record(physics)
            true_obs = obs
        else:  # the instruments read the truth; the reward and the record (metrics) stay the truth's
            truth = physics.truth()
            true_obs, row = observe(truth), record(truth)
            obs = dict(true_obs)
            for key, value in self._instruments.read(truth).items():
                obs[key] = np.asarray(value, dtype=np.float64)
        for key, value in self.references(physics).items():
            obs[key] = true_obs[key] = np.asarray(value, dtype=np.float64)
        self._measured = (physics.time(), obs, row, true_obs)
        return obs, row

    def get_observation(self, physics):
        """The observation of the current state (see :meth:`measurement`).

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        obs = self.measurement(physics)[0]
        self.last_true_observation = self._measured[3]  # the same state, as the truth has it
        self._measured = None
        self.last_observation = obs
        return self.observation_of(obs)

    def observation_of(self, measured: dict) -> dict:
        """The observation handed out for a measurement: its ``true_state`` as a
        :class:`~sailmujoco.measurement.observation.TrueState`, or without it (``include_true_state=False``).

        Parameters
        ----------
        measured : dict
            A measurement with the task's references (:meth:`measurement`).
        """
        obs = type(measured)(measured)
        if not self.include_true_state:
            obs.pop("true_state", None)
        elif "true_state" in obs:
            obs["true_state"] = TrueState(obs["true_state"])
        return obs

    def observation_spec(self, physics):
        """Array specs with the shapes of the current observation.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        return _spec_of(self.get_observation(physics))

    def get_reward(self, physics):
        # dm_control asks for the reward before the observation: the same measurement serves
        # both (see measurement)
        """The sum of :meth:`reward_terms` for the current state.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        observation = self.measurement(physics)[0]
        self.last_observation = observation
        # the reward is the true boat's (with instruments, the observation is what they read)
        self.last_reward_terms = self.reward_terms(physics, self._measured[3])
        return float(sum(self.last_reward_terms.values()))

    def stop_reward(self, steps: int) -> float:
        """The reward of a step that ends the episode early: the term ``stopped`` =
        ``steps * (floor - 1)``, with ``floor`` the :meth:`reward_floor` (0 without one).

        Parameters
        ----------
        steps : int
            That step and the steps the episode had left.
        """
        floor = getattr(self, "_floor", None)
        self.last_reward_terms = {"stopped": 0.0 if floor is None else steps * (floor - 1.0)}
        return float(sum(self.last_reward_terms.values()))

    def get_termination(self, physics):
        """0.0 (discount) once the world has stopped (capsize, non-finite state), else None.

        Parameters
        ----------
        physics : World
            The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
        """
        if getattr(physics, "stop_reason", None):
            return 0.0
        return None

    def metrics(self) -> dict:
        out = self.summarise(self._records) if self._records else {}
        out["stopped"] = self.stopped
        out["duration"] = self._records[-1]["t"] if self._records else 0.0
        return out


def action_name(physics) -> str:
    """The action's fields with their units: "rudder_rad,sail_rad" or "rudder_rad,sheet_m".

    Parameters
    ----------
    physics : World
        The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
    """
    names = getattr(physics, "actuator_names", None) or ["rudder", "sail"]
    return ",".join(("sheet_m" if name == "sheet" else f"{name}_rad") for name in names)


def action_bounds(physics):
    """(low, high) of [rudder, sail] for any world (its ``action_bounds``).

    Parameters
    ----------
    physics : World
        The world the task runs on (:class:`~sailmujoco.tasks.world.World`).
    """
    return physics.action_bounds()


def _spec_of(observation):
    out = OrderedDict()
    for key, value in observation.items():
        if isinstance(value, dict):
            out[key] = _spec_of(value)
        else:
            out[key] = specs.Array(np.shape(value), np.float64, name=key)
    return out


def wrap(angle: float) -> float:
    """An angle wrapped to [-pi, pi), as a float.

    Parameters
    ----------
    angle : float
        Angle, rad.
    """
    return float(frames.wrap_angle(angle))


def amplitude(values) -> float:
    """Half the peak-to-peak of a signal.

    Parameters
    ----------
    values : array_like
        The signal's samples.
    """
    values = np.asarray(values, dtype=float)
    return float(0.5 * (values.max() - values.min())) if values.size else float("nan")
