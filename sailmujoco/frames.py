"""Reference frames and sign conventions, defined once for the whole package.

World (MuJoCo)
    x east, y north, z up (ENU). The flat water surface is the plane z = 0.
Body
    origin CO: midship, on the design waterline, above the centre of gravity of the
    Wille yacht (Wille 2016a §2: "CO ... at CG midship and at the waterline").
    x forward, y to port, z up (FLU).

The papers use other frames; convert here and nowhere else:

* Wille (2016a, 2016b): NED world, body x forward, y starboard, z down (FRD), SNAME.
* Saoud (2015): NWU world (x north, y west, z up), body FLU.
* Viel (2019): a planar frame, x east, y north (the same as our world's x-y plane).

Angles (all radians inside the package)

* ``heel`` phi: roll about body x, positive starboard side down. Identical in FLU and FRD
  (a half-turn about x keeps it), so it equals Wille's and Saoud's phi.
* ``pitch`` theta: SNAME pitch, positive bow up.
* ``yaw`` psi: rotation about world z, counter-clockwise from east (ENU yaw).
  ``heading`` is the compass heading, clockwise from north: Wille's psi (NED yaw).
  Saoud's psi (NWU) is ``yaw - pi/2``.
* Wind *direction* means where the wind comes **from**, as a compass bearing (0 = from the
  north, pi/2 = from the east). Wille's beta_w is the direction the wind blows *towards*
  (eq. 42: V_w = U [cos beta_w, sin beta_w] in NED), i.e. ``from + pi``.
* ``apparent wind angle`` (AWA): angle from the bow to the direction the apparent wind comes
  from, measured in the body x-y plane, positive when it comes from starboard.
  Saoud's Theta_V (the angle of v_as = v - v_w, counter-clockwise, in the heading frame) is
  ``-AWA`` up to the heel projection: ``tan AWA = -cos(phi) tan(Theta_V)`` (Saoud §IV).
* Angle of attack of a foil: see :mod:`sailmujoco.forces.foil_geometry`.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

# Permutation/sign matrices between frames (vectors, not rotations of the boat).
_ENU_TO_NED = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
_ENU_TO_NWU = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
_FLU_TO_FRD = np.diag([1.0, -1.0, -1.0])


@register_jitable(nogil=True, error_model="numpy")
def wrap_angle(angle):
    """Wrap an angle (or array of angles) to [-pi, pi): ``(angle + pi) % (2 pi) - pi``.

    The package's one angle wrap. It runs on a Python float (Python's ``%``), on a numpy
    scalar or array (numpy's remainder) and inside a compiled kernel (numba compiles it into
    its caller, with the kernels' flags of :func:`sailmujoco.jit.kernel.kernel`). All three
    take C's ``fmod`` and move a remainder of the wrong sign onto the divisor's side, so a
    float, an array element and a kernel give the same bits for the same angle.

    Parameters
    ----------
    angle : float or numpy.ndarray
        Angle(s), rad (a list: convert it with ``np.asarray`` first).

    Returns
    -------
    float or numpy.ndarray
        The same angle(s) in [-pi, pi), rad, of the type of ``angle`` (a float for a float).
    """
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def ned_from_enu(v):
    """World vector ENU -> NED (Wille).

    Parameters
    ----------
    v : array_like, shape (3,)
        World vector in ENU (x east, y north, z up), any unit.

    Returns
    -------
    numpy.ndarray, shape (3,)
        The same vector in NED (x north, y east, z down).
    """
    return _ENU_TO_NED @ np.asarray(v, dtype=float)


def enu_from_ned(v):
    """World vector NED -> ENU.

    Parameters
    ----------
    v : array_like, shape (3,)
        World vector in NED (x north, y east, z down), any unit.

    Returns
    -------
    numpy.ndarray, shape (3,)
        The same vector in ENU (x east, y north, z up).
    """
    return _ENU_TO_NED.T @ np.asarray(v, dtype=float)


def nwu_from_enu(v):
    """World vector ENU -> NWU (Saoud).

    Parameters
    ----------
    v : array_like, shape (3,)
        World vector in ENU (x east, y north, z up), any unit.

    Returns
    -------
    numpy.ndarray, shape (3,)
        The same vector in NWU (x north, y west, z up).
    """
    return _ENU_TO_NWU @ np.asarray(v, dtype=float)


def enu_from_nwu(v):
    """World vector NWU -> ENU.

    Parameters
    ----------
    v : array_like, shape (3,)
        World vector in NWU (x north, y west, z up), any unit.

    Returns
    -------
    numpy.ndarray, shape (3,)
        The same vector in ENU (x east, y north, z up).
    """
    return _ENU_TO_NWU.T @ np.asarray(v, dtype=float)


def frd_from_flu(v):
    """Body vector FLU (ours) -> FRD (Wille, SNAME). Its own inverse (``flu_from_frd``).

    Parameters
    ----------
    v : array_like, shape (3,)
        Body vector in FLU (x forward, y port, z up), or in FRD for the inverse; any unit.

    Returns
    -------
    numpy.ndarray, shape (3,)
        The same vector in FRD (x forward, y starboard, z down), or in FLU for the inverse.
    """
    return _FLU_TO_FRD @ np.asarray(v, dtype=float)


flu_from_frd = frd_from_flu


def heading_from_yaw(yaw):
    """ENU yaw (ccw from east) -> compass heading (cw from north) = Wille's NED psi.

    Parameters
    ----------
    yaw : float or array_like
        ENU yaw, rad, counter-clockwise from east.

    Returns
    -------
    numpy.ndarray
        Compass heading, rad, clockwise from north, wrapped to [-pi, pi).
    """
    return wrap_angle(np.pi / 2.0 - np.asarray(yaw))


def yaw_from_heading(heading):
    """Compass heading (cw from north) -> ENU yaw (ccw from east).

    Parameters
    ----------
    heading : float or array_like
        Compass heading, rad, clockwise from north.

    Returns
    -------
    numpy.ndarray
        ENU yaw, rad, counter-clockwise from east, wrapped to [-pi, pi).
    """
    return wrap_angle(np.pi / 2.0 - np.asarray(heading))


def saoud_yaw_from_yaw(yaw):
    """ENU yaw -> Saoud's NWU yaw (ccw from north).

    Parameters
    ----------
    yaw : float or array_like
        ENU yaw, rad, counter-clockwise from east.

    Returns
    -------
    numpy.ndarray
        Saoud's psi, rad, counter-clockwise from north, wrapped to [-pi, pi).
    """
    return wrap_angle(np.asarray(yaw) - np.pi / 2.0)


def wind_velocity(speed, direction_from):
    """World (ENU) velocity of a wind of ``speed`` coming from compass bearing ``direction_from``.

    Parameters
    ----------
    speed : float
        Wind speed, m/s.
    direction_from : float
        Compass bearing the wind comes from, rad, clockwise from north (0: from the north).

    Returns
    -------
    numpy.ndarray, shape (3,)
        Velocity of the air in the world frame (ENU), m/s, horizontal.
    """
    return -speed * np.array([math.sin(direction_from), math.cos(direction_from), 0.0])


def wille_beta_w(direction_from):
    """Wille's beta_w (NED direction the wind blows towards) from our 'comes from' bearing.

    Parameters
    ----------
    direction_from : float or array_like
        Compass bearing the wind comes from, rad.

    Returns
    -------
    numpy.ndarray
        Wille's beta_w, rad, the NED bearing the wind blows towards, wrapped to [-pi, pi).
    """
    return wrap_angle(np.asarray(direction_from) + np.pi)


def direction_from_wille_beta_w(beta_w):
    """Our 'comes from' compass bearing from Wille's beta_w (blows towards, NED).

    Parameters
    ----------
    beta_w : float or array_like
        Wille's beta_w, rad, the NED bearing the wind blows towards (Wille 2016a eq. 42).

    Returns
    -------
    numpy.ndarray
        Compass bearing the wind comes from, rad, wrapped to [-pi, pi).
    """
    return wrap_angle(np.asarray(beta_w) + np.pi)


def euler_from_matrix(rot):
    """(heel, pitch, yaw) of a body->world rotation matrix, R = Rz(yaw) Ry(-pitch) Rx(heel).

    heel > 0: starboard down; pitch > 0: bow up (SNAME); yaw: ENU, ccw from east.

    Parameters
    ----------
    rot : array_like, shape (3, 3) or (9,)
        Rotation matrix from the body frame (FLU) to the world frame (ENU), row-major.

    Returns
    -------
    heel, pitch, yaw : float
        Angles, rad.
    """
    rot = np.asarray(rot, dtype=float).reshape(3, 3)
    heel = math.atan2(rot[2, 1], rot[2, 2])  # the C library's, as everywhere per step: numpy's
    pitch = math.asin(min(max(float(rot[2, 0]), -1.0), 1.0))  # SIMD kernels vary by CPU
    yaw = math.atan2(rot[1, 0], rot[0, 0])
    return heel, pitch, yaw


def matrix_from_euler(heel, pitch, yaw):
    """Body->world rotation for (heel, pitch, yaw) as defined in :func:`euler_from_matrix`.

    Parameters
    ----------
    heel : float
        Roll about body x, rad, positive starboard side down.
    pitch : float
        Pitch, rad, positive bow up (SNAME).
    yaw : float
        ENU yaw, rad, counter-clockwise from east.

    Returns
    -------
    numpy.ndarray, shape (3, 3)
        R = Rz(yaw) Ry(-pitch) Rx(heel), body (FLU) to world (ENU).
    """
    ch, sh = math.cos(heel), math.sin(heel)
    cp, sp = math.cos(-pitch), math.sin(-pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    # Rz Ry Rx multiplied out (its zero terms dropped), each entry in one written order
    a00, a02, a10, a12 = cy * cp, cy * sp, sy * cp, sy * sp  # Rz Ry
    return np.array([[a00, -sy * ch + a02 * sh, sy * sh + a02 * ch],
                     [a10, cy * ch + a12 * sh, -cy * sh + a12 * ch],
                     [-sp, cp * sh, cp * ch]])


def quat_from_euler(heel, pitch, yaw):
    """MuJoCo quaternion (w, x, y, z) for (heel, pitch, yaw).

    Parameters
    ----------
    heel : float
        Roll about body x, rad, positive starboard side down.
    pitch : float
        Pitch, rad, positive bow up (SNAME).
    yaw : float
        ENU yaw, rad, counter-clockwise from east.

    Returns
    -------
    numpy.ndarray, shape (4,)
        Unit quaternion (w, x, y, z) of the body->world rotation of :func:`matrix_from_euler`.
    """
    return quat_from_matrix(matrix_from_euler(heel, pitch, yaw))


def quat_from_matrix(rot):
    """Unit quaternion (w, x, y, z) of a rotation matrix, w >= 0 where it can be.

    Parameters
    ----------
    rot : array_like, shape (3, 3) or (9,)
        A rotation matrix, row-major.

    Returns
    -------
    numpy.ndarray, shape (4,)
        (w, x, y, z), unit norm.
    """
    rot = np.asarray(rot, dtype=float).reshape(3, 3)
    w = np.sqrt(max(0.0, 1.0 + rot[0, 0] + rot[1, 1] + rot[2, 2])) / 2.0
    if w > 1e-6:
        x = (rot[2, 1] - rot[1, 2]) / (4.0 * w)
        y = (rot[0, 2] - rot[2, 0]) / (4.0 * w)
        z = (rot[1, 0] - rot[0, 1]) / (4.0 * w)
        q = np.array([w, x, y, z])
    else:  # half-turn: fall back to the largest diagonal element
        i = int(np.argmax(np.diag(rot)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = np.sqrt(max(0.0, 1.0 + rot[i, i] - rot[j, j] - rot[k, k])) * 2.0
        q = np.zeros(4)
        q[0] = (rot[k, j] - rot[j, k]) / s
        q[1 + i] = s / 4.0
        q[1 + j] = (rot[j, i] + rot[i, j]) / s
        q[1 + k] = (rot[k, i] + rot[i, k]) / s
    return q / math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])


def ned_frd_quaternion(rot):
    """ArduPilot's attitude: the quaternion (w, x, y, z) of the rotation from body FRD to world
    NED, from our body FLU -> world ENU rotation: ``R_ned_frd = T_ned_enu R T_flu_frd``.

    Parameters
    ----------
    rot : array_like, shape (3, 3) or (9,)
        Rotation from the body frame (FLU) to the world frame (ENU).

    Returns
    -------
    numpy.ndarray, shape (4,)
        (w, x, y, z) of body FRD -> world NED; its Euler angles (3-2-1) are the heel (roll,
        starboard down positive), the pitch (bow up positive) and the compass heading (yaw).
    """
    return quat_from_matrix(_ENU_TO_NED @ np.asarray(rot, dtype=float).reshape(3, 3) @ _FLU_TO_FRD)


def euler_from_ned_quaternion(q):
    """(roll, pitch, yaw) of a body FRD -> world NED quaternion, 3-2-1 (aerospace) order, rad;
    yaw is the compass heading.

    Parameters
    ----------
    q : array_like, shape (4,)
        (w, x, y, z).
    """
    w, x, y, z = (float(v) for v in q)
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return roll, pitch, yaw


def apparent_wind_angle(flow_body):
    """AWA from the apparent wind velocity in the body frame (FLU).

    The wind comes from ``-flow``; AWA is positive when it comes from starboard (-y).

    Parameters
    ----------
    flow_body : array_like, shape (2,) or (3,)
        Velocity of the air relative to the point (where it blows to), in the body frame
        (x forward, y port), m/s; only x and y are read.

    Returns
    -------
    float
        Apparent wind angle, rad, in (-pi, pi]: 0 wind from ahead, positive from starboard.
    """
    fx, fy = float(flow_body[0]), float(flow_body[1])
    return math.atan2(fy, -fx)


def saoud_theta_v(flow_heading_frame):
    """Saoud's Theta_V from the apparent wind in the (un-heeled) heading frame, FLU.

    Saoud §IV: V = R_z(psi)^T (v - v_w) = -flow, Theta_V = atan2(V2, V1).

    Parameters
    ----------
    flow_heading_frame : array_like, shape (2,) or (3,)
        Velocity of the air relative to the boat in the heading frame (x forward along the
        heading, y to port, horizontal), m/s.

    Returns
    -------
    float
        Saoud's Theta_V, rad, counter-clockwise.
    """
    return math.atan2(-float(flow_heading_frame[1]), -float(flow_heading_frame[0]))
