"""The physics step: the ``timestep`` option checked, and counted in a control step.

Each world integrates with its own step unless the ``timestep`` physics option
(:class:`sailmujoco.options.PhysicsOptions`) gives another:

* the MuJoCo world: MuJoCo's RK4 step, ``model.opt.timestep``
  (:data:`sailmujoco.boat.mjcf.TIMESTEP`, 0.005 s, unless given);
* Wille's 4-DOF paper world: the longest step of its RK4, which crosses a control step in equal
  steps of at most that (:data:`sailmujoco.reference.wille.RK4_MAX_STEP`, 0.05 s);
* Viel's 3-DOF paper world: the same (:data:`sailmujoco.reference.viel_model.RK4_MAX_STEP`, 0.01 s).

A step given must divide the control step into whole sub-steps, so that every control step ends
on a physics step (:func:`sub_steps`). How large a step may be, measured against the studies'
figures of merit: docs/physics.md, "The time step", and ``benchmarks/timestep_convergence.py``.
"""

from __future__ import annotations

import math

import numpy as np

STEP_TOLERANCE = 1e-8  # -, a ratio this close to a whole number is one (dm_control's compute_n_steps)


def check_timestep(value) -> float | None:
    """The ``timestep`` option as a float, or None; one line unless a finite time > 0 or None.

    Parameters
    ----------
    value : object
        The ``timestep`` given, s.
    """
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) \
            or not math.isfinite(value) or value <= 0.0:
        raise ValueError(f"timestep must be a time > 0 in s that divides the control step, or None "
                         f"(the world's own step), got {value!r}")
    return float(value)


def sub_steps(timestep: float, control_timestep: float) -> int:
    """The whole number of physics steps ``timestep`` in one control step; one line if none.

    The step divides the control step when their ratio is a whole number to 1e-8, dm_control's
    tolerance (``control.compute_n_steps``). The message names the option, the control step
    and the nearest steps that divide it.

    Parameters
    ----------
    timestep : float
        The physics step, s, > 0.
    control_timestep : float
        The control step, s, > 0.

    Returns
    -------
    int
        ``control_timestep / timestep``, >= 1.
    """
    ratio = control_timestep / timestep
    n = round(ratio)
    if n >= 1 and abs(ratio - n) <= STEP_TOLERANCE:
        return int(n)
    below, above = max(1, math.ceil(ratio)), max(1, math.floor(ratio))
    near = " or ".join(dict.fromkeys(f"{control_timestep / k:.6g}" for k in (below, above)))
    raise ValueError(f"timestep {timestep:g} s must divide control_timestep {control_timestep:g} s into "
                     f"whole sub-steps: control_timestep / n for a whole n >= 1 (nearest: {near} s), "
                     f"or None (the world's own step)")
