"""The world a task runs on: one protocol, met by the MuJoCo boat and both paper worlds.

A task (:class:`sailmujoco.tasks.base.SailTask`) never asks what kind of world it drives: it
places the boat, sets the control, steps, and reads the world's true state (``truth()``), which
:mod:`sailmujoco.measurement.observation` turns into the observation. Three worlds meet
:class:`World`:

* :class:`sailmujoco.physics.BoatPhysics`, the 6-DOF (or 4-DOF) MuJoCo boat;
* :class:`PaperPhysics` around :class:`sailmujoco.reference.wille.Wille4DOF`, Wille's 4-DOF
  equations (the Wille and Saoud tasks' paper world);
* :class:`VielPhysics` around :class:`sailmujoco.reference.viel.VielWorld`, Viel's 3-DOF model
  (position keeping's paper world).

The two adapters give the paper worlds dm_control's Physics methods (``reset``,
``after_reset``, ``copy``, ``reset_context``) so that ``dm_control.rl.control.Environment`` can
drive them. A world of your own needs the methods of :class:`World` (and those of
dm_control's Physics if it runs in a :class:`~sailmujoco.tasks.environment.SailEnvironment`).
"""

from __future__ import annotations

import copy
import math
from typing import Protocol, runtime_checkable

import numpy as np
from dm_control.rl import control

from ..errors import SimulationStopped
from ..measurement.observation import Truth, observation_and_record, observe


@runtime_checkable
class World(Protocol):
    """What a task reads and drives (our frames: world x east, y north; body FLU; SI).

    Attributes
    ----------
    stop_reason : str or None
        Why the simulation stopped (capsized, non-finite state), None while it runs.
    """

    stop_reason: str | None

    def step(self, n_sub_steps: int = 1) -> None:
        """Advance ``n_sub_steps`` physics sub-steps holding the control.

        Parameters
        ----------
        n_sub_steps : int
            Sub-steps of :meth:`timestep` seconds each.
        """

    def time(self) -> float:
        """Simulated time, s."""

    def timestep(self) -> float:
        """The physics sub-step, s."""

    def set_control(self, control) -> None:
        """Set the commands [rudder, sail] held over the next step.

        Parameters
        ----------
        control : array_like
            Two finite numbers: rudder angle (rad), then sail angle (rad) or sheet length (m).
        """

    def place(self, position=(0.0, 0.0), yaw: float = 0.0, surge: float = 0.0) -> None:
        """Put the boat upright at ``position`` heading ``yaw``, moving ahead at ``surge``.

        Parameters
        ----------
        position : tuple of float
            World (east, north) position, m.
        yaw : float
            ENU yaw, rad, counter-clockwise from east.
        surge : float
            Speed ahead, m/s.
        """

    def action_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(low, high) of the commands [rudder, sail]."""

    def truth(self) -> Truth:
        """The world's true state now; :mod:`sailmujoco.measurement.observation` makes the
        observation (:func:`~sailmujoco.measurement.observation.observe`) and the task's record
        (:func:`~sailmujoco.measurement.observation.record`) from it.

        Returns
        -------
        Truth
            The world's true state.
        """

    def diagnostic_record(self) -> dict:
        """The assumption study's per-step diagnostics (empty where the world has none).

        Returns
        -------
        dict
            See :meth:`sailmujoco.measurement.accessors.BoatAccessors.diagnostic_record`.
        """


class PaperPhysics(control.Physics):
    """A paper world (reduced ODE model) behind dm_control's Physics interface.

    Parameters
    ----------
    world : sailmujoco.reference.wille.Wille4DOF
        The paper world; its named accessors are reached through this object too.
    """

    def __init__(self, world):
        self.world = world

    def truth(self) -> Truth:
        """The world's true state now (:meth:`World.truth`)."""
        return self.world.truth()

    def measure(self) -> tuple[dict, dict]:
        """(observation, record) of the world now
        (:func:`~sailmujoco.measurement.observation.observation_and_record`)."""
        return observation_and_record(self)

    def diagnostic_record(self) -> dict:
        """The world's diagnostics (:meth:`World.diagnostic_record`)."""
        return self.world.diagnostic_record()

    def step(self, n_sub_steps=1):
        """Advance ``n_sub_steps`` sub-steps holding the control.

        Parameters
        ----------
        n_sub_steps : int
            Sub-steps of :meth:`timestep` seconds each.
        """
        self.world.step(n_sub_steps)

    def time(self):
        """Simulated time, s."""
        return self.world.time()

    def timestep(self):
        """The world's base time step, s."""
        return self.world.timestep()

    def set_control(self, control):
        """Set the commands [rudder, sail], rad, held over the next step.

        Parameters
        ----------
        control : array_like
            Two finite numbers.
        """
        self.world.set_control(control)

    def reset(self):
        """Reset the world to its home state."""
        self.world.reset()

    def after_reset(self):
        """Nothing to bring up to date after a reset (dm_control's hook)."""

    def copy(self, share_model=False):
        """An independent copy in the same state (as ``BoatPhysics.copy``).

        Parameters
        ----------
        share_model : bool
            Ignored: a paper world holds no model to share.
        """
        return copy.deepcopy(self)

    def __getattr__(self, name):  # the named accessors of the world
        if name == "world":
            raise AttributeError(name)
        return getattr(self.world, name)


