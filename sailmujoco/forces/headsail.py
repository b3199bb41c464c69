"""The headsail: its trim rule, its block of the packed parameters, and how it and the main interact.

**The sail.** A flat triangle on the forestay (:class:`~sailmujoco.boat.params.Headsail`), with
the main's coefficients (:func:`sailmujoco.forces.sail.sail_force`: Saoud's C_N or the finite
wing's, at the headsail's own aspect ratio), in the wind at its own centroid's height. Its
sheet leads to the deck, so its force goes to the hull and it has no hinge.

**The trim rule** (:func:`headsail_angle`, ours, stated): delta = the main's lambda, with |delta|
held between the sheet lead's ``min_angle`` and ``max_angle``. Two sails set at the same angle to
the centreline is the rule of thumb sailors trim a jib to the main by, and the lead's inboard limit
is what a fixed jib car gives.

**The interaction** (``ForceSwitches(rig_interaction=...)``):

* ``"none"``: each sail in the flow it would meet alone; the rig's force is the sum of the
  two sails' (what a VPP that adds per-sail coefficients does before its interaction terms).
* ``"lumped_vortex"`` (as built): each sail's section at its centroid's height is one lumped
  vortex at its quarter chord (Katz & Plotkin, *Low-Speed Aerodynamics*, 2nd ed. 2001, §5.2,
  the lumped-vortex element, and §11.1 for the multi-element wing of that model). A sail's
  circulation per unit span follows from its lift by Kutta-Joukowski, L' = rho V x Gamma,
  with the span its luff height; each vortex's velocity, Gamma/(2 pi r) normal to r, is added
  to the other sail's flow at its three-quarter-chord point: the main's upwash lifts the jib
  and the jib's downwash heads the main, the two effects Gentry (1971, "The aerodynamics of
  sail interaction", AIAA Symposium on the Aero/Hydronautics of Sailing) describes. Choices
  of ours: one Jacobi step (each sail's circulation as it would be alone; the exact coupled
  solution differs from it by the square of the coupling), and a vortex core of a quarter of
  the inducing sail's chord (Gamma d / (2 pi (|d|^2 + r_c^2))), as a lumped vortex cannot
  resolve the flow closer to it than that.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel
from .finite_wing import THIN_AIRFOIL_SLOPE, helmbold_lift_slope, viterna_corrigan_cd_max
from .sail import sail_force
from .sail_camber import add_camber_lift

# Offsets inside the headsail's block of P (boat_parameters.P_HEADSAIL_BLOCK)
(HB_AREA, HB_TACK_X, HB_CE_AFT, HB_CE_HEIGHT, HB_MIN, HB_MAX, HB_SLOPE, HB_CD_MAX, HB_SPAN,
 HB_CHORD, HB_MAIN_SPAN, HB_MAIN_CHORD, HB_INTERACTION, HB_CAMBER, HB_MAIN_SLOPE) = range(15)
# HB_CAMBER and HB_MAIN_SLOPE: the rig's camber and the main's finite-wing slope (forces/sail_camber.py)
HEADSAIL_BLOCK_SIZE = 16
CORE_PER_CHORD = 0.25  # vortex core radius / the inducing sail's section chord (module docstring)


def pack_headsail(p, block: np.ndarray) -> None:
    """Write a boat's headsail, and its rig's camber, into their block of P (zero where it has none).

    Parameters
    ----------
    p : BoatParams
        The boat.
    block : numpy.ndarray, shape (HEADSAIL_BLOCK_SIZE,)
        The block, written in place (the interaction switch's slot is left to the switches).
    """
    h = p.headsail
    block[HB_CAMBER] = p.sail.camber  # the rig's camber (forces/sail_camber.py), with or without a headsail
    block[HB_MAIN_SLOPE] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, p.sail.aspect_ratio)
    if not p.carries_headsail:
        block[:HB_INTERACTION] = 0.0
        return
    block[HB_AREA], block[HB_TACK_X] = h.area, h.tack_x
    block[HB_CE_AFT], block[HB_CE_HEIGHT] = h.ce_aft, h.ce_height
    block[HB_MIN], block[HB_MAX] = h.min_angle, h.max_angle
    block[HB_SLOPE] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, h.aspect_ratio)
    block[HB_CD_MAX] = viterna_corrigan_cd_max(h.aspect_ratio)
    block[HB_SPAN], block[HB_CHORD] = h.luff_height, h.section_chord
    block[HB_MAIN_SPAN], block[HB_MAIN_CHORD] = p.sail.luff, 2.0 * p.sail.foot / 3.0


@kernel
def headsail_angle(main_angle, main_rate, low, high):
    """(delta, its rate): the headsail's angle by the trim rule, from the main's.

    Parameters
    ----------
    main_angle, main_rate : float
        The main's angle lambda (rad) and its rate (rad/s).
    low, high : float
        The smallest and largest |delta|, rad.
    """
    size = abs(main_angle)
    sign = 1.0 if main_angle >= 0.0 else -1.0
    if size < low:
        return sign * low, 0.0
    if size > high:
        return sign * high, 0.0
    return main_angle, main_rate


@kernel
def circulation(force, flow, rho, span):
    """The circulation Gamma (about +z, m^2/s) of a sail section whose force is ``force``.

    Kutta-Joukowski, L' = rho V x (Gamma z): Gamma = L'.(V_y, -V_x) / (rho |V|^2), with L' the
    force per unit span; the drag (along V) drops out of the product.

    Parameters
    ----------
    force : numpy.ndarray, shape (3,)
        The sail's force, N (its xy part is used).
    flow : numpy.ndarray, shape (3,)
        The air's velocity relative to the sail, m/s.
    rho : float
        Air density, kg/m^3.
    span : float
        The sail's span (luff height), m.
    """
    v2 = flow[0] * flow[0] + flow[1] * flow[1]
    if v2 <= 0.0:
        return 0.0
    return (force[0] * flow[1] - force[1] * flow[0]) / (rho * v2 * span)


@kernel
def add_induced(gamma, from_x, from_y, at_x, at_y, core, flow):
    """Add a 2-D vortex's velocity at (at_x, at_y) to ``flow``: Gamma z x d / (2 pi (|d|^2 + core^2)).

    Parameters
    ----------
    gamma : float
        Circulation about +z, m^2/s.
    from_x, from_y : float
        The vortex, m.
    at_x, at_y : float
        Where its velocity is wanted, m.
    core : float
        Core radius, m.
    flow : numpy.ndarray, shape (3,)
        Gains the induced velocity in x and y.
    """
    dx, dy = at_x - from_x, at_y - from_y
    k = gamma / (2.0 * math.pi * (dx * dx + dy * dy + core * core))
    flow[0] += -k * dy
    flow[1] += k * dx


@kernel
def interact(main_flow, jib_flow, main_angle, jib_angle, main_point, jib_point, block, tangential,
             suction, stall, friction, rho_air, main_area, main_slope, main_cd_max, chord, normal, main_force,
             jib_force):
    """Each sail's flow gains the other's lumped vortex (one Jacobi step; module docstring).

    Parameters
    ----------
    main_flow, jib_flow : numpy.ndarray, shape (3,)
        The air relative to each sail at its centroid, m/s; each gains the other's velocity.
    main_angle, jib_angle : float
        lambda and delta, rad.
    main_point, jib_point : numpy.ndarray, shape (3,)
        Each sail's centroid, body frame about CO, m (as the force kernel placed them).
    block : numpy.ndarray
        The headsail's block of P.
    tangential, suction, stall, friction, rho_air, main_area, main_slope, main_cd_max
        The coefficients' arguments of :func:`sailmujoco.forces.sail.sail_force` for the main
        (the headsail takes its own area, slope and C_D,max from ``block``).
    chord, normal, main_force, jib_force : numpy.ndarray, shape (3,)
        Work arrays.
    """
    speed, alpha, _, _ = sail_force(main_flow, main_angle, tangential, suction, stall, friction, rho_air,
                                    main_area, main_slope, main_cd_max, chord, normal, main_force)
    add_camber_lift(main_flow, chord, normal, alpha, speed, block[HB_CAMBER], block[HB_MAIN_SLOPE], stall,
                    rho_air, main_area, main_force)
    jib_slope = block[HB_SLOPE] if main_slope > 0.0 else 0.0
    speed, alpha, _, _ = sail_force(jib_flow, jib_angle, tangential, suction, stall, friction, rho_air,
                                    block[HB_AREA], jib_slope, block[HB_CD_MAX], chord, normal, jib_force)
    add_camber_lift(jib_flow, chord, normal, alpha, speed, block[HB_CAMBER], block[HB_SLOPE], stall, rho_air,
                    block[HB_AREA], jib_force)
    gamma_main = circulation(main_force, main_flow, rho_air, block[HB_MAIN_SPAN])
    gamma_jib = circulation(jib_force, jib_flow, rho_air, block[HB_SPAN])
    # quarter- and three-quarter-chord points of each section, along its chord (aft of the CE: +)
    cm, sm = -math.cos(main_angle), math.sin(main_angle)  # the main's chord direction, mast -> leech
    cj, sj = -math.cos(jib_angle), math.sin(jib_angle)
    main_x, main_y, jib_x, jib_y = main_point[0], main_point[1], jib_point[0], jib_point[1]
    qm, qj = 0.25 * block[HB_MAIN_CHORD], 0.25 * block[HB_CHORD]
    add_induced(gamma_jib, jib_x - qj * cj, jib_y - qj * sj, main_x + qm * cm, main_y + qm * sm, qj,
                main_flow)
    add_induced(gamma_main, main_x - qm * cm, main_y - qm * sm, jib_x + qj * cj, jib_y + qj * sj, qm,
                jib_flow)
