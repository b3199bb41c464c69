"""The sail look-up tables of Wille, Hassani & Sprenger (2016b), §2.1-2.2, eqs. 60-63.

* **Off-line look-up tables** (§2.1-2.2, eqs. 60-63). For the apparent-wind angle at the sail
  CE, beta_ws, on a 1 deg grid, every feasible sail angle lambda (eqs. 61-62, with lambda_sat)
  is traversed with *our* sail force model (:mod:`sailmujoco.forces.sail`, the same functions
  the physics kernel calls) for a unit apparent wind. This gives the relative surge force
  S_x'r = S_x' / V_ws^2 and relative roll moment S_phi_r = S_phi / V_ws^2. Stored per row:
  lambda_100 (maximum surge force) and lambda_67, lambda_33, lambda_0 (maximum surge force
  with a relative moment of at most 67 %, 33 %, 0 % of lambda_100's, the last "or as low as
  possible"), each found on the far side of the previous one (sign continuity).
* **On-line inversion.** For a measured beta_ws the four solutions are interpolated linearly
  between the two neighbouring grid rows (unless a solution jumps between them, then the
  nearest row is used), and lambda is interpolated linearly in the relative moment between
  the four (moment, lambda) pairs.

The tables are what :class:`controllers.wille_roll.WilleRollSail` inverts for the sail angle
that gives the roll moment its LQR asks for.

Wille's beta_ws in our frames
-----------------------------
Wille (2016a) eq. 26 gives V_ws, the velocity of the air relative to the sail CE (where it
blows *to*) in his body frame FRD (x forward, y starboard), and eq. 27
beta_ws = atan2(V_ws_v, V_ws_u). Our observation ``true_state["apparent_wind_ce"]`` is the same
air velocity in our body frame FLU (x forward, y port), flow = (f_x, f_y), so::

    beta_ws = atan2(-f_y, f_x)           (FRD y = -FLU y, see frames.frd_from_flu)
    beta_ws = wrap(AWA + pi)             (AWA: where the wind comes from, + from starboard)

beta_ws = 0: wind from astern; +pi/2: the air blows to starboard, i.e. the wind comes from
port; +-pi: head to wind. beta_ws > 0 (wind from port) heels the boat to starboard (phi > 0)
and needs lambda <= 0 (boom to starboard); beta_ws < 0 is the mirror image. Wille's lambda and
our sail angle are the same number (trailing edge to port positive, :mod:`sailmujoco.frames`).
Our angle of attack (forces/foil_geometry.py) is minus Wille's alpha_s of eq. 28; the tables never use either.
S_x' is the body-x force (the same axis in FRD and FLU); S_phi = h1 S_y'(FRD) (eq. 29, third
row) is the roll moment about CO, which in FLU is -h1 F_y: positive heels to starboard, our
heel sign. The tables hold the *whole* force of our model (our flat AR 5 sail, C_N and C_T),
not Marchaj's coefficients that Wille used.

Readings chosen where the extracted text of the papers is garbled or silent
---------------------------------------------------------------------------
* The 2016b text writes beta_wr in two places (§2.2, §4) where the tables are indexed by
  beta_ws (eqs. 60, 63): we read beta_ws.
* "Relative moment of 67 % or less compared to that of lambda_100": the moment counted in the
  heeling direction of the wind's side, side * S_phi_r <= 0.67 side * S_phi_r(lambda_100),
  with side = sign(beta_ws). A windward (negative) moment satisfies the 0 % constraint.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from sailmujoco.boat.catalogue import wille_yacht
from sailmujoco.boat.params import BoatParams
from sailmujoco.forces.sail import sail_forces

# ---- numbers of Wille (2016b) §2 and ours ---------------------------------------------------
FRACTIONS = (0.67, 0.33, 0.0)  # §2.2, moment limits of lambda_67, lambda_33, lambda_0
SOLUTIONS = ("lambda_100", "lambda_67", "lambda_33", "lambda_0")
BETA_STEP = math.radians(1.0)  # rad, grid of beta_ws (§2.1: "a step size of 1deg")
LAMBDA_STEP = math.radians(0.1)  # rad, traversal step in lambda (ours; not given)
MAX_JUMP = math.radians(5.0)  # rad, largest change between grid rows still linearised (ours)


# ================================================================================ frames
def beta_ws_from_flow(flow_body) -> float:
    """Wille's beta_ws (eq. 27) from the air velocity relative to the sail CE in our body frame.

    Parameters
    ----------
    flow_body : array_like, (2,) or (3,)
        Air velocity relative to the CE (where it blows to), body FLU [m/s].

    Returns
    -------
    float
        beta_ws = atan2(V_ws_v, V_ws_u) with V_ws in FRD, i.e. atan2(-f_y, f_x) [rad].
    """
    flow = np.asarray(flow_body, dtype=float)
    return float(math.atan2(-flow[1], flow[0]))  # Wille (2016a) eq. 27, FRD y = -FLU y


def flow_from_beta_ws(beta_ws: float, speed: float = 1.0) -> np.ndarray:
    """Body-FLU air velocity (3,) [m/s] of an apparent wind of ``speed`` at angle ``beta_ws``.

    Parameters
    ----------
    beta_ws : float
        Apparent-wind angle at the CE [rad] (eq. 27).
    speed : float
        Apparent wind speed [m/s].
    """
    return np.array([speed * math.cos(beta_ws), -speed * math.sin(beta_ws), 0.0])


def feasible_sail_range(beta_ws: float, lambda_sat: float, side: int | None = None):
    """Sail angles the sheet can hold, Wille (2016b) eqs. 61-62 with lambda_sat.

    Parameters
    ----------
    beta_ws : float
        Apparent-wind angle at the CE [rad], in [-pi, pi].
    lambda_sat : float
        Largest sail angle [rad].
    side : {+1, -1}, optional
        +1: wind from port (the beta_ws > 0 branch), -1: from starboard (beta_ws < 0). Needed
        only at beta_ws = 0, where eqs. 61-62 leave the branch open; default sign(beta_ws),
        +1 at 0.

    Returns
    -------
    (float, float)
        (lambda_l, lambda_u) [rad].
    """
    if side is None:
        side = 1 if beta_ws >= 0.0 else -1
    if side > 0:  # beta_ws > 0: eq. 61 lambda_u = 0, eq. 62 lambda_l = beta_ws - pi
        return max(beta_ws - math.pi, -lambda_sat), 0.0
    return 0.0, min(beta_ws + math.pi, lambda_sat)  # beta_ws < 0: eq. 61, eq. 62


# ================================================================================ sail force
def relative_sail_force(beta_ws: float, sail_angle, params: BoatParams | None = None, *,
                        tangential: bool = True) -> np.ndarray:
    """Sail force per squared apparent wind speed, from our sail model.

    The flow at the CE is a unit apparent wind at angle ``beta_ws``; the force is
    F = q A (C_T c - C_N n), q = rho_a |w|^2 / 2, with c = (cos l, -sin l, 0) and
    n = (sin l, cos l, 0), exactly as :func:`sailmujoco.forces.boat.boat_forces` builds it.

    Parameters
    ----------
    beta_ws : float
        Wille's apparent-wind angle at the CE [rad] (eq. 27).
    sail_angle : float or array_like
        lambda [rad], positive with the trailing edge to port.
    params : BoatParams, optional
        Boat (default :func:`~sailmujoco.boat.catalogue.wille_yacht`).
    tangential : bool
        Keep the sail's tangential force coefficient C_T (the physics default).

    Returns
    -------
    np.ndarray, shape (..., 3)
        Body-FLU force / V_ws^2 [N s^2/m^2 = kg/m]. S_x'r (eq. 60) is ``[..., 0]``; the
        relative roll moment about CO, S_phi_r (eq. 63), is ``-h1 * [..., 1]`` [kg].
    """
    p = wille_yacht() if params is None else params
    s = p.sail
    lam = np.asarray(sail_angle, dtype=float)
    result = np.empty((lam.size, 3))
    sail_forces(flow_from_beta_ws(beta_ws), lam.ravel(), tangential, s.suction_efficiency, s.suction_stall,
                s.friction_coefficient, p.rho_air, s.area, result)
    return result.reshape(lam.shape + (3,))


def relative_surge_and_moment(beta_ws: float, sail_angle, params: BoatParams | None = None, *,
                              tangential: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(S_x'r, S_phi_r) of eqs. 60 and 63 [kg/m, kg] for sail angle(s) ``sail_angle`` [rad].

    Parameters
    ----------
    beta_ws : float
        Apparent-wind angle at the CE [rad] (eq. 27).
    sail_angle : float or array_like
        lambda [rad].
    params : BoatParams, optional
        Boat (default the Wille yacht).
    tangential : bool
        Keep C_T in the sail force.
    """
    p = wille_yacht() if params is None else params
    force = relative_sail_force(beta_ws, sail_angle, p, tangential=tangential)
    # Wille (2016a) eq. 29 rows 1 and 3: S_x', S_phi = h1 S_y'(FRD) = -h1 F_y(FLU)
    return force[..., 0], -p.sail.ce_height * force[..., 1]


