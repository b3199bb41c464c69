"""A 6-DOF boat's side of the compiled closed loop (:mod:`sailmujoco.loop`): what a loop reads and
writes of :class:`sailmujoco.physics.BoatPhysics`, and the boat brought up to date after it, as
its own Python step would have left it (the physics' own module: it reads the boat's private
state, as :mod:`sailmujoco.step.native` does).
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import NamedTuple

import mujoco
import numpy as np

from ..forces import boat as kernels
from .native import Stepping
from .registry import REGISTRY


class LoopHandles(NamedTuple):
    """What a compiled closed loop (:mod:`sailmujoco.loop`) reads and writes of a 6-DOF boat:
    the arguments of :func:`sailmujoco.loop.truth.mujoco_truth` and
    :func:`sailmujoco.loop.worlds.mujoco_step`, in the order their kernels take them."""

    m_address: int
    d_address: int
    qpos: np.ndarray
    qvel: np.ndarray
    ctrl: np.ndarray
    site_xpos: np.ndarray
    site: int
    rudder_at: int
    sail_at: int
    row: np.ndarray  # the boat's slot of the registry, while it steps
    diag: np.ndarray
    saved: np.ndarray
    warnings: np.ndarray
    warnings_before: np.ndarray
    warnings_stop: bool
    current: np.ndarray


@contextmanager
def closed_loop(physics, seconds: float):
    """A 6-DOF boat (:class:`sailmujoco.physics.BoatPhysics`) ready for a compiled closed loop of
    ``seconds``: the wind drawn for all of it and its arrays bound, the boat in the step registry
    and the stage callback installed (as :class:`Stepping`) while the block runs; yields its
    :class:`LoopHandles`.

    Parameters
    ----------
    physics : BoatPhysics
        A 6-DOF boat stepped by RK4 (``compiled_loop``), not stopped.
    seconds : float
        The simulated time the loop may cover, s.
    """
    physics._prepare(seconds)  # the wander the run reads, drawn up front: the same values
    m, d = physics.model.ptr, physics.data.ptr
    rudder_at, _, sail_at, _ = physics._idx.tolist()
    site = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "masthead")
    with Stepping(d._address, physics._row) as slots:
        yield LoopHandles(m._address, d._address, d.qpos, d.qvel, d.ctrl, d.site_xpos, site, rudder_at,
                          sail_at, REGISTRY[slots[0]], physics._diag, physics._saved, physics._warnings,
                          physics._warnings_before, bool(physics._warnings_cause_exception),
                          physics.wind.current)


def closed_loop_ended(physics, status: int, warned: bool, force_status: int) -> str | None:
    """Bring the boat's own state up to date after a compiled closed loop, as its Python step
    would have left it; the stop reason, or None if the boat sails on.

    Parameters
    ----------
    physics : BoatPhysics
        The boat.
    status : int
        The force kernel's stop status of the last step taken (``STATUS_OK`` for none).
    warned : bool
        Whether a new MuJoCo warning stopped that step (where warnings stop the run).
    force_status : int
        The force kernel's status at the loop's last measurement of the state.
    """
    physics._status = force_status
    if status != kernels.STATUS_OK:  # BoatPhysics._stop
        physics._record_stop(status)
    elif warned:  # BoatPhysics.step's PhysicsError
        physics._record_stop(kernels.STATUS_NONFINITE,
                             f"non-finite or out-of-range state ({physics._warnings_message()})")
    # a stop leaves the kinematics and forces as the measurement before the step made them
    physics._fresh = physics.stop_reason is not None
    return physics.stop_reason


def closed_loop_ready(physics) -> bool:
    """Whether a compiled closed loop can step this boat (:func:`closed_loop`): 6 DOF, RK4 by the
    compiled step, an actuated sail and a rudder, a :class:`~sailmujoco.forces.wind.WindField`,
    not stopped.

    Parameters
    ----------
    physics : BoatPhysics
        The boat.
    """
    from ..forces.wind import WindField

    rk4 = physics.model.ptr.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4
    return (physics.dofs == 6 and physics.compiled_loop and rk4
            and physics.model.nu == 2 and physics.sail_mode == "actuated" and type(physics.wind) is WindField
            and physics.stop_reason is None)
