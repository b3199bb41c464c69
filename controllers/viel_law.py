"""The laws of Viel, Vautier, Wan and Jaulin (2019), position keeping, in Viel's planar frame
(:mod:`sailmujoco.reference.viel`: theta ccw from east, psi_tw/psi_aw the directions the wind
blows *towards*, rudder/sail positive with the trailing edge to starboard):

* rudder, eqs. 10-11, steering the course phi when it is within epsilon_theta of the heading;
* sail, eqs. 12-17: the sail angle is moved at a rate set by the error between the desired
  and the measured acceleration, between the optimal angle (15) and the luffing limit (12);
* velocity, eq. 18: desired acceleration from the distance to the target;
* orientation, §4.3 steps 1-4: direct path, go round the target area to arrive from
  downwind, one tack to go upwind, and head to wind inside the target area (19-22).

The controller that applies them is :class:`controllers.viel.VielController`. The functions are
plain Python; ``register_jitable`` lets the compiled closed loop (:mod:`controllers.viel_loop`)
compile the very same source.

Readings of garbled or inconsistent text (each marked where it is used):

* Eqs. 13-14 mix ``sign(delta_s)`` in the rate with ``|delta_s|`` in the update, and the
  branches "delta_s* dot < 0: speed up" only make sense for a rate of the *magnitude*
  ``|delta_s|``: with the literal sign the law would flip on the port tack. We use the
  magnitude rate ``-k_s (vdot* - vdot)`` (equal to the printed one for delta_s > 0).
* Eq. 18 writes ``v0 = max(0, u tan(theta - hat theta))``; hat theta is never defined. The proof
  (A.2, A.5) uses ``tilde theta = atan(y/x)``, the bearing from the target to the boat
  (= theta* + pi), which we use.
* Step 3: "q is used to select and keep the closer tack", but with q = 1 when theta* is
  nearer ``psi_tw + pi - delta`` the printed ``psi_tw + pi + q delta`` is the *farther* tack,
  and makes the boat tack back and forth on the layline. We use ``psi_tw + pi - q delta``
  (the closer tack, one tack as the text says).
* ε: §5.1 gives only ``epsilon_delta_s = pi/36`` (5 deg, the sail margin of eq. 16);
  epsilon_theta of eq. 10 is not given; its default here is 5 deg too (a guess).
* Eq. 20 is not bounded by delta_s,max; we bound it (the luffing angle head to wind is small).
* "this strategy is maintained only if v >= 0" (end of step 4) is read as the two cases
  (19-20) for v > 0 and (21-22) for v <= 0 as printed.
"""

from __future__ import annotations

import math

from numba.extending import register_jitable

# Modes reported in ``VielController.info["mode"]``: step 1, step 2, step 3, step 4 (eqs. 19-20, 21-22).
GO_DIRECT, GO_ROUND, TACK = "direct", "go_round", "tack"
UPWIND_STOP, UPWIND_DRIVE = "upwind_v>0", "upwind_v<=0"


@register_jitable
def sign(x: float) -> float:
    """np.sign on a float: -1, 0 or 1, NaN for NaN.

    Parameters
    ----------
    x : float
        The number.
    """
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else (0.0 if x == 0.0 else math.nan))


# --- the laws, Viel signs ---------------------------------------------------------------------


@register_jitable
def rudder_law(theta: float, phi: float, theta_bar: float, rudder_max: float, epsilon_theta: float) -> float:
    """delta_r [rad] (Viel sign: positive turns clockwise), eqs. 10-11.

    Steers the course phi when ``cos(theta - phi) >= cos(epsilon_theta)``, else the heading theta.

    Parameters
    ----------
    theta : float
        Heading, ccw from east [rad].
    phi : float
        Course over ground, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    rudder_max : float
        delta_r,max [rad].
    epsilon_theta : float
        Course/heading switch of eq. 10 [rad].
    """
    big_theta = phi if math.cos(theta - phi) - math.cos(epsilon_theta) >= 0.0 else theta  # Viel §3.1
    e = big_theta - theta_bar
    if math.cos(e) >= 0.0:
        return rudder_max * math.sin(e)  # Viel eq. 10
    return rudder_max * sign(math.sin(e))  # Viel eq. 11


@register_jitable
def sail_limit(psi_aw: float, sail_max: float) -> float:
    """delta_s,M = min(|pi - |psi_aw||, delta_s,max) [rad], eq. 12 (the luffing angle).

    Parameters
    ----------
    psi_aw : float
        Direction the apparent wind blows towards, ccw from the bow [rad].
    sail_max : float
        delta_s,max [rad].
    """
    return min(abs(math.pi - abs(psi_aw)), sail_max)  # Viel eq. 12


@register_jitable
def optimal_sail(psi_tw: float, theta_bar: float) -> float:
    """delta_s^opt = (pi/2) (cos(psi_tw - theta_bar) + 1) / 2 [rad], eq. 15.

    Parameters
    ----------
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    """
    return 0.5 * math.pi * (math.cos(psi_tw - theta_bar) + 1.0) / 2.0  # Viel eq. 15