# ================================================================================ tables
@dataclass(frozen=True, eq=False)
class SailTable:
    """The look-up table of one wind side (Wille 2016b §2.1-2.2).

    Attributes
    ----------
    side : int
        +1: wind from port, beta_ws in [0, pi], lambda <= 0, heel > 0.
        -1: wind from starboard, beta_ws in [-pi, 0], lambda >= 0, heel < 0.
    beta_ws : np.ndarray, (n,)
        Ascending grid of beta_ws [rad].
    sail_angle : np.ndarray, (n, 4)
        lambda_100, lambda_67, lambda_33, lambda_0 [rad].
    surge : np.ndarray, (n, 4)
        S_x'r at those angles [kg/m] (eq. 60).
    moment : np.ndarray, (n, 4)
        S_phi_r at those angles [kg] (eq. 63), signed like the heel.
    """

    side: int
    beta_ws: np.ndarray
    sail_angle: np.ndarray
    surge: np.ndarray
    moment: np.ndarray

    def solutions(self, beta_ws: float, max_jump: float = MAX_JUMP):
        """The four solutions at ``beta_ws``, linearised between grid rows (§2.1).

        Rows i and i+1 around ``beta_ws`` are blended linearly when no lambda differs by more
        than ``max_jump`` [rad] between them ("only a small difference"); otherwise the
        nearest row is used. Returns (sail_angle (4,), surge (4,), moment (4,)).

        Parameters
        ----------
        beta_ws : float
            Apparent-wind angle at the CE [rad] (eq. 27).
        max_jump : float
            Largest lambda change between rows still blended [rad].
        """
        row = self._solution_row(beta_ws, max_jump)
        return row[0:4].copy(), row[4:8].copy(), row[8:12].copy()

    @cached_property
    def _lookup(self):
        """The grid as floats, each row's largest lambda change to the next, and the rows of
        sail_angle, surge and moment side by side (n, 12): what a look-up reads."""
        jumps = np.max(np.abs(np.diff(self.sail_angle, axis=0)), axis=1)
        rows = np.hstack([self.sail_angle, self.surge, self.moment])
        rows.flags.writeable = False
        return self.beta_ws.tolist(), jumps.tolist(), rows, [(None, None, None)]

    def _solution_row(self, beta_ws: float, max_jump: float) -> np.ndarray:
        """The (12,) row of :meth:`solutions` (read-only). The last one is kept, since a
        controller asks for the same wind angle more than once a step: for the very same
        float objects (same bits), in one tuple (threads sharing the table see whole ones)."""
        grid, jumps, rows, last = self._lookup
        kept_beta, kept_jump, kept_row = last[0]
        if kept_beta is beta_ws and kept_jump is max_jump:
            return kept_row
        b = min(max(beta_ws, grid[0]), grid[-1])
        # np.searchsorted(grid, b) - 1, clipped to a row with a next one (NaN sorts last)
        i = bisect.bisect_left(grid, b) if b == b else len(grid)
        i = min(max(i - 1, 0), len(grid) - 2)
        t = (b - grid[i]) / (grid[i + 1] - grid[i])
        if jumps[i] > max_jump:
            row = rows[i if t < 0.5 else i + 1]
        else:
            row = (1.0 - t) * rows[i] + t * rows[i + 1]
            row.flags.writeable = False
        last[0] = (beta_ws, max_jump, row)
        return row


