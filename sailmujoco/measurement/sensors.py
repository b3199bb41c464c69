"""Sensor models: what a boat's instruments read, given the true state.

Each model is a plain object stepped once per control step (period ``dt``) with the truth of
that step, drawing from a :class:`numpy.random.Generator` of its own, and returning what the
instrument reports:

* :class:`Gnss` — position and velocity over ground: a fix every ``1 / rate`` s, held between
  fixes, describing the boat ``latency`` s earlier, its position error a Gauss-Markov process
  (:class:`~sailmujoco.measurement.noise.GaussMarkov`) and its velocity error white. A receiver's
  horizontal accuracy is quoted as CEP (the radius holding half the fixes); for a circular
  normal error of per-axis sigma, CEP = sigma sqrt(2 ln 2) = 1.1774 sigma.
* :class:`Compass` — heading: the reading of a magnetometer fixed to the hull
  (:func:`untilted_heading`, whose error grows with heel through the field's dip) or of a
  tilt-compensated one (:func:`tilt_compensated_heading`, wrong by its inclinometer's error),
  plus a fixed deviation and white noise.
* :class:`Gyro` — body rates with white noise and a bias that random-walks.
* :class:`MastheadVane` — apparent wind angle and speed: the air relative to the masthead in the
  mast's own (heeled) plane, so the boat's motion is in the reading (:func:`masthead_flow`),
  plus white noise on each flow component and a first-order filter.
* :class:`SpeedLog` — speed through the water with a calibration (scale) error and noise.

Frames are the package's (:mod:`sailmujoco.frames`): world ENU, body FLU, compass headings
clockwise from north, heel positive starboard down, AWA positive from starboard.
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np

from ..errors import check_number
from ..frames import matrix_from_euler, wrap_angle
from ..jit.ordered import mat_t_vec, mat_vec
from .noise import GaussMarkov, LowPass

CEP_PER_SIGMA = math.sqrt(2.0 * math.log(2.0))  # CEP / per-axis sigma of a circular normal error


def earth_field(dip: float) -> np.ndarray:
    """The unit magnetic field in the world (ENU), declination zero: north and ``dip`` below
    the horizon (dip > 0 in the northern hemisphere, where the field points down).

    Parameters
    ----------
    dip : float
        Magnetic inclination, rad, in [-pi/2, pi/2].
    """
    return np.array([0.0, math.cos(dip), -math.sin(dip)])


def untilted_heading(rot, dip: float) -> float:
    """The compass heading a magnetometer fixed to the hull reports, taking its own x-y plane
    for the horizontal: ``atan2(m_y, m_x)`` of the field in body axes (rad, clockwise from north).

    Level, it reads the heading exactly; heeled, the vertical part of the field leaks into its
    athwartships axis and it errs by an amount set by the dip, the heel and the heading.

    Parameters
    ----------
    rot : array_like, shape (3, 3)
        Body (FLU) -> world (ENU) rotation.
    dip : float
        Magnetic inclination, rad.
    """
    return tilt_compensated_heading(rot, dip, 0.0, 0.0)


def tilt_compensated_heading(rot, dip: float, heel: float, pitch: float) -> float:
    """The heading a tilt-compensated compass reports: its magnetometer's field rotated back to
    the horizontal with the heel and pitch its inclinometer gives (exact when they are true).

    Parameters
    ----------
    rot : array_like, shape (3, 3)
        Body (FLU) -> world (ENU) rotation.
    dip : float
        Magnetic inclination, rad.
    heel, pitch : float
        The inclinometer's heel and pitch, rad.
    """
    m = mat_t_vec(np.asarray(rot, dtype=np.float64).reshape(3, 3), earth_field(dip))
    level = mat_vec(matrix_from_euler(heel, pitch, 0.0), m)
    return math.atan2(float(level[1]), float(level[0]))


def field_in_body(heel: float, pitch: float, yaw: float, dip: float) -> tuple[float, float, float]:
    """The unit magnetic field of :func:`earth_field` in body axes, ``R^T B`` for
    ``R = Rz(yaw) Ry(-pitch) Rx(heel)`` (:func:`sailmujoco.frames.matrix_from_euler`), written out
    on floats: the per-step path of :class:`Compass` (``tests/test_sensors.py`` holds it to the
    matrix form).

    Parameters
    ----------
    heel, pitch, yaw : float
        The attitude, rad (yaw ENU, counter-clockwise from east).
    dip : float
        Magnetic inclination, rad.
    """
    horizontal, down = math.cos(dip), math.sin(dip)
    north_x, north_y = math.sin(yaw) * horizontal, math.cos(yaw) * horizontal  # Rz^T B
    cp, sp = math.cos(pitch), math.sin(pitch)
    a0, a2 = cp * north_x - sp * down, -sp * north_x - cp * down  # Ry(-pitch)^T, the vertical -down
    ch, sh = math.cos(heel), math.sin(heel)
    return a0, ch * north_y + sh * a2, -sh * north_y + ch * a2


def level_heading(m: tuple[float, float, float], heel: float, pitch: float) -> float:
    """The heading of a body-axes field ``m`` rotated back to the horizontal by ``heel`` and
    ``pitch`` (``Ry(-pitch) Rx(heel) m``, then ``atan2`` of its y and x), rad.

    Parameters
    ----------
    m : tuple of float
        The field in body axes.
    heel, pitch : float
        The tilt taken out, rad (zero: the untilted compass's reading).
    """
    ch, sh = math.cos(heel), math.sin(heel)
    b1, b2 = ch * m[1] - sh * m[2], sh * m[1] + ch * m[2]
    return math.atan2(b1, math.cos(pitch) * m[0] - math.sin(pitch) * b2)


def masthead_flow(rot, velocity, omega_body, r_body, wind) -> np.ndarray:
    """The air's velocity relative to a point of the boat, in body axes:
    ``R^T (wind - v) - omega x r`` (the boat's translation and rotation both in it).

    Parameters
    ----------
    rot : array_like, shape (3, 3)
        Body (FLU) -> world (ENU) rotation.
    velocity : array_like, shape (3,)
        World velocity of the body origin, m/s.
    omega_body : array_like, shape (3,)
        Angular velocity in body axes, rad/s.
    r_body : array_like, shape (3,)
        The point (the masthead) from the body origin, body axes, m.
    wind : array_like, shape (3,)
        The air's world velocity at the point, m/s.
    """
    rot = np.asarray(rot, dtype=np.float64).reshape(3, 3)
    air = mat_t_vec(rot, np.asarray(wind, dtype=np.float64) - np.asarray(velocity, dtype=np.float64))
    return air - np.cross(np.asarray(omega_body, dtype=np.float64), np.asarray(r_body, dtype=np.float64))


def vane_reading(flow_body) -> tuple[float, float]:
    """(AWA, AWS) a vane and anemometer turning about the mast read from the air's velocity in
    body axes: the flow in the mast's own x-y plane (rad from the bow, positive from starboard;
    m/s).

    Parameters
    ----------
    flow_body : array_like, shape (2,) or (3,)
        The air's velocity relative to the masthead, body axes, m/s.
    """
    fx, fy = float(flow_body[0]), float(flow_body[1])
    return math.atan2(fy, -fx), math.hypot(fx, fy)


class Gnss:
    """A GNSS receiver: position and velocity over ground, held between fixes, ``latency`` late.

    Parameters
    ----------
    dt : float
        Control period (one :meth:`measure` per period), s.
    rng : numpy.random.Generator
        The receiver's stream.
    rate : float
        Fixes per second, > 0 (rounded to a whole number of control periods between fixes, at
        least one).
    latency : float
        Age of a fix when it is reported, s, >= 0 (rounded to whole control periods).
    position_sigma : float
        Per-axis standard deviation of the position error, m (CEP / 1.1774).
    position_tau : float
        Correlation time of the position error, s.
    velocity_sigma : float
        Per-axis standard deviation of the (white) velocity error, m/s.
    """

    def __init__(self, dt: float, rng: np.random.Generator, rate: float = 5.0, latency: float = 0.0,
                 position_sigma: float = 0.0, position_tau: float = 60.0, velocity_sigma: float = 0.0):
        dt = check_number("dt", dt, 0.0, low_open=True)
        self.every = max(1, int(round(1.0 / (check_number("rate", rate, 0.0, low_open=True) * dt))))
        self.delay = int(round(check_number("latency", latency, 0.0) / dt))
        self.rng = rng
        self.velocity_sigma = check_number("velocity_sigma", velocity_sigma, 0.0)
        self.error = GaussMarkov(position_sigma, position_tau, self.every * dt, rng, shape=(2,))
        self.history: deque = deque(maxlen=self.delay + 1)
        self.steps = 0
        self.fix = None

    def measure(self, position, velocity) -> tuple[np.ndarray, np.ndarray]:
        """This control step's (position, velocity), world east and north (m, m/s).

        Parameters
        ----------
        position, velocity : array_like, shape (2,)
            The true position (m) and velocity over ground (m/s) now.
        """
        now = np.array(position[:2], dtype=np.float64), np.array(velocity[:2], dtype=np.float64)
        self.history.append(now)
        if self.steps % self.every == 0:  # a new fix: new arrays (a held fix is never written to)
            old_position, old_velocity = self.history[0]
            noise = self.velocity_sigma * self.rng.standard_normal(2)
            self.fix = (old_position + self.error.step(), old_velocity + noise)
        self.steps += 1
        return self.fix


class Compass:
    """A magnetic compass: untilted or tilt-compensated, with a deviation and white noise.

    Parameters
    ----------
    rng : numpy.random.Generator
        The compass's stream.
    dip : float
        Magnetic inclination, rad (about 1.2 rad, 69 deg, in the English Channel).
    tilt_compensated : bool
        True: the field is rotated back to the horizontal with the inclinometer's heel and pitch.
    noise : float
        Standard deviation of the white noise, rad.
    deviation : float
        A fixed error (the installation's deviation), rad.
    inclinometer_noise : float
        Standard deviation of the inclinometer's heel and pitch errors, rad (tilt-compensated).
    """

    def __init__(self, rng: np.random.Generator, dip: float = 0.0, tilt_compensated: bool = True,
                 noise: float = 0.0, deviation: float = 0.0, inclinometer_noise: float = 0.0):
        ok = isinstance(dip, (int, float)) and math.isfinite(dip) and abs(dip) <= math.pi / 2
        if not ok:
            raise ValueError(f"dip must be a finite angle within [-pi/2, pi/2] rad, got {dip!r}")
        self.rng, self.dip, self.tilt_compensated = rng, float(dip), bool(tilt_compensated)
        self.noise = check_number("noise", noise, 0.0)
        self.deviation = float(deviation)
        self.inclinometer_noise = check_number("inclinometer_noise", inclinometer_noise, 0.0)

    def measure(self, heel: float, pitch: float, yaw: float) -> float:
        """The heading reported now, rad clockwise from north, wrapped to [-pi, pi).

        Parameters
        ----------
        heel, pitch, yaw : float
            The true attitude, rad (a tilt-compensated compass's inclinometer reads heel and
            pitch with its noise).
        """
        noise = self.rng.standard_normal(3).tolist()
        m = field_in_body(heel, pitch, yaw, self.dip)
        if self.tilt_compensated:
            heading = level_heading(m, heel + self.inclinometer_noise * noise[1],
                                    pitch + self.inclinometer_noise * noise[2])
        else:
            heading = level_heading(m, 0.0, 0.0)
        return float(wrap_angle(heading + self.deviation + self.noise * noise[0]))


class Gyro:
    """A rate gyro: the body rates plus white noise and a bias random walk (one per axis).

    Parameters
    ----------
    dt : float
        Control period, s.
    rng : numpy.random.Generator
        The gyro's stream.
    noise : float
        Standard deviation of the white noise per sample, rad/s.
    bias_walk : float
        Random-walk intensity of the bias, rad/s per square-root second.
    bias : float
        The bias at start, rad/s (each axis).
    """

    def __init__(self, dt: float, rng: np.random.Generator, noise: float = 0.0, bias_walk: float = 0.0,
                 bias: float = 0.0):
        self.rng, self.noise = rng, check_number("noise", noise, 0.0)
        dt = check_number("dt", dt, 0.0, low_open=True)
        self.walk = check_number("bias_walk", bias_walk, 0.0) * math.sqrt(dt)
        self.bias = np.full(3, float(bias))

    def measure(self, rates) -> np.ndarray:
        """The body rates reported now (roll, pitch, yaw), rad/s.

        Parameters
        ----------
        rates : array_like, shape (3,)
            The true body rates, rad/s.
        """
        w = self.rng.standard_normal(6)  # the bias's steps (a random walk, as noise.RandomWalk), the noise
        self.bias = self.bias + self.walk * w[:3]
        return np.asarray(rates, dtype=np.float64)[:3] + self.bias + self.noise * w[3:]


class MastheadVane:
    """A masthead vane and cup anemometer: the flow in the mast's plane, noisy, filtered.

    Parameters
    ----------
    dt : float
        Control period, s.
    rng : numpy.random.Generator
        The vane's stream.
    noise : float
        Standard deviation of the white noise on each flow component before the filter, m/s.
    tau : float
        Time constant of the first-order filter on the flow vector, s (ArduPilot's vane filter
        of 0.5 Hz is tau = 1 / (2 pi 0.5) = 0.32 s); 0: no filter.
    upwash : float
        The sail's upwash at the masthead close-hauled, rad: the flow reaches the vane turned
        away from the bow by ``upwash cos(AWA)`` forward of the beam, and not at all abaft it
        (:func:`upwash_shift`); 0: none.
    """

    def __init__(self, dt: float, rng: np.random.Generator, noise: float = 0.0, tau: float = 0.0,
                 upwash: float = 0.0):
        self.rng, self.noise = rng, check_number("noise", noise, 0.0)
        self.upwash = check_number("upwash", upwash, 0.0)
        self.filter = LowPass(tau, dt)

    def measure(self, flow_body) -> tuple[float, float]:
        """(AWA rad, AWS m/s) reported now.

        Parameters
        ----------
        flow_body : array_like, shape (2,) or (3,)
            The air's velocity relative to the masthead, body axes, m/s (:func:`masthead_flow`).
        """
        fx, fy = float(flow_body[0]), float(flow_body[1])
        if self.upwash:
            awa, aws = vane_reading((fx, fy))
            awa += upwash_shift(awa, self.upwash)
            fx, fy = -aws * math.cos(awa), aws * math.sin(awa)
        wx, wy = self.rng.standard_normal(2).tolist()
        return vane_reading(self.filter.step((fx + self.noise * wx, fy + self.noise * wy)))


def upwash_shift(awa: float, upwash: float) -> float:
    """How far the sail's upwash turns the flow at the masthead away from the bow, rad:
    ``upwash cos(AWA)`` forward of the beam (the sail drawing, its bound circulation turning the
    flow ahead of it), none abaft the beam (the sail stalled). The form is ours: B&G's masthead
    unit manuals (H2000 pilot, "Upwash") describe the reading deflected by the sails and
    corrected from a table per wind speed, of the size that makes the true wind "tack" by
    2-3 degrees, without a formula.

    Parameters
    ----------
    awa : float
        The apparent wind angle at the masthead, rad, positive from starboard.
    upwash : float
        The shift close-hauled (at AWA -> 0), rad.
    """
    c = math.cos(awa)
    return math.copysign(upwash * c, awa) if c > 0.0 else 0.0


class SpeedLog:
    """A paddle-wheel or ultrasonic log: speed through the water, scaled by its calibration error.

    Parameters
    ----------
    rng : numpy.random.Generator
        The log's stream.
    scale_error : float
        Calibration error as a fraction (0.05 reads 5 % high), > -1.
    noise : float
        Standard deviation of the white noise, m/s.
    """

    def __init__(self, rng: np.random.Generator, scale_error: float = 0.0, noise: float = 0.0):
        if not (isinstance(scale_error, (int, float)) and math.isfinite(scale_error) and scale_error > -1.0):
            raise ValueError(f"scale_error must be a finite number > -1, got {scale_error!r}")
        self.rng, self.scale, self.noise = rng, 1.0 + float(scale_error), check_number("noise", noise, 0.0)

    def measure(self, surge_through_water: float) -> float:
        """The speed through the water reported now, m/s.

        Parameters
        ----------
        surge_through_water : float
            The true forward speed through the water, m/s.
        """
        return self.scale * float(surge_through_water) + self.noise * float(self.rng.standard_normal())


__all__ = ["CEP_PER_SIGMA", "Compass", "Gnss", "Gyro", "MastheadVane", "SpeedLog",
           "earth_field", "field_in_body", "level_heading", "masthead_flow", "tilt_compensated_heading",
           "untilted_heading", "upwash_shift", "vane_reading"]
