"""The task's measurements of a MuJoCo boat or of Wille's 4-DOF paper world, taken once per
control step.

:func:`measure_boat` gives what :func:`sailmujoco.tasks.base.measure` builds from a world's
named accessors (``rotation``, ``body_velocity``, ``heel`` ... ``apparent_wind_masthead``),
plus what :meth:`SailTask.record` keeps, from one rotation matrix and the arrays the physics
holds (MuJoCo's qpos/qvel, the force kernel's terms and diagnostics): no accessor is called
twice, none re-derives the rotation or the Euler angles.

Every value is computed by the same operations, on the same numbers, as the accessor it
replaces (the same numpy and MuJoCo functions where a library computes it, since numpy's
SIMD transcendental functions need not agree with ``math``'s to the last bit), so the
observation is identical bit for bit: ``tests/test_measurement.py`` compares the two on
real trajectories. The accessors stay the reference and the only path for other worlds.

:func:`measure_wille` does the same for :class:`~sailmujoco.reference.wille.Wille4DOF` (the
paper world of the Wille and Saoud tasks, where the accessors were over half the cost of a
control step): one rotation, one masthead flow, one packing of the kernels' arguments for the
force terms and the sail flow. It reads the world's ``state``, ``_time``, ``wind`` and ``params``
and calls its own :meth:`~sailmujoco.reference.wille.Wille4DOF.terms_and_sail_flow` and
:meth:`~sailmujoco.reference.wille.Wille4DOF.masthead_flow`, which the accessors call too.

It reads these members of :class:`~sailmujoco.physics.BoatPhysics` (the accessors' own
sources): ``_free_state`` (hull pose and velocity in free-joint layout, also for 4 DOF),
``_ensure_fresh`` (kinematics and forces brought up to the current state), ``_diag`` and
``_terms`` (the force kernel's outputs) and ``_idx`` (rudder and sail joint addresses).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from .. import frames
from ..forces import boat as kernels
from ..reference import wille_model

# force term of the physics -> key of the observation's "<key>_wrench" (true_state)
WRENCH_KEYS = {"sail": "sail", "keel": "keel", "rudder": "rudder", "damping": "damping",
               "added_mass": "added_mass", "hydrostatics": "restoring", "restoring": "restoring"}
WRENCH_NAMES = ("sail", "keel", "rudder", "damping", "added_mass", "restoring")

_SITE = mujoco.mjtObj.mjOBJ_SITE
_PI = math.pi
_TWO_PI = 2.0 * math.pi


def _wrench_rows(terms: tuple[str, ...]) -> tuple[tuple[str, ...], np.ndarray]:
    """The observation's wrench keys in the order measure() inserts them (a later name for a
    key overwrites an earlier one in place, then any of the six the physics lacks), and the
    row of each in the physics' terms (``len(terms)``: a row of zeros)."""
    rows: dict[str, int] = {}
    for name, key in WRENCH_KEYS.items():
        if name in terms:
            rows[f"{key}_wrench"] = terms.index(name)
    for key in WRENCH_NAMES:
        rows.setdefault(f"{key}_wrench", len(terms))
    return tuple(rows), np.array(list(rows.values()), dtype=np.int64)


_WRENCH_KEYS, _WRENCH_ROWS = _wrench_rows(kernels.TERMS)
_WILLE_KEYS, _WILLE_ROWS = _wrench_rows(wille_model.TERMS)
_N_WILLE = len(wille_model.TERMS)
_N_TERMS = len(kernels.TERMS)
_D_WIND = kernels.D_WIND_X
_D_FLOW = kernels.D_SAIL_FLOW_X


def _wrap(angle: float) -> float:
    """frames.wrap_angle on a float: the same operations (fmod-based remainder) as numpy's."""
    return (angle + _PI) % _TWO_PI - _PI