@dataclass(frozen=True, eq=False)
class SailCommand:
    """Result of the on-line inversion: the sail angle and where it lies in the table.

    Parameters
    ----------
    sail_angle : float
        The sail angle that gives the relative moment asked for, rad.
    saturation : int
        +1 at lambda_100 (no more moment available), -1 at lambda_0 (no less), 0 in between.
    lambda_100 : float
        The maximum-surge sail angle, rad.
    moment_100, moment_0 : float
        Relative roll moments of lambda_100 and lambda_0, kg (N m per (m/s)^2).
    """

    sail_angle: float
    saturation: int
    lambda_100: float
    moment_100: float
    moment_0: float


@dataclass(frozen=True, eq=False)
class WilleSailTables:
    """Both wind sides of the look-up table and the on-line inversion (Wille 2016b §2).

    Parameters
    ----------
    port, starboard : SailTable
        The tables for the wind from port (beta_ws > 0) and from starboard.
    max_jump : float
        Largest change of a solution between grid rows still linearised, rad.
    """

    port: SailTable
    starboard: SailTable
    max_jump: float = MAX_JUMP

    def table(self, beta_ws: float, side: int | None = None) -> SailTable:
        """The half for ``beta_ws`` [rad]: port for beta_ws > 0 (and 0 unless ``side`` = -1).

        Parameters
        ----------
        beta_ws : float
            Apparent-wind angle at the CE [rad] (eq. 27).
        side : {+1, -1}, optional
            +1 port, -1 starboard; default sign(beta_ws), port at 0.
        """
        if side is None:
            side = 1 if beta_ws >= 0.0 else -1
        return self.port if side > 0 else self.starboard

    def solutions(self, beta_ws: float, side: int | None = None):
        """(sail_angle (4,), surge (4,), moment (4,)) of lambda_100, _67, _33, _0 at beta_ws.

        Parameters
        ----------
        beta_ws : float
            Apparent-wind angle at the CE [rad] (eq. 27).
        side : {+1, -1}, optional
            Wind side; needed only at beta_ws = 0 (see :meth:`table`).
        """
        return self.table(beta_ws, side).solutions(beta_ws, self.max_jump)

    def optimal_sail_angle(self, beta_ws: float, side: int | None = None) -> float:
        """lambda_100 [rad]: the sail angle of maximum surge force (§2.1).

        Parameters
        ----------
        beta_ws : float
            Apparent-wind angle at the CE [rad] (eq. 27).
        side : {+1, -1}, optional
            Wind side; needed only at beta_ws = 0 (see :meth:`table`).
        """
        return float(self.table(beta_ws, side)._solution_row(beta_ws, self.max_jump)[0])

    def sail_command(self, beta_ws: float, relative_moment: float,
                     side: int | None = None) -> SailCommand:
        """Sail angle giving the desired relative roll moment (§2.2, the reverse process).

        Parameters
        ----------
        beta_ws : float
            Apparent-wind angle at the CE [rad].
        relative_moment : float
            Desired S_phi_r = S_phi / V_ws^2 [kg], signed like the heel.
        side : {+1, -1}, optional
            Wind side at beta_ws = 0 (see :meth:`table`).

        Returns
        -------
        SailCommand
            lambda interpolated linearly in the moment between the four solutions, clamped at
            lambda_100 and lambda_0.
        """
        half = self.table(beta_ws, side)
        row = half._solution_row(beta_ws, self.max_jump).tolist()
        lam, moment = row[0:4], row[8:12]
        # in the heeling direction of this wind side the moments rise from lambda_0 to
        # lambda_100; reverse to ascending order
        heeling = [half.side * m for m in moment[::-1]]
        angles = lam[::-1]
        wanted = half.side * relative_moment
        if wanted >= heeling[-1]:
            angle, saturation = angles[-1], 1
        elif wanted <= heeling[0]:
            angle, saturation = angles[0], -1
        else:
            k = bisect.bisect_right(heeling, wanted) - 1  # np.searchsorted(side="right") - 1
            t = (wanted - heeling[k]) / (heeling[k + 1] - heeling[k])
            angle, saturation = angles[k] + t * (angles[k + 1] - angles[k]), 0
        return SailCommand(float(angle), saturation, lam[0], moment[0], moment[3])


