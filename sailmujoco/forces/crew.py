"""The crew as movable ballast: where it sits, how it crosses in a tack, and its block of ``P``.

The crew is a mass on a slide across the deck (the body y axis), the model's last joint
(:func:`sailmujoco.boat.mjcf.boat_spec`); MuJoCo carries its weight and its inertia, so its
righting moment, m g y cos(heel) about the boat's roll axis against the crew on the centreline,
and the reaction of its moves on the hull come out of the multibody equations, not from a
formula here. What this module gives is the crew's own drive: the force along the slide by
which the crew moves itself.

**Where it sits** (:func:`crew_target`, ours, stated): on the side opposite the boom, the
weather side, ``arm`` off the centreline; within :data:`CENTRED_BOOM` of the centreline (head
to wind) the target moves across linearly, so that it is a continuous function of the boom's
angle and the crew does not chatter between the rails when the boom hangs amidships.

**How it moves** (:func:`crew_drive`, ours): the crew walks across at a steady speed,
2 arm / T_shift, so that a crossing from rail to rail takes T_shift, and settles on its place
with the time constant 1 / :data:`APPROACH_RATE`: its wanted speed is APPROACH_RATE times the way
left, held within that walk, and it reaches it at :data:`HOLD_RATE` (a stiff hold: the boat's roll
and sway shake it by millimetres). The drive also holds the crew against the slope of the heeled
deck (it cancels gravity's component along the slide), as people on a rail hold on: the crew
stays where it sits at any heel.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..jit.kernel import kernel

APPROACH_RATE = 4.0  # 1/s, the crew's wanted speed per metre left to go, near its place (ours)
HOLD_RATE = 20.0  # 1/s, how fast the crew takes up its wanted speed (ours; >> APPROACH_RATE)
CENTRED_BOOM = math.radians(5.0)  # rad, boom angles within which the crew's target is on the move
(CB_MASS, CB_ARM, CB_SPEED) = range(3)
CREW_BLOCK_SIZE = 4


def pack_crew(p, block: np.ndarray) -> None:
    """Write the crew's block of the packed parameters (all 0 without a crew).

    Parameters
    ----------
    p : BoatParams
        The boat.
    block : numpy.ndarray, shape (CREW_BLOCK_SIZE,)
        Its slice of ``P``, written in place.
    """
    block[:] = 0.0
    if p.carries_crew:
        c = p.crew
        block[CB_MASS], block[CB_ARM] = c.mass, c.arm
        block[CB_SPEED] = 2.0 * c.arm / c.shift_time


def loaded_canoe_body(p):
    """The canoe body of ``p`` sunk to carry its crew too (itself without a crew).

    Parameters
    ----------
    p : BoatParams
        The boat.

    Returns
    -------
    HullShape
        The canoe body with its draft times (m + m_crew) / m: its half-elliptic sections, and so
        its volume, scale with the draft.
    """
    if not p.carries_crew:
        return p.hull
    return replace(p.hull, canoe_draft=p.hull.canoe_draft * (p.mass + p.crew.mass) / p.mass)


@kernel
def crew_target(boom_angle, arm):
    """Where the crew sits, m along body y (+ port): opposite the boom, ``arm`` off the centreline.

    Parameters
    ----------
    boom_angle : float
        The main's angle lambda, rad (positive: boom to port).
    arm : float
        The crew's arm on the rail, m.

    Returns
    -------
    float
    """
    share = boom_angle / CENTRED_BOOM
    if share > 1.0:
        share = 1.0
    elif share < -1.0:
        share = -1.0
    return -arm * share


@kernel
def crew_drive(y, y_rate, target, mass, speed, gravity_along):
    """The crew's own force along its slide, N.

    Parameters
    ----------
    y, y_rate : float
        The crew's place on its slide (m, + port) and its rate (m/s).
    target : float
        Where it goes (:func:`crew_target`), m.
    mass : float
        The crew's mass, kg.
    speed : float
        Its walk across, 2 arm / T_shift, m/s.
    gravity_along : float
        Gravity's acceleration along the slide (body y), m/s^2; the drive cancels it.

    Returns
    -------
    float
    """
    wanted = APPROACH_RATE * (target - y)
    if wanted > speed:
        wanted = speed
    elif wanted < -speed:
        wanted = -speed
    return mass * (HOLD_RATE * (wanted - y_rate) - gravity_along)