def rotation_of(qpos) -> np.ndarray:
    """BoatPhysics.rotation() from the hull's free-joint qpos (``physics._free_state()[0]``)
    already in hand: the same MuJoCo call on the same quaternion."""
    out = np.empty(9)
    mujoco.mju_quat2Mat(out, qpos[3:7])
    return out.reshape(3, 3)


def euler_of(rot) -> tuple[float, float, float]:
    """frames.euler_from_matrix as floats: (heel, pitch, yaw), the same numpy functions on the
    same numbers (np.clip keeps a NaN, as this does), without its array handling."""
    heel = float(np.arctan2(rot[2, 1], rot[2, 2]))
    sin_pitch = rot[2, 0]
    if sin_pitch > 1.0:
        sin_pitch = 1.0
    elif sin_pitch < -1.0:
        sin_pitch = -1.0
    return heel, float(np.arcsin(sin_pitch)), float(np.arctan2(rot[1, 0], rot[0, 0]))


def measure_boat(physics) -> tuple[dict, dict]:
    """(observation, record) of a :class:`~sailmujoco.physics.BoatPhysics` now.

    The observation equals ``measure(physics)``: the same keys in the same order, shapes,
    dtypes and values, in plain dicts (a paper world's observation is one too); the record
    equals what :meth:`SailTask.record` builds from the accessors.
    """
    d = physics.data.ptr
    qpos, qvel = physics._free_state()
    rot = rotation_of(qpos)
    rot_t = rot.T
    body = rot_t @ qvel[0:3]  # body_velocity()
    rates = qvel[3:6]  # angular_velocity(), read before _ensure_fresh refills it (4 DOF): same values
    wind = physics.wind
    current = wind.current
    current_body = rot_t @ current
    t = d.time
    heel, pitch, yaw = euler_of(rot)
    heading = _wrap(_PI / 2.0 - yaw)  # frames.heading_from_yaw
    idx = physics._idx
    rudder, sail = float(d.qpos[idx[0]]), float(d.qpos[idx[2]])

    physics._ensure_fresh()  # the force terms and diagnostics of this very state
    diag = physics._diag
    # apparent_wind_masthead(): the air relative to the masthead, body axes
    m = physics.model.ptr
    site = mujoco.mj_name2id(m, _SITE, "masthead")
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(m, d, _SITE, site, vel, 0)
    air = wind.velocity(t, float(d.site_xpos[site][2])) - vel[3:]
    flow = rot_t @ air
    awa = float(np.arctan2(float(flow[1]), -float(flow[0])))  # frames.apparent_wind_angle
    aws = float(np.hypot(flow[0], flow[1]))

    terms = np.zeros((_N_TERMS + 1, 6))  # with a row of zeros for a wrench the physics lacks
    terms[:_N_TERMS] = physics._terms
    observation = _observation(
        body, current_body, rates, (yaw, heel, pitch, rudder, sail, heading, awa, aws), wind, t,
        diag[_D_WIND:_D_WIND + 2].copy(), diag[_D_FLOW:_D_FLOW + 2].copy(),
        dict(zip(_WRENCH_KEYS, terms[_WRENCH_ROWS], strict=True)), qpos[0:2].copy(),
        qvel[0:2].copy())
    v0, v1 = qvel[0], qvel[1]
    record = {"t": t, "position": qpos[0:2].copy(), "heading": heading, "heel": heel,
              "roll_rate": float(rates[0]), "surge": float(body[0]),
              "course": float(math.atan2(v1, v0)), "speed": float(np.hypot(v0, v1))}
    return observation, record