def pick_solutions(lam: np.ndarray, surge: np.ndarray, heeling: np.ndarray) -> np.ndarray:
    """Indices of lambda_100, _67, _33, _0 in one row of the traversal.

    ``heeling`` is the moment in the heeling direction of the wind side. Ties in surge go to
    the smaller moment, which keeps the four moments ordered.

    Parameters
    ----------
    lam : np.ndarray
        Sail angles of the traversal [rad], (m,).
    surge : np.ndarray
        S_x'r at those angles [kg/m], (m,).
    heeling : np.ndarray
        S_phi_r in the heeling direction of the wind side [kg], (m,).

    Returns
    -------
    np.ndarray
        (4,) indices into ``lam``.
    """

    def best(mask):
        candidates = np.flatnonzero(mask)
        top = surge[candidates].max()
        tied = candidates[surge[candidates] == top]
        return int(tied[np.argmin(heeling[tied])])

    i100 = best(np.ones(lam.size, dtype=bool))
    m100 = heeling[i100]
    if m100 <= 1e-9:  # no heeling moment to reduce (head to wind, dead run)
        return np.array([i100] * 4)
    chosen = [i100]
    direction = 0.0
    for fraction in FRACTIONS:
        previous = chosen[-1]
        if len(chosen) == 1:
            allowed = np.ones(lam.size, dtype=bool)
        else:  # sign continuity: on the far side of the previous solution
            allowed = direction * (lam - lam[previous]) >= 0.0
        within = allowed & (heeling <= fraction * m100)
        if within.any():
            index = best(within)
        else:  # "or as low as possible"
            lowest = heeling[allowed].min()
            index = best(allowed & (heeling == lowest))
        if len(chosen) == 1:
            direction = float(np.sign(lam[index] - lam[i100]))
        chosen.append(index)
    return np.array(chosen)


