"""The random processes and filters a sensor model is made of, each stepped once per sample.

* :class:`GaussMarkov` — a first-order Gauss-Markov error (an Ornstein-Uhlenbeck process sampled
  exactly): stationary standard deviation ``sigma``, autocorrelation ``exp(-|lag| / tau)``. The
  error of a GNSS fix and a compass's slowly wandering deviation are of this kind; white noise
  would average away over a few samples, which a real receiver's error does not.
* :class:`RandomWalk` — a gyro's bias: ``b(t + dt) = b(t) + sigma_rw sqrt(dt) w``.
* :class:`LowPass` and :class:`AngleLowPass` — a first-order filter ``tau dy/dt = x - y``
  sampled exactly (the step response reaches ``1 - exp(-t / tau)``); an angle is filtered as
  the vector it points along, so that it never averages across the +-pi seam.

Every process draws from the :class:`numpy.random.Generator` handed to it, and nothing else: a
sensor's stream is its own, seeded from the run's seed (:mod:`sailmujoco.measurement.sensors`).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import check_number


class GaussMarkov:
    """First-order Gauss-Markov process, sampled exactly every ``dt``.

    ``x[k+1] = a x[k] + sigma sqrt(1 - a^2) w[k]`` with ``a = exp(-dt / tau)`` and ``w`` standard
    normal: the Ornstein-Uhlenbeck process ``dx = -x / tau dt + sigma sqrt(2 / tau) dW`` updated
    exactly for any dt (Gillespie, Phys. Rev. E 54, 2084, 1996). It starts stationary:
    ``x[0]`` is drawn from N(0, sigma^2).

    Parameters
    ----------
    sigma : float
        Stationary standard deviation (the error's unit), >= 0.
    tau : float
        Correlation time, s, > 0.
    dt : float
        Sample period, s, > 0.
    rng : numpy.random.Generator
        The stream it draws from.
    shape : tuple of int
        Shape of one sample (``(2,)`` for a horizontal position error).
    """

    def __init__(self, sigma: float, tau: float, dt: float, rng: np.random.Generator, shape=()):
        self.sigma = check_number("sigma", sigma, 0.0)
        self.tau = check_number("tau", tau, 0.0, low_open=True)
        dt = check_number("dt", dt, 0.0, low_open=True)
        self.a = math.exp(-dt / self.tau)
        self.b = self.sigma * math.sqrt(1.0 - self.a * self.a)
        self.rng = rng
        self.value = self.sigma * rng.standard_normal(shape)

    def step(self):
        """Advance one sample; the new value."""
        self.value = self.a * self.value + self.b * self.rng.standard_normal(np.shape(self.value))
        return self.value


class RandomWalk:
    """A random walk sampled every ``dt``: ``b[k+1] = b[k] + sigma_rw sqrt(dt) w[k]``, from ``start``
    (a float, or an array of independent walks).

    Parameters
    ----------
    sigma_rw : float
        Random-walk intensity (the unit per square-root second), >= 0.
    dt : float
        Sample period, s, > 0.
    rng : numpy.random.Generator
        The stream it draws from.
    start : float or numpy.ndarray
        The value at the first sample (an array: one walk per entry).
    """

    def __init__(self, sigma_rw: float, dt: float, rng: np.random.Generator, start=0.0):
        dt = check_number("dt", dt, 0.0, low_open=True)
        self.scale = check_number("sigma_rw", sigma_rw, 0.0) * math.sqrt(dt)
        self.rng = rng
        self.value = np.array(start, dtype=np.float64) if np.ndim(start) else float(start)

    def step(self):
        """Advance one sample; the new value."""
        if isinstance(self.value, float):
            self.value += self.scale * float(self.rng.standard_normal())
        else:
            self.value = self.value + self.scale * self.rng.standard_normal(self.value.shape)
        return self.value


def smoothing(tau: float, dt: float) -> float:
    """The gain ``1 - exp(-dt / tau)`` of a first-order filter sampled every ``dt`` (1 for tau = 0).

    Parameters
    ----------
    tau : float
        Time constant, s, >= 0 (0: no filter).
    dt : float
        Sample period, s, > 0.
    """
    tau, dt = check_number("tau", tau, 0.0), check_number("dt", dt, 0.0, low_open=True)
    return 1.0 if tau == 0.0 else 1.0 - math.exp(-dt / tau)


class LowPass:
    """First-order low-pass filter ``tau dy/dt = x - y``, sampled every ``dt``; it starts at the
    first input (no transient from zero). It filters a number or a short vector (a tuple of
    numbers, each entry on its own), on Python floats: one step costs about a microsecond.

    Parameters
    ----------
    tau : float
        Time constant, s (a cut-off of f Hz is ``tau = 1 / (2 pi f)``); 0 passes the input.
    dt : float
        Sample period, s.
    """

    def __init__(self, tau: float, dt: float):
        self.gain = smoothing(tau, dt)
        self.value = None

    def step(self, x):
        """Filter one input; the output, of the same kind (a tuple for a sequence).

        Parameters
        ----------
        x : float or sequence of float
            The input.
        """
        g, y = self.gain, self.value
        if isinstance(x, (int, float, np.number)) or np.ndim(x) == 0:  # the first test: no numpy call
            self.value = float(x) if y is None else y + g * (float(x) - y)
        elif y is None:
            self.value = tuple(float(v) for v in x)
        elif len(y) == 2:  # a flow or a wind in the plane: the same arithmetic, written out
            self.value = (y[0] + g * (float(x[0]) - y[0]), y[1] + g * (float(x[1]) - y[1]))
        else:
            self.value = tuple(a + g * (float(b) - a) for a, b in zip(y, x, strict=True))
        return self.value


class AngleLowPass:
    """First-order low-pass filter of an angle, through the unit vector it points along.

    Parameters
    ----------
    tau : float
        Time constant, s; 0 passes the input.
    dt : float
        Sample period, s.
    """

    def __init__(self, tau: float, dt: float):
        self.vector = LowPass(tau, dt)

    def step(self, angle: float) -> float:
        """Filter one angle; the output, rad in [-pi, pi].

        Parameters
        ----------
        angle : float
            The input, rad.
        """
        c, s = self.vector.step((math.cos(angle), math.sin(angle)))
        return math.atan2(s, c)
