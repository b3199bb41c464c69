"""A world's true state as one vector, for the compiled closed loops.

The Python path hands the observation a :class:`sailmujoco.measurement.observation.Truth`; a
compiled loop writes the same numbers into one float64 vector laid out by the indices below
(the force wrenches aside), by the same operations in the same order as each world's
``truth()``:

* :func:`viel_truth`: :meth:`sailmujoco.reference.viel.VielWorld.truth`;
* :func:`mujoco_truth`: :meth:`sailmujoco.measurement.accessors.BoatAccessors.truth` of a 6-DOF
  MuJoCo boat, MuJoCo's own functions (``mju_quat2Mat``, ``mj_kinematics``, ``mj_comPos``,
  ``mj_comVel``, ``mj_objectVelocity``) called through their C symbols and the force kernel on
  the boat's registry row, as ``_ensure_fresh`` calls them.

The vector is also each state's row in what a loop hands back: the Python side builds the
task's records and the trajectory samples from it (:mod:`sailmujoco.loop.episode`).
"""

from __future__ import annotations

import math

import mujoco
import numba
import numpy as np

from ..forces import boat as kernels
from ..forces.wind_kernels import wander_angle, wind_velocity
from ..frames import wrap_angle
from ..jit.kernel import kernel
from ..jit.ordered import mat_t_vec
from ..reference.hypot import hypot
from ..reference.viel_model import apparent_wind, forces_kernel
from ..step.mujoco_calls import (
    address,
    mj_comPos,
    mj_comVel,
    mj_kinematics,
    mj_objectVelocity,
    mju_quat2Mat,
    pointer,
    time_byte_offset,
)
from ..step.registry import R_FIRST, kernel_forces

# the truth vector (our frames: world x east, y north, z up; body x forward, y port, z up; SI)
(TIME, X, Y, EAST, NORTH, U, V, W, CURRENT_U, CURRENT_V, CURRENT_W, P, Q, R, YAW, HEEL, PITCH, HEADING,
 RUDDER, SAIL, AWA, AWS, WIND_E, WIND_N, FLOW_X, FLOW_Y, SPEED_10, DIRECTION_FROM, CURRENT_E,
 CURRENT_N) = range(30)
SIZE = 30

_D_WIND, _D_FLOW = kernels.D_WIND_X, kernels.D_SAIL_FLOW_X
_SITE = int(mujoco.mjtObj.mjOBJ_SITE)  # a constant of the compiled code


@kernel(inline=True)
def direction_from(t, wind, wander):
    """:meth:`sailmujoco.forces.wind.WindField.direction_from`: the compass bearing the wind
    comes from at ``t`` (rad, not wrapped).

    Parameters
    ----------
    t : float
        Time, s.
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`sailmujoco.loop.episode.wind_arguments`): U_m10 (m/s),
        mean bearing (rad), direction oscillation (rad), its frequency (Hz), the wander's step (s).
    wander : numpy.ndarray
        The wander (rad) at multiples of the wander's step.
    """
    return (wind[1] + wander_angle(t, wind[4], wander)
            + wind[2] * math.sin(2.0 * math.pi * wind[3] * t))


@kernel(inline=True)
def viel_truth(state, t, applied0, applied1, packed, z, wind, tables, w, forces, out):
    """Viel's world's truth at (t, state) with the applied action into ``out``.

    Parameters
    ----------
    state : numpy.ndarray, shape (6,)
        Viel's state (x, y, theta, v, u, omega).
    t : float
        Time, s.
    applied0, applied1 : float
        The world's applied rudder and sail angles (ours, rad).
    packed : numpy.ndarray
        The world's parameters (``pack_parameters``).
    z : float
        The wind's height, m.
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`direction_from`).
    tables : tuple of numpy.ndarray
        The wind's tables (:func:`sailmujoco.loop.episode.wind_arguments`).
    w : numpy.ndarray, shape (3,)
        Scratch for the wind velocity.
    forces : numpy.ndarray, shape (9,)
        Receives the world's force terms.
    out : numpy.ndarray, shape (SIZE,)
        Receives the truth.

    Returns
    -------
    bool
        False where the world's force terms fail their domain check (the Python path raises).
    """
    oscillation, frequency, phase, amplitude, log_z, wander = tables
    x, y, theta, v, u, omega = state[0], state[1], state[2], state[3], state[4], state[5]
    wind_velocity(t, z, wind[0], wind[1], oscillation, frequency, phase, amplitude, log_z, wind[4], wander, w)
    a_tw, psi_tw = hypot(w[0], w[1]), math.atan2(w[1], w[0])
    a_aw, psi_aw = apparent_wind(a_tw, psi_tw, theta, v)
    if not forces_kernel(packed, state, -applied0, -applied1, a_tw, psi_tw, forces):
        return False
    c, s = math.cos(theta), math.sin(theta)
    out[TIME], out[X], out[Y] = t, x, y
    out[EAST], out[NORTH] = v * c - u * s, v * s + u * c
    out[U], out[V], out[W] = v, u, 0.0
    out[CURRENT_U], out[CURRENT_V], out[CURRENT_W] = 0.0, 0.0, 0.0
    out[P], out[Q], out[R] = 0.0, 0.0, omega
    out[YAW], out[HEEL], out[PITCH] = theta, 0.0, 0.0
    out[HEADING] = wrap_angle(math.pi / 2.0 - theta)  # frames.heading_from_yaw
    out[RUDDER], out[SAIL] = applied0, applied1
    out[AWA], out[AWS] = wrap_angle(math.pi - psi_aw), a_aw  # viel_model.awa_from_psi_aw
    out[WIND_E], out[WIND_N] = a_tw * math.cos(psi_tw), a_tw * math.sin(psi_tw)
    out[FLOW_X], out[FLOW_Y] = a_aw * math.cos(psi_aw), a_aw * math.sin(psi_aw)
    out[SPEED_10], out[DIRECTION_FROM] = wind[0], direction_from(t, wind, wander)
    out[CURRENT_E], out[CURRENT_N] = 0.0, 0.0
    return True


