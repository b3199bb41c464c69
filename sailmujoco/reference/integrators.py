"""Fixed-step integration shared by the paper worlds (Viel 3-DOF, Wille 4-DOF).

Both worlds hold the control over a control period and integrate a smooth ODE across it; a
classical Runge-Kutta step of a few hundredths of a second matches scipy's adaptive RK45 to the
digits the studies print (tested in each world) at a fraction of its calls, because RK45 restarts
(initial-step selection and all) at every control period.

Each world's RK4 over a control period is one compiled call (its ``*_advance`` kernel) built from
:func:`rk4_stage` and :func:`rk4_update`, which do numpy's arithmetic of :func:`rk4` in numpy's
order, so the compiled worlds reproduce the Python ones bit for bit. A compiled right-hand side
cannot raise: where the Python one raised ``ValueError`` (``math.cos(inf)`` of a state that ran
away) it returns False, and the advance kernel stops with ``STATUS_RAN_AWAY``; ``MESSAGES`` holds
the words :func:`integrate` gave each outcome.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from ..jit.kernel import kernel

INTEGRATORS = ("rk4", "rk45")  # a paper world's integrator=...: fixed-step RK4, or solve_ivp's RK45
STATUS_OK, STATUS_RAN_AWAY, STATUS_NONFINITE = 0, 1, 2
DOMAIN_ERROR = "math domain error"  # what math.cos(inf) raises, the Python RHS's words for a runaway
MESSAGES = ("", f"the state ran away: {DOMAIN_ERROR}", "non-finite state")  # by status


def steps_for(dt: float, max_step: float) -> int:
    """The number of equal steps of at most ``max_step`` that span ``dt``.

    Parameters
    ----------
    dt, max_step : float
        The span and the longest step, s.
    """
    return max(1, math.ceil(dt / max_step - 1e-9))


def rk4(rhs, t0: float, y0, dt: float, n: int) -> np.ndarray:
    """``n`` classical Runge-Kutta steps of ``dt / n`` of y' = rhs(t, y) from (t0, y0).

    Parameters
    ----------
    rhs : callable
        ``rhs(t, y) -> y'``, numpy arrays.
    t0, y0 : float, array_like
        Initial time (s) and state.
    dt : float
        Time span, s.
    n : int
        Number of steps.
    """
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


@kernel
def rk4_stage(y, a, k, out):
    """out = y + a k: an RK4 stage's state (numpy's ``y + 0.5 * h * k1`` with a = 0.5 * h).

    Parameters
    ----------
    y, k : numpy.ndarray
        State and a stage's rate.
    a : float
        Factor of ``k`` (0.5 h or h), s.
    out : numpy.ndarray
        Receives the stage's state.
    """
    for i in range(y.shape[0]):
        out[i] = y[i] + a * k[i]


@kernel
def rk4_update(y, h, k1, k2, k3, k4):
    """y = y + (h / 6) (k1 + 2 k2 + 2 k3 + k4), in place, in :func:`rk4`'s order.

    Parameters
    ----------
    y : numpy.ndarray
        State, updated in place.
    h : float
        Step, s.
    k1, k2, k3, k4 : numpy.ndarray
        The four stages' rates.
    """
    c = h / 6.0
    for i in range(y.shape[0]):
        y[i] = y[i] + c * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])


@kernel
def final_status(y):
    """STATUS_OK, or STATUS_NONFINITE if ``y`` holds a NaN or an infinity.

    Parameters
    ----------
    y : numpy.ndarray
        State.
    """
    for i in range(y.shape[0]):
        if not math.isfinite(y[i]):
            return STATUS_NONFINITE
    return STATUS_OK


def integrate(rhs, t0: float, y0, dt: float, integrator: str, max_step: float, rtol: float,
              atol: float) -> tuple[np.ndarray, str]:
    """y(t0 + dt) of y' = rhs(t, y), and "" or why the integration failed.

    ``integrator`` "rk4": :func:`rk4` in equal steps of at most ``max_step``; "rk45": scipy's
    ``solve_ivp`` with ``rtol``/``atol``. A failure (RK45's message, a state that ran away, a
    non-finite result) is reported, not raised: each world raises its own error with its state.

    Parameters
    ----------
    rhs : callable
        ``rhs(t, y) -> y'``, numpy arrays.
    t0, y0 : float, array_like
        Initial time (s) and state.
    dt : float
        Time span, s.
    integrator : {"rk4", "rk45"}
        The method (:data:`INTEGRATORS`).
    max_step : float
        Longest RK4 step, s.
    rtol, atol : float
        RK45's relative and absolute tolerances.
    """
    if integrator == "rk4":
        try:
            y = rk4(rhs, t0, y0, dt, steps_for(dt, max_step))
        except (ValueError, OverflowError) as err:  # math.cos(inf) of a state that ran away
            return np.asarray(y0, dtype=float), f"the state ran away: {err}"
    else:
        sol = solve_ivp(rhs, (t0, t0 + dt), y0, method="RK45", rtol=rtol, atol=atol)
        y = sol.y[:, -1]
        if not sol.success:
            return y, sol.message
    return y, "" if np.all(np.isfinite(y)) else "non-finite state"
