"""Shared helpers: boats load in ~0.1 s once the kernels are compiled (cached on disk)."""

import math

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


def only_hull(boat="wille_yacht", hydrostatics="off", **extra):
    """The bare hull: no foils, no damping; added mass on unless switched off."""
    kwargs = dict(hydrostatics=hydrostatics, sail=False, keel=False, rudder=False,
                  damping=False)
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