@kernel(inline=True)
def mujoco_truth(m, d, qpos, qvel, site_xpos, site, rudder_at, sail_at, row, diag, wind, tables, current,
                 scratch, out):
    """A 6-DOF MuJoCo boat's truth now into ``out``; its kinematics and force terms brought up
    to the state on the way (``BoatPhysics._ensure_fresh``).

    Parameters
    ----------
    m, d : void pointer
        The boat's MjModel and MjData.
    qpos, qvel, site_xpos : numpy.ndarray
        MjData's arrays.
    site : int
        The masthead site's id.
    rudder_at, sail_at : int
        The rudder's and the sail's qpos addresses.
    row : numpy.ndarray of int64
        The boat's registry row (its force kernel's arrays).
    diag : numpy.ndarray
        The force kernel's diagnostics (the row's).
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`direction_from`).
    tables : tuple of numpy.ndarray
        The wind's tables (:func:`sailmujoco.loop.episode.wind_arguments`).
    current : numpy.ndarray, shape (3,)
        The water current (ENU, m/s).
    scratch : numpy.ndarray, shape (4, 9)
        Work space.
    out : numpy.ndarray, shape (SIZE,)
        Receives the truth.

    Returns
    -------
    int
        The force kernel's status at this state.
    """
    oscillation, frequency, phase, amplitude, log_z, wander = tables
    flat, vel, air, w = scratch[0], scratch[1], scratch[2], scratch[3]
    rot = flat.reshape((3, 3))
    mju_quat2Mat(pointer(flat.ctypes.data), pointer(qpos[3:7].ctypes.data))
    body = mat_t_vec(rot, qvel[0:3])
    current_body = mat_t_vec(rot, current)
    t = numba.carray(pointer(address(d) + time_byte_offset()), (1,), np.float64)[0]
    heel = math.atan2(flat[7], flat[8])  # observation.euler_of_entries
    sin_pitch = flat[6]
    if sin_pitch > 1.0:
        sin_pitch = 1.0
    elif sin_pitch < -1.0:
        sin_pitch = -1.0
    pitch, yaw = math.asin(sin_pitch), math.atan2(flat[3], flat[0])
    # _ensure_fresh: MuJoCo's kinematics, then the force kernel (no added mass) at this state
    mj_kinematics(m, d)
    mj_comPos(m, d)
    mj_comVel(m, d)
    status = kernel_forces(row, t, row[R_FIRST] == 0)
    mj_objectVelocity(m, d, _SITE, site, pointer(vel.ctypes.data), 0)
    wind_velocity(t, site_xpos[site, 2], wind[0], wind[1], oscillation, frequency, phase, amplitude, log_z,
                  wind[4], wander, w)
    for k in range(3):
        air[k] = w[k] - vel[3 + k]
    flow = mat_t_vec(rot, air[0:3])
    out[TIME], out[X], out[Y] = t, qpos[0], qpos[1]
    out[EAST], out[NORTH] = qvel[0], qvel[1]
    out[U], out[V], out[W] = body[0], body[1], body[2]
    out[CURRENT_U], out[CURRENT_V], out[CURRENT_W] = current_body[0], current_body[1], current_body[2]
    out[P], out[Q], out[R] = qvel[3], qvel[4], qvel[5]
    out[YAW], out[HEEL], out[PITCH] = yaw, heel, pitch
    out[HEADING] = wrap_angle(math.pi / 2.0 - yaw)
    out[RUDDER], out[SAIL] = qpos[rudder_at], qpos[sail_at]
    out[AWA], out[AWS] = math.atan2(flow[1], -flow[0]), hypot(flow[0], flow[1])
    out[WIND_E], out[WIND_N] = diag[_D_WIND], diag[_D_WIND + 1]
    out[FLOW_X], out[FLOW_Y] = diag[_D_FLOW], diag[_D_FLOW + 1]
    out[SPEED_10], out[DIRECTION_FROM] = wind[0], direction_from(t, wind, wander)
    out[CURRENT_E], out[CURRENT_N] = current[0], current[1]
    return status
