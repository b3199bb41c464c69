"""The roll LQR of Wille, Hassani & Sprenger (2016b), §4, eqs. 64-71: the linearised roll
model about the heel phi_w = phi_d and its gain, for :class:`controllers.wille_roll.WilleRollSail`.

Readings chosen where the extracted text of the papers is garbled or silent
---------------------------------------------------------------------------
* Eq. 66 prints ``rho_w g V GM_t ((1 - 2 sin(phi_w)^2) phi + C_1`` with an unbalanced
  parenthesis. The Taylor expansion of eq. 20, k sin(phi) cos(phi), about phi_w is
  k (1 - 2 sin^2 phi_w)(phi - phi_w) + k sin(phi_w) cos(phi_w), which has eq. 67's C_1 as its
  constant only when written in the deviation phi - phi_w; eq. 70 also feeds back phi - phi_d
  with phi_d = phi_w. We read eq. 66 as G_phi = k (1 - 2 sin^2 phi_w)(phi - phi_w) + C_1.
* Eq. 69 prints B as a column "0, 1, I_xx - K_pdot": the fraction bar was lost. We read
  B = [0, 1 / (I_xx - K_pdot)]^T (u is a moment, eq. 70).

The Riccati equation of this two-state, one-input model is solved in closed form (below), not
by scipy's CARE solver: LAPACK takes its kernels from the CPU, and the gain's last bits with
them, and every later bit of a run follows the gain.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sailmujoco.boat.catalogue import wille_yacht
from sailmujoco.boat.params import BoatParams
from sailmujoco.constants import GRAVITY

# ---- numbers of Wille (2016b) §4 ------------------------------------------------------------
PHI_D = math.radians(10.0)  # rad, desired heel = linearisation point phi_w (§4)
Q_WEIGHTS = (0.75, 1.0)  # eq. 71, weights on (phi - phi_d) [1/rad^2] and p [s^2/rad^2]
R_WEIGHT = 1e-10  # §4, weight on u [1/(N m)^2]


@dataclass(frozen=True, eq=False)
class RollLQR:
    """The linearised roll model and its LQR gain, Wille (2016b) eqs. 64-71.

    Attributes
    ----------
    A, B : np.ndarray
        (2, 2) and (2, 1), state x = (phi - phi_w, p) [rad, rad/s], input u [N m].
    Q, R : np.ndarray
        Weights (eq. 71 and §4).
    K : np.ndarray, (2,)
        Gain [N m/rad, N m s/rad], u = -K x.
    stiffness : float
        rho_w g V GM_t [N m/rad] (eq. 20).
    inertia : float
        I_xx - K_pdot [kg m^2].
    phi_w : float
        Linearisation point [rad].
    """

    A: np.ndarray
    B: np.ndarray
    Q: np.ndarray
    R: np.ndarray
    K: np.ndarray
    stiffness: float
    inertia: float
    phi_w: float

    def c1(self, phi_w: float | None = None) -> float:
        """C_1 = rho_w g V GM_t cos(phi_w) sin(phi_w) [N m], eq. 67 (odd in phi_w).

        Parameters
        ----------
        phi_w : float, optional
            Linearisation heel [rad]; default :attr:`phi_w`.
        """
        phi = self.phi_w if phi_w is None else phi_w
        return self.stiffness * math.cos(phi) * math.sin(phi)  # Wille (2016b) eq. 67


def roll_lqr(params: BoatParams | None = None, *, phi_w: float = PHI_D,
             q: tuple[float, float] = Q_WEIGHTS, r: float = R_WEIGHT) -> RollLQR:
    """Build A, B (eqs. 68-69) and solve the LQR (eq. 71) in closed form.

    With A = [[0, 1], [a, 0]], B = [0, b]^T, Q = diag(q1, q2), R = r and P = [[p1, p2], [p2, p3]],
    the algebraic Riccati equation A^T P + P A - P B R^-1 B^T P + Q = 0 reads, entry by entry,
    2 a p2 - (b^2/r) p2^2 + q1 = 0, 2 p2 - (b^2/r) p3^2 + q2 = 0 and
    p1 + a p3 - (b^2/r) p2 p3 = 0. The stabilising solution (A - B K Hurwitz, P > 0) takes
    p2 = (r/b^2)(a + sqrt(a^2 + q1 b^2/r)) = q1 / (sqrt(a^2 + q1 b^2/r) - a) and
    p3 = sqrt((r/b^2)(2 p2 + q2)); K = (b/r)(p2, p3) (MATLAB's lqr, K = R^-1 B^T P).
    tests/test_cpu_targets.py holds it to scipy's CARE solver.

    Parameters
    ----------
    params : BoatParams, optional
        Boat (default the Wille yacht): I_xx, K_pdot, m, rho_w, GM_t. The displacement is
        V = m / rho_w.
    phi_w : float
        Equilibrium heel [rad]; A depends on it only through cos(2 phi_w).
    q, r : weights of eq. 71 and §4.
    """
    p = wille_yacht() if params is None else params
    inertia = p.inertia[0] - p.added_mass[3]  # I_xx - K_pdot, kg m^2 (K_pdot < 0)
    stiffness = p.rho_water * GRAVITY * p.displaced_volume * p.gm_t  # N m/rad, eq. 20
    # Wille (2016b) eq. 68 (the slope of eq. 66)
    A = np.array([[0.0, 1.0],
                  [-stiffness * (1.0 - 2.0 * math.sin(phi_w) ** 2) / inertia, 0.0]])
    B = np.array([[0.0], [1.0 / inertia]])  # Wille (2016b) eq. 69, see the module docstring
    Q = np.diag(q)  # Wille (2016b) eq. 71
    R = np.array([[r]])
    a, b, (q1, q2) = float(A[1, 0]), float(B[1, 0]), (float(v) for v in q)
    root = math.sqrt(a * a + q1 * b * b / r)
    # a + root cancels where a < 0 (a heel below 45 deg): there its conjugate form
    p2 = r / (b * b) * (a + root) if a >= 0.0 else q1 / (root - a)
    p3 = math.sqrt(r / (b * b) * (2.0 * p2 + q2))
    K = np.array([b / r * p2, b / r * p3])  # K = R^-1 B^T P
    for array in (A, B, Q, R, K):
        array.flags.writeable = False
    return RollLQR(A, B, Q, R, K, stiffness, inertia, phi_w)
