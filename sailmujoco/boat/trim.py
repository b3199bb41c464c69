"""The depowering trims a VPP may choose: reefing the main and flattening the rig.

Both follow the ORC VPP's depowering parameters (ORC VPP Documentation, "Optimization and
De-powering"; as Python-VPP implements them, M. Lauber, github.com/marinlauber/Python-VPP,
``SailMod.py`` and ``AeroMod.py``):

* **reef** r: the main hoisted to r of its luff, a slab reef that keeps the sail's shape, so
  its luff and foot scale by r, its area by r^2 and its centre of effort comes down to a third
  of the reefed luff above the boom (the boom stays where it is). ORC's reef runs from 1 down.
* **flat** f: ORC multiplies the rig's lift coefficient by f (0.62-1 in its optimiser's bounds).
  Here the sails themselves are flattened: their camber ratio times f, so the camber's share
  of the lift (2 a camber, :mod:`sailmujoco.forces.sail_camber`) scales by f and the flat
  plate's lift of the incidence stays. That is what a trimmer's outhaul, backstay and
  cunningham do; f = 0 is the flat plate.

A trim returns a new :class:`~sailmujoco.boat.params.BoatParams`; r = f = 1 returns the boat
unchanged (the same object).
"""

from __future__ import annotations

import math
from dataclasses import replace

from .params import BoatParams

FLAT_RANGE = (0.0, 1.0)  # camber multiplier; ORC's optimiser goes down to 0.62
REEF_RANGE = (0.5, 1.0)  # the main's hoist; below half the luff a boat would change sails


def reefed(p: BoatParams, reef: float) -> BoatParams:
    """``p`` with its main reefed to ``reef`` of its luff (area x reef^2, CE lowered).

    Parameters
    ----------
    p : BoatParams
        The boat.
    reef : float
        The reefed luff over the full luff, in :data:`REEF_RANGE`.
    """
    _check("reef", reef, REEF_RANGE)
    if reef == 1.0:
        return p
    s = p.sail
    sail = replace(s, area=s.area * reef**2, ce_aft=s.ce_aft * reef,
                   ce_height=s.boom_height + reef * s.luff / 3.0)
    return p.with_(sail=sail)


def flattened(p: BoatParams, flat: float) -> BoatParams:
    """``p`` with its sails' camber times ``flat``.

    Parameters
    ----------
    p : BoatParams
        The boat.
    flat : float
        The camber multiplier, in :data:`FLAT_RANGE`.
    """
    _check("flat", flat, FLAT_RANGE)
    if flat == 1.0:
        return p
    return p.with_(sail=replace(p.sail, camber=p.sail.camber * flat))


def _check(name: str, value, bounds: tuple[float, float]) -> None:
    low, high = bounds
    if not isinstance(value, (int, float)) or not math.isfinite(value) or not low <= value <= high:
        raise ValueError(f"{name} must be a number in [{low:g}, {high:g}], got {value!r}")