class VielPhysics:
    """Viel's 3-DOF world with the accessors and the dm_control Physics methods the tasks use.

    Heel, pitch and their rates are zero.

    Parameters
    ----------
    world : sailmujoco.reference.viel.VielWorld
        The world.
    timestep : float
        The sub-step, s: the action may change only at its multiples.
    """

    legacy_step = False

    def __init__(self, world, timestep: float = 0.05):
        self.world = world
        self._dt = timestep
        self._control = np.zeros(2)
        self.stop_reason = None

    @classmethod
    def for_control(cls, world, control_timestep: float, longest: float = 0.05) -> VielPhysics:
        """The world stepped at the largest sub-step <= ``longest`` that divides the control period.

        dm_control needs a whole number of sub-steps; the world integrates in steps of at most
        0.01 s inside each, so the sub-step only sets where the action may change.

        Parameters
        ----------
        world : sailmujoco.reference.viel.VielWorld
            The world.
        control_timestep : float
            The control period, s.
        longest : float
            The longest sub-step, s.
        """
        return cls(world, timestep=control_timestep / math.ceil(control_timestep / longest))

    # dm_control Physics
    def step(self, n_sub_steps=1):
        """Advance ``n_sub_steps`` sub-steps holding the control.

        Parameters
        ----------
        n_sub_steps : int
            Sub-steps of :meth:`timestep` seconds each.
        """
        if self.stop_reason:
            raise SimulationStopped(self.stop_reason, self.world.time)
        try:
            self.world.step(self._control, n_sub_steps * self._dt)
        except (FloatingPointError, ValueError) as err:
            self.stop_reason = f"non-finite state ({err})"
            raise SimulationStopped(self.stop_reason, self.world.time) from None

    def time(self):
        """Simulated time, s."""
        return self.world.time

    def closed_loop_ready(self) -> bool:
        """Whether a compiled closed loop can step this world (:mod:`sailmujoco.loop.worlds`):
        the world's own say (:meth:`sailmujoco.reference.viel.VielWorld.loop_ready`), not stopped."""
        ready = getattr(self.world, "loop_ready", None)
        return ready is not None and ready() and not self.stop_reason

    def closed_loop_arguments(self, n_sub_steps: int, seconds: float) -> tuple:
        """:meth:`sailmujoco.reference.viel.VielWorld.loop_arguments` for a control step of
        ``n_sub_steps`` sub-steps (as :meth:`step` holds the control over them).

        Parameters
        ----------
        n_sub_steps : int
            Sub-steps per control step.
        seconds : float
            The time the loop may cover, s.
        """
        return self.world.loop_arguments(n_sub_steps * self._dt, seconds)

    def closed_loop_ended(self, state, time: float, action, command) -> None:
        """Take the state a compiled closed loop reached.

        Parameters
        ----------
        state : numpy.ndarray, shape (6,)
            Viel's state.
        time : float
            Time, s.
        action : numpy.ndarray, shape (2,)
            The world's applied (saturated) action, ours, rad.
        command : numpy.ndarray, shape (2,)
            The command it was last given (``set_control``'s), ours, rad.
        """
        self.world.loop_ended(state, time, action)
        self._control = np.array(command, dtype=np.float64)

    def timestep(self):
        """The sub-step, s."""
        return self._dt

    def set_control(self, control):
        """Set the commands [rudder, sail], rad, held over the next step.

        Parameters
        ----------
        control : array_like
            Two finite numbers.
        """
        control = np.asarray(control, dtype=float)
        if control.shape != (2,) or not np.isfinite(control).all():
            raise ValueError(f"control must be 2 finite numbers [rudder, sail] (rad), got {control}")
        self._control = control.copy()

    def reset(self):
        """Reset the world, the command and the stop."""
        self.world.reset()
        self._control = np.zeros(2)
        self.stop_reason = None

    def after_reset(self):
        """Nothing to bring up to date after a reset (dm_control's hook)."""

    def copy(self, share_model=False):
        """An independent copy in the same state.

        Parameters
        ----------
        share_model : bool
            Ignored: a paper world holds no model to share.
        """
        return copy.deepcopy(self)

    def reset_context(self):
        """dm_control's reset context (Physics.reset_context), for Environment.reset."""
        return control.Physics.reset_context(self)

    def action_bounds(self):
        """(low, high) of [rudder, sail], rad (Viel's saturations)."""
        p = self.world.params
        high = np.array([p.rudder_max, p.sail_max])
        return -high, high

    def place(self, position=(0.0, 0.0), yaw: float = 0.0, surge: float = 0.0):
        """Put the boat at ``position`` heading ``yaw``, moving ahead at ``surge``.

        Parameters
        ----------
        position : tuple of float
            World (east, north) position, m.
        yaw : float
            Viel's theta (ENU yaw), rad.
        surge : float
            Speed ahead, m/s.
        """
        self.world.reset(state=[position[0], position[1], yaw, surge, 0.0, 0.0])

    # what the tasks read
    def truth(self) -> Truth:
        """The world's true state now (:meth:`World.truth`,
        :meth:`sailmujoco.reference.viel.VielWorld.truth`)."""
        return self.world.truth()

    def measure(self) -> tuple[dict, dict]:
        """(observation, record) of the world now
        (:func:`~sailmujoco.measurement.observation.observation_and_record`)."""
        return observation_and_record(self)

    def observation(self) -> dict:
        """The observation of the world now (:func:`~sailmujoco.measurement.observation.observe`)."""
        return observe(self.truth())

    def diagnostic_record(self) -> dict:
        """None for Viel's 3-DOF world (:meth:`World.diagnostic_record`): an empty dict."""
        return {}

    def position(self):
        """World position (east, north, 0), m."""
        return np.array([*self.world.position(), 0.0])

    def heading(self):
        """Compass heading, rad."""
        return self.world.heading()

    def heel(self):
        """Heel, rad: zero in Viel's model."""
        return 0.0

    def body_velocity(self):
        """(u, v, w) in FLU, m/s."""
        return np.array([self.world.forward_speed(), self.world.sway_speed(), 0.0])

    def angular_velocity(self):
        """(p, q, r) in FLU, rad/s."""
        return np.array([0.0, 0.0, self.world.yaw_rate()])

    def ground_velocity(self):
        """World (east, north) velocity, m/s."""
        return self.world.velocity()

    def course(self):
        """Course over ground, ENU, rad."""
        ve, vn = self.world.velocity()
        return float(math.atan2(vn, ve))

    def speed_over_ground(self):
        """Speed over ground, m/s."""
        return math.hypot(*self.world.velocity())
