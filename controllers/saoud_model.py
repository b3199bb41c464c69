"""The reduced model of Saoud, Hua, Plumet, Ben Amar (2015), "Optimal sail angle computation for
an autonomous sailboat robot", IEEE CDC 2015, pp. 807-813 (hal-03135868): its parameters,
frames, equations (eqs. 3-13) and the tolerances of the solvers built on them.

Solved by :func:`controllers.saoud_optimum.optimal_sail` (readable) and
:func:`controllers.saoud_solver.optimal_sail_compiled` (the same numbers, compiled); used as a
sail law by :class:`controllers.saoud.SaoudSail`.

The sail is trimmed to maximise the longitudinal sail force under the roll equilibrium:

    min  J(delta_s, phi) = f(sin alpha_s) sin delta_s                           (eq. 5)
    s.t. beta sin phi + f(sin alpha_s) cos delta_s = 0,   [ |phi| <= phi_max ]   (eqs. 5, 14)
    sin alpha_s = V1_bar sin delta_s - V2_bar cos phi cos delta_s
    beta = m g l_phi / (lambda_s h_s |V|^2),   lambda_s = rho_air S_s / 2

with f = C_N, the sail's normal force coefficient as a function of sin alpha_s
(:func:`sailmujoco.forces.sail.saoud_normal_coefficient`). The longitudinal sail force is
F_s1 = -lambda_s |V|^2 J (eq. 3), so minimising J maximises the thrust.

Frames and signs (Saoud's own, used by every function here except the controllers' output)
    World NWU, body FLU (x forward, y port, z up). V = R_z(psi)^T (v - v_w) is the velocity of
    the boat through the air in the heading frame (the *opposite* of the apparent wind flow) and
    Theta_V = atan2(V2, V1) (§IV): Theta_V = 0 head to wind, +-pi running, Theta_V > 0 when the
    wind comes from port. phi is the heel, positive starboard side down (eq. 4: the restoring
    moment is -m g l_phi sin phi about body x).
Saoud's sail angle delta_s versus ours
    §IV writes v_as2^S = -V1 sin delta_s + V2 cos phi cos delta_s: the heeled body components of
    v_as are (V1, V2 cos phi, -V2 sin phi) and the sail frame S is R_z(delta_s) of the body
    frame, so i_s = (cos delta_s, sin delta_s, 0) in the body. A positive delta_s turns i_s
    counter-clockwise (towards port). With delta_s in [-pi/2, pi/2] (Remark 2) i_s points
    forward: it is the chord from the clew to the mast, and the boom lies along
    -i_s = (-cos delta_s, -sin delta_s): a positive delta_s swings the boom to STARBOARD.
    Our sail angle lambda (controllers.base) swings the trailing edge to PORT when positive
    (a turn about -z), so lambda = -delta_s: :func:`sail_angle_from_saoud`. Check: wind from
    starboard (Theta_V < 0) gives delta_s* < 0, the boom to port (leeward), lambda > 0.

The heel projection of the wind angle (§IV: tan AWA = cos phi tan Theta_V) is undone in
:func:`saoud_apparent_wind`.

Readings of the text (two extractions: 000_3829400af9344756.txt and 001_a17fd47305b41ae5.txt)
    * Assumption 4 writes F_s ~ -lambda_s C_N |V|^2 j_s, one line after F_s = +lambda_s C_N |V|^2
      j_s - lambda_s C_T |V|^2 i_s. Eq. 3 (tau_s1 = -lambda_s h_s f |V|^2 cos delta_s, F_s1 =
      -lambda_s f |V|^2 sin delta_s) follows only from the + sign (j_s = (-sin delta_s,
      cos delta_s, 0)), which is also the physical one (air flowing towards +j_s, i.e.
      alpha_s > 0, pushes the sail towards +j_s). We read +; only eq. 3 is used.
    * The tangential term is "parallel to v_s" in 000 and "parallel to i_s" in 001; i_s is
      meant (C_T is along the chord). Unused here (Assumption 4).
    * §VI-B: "a straightforward way to solve (13)" means problem (14); "the roll motion
      equilibrium in 5" is the constraint of (5); "excluding solutions where |phi| < phi_max"
      has its inequality reversed: solutions with |phi| > phi_max are excluded (the sentence
      ends "so that ... |phi| < phi_max").
    * Remark 1 bounds |phi*| by pi/4 from tan(2 phi) (eq. 8c), which by itself leaves the branch
      cos(2 phi) < 0 open; eqs. 10c-11 write sqrt(1 - y^2) = 1/sqrt(1 + g_bar^2) > 0, i.e. they
      take cos(2 phi) > 0. We follow eqs. 10c-11, and the tests check Remark 1 on an
      exhaustive search over every heel in [-pi/2, pi/2].
    * The (+-) of eq. 11 and the division by V1 in eq. 12 are replaced by the sign of
      sin delta_s that satisfies eq. 8a (see
      :func:`controllers.saoud_optimum.candidates_from_root`): eq. 12 is singular at beam
      reach.
    * §VII-A's two secant runs can both converge to the same root near beam reach; see
      :func:`controllers.saoud_optimum.eq13_roots` for the fallback.
    * Fig. 5's breakpoints survive only in 001 (see :mod:`controllers.briere`).

Differences from our 6-DOF sail (:mod:`sailmujoco.forces.sail`): Saoud normalises the angle of
attack by the full |V| (sin alpha_s = -v_as2^S / |V|, spanwise flow included) where our sail
drops the spanwise flow; and with lambda = -delta_s the sail normal n equals j_s, so our
alpha is -alpha_s while C_N(alpha) n = C_N(alpha_s) j_s (the force agrees; a test checks it
at zero heel).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from sailmujoco import constants
from sailmujoco.forces.sail import saoud_normal_coefficient
from sailmujoco.frames import saoud_theta_v, wrap_angle

# --- the solvers' tolerances (shared by the readable and the compiled solver) --------------

DERIVATIVE_STEP = 1e-3
"""Largest step of the five-point derivative of f, in x = sin(alpha_s) (error ~1e-11)."""
ROOT_TOL = 1e-12
"""Secant step tolerance on x = sin(alpha_s): the run stops when a step is smaller."""
SECANT_ITERATIONS = 100
"""Most steps of one secant run on eq. 13."""
SAME_ROOT = 1e-8
"""Two roots |x| of eq. 13 closer than this are one."""
BRANCH_TOL = 1e-6
"""Largest residual of eq. 8a for a (delta_s, phi) recovered from a root to be kept."""
ROLL_SCAN = 64
"""Intervals of the delta_s scan over [-pi/2, pi/2] that brackets the roots of the roll
equilibrium at the roll limit (§VI-B)."""
ROOT_SCAN = 48
"""Intervals of the linear part of the |x| scan that brackets the thrust-branch roots (the
fallback near beam reach)."""


@dataclass(frozen=True)
class SaoudParams:
    """Parameters of Saoud's reduced model, SI units (Saoud 2015, Table I).

    Attributes
    ----------
    mass : float
        Boat mass m [kg].
    sail_area : float
        Sail area S_s [m^2].
    gravity : float
        Gravitational acceleration g [m/s^2].
    rho_air : float
        Air density [kg/m^3].
    h_s : float
        Height of the sail's centre of pressure G_s above the CoM G, h_s = GG_s . k_s [m].
    """

    mass: float = 15.0  # kg, Table I
    sail_area: float = 1.0  # m^2, Table I
    gravity: float = constants.GRAVITY  # m/s^2, Table I (9.81)
    rho_air: float = constants.RHO_AIR_SAOUD  # kg/m^3, Table I (1.225)
    h_s: float = 0.8  # m, Table I

    @property
    def lambda_s(self) -> float:
        """lambda_s = rho_air S_s / 2 [kg/m] (§IV)."""
        return 0.5 * self.rho_air * self.sail_area

    def beta(self, l_phi: float, apparent_speed: float) -> float:
        """beta = m g l_phi / (lambda_s h_s |V|^2) [-] (§V, below eq. 5).

        The ratio of the largest righting moment to the sail's heeling moment scale.

        Parameters
        ----------
        l_phi : float
            Metacentric height [m].
        apparent_speed : float
            |V| [m/s].
        """
        return self.mass * self.gravity * l_phi / (self.lambda_s * self.h_s * apparent_speed**2)


TABLE_I = SaoudParams()
"""Saoud (2015) Table I: the default parameters of every solver and of the sail law."""


@dataclass(frozen=True)
class SailOptimum:
    """Solution of problem (5) or (14), in Saoud's frames (radians).

    Attributes
    ----------
    delta : float
        Optimal sail angle delta_s* [rad], in [-pi/2, pi/2] (Remark 2; delta_s* +- pi is the
        same sail line and equally optimal, Lemma 1). Ours is ``sail_angle_from_saoud(delta)``.
    phi : float
        Steady heel phi* [rad], positive starboard side down.
    alpha : float
        Angle of attack alpha_s* [rad]: sin(alpha) = sin(alpha_s*) exactly, and |alpha| > pi/2
        when the air meets the sail from its clew side (only sin alpha_s enters the model).
    cost : float
        J* = f(sin alpha_s*) sin delta_s* [-]; the thrust is F_s1 = -lambda_s |V|^2 J*.
    roll_limited : bool
        True when the optimum is the roll-limit candidate phi = sign(V2) phi_max (§VI-B).
    """

    delta: float
    phi: float
    alpha: float
    cost: float
    roll_limited: bool = False


# --- conversions --------------------------------------------------------------------------


def fold_sail_angle(delta: float) -> float:
    """delta_s folded into [-pi/2, pi/2] by Lemma 1 (delta_s and delta_s +- pi: one sail line).

    Angles already in [-pi/2, pi/2] come back unchanged (the ends included).

    Parameters
    ----------
    delta : float
        Saoud's sail angle delta_s [rad].
    """
    folded = float(wrap_angle(delta))
    if folded > 0.5 * math.pi:
        folded -= math.pi
    elif folded < -0.5 * math.pi:
        folded += math.pi
    return folded


def sail_angle_from_saoud(delta: float) -> float:
    """Our sail angle lambda [rad] from Saoud's delta_s [rad]: lambda = -delta_s.

    The one place where the sign is converted (see the module docstring): Saoud's delta_s
    turns the chord i_s counter-clockwise, so the boom (aft of the mast, along -i_s) swings to
    starboard, whereas our lambda > 0 swings it to port. delta_s is first folded into
    [-pi/2, pi/2] (Lemma 1) so that the boom is aft of the mast.

    Parameters
    ----------
    delta : float
        Saoud's sail angle delta_s [rad].
    """
    return -fold_sail_angle(delta)


def saoud_from_sail_angle(sail_angle: float) -> float:
    """Saoud's delta_s [rad] from our sail angle lambda [rad] in [-pi/2, pi/2]; inverse of
    :func:`sail_angle_from_saoud`.

    Parameters
    ----------
    sail_angle : float
        Our sail angle lambda [rad].
    """
    return -fold_sail_angle(sail_angle)


def saoud_apparent_wind(flow_body_xy, heel: float) -> tuple[float, float]:
    """Saoud's (Theta_V, |V|) from the apparent wind measured in the heeled body frame.

    Parameters
    ----------
    flow_body_xy : array_like, shape (2,)
        Velocity of the air relative to the sail (where it blows to), body x-y components
        (FLU, heeled) [m/s], e.g. ``true_state["apparent_wind_ce"]``.
    heel : float
        Heel phi [rad], positive starboard down.

    Returns
    -------
    theta_v : float
        Theta_V = atan2(V2, V1) [rad] (§IV).
    speed : float
        |V| [m/s].

    Notes
    -----
    With the wind parallel to the water (Assumption 2) and the pitch neglected (Assumption 1),
    the heeled body components of v_as = -flow are R_x(phi)^T V = (V1, V2 cos phi, -V2 sin phi).
    The body x-y reading is therefore (V1, V2 cos phi) and tan(AWA) = cos(phi) tan(Theta_V)
    (§IV; our AWA has the opposite sign, see :mod:`sailmujoco.frames`). Dividing the lateral
    component by cos(phi) restores the heading-frame vector; cos(phi) is floored at 0.1 so that
    a knock-down (|phi| > 84 deg) does not blow it up.
    """
    fx, fy = float(flow_body_xy[0]), float(flow_body_xy[1])
    fy_heading = fy / max(math.cos(heel), 0.1)  # heading-frame lateral flow, -V2
    return saoud_theta_v((fx, fy_heading)), math.hypot(fx, fy_heading)


# --- the model: f, grad f, g and the equations -------------------------------------------


def normal_coefficient(x: float) -> float:
    """Saoud's f(x) = C_N(x), the sail's normal force coefficient (§IV, §VII-A).

    Parameters
    ----------
    x : float
        sin(alpha_s), the sine of the angle of attack [-].

    Returns
    -------
    float
        C_N [-], odd in x.
    """
    return float(saoud_normal_coefficient(x))


def _df(x: float) -> float:
    """grad f(x), by the five-point central difference of f (grad f is even, properties (2)).

    f is only piecewise smooth at 0 (its odd extension, §VII-A), so the stencil is kept on one
    side of 0 (h <= |x|/3); at x = 0, grad f(0) = lim f(h)/h, Richardson-extrapolated.
    """
    if x == 0.0:
        h = 1e-6
        return 2.0 * normal_coefficient(h) / h - normal_coefficient(2.0 * h) / (2.0 * h)
    h = min(DERIVATIVE_STEP, abs(x) / 3.0)
    return (8.0 * (normal_coefficient(x + h) - normal_coefficient(x - h))
            - (normal_coefficient(x + 2.0 * h) - normal_coefficient(x - 2.0 * h))) / (12.0 * h)


def _g(x: float) -> float:
    """g(x) = f grad f / (x grad f + f) (§VI-A, above eq. 11); even, positive for increasing f.

    At x = 0 it is 0/0; its limit is grad f(0) / 2 (f ~ f'(0) x).
    """
    d = _df(x)
    if x == 0.0:
        return 0.5 * d
    fx = normal_coefficient(x)
    return fx * d / (x * d + fx)


def eq13_residual(x: float, v1: float, v2: float, beta: float) -> float:
    """Left-hand side of Saoud (2015) eq. 13 at x = sin(alpha_s).

    2 [x f sqrt(1 + gb^2) - V2^2 g]^2 + V1^2 beta^2 gb^2 sqrt(1 + gb^2) / (1 + sqrt(1 + gb^2))
        - 2 V1^2 f^2 (1 + gb^2),    gb = 2 V2 g / beta,

    with V1, V2 the normalised V_bar_1, V_bar_2. Even in x (Lemma 2), in V1 and in V2.

    Parameters
    ----------
    x : float
        sin(alpha_s) [-].
    v1, v2 : float
        V_bar_1 = cos(Theta_V), V_bar_2 = sin(Theta_V) [-] (§V).
    beta : float
        beta of :meth:`SaoudParams.beta` [-].

    Returns
    -------
    float
        The residual [-]; zero at a root.
    """
    fx = normal_coefficient(x)
    gx = _g(x)
    gb = 2.0 * v2 * gx / beta  # g_bar, §VI-A
    q = math.sqrt(1.0 + gb * gb)
    # Saoud (2015) eq. 13
    return (2.0 * (x * fx * q - v2 * v2 * gx) ** 2 + v1 * v1 * beta * beta * gb * gb * q / (1.0 + q)
            - 2.0 * v1 * v1 * fx * fx * (1.0 + gb * gb))


def branch_point(x: float, v1: float, v2: float, beta: float) -> tuple[float, float] | None:
    """(phi, cos delta_s) of eqs. 10c and 8b at x = sin(alpha_s), or None where f(x) = 0.

    Parameters
    ----------
    x : float
        sin(alpha_s) [-].
    v1, v2 : float
        V_bar_1, V_bar_2 [-] (§V); ``v1`` does not enter eqs. 10c and 8b.
    beta : float
        beta of :meth:`SaoudParams.beta` [-].

    Returns
    -------
    tuple of float or None
        The heel phi [rad] on the branch cos(2 phi) > 0 and cos(delta_s) [-] (not clipped).
    """
    fx = normal_coefficient(x)
    if fx == 0.0:
        return None
    gb = 2.0 * v2 * _g(x) / beta  # g_bar (§VI-A)
    phi = 0.5 * math.atan(gb)  # Saoud (2015) eq. 10c = 8c: tan(2 phi) = g_bar, cos(2 phi) > 0
    return phi, -beta * math.sin(phi) / fx  # Saoud (2015) eq. 8b


def _angle_of_attack(x: float, v1: float, v2: float, delta: float, phi: float) -> float:
    """alpha_s with sin alpha_s = x (§IV), on the side of the chord the air comes from.

    cos alpha_s takes the sign of v_as1^S / |V| = V1 cos delta + V2 cos phi sin delta (the
    chordwise component of v_as in the sail frame): negative when the air meets the clew first.
    """
    chordwise = v1 * math.cos(delta) + v2 * math.cos(phi) * math.sin(delta)
    return math.atan2(x, math.copysign(math.sqrt(max(0.0, 1.0 - x * x)), chordwise))


def sail_candidate(delta: float, phi: float, v1: float, v2: float,
                   roll_limited: bool = False) -> SailOptimum:
    """A point of problem (5): alpha_s from eq. 8a, its cost J = f(x) sin delta (eq. 5).

    Parameters
    ----------
    delta : float
        Sail angle delta_s [rad] (Saoud's).
    phi : float
        Heel [rad], positive starboard side down.
    v1, v2 : float
        V_bar_1, V_bar_2 [-] (§V).
    roll_limited : bool
        Marks a candidate of the roll limit (§VI-B).

    Returns
    -------
    SailOptimum
        The point with its angle of attack and cost.
    """
    x = v1 * math.sin(delta) - v2 * math.cos(phi) * math.cos(delta)  # Saoud (2015) eq. 8a
    cost = normal_coefficient(x) * math.sin(delta)  # Saoud (2015) eq. 5, J = f(x) z (below eq. 9)
    return SailOptimum(delta, phi, _angle_of_attack(x, v1, v2, delta, phi), cost, roll_limited)




def check_arguments(apparent_speed: float, l_phi: float, phi_max: float | None) -> None:
    """The argument checks of the optimal-sail solvers: one-line errors.

    Parameters
    ----------
    apparent_speed : float
        |V| [m/s]; must be positive (Assumption 3).
    l_phi : float
        Metacentric height [m]; must be positive.
    phi_max : float or None
        Roll limit [rad]; None, or in (0, pi/2).

    Raises
    ------
    ValueError
        When an argument is out of its range.
    """
    if not apparent_speed > 0.0:
        raise ValueError(f"apparent_speed must be positive (Assumption 3), got {apparent_speed!r}")
    if not l_phi > 0.0:
        raise ValueError(f"l_phi (metacentric height) must be positive, got {l_phi!r}")
    if phi_max is not None and not 0.0 < phi_max < 0.5 * math.pi:
        raise ValueError(f"phi_max must lie in (0, pi/2) rad, got {phi_max!r}")