@register_jitable
def adaptive_sail(sail_previous: float, vdot_star: float, vdot: float, psi_aw: float, psi_tw: float,
                  theta_bar: float, k_s: float, dt: float, epsilon_sail: float, sail_max: float) -> float:
    """delta_s [rad] (Viel sign), eqs. 13-14, 16-17.

    ``sail_previous`` is the last delta_s; ``vdot_star``, ``vdot`` the desired and measured
    accelerations [m/s^2]. The rate acts on |delta_s| (see the module docstring).

    Parameters
    ----------
    sail_previous : float
        Last delta_s [rad] (Viel sign).
    vdot_star : float
        Desired acceleration [m/s^2] (eq. 18).
    vdot : float
        Measured acceleration [m/s^2].
    psi_aw : float
        Direction the apparent wind blows towards, ccw from the bow [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    k_s : float
        Sail adaptation gain, eq. 13 [rad s/m].
    dt : float
        Control period [s].
    epsilon_sail : float
        epsilon_delta_s, the sail margin of eq. 16 [rad].
    sail_max : float
        delta_s,max [rad].
    """
    rate = -k_s * (vdot_star - vdot)  # Viel eq. 13, as the rate of |delta_s| (reading, see above)
    star = max(abs(sail_previous) + rate * dt, 0.0)  # Viel eq. 14
    limit = sail_limit(psi_aw, sail_max)  # Viel eq. 12
    side = -sign(psi_aw)  # Viel eq. 12: to leeward
    if rate < 0.0:  # speed up
        lim = max(limit - epsilon_sail, 0.0)  # Viel, below eq. 16: delta_s^lim
        return side * max(star, min(abs(optimal_sail(psi_tw, theta_bar)), lim))  # Viel eq. 16
    return side * min(star, limit)  # Viel eq. 17 (slow down)


@register_jitable
def desired_acceleration(v: float, u: float, theta: float, theta_tilde: float, distance: float,
                         k_v: float, k_p: float) -> float:
    """vdot* = -k_v (v - v0) + k_p d_ST [m/s^2], v0 = max(0, u tan(theta - theta_tilde)), eq. 18.

    Parameters
    ----------
    v : float
        Forward speed [m/s].
    u : float
        Speed to port [m/s].
    theta : float
        Heading, ccw from east [rad].
    theta_tilde : float
        Bearing from the target to the boat, ccw from east [rad].
    distance : float
        Distance to the target d_ST [m].
    k_v : float
        Velocity gain [1/s].
    k_p : float
        Distance gain [1/s^2].
    """
    v0 = max(0.0, u * math.tan(theta - theta_tilde))  # Viel eq. 18 (hat theta read as tilde theta)
    return -k_v * (v - v0) + k_p * distance  # Viel eq. 18


@register_jitable
def go_round(theta_star: float, alpha: float, psi_tw: float, distance: float, d_T: float,
             d_M: float) -> tuple[float, bool]:
    """Step 2: (theta*, turned) — turn theta* by +-pi/2 in the pre-arrival area when the direct
    path would arrive downwind. ``alpha`` is the bearing from the target to the boat [rad].

    Parameters
    ----------
    theta_star : float
        Direct-path heading theta* [rad].
    alpha : float
        Bearing from the target to the boat [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    distance : float
        Distance to the target [m].
    d_T : float
        Radius of the target area [m].
    d_M : float
        Radius of the pre-arrival area [m].
    """
    if d_T <= distance <= d_M and math.cos(theta_star - psi_tw) > 0.0:  # Viel §4.3 step 2
        if math.cos(alpha - (psi_tw + 0.5 * math.pi)) > math.cos(alpha - (psi_tw - 0.5 * math.pi)):
            return theta_star + 0.5 * math.pi, True
        return theta_star - 0.5 * math.pi, True
    return theta_star, False


@register_jitable
def tack(theta_star: float, psi_tw: float, delta: float, q: int) -> tuple[float, int, bool]:
    """Step 3: (theta_bar, q, in_dead_area). q in {-1, 1}; 0 means not chosen yet.

    Parameters
    ----------
    theta_star : float
        Heading theta* of steps 1-2 [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    delta : float
        Hauled angle of the dead area [rad].
    q : int
        The tack kept so far: -1, 1, or 0 for none yet.
    """
    nearer_minus = math.cos(theta_star - (psi_tw + math.pi - delta)) > math.cos(
        theta_star - (psi_tw + math.pi + delta))
    if math.cos(psi_tw - theta_star) + math.cos(delta) > 0.0:  # Viel §4.3 step 3: outside the dead area
        return theta_star, (1 if nearer_minus else -1), False
    if q == 0:  # entering with no history: take the closer tack
        q = 1 if nearer_minus else -1
    return psi_tw + math.pi - q * delta, q, True  # Viel step 3 (sign of q delta: reading, see above)
