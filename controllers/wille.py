"""Wille, Hassani & Sprenger (2016a): heading control by feedback linearisation (eqs. 44-51)
and its course correction (eqs. 52-59).

Both work in the paper's frames (NED, FRD): the observation (ours: ENU/FLU) is converted in
:func:`_paper_state`, and the rudder angle sigma has our sign already (trailing edge to port
= Wille's positive sigma, see :mod:`sailmujoco.boat.mjcf`).

Eq. 48 cancels the yaw-row nonlinearities: R_psi_d = -C_psi (S + K - C_A(nu_r) nu_r) -
K_p e1 - K_d e2, with e1 = psi - psi_d (eq. 46), e2 = r (eq. 47). The moments S, K and
-C_A(nu_r) nu_r come from the measured full state (``true_state`` wrenches), as the paper
assumes them known ("not meant to be an applicable controller in a real system", §3.1).
Eq. 51 turns the desired moment into a rudder angle with the linearised lift C_L0 (eq. 49).

Course correction: e1 = psi + beta_b - chi_d (eq. 52) with the drift angle the keel needs,
beta_b = -alpha_k cos(phi) (eq. 59), alpha_k = 2 F_U / (rho A_k C_L0k (u^2 + v^2)) (eq. 58),
F_U ~ -S_y' - R_y' (eq. 57), limited to +-10 deg (§3.3).
"""

from __future__ import annotations

import math

import numpy as np

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.params import BoatParams, Foil
from sailmujoco.forces.foil_sections import hydrofoil_coefficients, naca0015
from sailmujoco.frames import wrap_angle

from .base import scalar


def lift_slope(foil: Foil, reynolds: float = 1e6) -> float:
    """C_L0 of eq. 49: dC_L/dalpha at zero incidence of our finite-span foil model, 1/rad.

    Parameters
    ----------
    foil : Foil
        The rudder or keel (aspect and thickness ratios).
    reynolds : float
        Reynolds number of the look-up [-].
    """
    t = naca0015()
    da = math.radians(1.0)
    c_plus = hydrofoil_coefficients(da, reynolds, foil.aspect_ratio, foil.thickness_ratio,
                                    t.alpha, t.log_re, t.cl, t.cd)[0]
    return c_plus / da


def _paper_state(observation: dict) -> dict:
    """Wille's variables (FRD, NED) from our observation."""
    ts = observation["true_state"]
    return {
        "psi": scalar(observation, "heading"),
        "phi": scalar(observation, "heel"),
        "u_r": scalar(ts, "u_r"), "v_r": -scalar(ts, "v_r"),
        "u": scalar(ts, "u"), "v": -scalar(ts, "v"),
        "p": scalar(ts, "roll_rate"), "r": -scalar(ts, "yaw_rate"),
        # FLU wrenches -> FRD yaw moments N and side forces Y
        "N_sail": -float(ts["sail_wrench"][5]), "N_keel": -float(ts["keel_wrench"][5]),
        "N_added": -float(ts["added_mass_wrench"][5]),
        "Y_sail": -float(ts["sail_wrench"][1]), "Y_rudder": -float(ts["rudder_wrench"][1]),
    }


class WilleHeading:
    """Rudder law of eqs. 46-51; with ``course=True`` the course controller of eqs. 52-59.

    Parameters
    ----------
    params : BoatParams
        The boat the controller is designed for (Appendix A for the yacht).
    kp, kd : float
        K_p (N m/rad) and K_d (N m s/rad), Appendix A: 3e5 and 1e6.
    desired : float, optional
        Desired heading (or course), compass rad; default: the observation's
        ``desired_heading`` (or ``desired_course``; a heading controller given only a course
        steers that course as its heading, the paper's beta = 0 assumption).
    course : bool
        Add the correction term beta_b (eq. 52).
    beta_limit : float
        |beta_b| limit, rad (10 deg, §3.3).
    reynolds : float
        Reynolds number at which the rudder's and keel's lift slopes C_L0 are read (eq. 49).
    """

    def __init__(self, params: BoatParams | None = None, kp: float = 3e5, kd: float = 1e6,
                 desired: float | None = None, course: bool = False,
                 beta_limit: float = math.radians(10.0), reynolds: float = 1e6):
        self.params = params or get_boat("wille_yacht")
        self.kp, self.kd = kp, kd
        self.desired = desired
        self.course = course
        self.beta_limit = beta_limit
        self.cl0_rudder = lift_slope(self.params.rudder, reynolds)
        self.cl0_keel = lift_slope(self.params.keel, reynolds)
        self.last_beta_b = 0.0

    def reset(self, seed: int | None = None) -> None:
        """Clear the internal state.

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.last_beta_b = 0.0

    def correction(self, s: dict) -> float:
        """beta_b of eqs. 57-59 (rad), limited to +-beta_limit; 0 when not moving.

        Parameters
        ----------
        s : dict
            Wille's variables (FRD, NED) of the observation: ``u``, ``v``, ``phi``, ``Y_sail``,
            ``Y_rudder``.
        """
        p = self.params
        speed2 = s["u"] ** 2 + s["v"] ** 2
        if speed2 < 1e-6:
            return 0.0
        f_u = -s["Y_sail"] - s["Y_rudder"]  # eq. 57
        alpha_k = 2.0 * f_u / (p.rho_water * p.keel.area * self.cl0_keel * speed2)  # eq. 58
        beta_b = -alpha_k * math.cos(s["phi"])  # eq. 59
        return float(np.clip(beta_b, -self.beta_limit, self.beta_limit))

    def __call__(self, observation: dict) -> float:
        """The rudder angle of eq. 51 for this observation.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Rudder angle sigma, rad, positive trailing edge to port, within the rudder's saturation.
        """
        p = self.params
        s = _paper_state(observation)
        desired = self.desired
        if desired is None:  # the task's reference; a heading controller on a course task
            key = "desired_course" if self.course or "desired_heading" not in observation \
                else "desired_heading"
            desired = scalar(observation, key)
        if self.course:
            self.last_beta_b = self.correction(s)
            e1 = wrap_angle(s["psi"] + self.last_beta_b - desired)  # eq. 52
        else:
            e1 = wrap_angle(s["psi"] - desired)  # eq. 46
        e2 = s["r"]  # eq. 47
        moment = -(s["N_sail"] + s["N_keel"] + s["N_added"]) - self.kp * e1 - self.kd * e2  # eq. 48
        # eq. 34 with eq. 31: the water's angle at the rudder
        l4, h3 = -p.rudder.x, -p.rudder.z
        vcr_u = -s["u_r"]
        vcr_v = -s["v_r"] + s["r"] * l4 + s["p"] * h3
        beta_cr = math.atan2(vcr_v, vcr_u)
        speed2 = vcr_u**2 + vcr_v**2
        denominator = l4 * p.rho_water * p.rudder.area * self.cl0_rudder * speed2 * math.cos(beta_cr)
        if abs(denominator) < 1e-6:
            return 0.0
        sigma = wrap_angle(beta_cr - math.pi) + 2.0 * moment / denominator  # eq. 51
        return float(np.clip(sigma, -p.rudder.max_angle, p.rudder.max_angle))