def measure_wille(world) -> tuple[dict, dict]:
    """(observation, record) of a :class:`~sailmujoco.reference.wille.Wille4DOF` now: what
    ``measure(PaperPhysics(world))`` and the accessor-built record give, bit for bit."""
    state, t, wind = world.state, world._time, world.wind
    heel = float(state[2])  # heel(); pitch() is 0
    yaw = float(_wrap(_PI / 2.0 - state[3]))  # yaw(): frames.yaw_from_heading
    heading = float(_wrap(state[3]))  # heading()
    rot = frames.matrix_from_euler(heel, 0.0, yaw)  # rotation()
    body = world.body_velocity()
    rates = world.angular_velocity()
    current = wind.current
    current_body = rot.T @ current
    flow = world.masthead_flow(rot, body, rates)  # apparent_wind_masthead()
    awa = float(np.arctan2(float(flow[1]), -float(flow[0])))  # frames.apparent_wind_angle
    aws = float(np.hypot(*flow[:2]))
    true_wind = wind.velocity(t, world.params.sail.ce_height * math.cos(heel))  # sail_wind()
    frd, (vws_u, vws_v) = world.terms_and_sail_flow(t, state)  # forces(), _sail_flow()
    # force_terms(): FRD (X, Y, K, N, M) -> FLU (Fx, Fy, Fz, Mx, My, Mz), a row of zeros after
    terms = np.zeros((_N_WILLE + 1, 6))
    terms[:_N_WILLE, 0] = frd[:, 0]
    terms[:_N_WILLE, 1] = -frd[:, 1]
    terms[:_N_WILLE, 3] = frd[:, 2]
    terms[:_N_WILLE, 4] = -frd[:, 4]
    terms[:_N_WILLE, 5] = -frd[:, 3]
    ground = world.ground_velocity()
    position = np.array([state[1], state[0]])
    observation = _observation(
        body, current_body, rates, (yaw, heel, 0.0, state[8], state[9], heading, awa, aws), wind,
        t, np.asarray(true_wind[:2], dtype=np.float64), np.array([vws_u, -vws_v]),
        dict(zip(_WILLE_KEYS, terms[_WILLE_ROWS], strict=True)), position, ground)
    record = {"t": t, "position": position.copy(), "heading": heading, "heel": heel,
              "roll_rate": float(rates[0]), "surge": float(body[0]),
              "course": float(math.atan2(ground[1], ground[0])),
              "speed": float(np.hypot(*ground))}
    return observation, record


def _observation(body, current_body, rates, angles, wind, t, true_wind, apparent_wind_ce,
                 wrenches, position, velocity) -> dict:
    """The observation dict of measure(), keys in its order, from the measured values;
    ``angles``: (yaw, heel, pitch, rudder, sail, heading, apparent wind angle and speed)."""
    yaw, heel, pitch, rudder, sail, heading, awa, aws = angles
    # every scalar a 0-d float64 array of its own (views into one array: one allocation)
    scalars = np.array([
        body[0], body[1], body[2], body[0] - current_body[0], body[1] - current_body[1],
        yaw, heel, pitch, rates[0], rates[1], rates[2], rudder, sail,
        wind.config.speed, _wrap(wind.direction_from(t)), t,
        heading, heel, rates[0], rates[2], awa, aws])
    (u, v, w, u_r, v_r, yaw_, heel_, pitch_, p, q, r, rudder_, sail_, speed_10, direction, time_,
     heading_, heel_top, p_top, r_top, awa_, aws_) = [scalars[i, ...] for i in range(22)]
    true_state = {
        "u": u, "v": v, "w": w, "u_r": u_r, "v_r": v_r, "yaw": yaw_, "heel": heel_,
        "pitch": pitch_, "roll_rate": p, "pitch_rate": q, "yaw_rate": r, "rudder": rudder_,
        "sail": sail_, "true_wind": true_wind, "wind_speed_10": speed_10,
        "wind_direction": direction, "apparent_wind_ce": apparent_wind_ce,
        "current": np.array(wind.current[:2], dtype=np.float64), "time": time_}
    true_state.update(wrenches)
    return {
        "position": position, "velocity": velocity, "heading": heading_,
        "heel": heel_top, "roll_rate": p_top, "yaw_rate": r_top, "apparent_wind_angle": awa_,
        "apparent_wind_speed": aws_, "true_state": true_state}
