"""Fixed-step integration shared by the paper worlds (Viel 3-DOF, Wille 4-DOF).

Both worlds hold the control over a control period and integrate a smooth ODE across it; a
classical Runge-Kutta step of a few hundredths of a second matches scipy's adaptive RK45 to the
digits the studies print (tested in each world) at a fraction of its calls, because RK45 restarts
(initial-step selection and all) at every control period.
"""

from __future__ import annotations

import math

import numpy as np


def steps_for(dt: float, max_step: float) -> int:
    """The number of equal steps of at most ``max_step`` that span ``dt``."""
    return max(1, math.ceil(dt / max_step - 1e-9))


def rk4(rhs, t0: float, y0, dt: float, n: int) -> np.ndarray:
    """``n`` classical Runge-Kutta steps of ``dt / n`` of y' = rhs(t, y) from (t0, y0)."""
    h = dt / n
    y = np.asarray(y0, dtype=float)
    for i in range(n):
        t = t0 + i * h
        k1 = rhs(t, y)
        k2 = rhs(t + 0.5 * h, y + 0.5 * h * k1)
        k3 = rhs(t + 0.5 * h, y + 0.5 * h * k2)
        k4 = rhs(t + h, y + h * k3)
        y = y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    return y