def _build_half(params, side, beta_step, lambda_step, tangential) -> SailTable:
    n = int(round(math.pi / beta_step))
    grid = side * np.linspace(0.0, math.pi, n + 1)
    if side < 0:
        grid = grid[::-1]
    lambda_sat = params.sail.max_angle
    angles = np.empty((grid.size, 4))
    surges = np.empty((grid.size, 4))
    moments = np.empty((grid.size, 4))
    for row, beta in enumerate(grid):
        low, high = feasible_sail_range(beta, lambda_sat, side)  # eqs. 61-62
        count = int(math.ceil((high - low) / lambda_step - 1e-9)) + 1
        # the grid grows from lambda = 0 outwards, so that both sides mirror exactly
        outward = np.linspace(0.0, high - low, count)
        lam = -outward if side > 0 else outward
        surge, moment = relative_surge_and_moment(beta, lam, params, tangential=tangential)
        pick = pick_solutions(lam, surge, side * moment)
        angles[row], surges[row], moments[row] = lam[pick], surge[pick], moment[pick]
    for array in (grid, angles, surges, moments):
        array.flags.writeable = False
    return SailTable(side, grid, angles, surges, moments)


@lru_cache(maxsize=8)
def build_sail_tables(params: BoatParams | None = None, *, beta_step: float = BETA_STEP,
                      lambda_step: float = LAMBDA_STEP, tangential: bool = True,
                      max_jump: float = MAX_JUMP) -> WilleSailTables:
    """Compute the look-up tables of Wille (2016b) §2.1-2.2 for a boat (cached).

    Parameters
    ----------
    params : BoatParams, optional
        Boat (default the Wille yacht). Uses the sail geometry, lambda_sat and rho_air.
    beta_step : float
        Grid step in beta_ws [rad] (1 deg in the paper).
    lambda_step : float
        Traversal step in lambda [rad].
    tangential : bool
        Keep C_T in the sail force (as the physics does by default).
    max_jump : float
        Largest lambda change between grid rows that is still linearised [rad].

    Returns
    -------
    WilleSailTables
    """
    p = wille_yacht() if params is None else params
    if not 0.0 < beta_step <= math.pi / 2.0 or abs(math.pi / beta_step - round(math.pi / beta_step)) > 1e-6:
        raise ValueError(f"beta_step must divide pi, got {beta_step}")
    if lambda_step > p.sail.max_angle or lambda_step <= 0.0:
        raise ValueError(f"lambda_step must be in (0, lambda_sat], got {lambda_step}")
    port = _build_half(p, 1, beta_step, lambda_step, tangential)
    starboard = _build_half(p, -1, beta_step, lambda_step, tangential)
    return WilleSailTables(port, starboard, max_jump)
