"""A PID heading controller: the baseline rudder law.

sigma = K_p e + K_i int e dt + K_d de/dt, e = wrap(heading - desired heading), with the
derivative taken from the measured yaw rate (de/dt = d(heading)/dt = -yaw_rate, since the
heading turns clockwise and yaw_rate counter-clockwise). A positive rudder turns the boat to
port, i.e. lowers the heading, so a heading above the desired one asks for positive rudder.
Saturated at ``max_angle`` with conditional integration (no wind-up).
"""

from __future__ import annotations

import math

from sailmujoco.frames import wrap_angle

from .base import scalar


def _sign(x: float) -> float:
    """np.sign on a float: -1, 0 or 1, NaN for NaN."""
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else (0.0 if x == 0.0 else math.nan))


class PIDHeading:
    """Rudder law holding a compass heading (rad). ``dt`` is the control period (s).

    Parameters
    ----------
    desired_heading : float, optional
        Compass heading to hold [rad]; None reads ``observation[reference_key]``.
    kp, ki, kd : float
        Proportional [-], integral [1/s] and derivative [s] gains (rudder radians per radian of
        heading error).
    max_angle : float
        Rudder saturation [rad].
    dt : float
        Control period [s] (the integral's step).
    reference_key : str
        Observation key of the desired heading when ``desired_heading`` is None.
    """

    def __init__(self, desired_heading: float | None = None, kp: float = 1.0, ki: float = 0.05,
                 kd: float = 2.0, max_angle: float = math.radians(35.0), dt: float = 0.1,
                 reference_key: str = "desired_heading"):
        self.desired_heading = desired_heading
        self.kp, self.ki, self.kd = kp, ki, kd
        self.max_angle = max_angle
        self.dt = dt
        self.reference_key = reference_key
        self.integral = 0.0

    def reset(self, seed: int | None = None) -> None:
        """Clear the internal state.

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.integral = 0.0

    def error(self, observation: dict) -> float:
        """The heading error.

        Parameters
        ----------
        observation : dict
            The observation (:mod:`controllers.base`).

        Returns
        -------
        float
            e = wrap(heading - desired heading) [rad].
        """
        desired = self.desired_heading
        if desired is None:
            desired = scalar(observation, self.reference_key)
        return wrap_angle(scalar(observation, "heading") - desired)

    def __call__(self, observation: dict) -> float:
        """The rudder angle for this observation (PID on the heading error, anti-windup).

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Rudder angle, rad, positive trailing edge to port, within +-``max_angle``.
        """
        e = self.error(observation)
        de = -scalar(observation, "yaw_rate")
        command = self.kp * e + self.ki * self.integral + self.kd * de
        if abs(command) < self.max_angle or _sign(command) != _sign(e):
            self.integral += e * self.dt
        high = self.max_angle  # np.clip(command, -high, high) on floats (NaN passes)
        return float(high if command > high else (-high if command < -high else command))
