"""Shared helpers: boats load in ~0.1 s once the kernels are compiled (cached on disk)."""

import math
import os

# The compile notice (sailmujoco.jit.notice) would add lines to the output that tests read
# exactly when CI starts with a cold kernel cache; tests/test_compile_progress.py checks it.
os.environ.setdefault("SAILMUJOCO_QUIET", "1")

import numpy as np
import pytest

from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

BOATS = ("wille_yacht", "saoud_robot", "viel_boat")
CALM = WindConfig(speed=0.0, gusts=False, wander=False)


def load(boat="wille_yacht", *, wind=CALM, sail_mode="actuated", dofs=6, **switches):
    """A BoatPhysics with the given force switches (ForceSwitches field names)."""
    return BoatPhysics.load(boat, wind=wind, sail_mode=sail_mode, forces=ForceSwitches(**switches),
                            dofs=dofs)


# The papers' forms of the four switches of the boat as built (the defaults are the boat as built)
PAPER_FORMS = dict(resistance="friction", foils="paper", keel_downwash=False, windage=False)


def only_hull(boat="wille_yacht", hydrostatics="off", **extra):
    """The bare hull: no foils, no damping, no windage; added mass on unless switched off."""
    kwargs = dict(hydrostatics=hydrostatics, sail=False, keel=False, rudder=False,
                  damping=False, windage=False)
    kwargs.update(extra)
    return load(boat, **kwargs)


def gusty(speed=10.0, seed=0, direction_deg=45.0):
    return WindConfig(speed=speed, direction_from=math.radians(direction_deg), seed=seed)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


def sail_observation(flow_xy, heel=0.0):
    """The part of an observation a sail law reads: the apparent wind at the sail CE (body x-y,
    FLU, heeled) and at the masthead, the heel, and the same flow as Saoud's V: a boat at rest
    facing east (yaw 0) in a true wind equal to the un-heeled flow. All three wind sources of
    :func:`controllers.saoud.observed_apparent_wind` then read the same (Theta_V, |V|)."""
    from sailmujoco.frames import apparent_wind_angle

    flow_xy = np.asarray(flow_xy, dtype=float)
    level = np.array([flow_xy[0], flow_xy[1] / max(np.cos(heel), 0.1)])
    return {"heel": np.array(heel), "apparent_wind_angle": np.array(apparent_wind_angle(flow_xy)),
            "apparent_wind_speed": np.array(np.hypot(*flow_xy)), "velocity": np.zeros(2),
            "true_state": {"apparent_wind_ce": flow_xy, "true_wind": level, "yaw": np.array(0.0)}}


def hull_solid_below_water(p, heave, trim, heel, n=(400, 160, 120)):
    """(volume, first moment about CO in body axes) of the hull solid below the plane z = 0, by
    a midpoint grid over the solid, independent of the column quadrature the physics integrates.

    The solid as sailmujoco/boat/hull.py defines it: at station x (s = 2x/L) the waterline
    half-breadth is b = b0 (1 - s^2) and the canoe depth t = t0 (1 - s^2); below the waterline
    a half-ellipse, z = -t sqrt(1 - (y/b)^2); outboard of it (b < |y| < k b) the topside,
    z = freeboard (|y| - b) / ((k - 1) b); a flat deck at z = freeboard. Body (x, y, z) goes to
    world height heave + R[2] . (x, y, z) with R from (heel, trim, 0) (frames.py).
    """
    from sailmujoco import frames

    h = p.hull
    k = h.flare
    nx, ny, nz = n
    x = (np.arange(nx) + 0.5) / nx * h.length - h.length / 2
    s = (np.arange(ny) + 0.5) / ny * 2.0 - 1.0  # y / (k b(x)), cell centres
    zeta = (np.arange(nz) + 0.5) / nz  # fraction of the height from the bottom to the deck
    r2 = frames.matrix_from_euler(heel, trim, 0.0)[2]
    volume, moment = 0.0, np.zeros(3)
    for xi in x:
        f = 1.0 - (2.0 * xi / h.length) ** 2
        b, t = h.half_beam * f, h.canoe_draft * f
        y = s * k * b
        inside = np.abs(y) < b
        bottom = np.where(inside, -t * np.sqrt(np.clip(1.0 - (y / b) ** 2, 0.0, None)),
                          h.freeboard * (np.abs(y) - b) / max((k - 1.0) * b, 1e-300))
        z = bottom[:, None] + zeta[None, :] * (h.freeboard - bottom)[:, None]
        cell = (h.length / nx) * (2 * k * b / ny) * ((h.freeboard - bottom) / nz)[:, None]
        wet = cell * (heave + r2[0] * xi + r2[1] * y[:, None] + r2[2] * z < 0.0)
        volume += np.sum(wet)
        moment += [xi * np.sum(wet), np.sum(wet * y[:, None]), np.sum(wet * z)]
    return volume, moment
