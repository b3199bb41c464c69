"""What every controller is, and the observation it reads.

A controller is a plain object::

    controller.reset(seed=None)              # clear internal state (integrators, filters)
    action = controller(timestep)            # dm_env.TimeStep -> np.ndarray action

``timestep.observation`` is a dict of float arrays, SI units, the frames of
:mod:`sailmujoco.frames` (world ENU, body FLU; angles in radians):

=========================  ===================================================================
key                        meaning
=========================  ===================================================================
``position``               (2,) GPS position of CO, x east, y north [m]
``velocity``               (2,) GPS ground velocity, east, north [m/s]
``heading``                compass heading, clockwise from north [rad] (= Wille's psi)
``heel``                   heel phi, positive starboard down [rad]
``roll_rate``              p, about body x [rad/s]
``yaw_rate``               r, about body z (up): positive turning to port [rad/s]
                           (Wille's FRD r is ``-yaw_rate``)
``apparent_wind_angle``    at the masthead, positive when the wind comes from starboard [rad]
``apparent_wind_speed``    at the masthead, in the body x-y plane [m/s]
``true_state``             dict of what full-state controllers need (below)
task references            e.g. ``desired_heading``, ``desired_course``, ``target_position``
=========================  ===================================================================

``true_state``: ``u``, ``v``, ``w`` body velocity of CO over ground, ``u_r``, ``v_r``
relative to the water [m/s]; ``yaw`` (ENU, ccw from east), ``heel``, ``pitch``, ``roll_rate``,
``pitch_rate``, ``yaw_rate``; ``rudder`` and ``sail`` actual angles [rad]; ``true_wind`` (2,)
world wind velocity at the sail CE (where it blows to) [m/s]; ``wind_speed_10`` mean wind at
10 m [m/s] and ``wind_direction`` (compass, where it comes from, mean + wander) [rad];
``apparent_wind_ce`` (2,) air velocity relative to the sail CE, body x-y [m/s]; ``current``
(2,) world current [m/s]; ``sail_wrench``, ``keel_wrench``, ``rudder_wrench``,
``damping_wrench``, ``added_mass_wrench``, ``restoring_wrench`` (6,) body wrenches about CO
[N, N m]; ``time`` [s].

The action is ``np.array([rudder, sail])`` in radians, positive when the trailing edge swings
to port (Wille's sign; a positive rudder turns the boat to port), or ``[rudder, sheet]`` with
the sheet length in metres for a sheeted sail.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np


class Controller(Protocol):
    """What a controller is: ``reset(seed)`` and ``controller(timestep) -> action``."""

    def reset(self, seed: int | None = None) -> None:
        """Clear the internal state (integrators, filters).

        Parameters
        ----------
        seed : int, optional
            Seed of any randomness the controller has.
        """

    def __call__(self, timestep) -> np.ndarray:
        """The action for this time step.

        Parameters
        ----------
        timestep : dm_env.TimeStep
            Its ``observation`` is the dict of this module's docstring.

        Returns
        -------
        numpy.ndarray, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].
        """


def scalar(observation: dict, key: str) -> float:
    """A scalar observation as a Python float.

    Parameters
    ----------
    observation : dict
        The observation (or its ``true_state``).
    key : str
        The entry to read; it must hold one number.

    Returns
    -------
    float
        The value.
    """
    value = observation[key]
    if type(value) is np.ndarray and value.ndim == 0:
        return float(value)  # the observation's own form, without a reshape
    return float(np.asarray(value).reshape(()))


class Composite:
    """A rudder law and a sail law combined into one controller.

    Parameters
    ----------
    rudder : callable
        ``rudder(observation) -> float``, the rudder angle [rad]; optionally with ``reset(seed)``.
    sail : callable
        ``sail(observation) -> float``, the sail angle [rad] (or sheet length [m]); optionally
        with ``reset(seed)``.
    """

    def __init__(self, rudder, sail):
        self.rudder = rudder
        self.sail = sail

    def reset(self, seed: int | None = None) -> None:
        """Reset both laws.

        Parameters
        ----------
        seed : int, optional
            Passed to each law's ``reset``.
        """
        for law in (self.rudder, self.sail):
            if hasattr(law, "reset"):
                law.reset(seed)

    def __call__(self, timestep) -> np.ndarray:
        """[rudder law, sail law] of this time step's observation.

        Parameters
        ----------
        timestep : dm_env.TimeStep
            Its ``observation`` is the dict of this module's docstring.

        Returns
        -------
        numpy.ndarray, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].
        """
        obs = timestep.observation
        return np.array([self.rudder(obs), self.sail(obs)], dtype=float)
