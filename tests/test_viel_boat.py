"""viel_boat: Viel et al. (2019) Table 1's 300 kg boat in 6-DOF (sailmujoco/boat/catalogue.py::viel_boat).

Floats at its design draft, its hull has the stated displacement, GM_t and LCB by an integral
independent of hull.py, and it sails a polar of the same order as Viel's own 3-DOF model.
"""

import math

import numpy as np
import pytest
from conftest import load

from sailmujoco import frames
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY, RHO_WATER
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches
from sailmujoco.reference.viel import VielWorld

MASS = 300.0  # kg, Viel Table 1 p9
GM_DESIGN = 1.05  # m, the design GM_t stated in params.viel_boat (a guess, xml/viel_boat/README.md)
CASE_1 = WindConfig(speed=10.0, direction_from=math.pi, gusts=False, wander=False)  # Viel §5.1 case 1


def test_floats_at_design_draft_free_six_dof():
    physics = load("viel_boat", hydrostatics="geometric")
    p = physics.params
    assert p.mass == MASS and p.inertia[2] == 400.0  # Viel Table 1 p9, p10
    physics.step(2000)  # 10 s in calm water, free 6-DOF
    assert physics.position()[2] == pytest.approx(0.0, abs=0.002 * p.hull.canoe_draft + 1e-4)
    assert math.degrees(abs(physics.heel())) < 0.05
    buoyancy = np.linalg.norm(physics.force_term("hydrostatics")[:3])
    assert buoyancy == pytest.approx(MASS * GRAVITY, rel=0.005)


def _midpoint_hull(p, nx=400, ny=200, nz=100):
    """Volume, centroid (x_B, z_B) and waterplane inertia I_T of the canoe body below the design
    waterline, by a midpoint grid over the solid: half-elliptic sections of half-breadth
    b(x) = b0 (1 - (2x/L)^2) and depth t(x) = t0 (1 - (2x/L)^2) (the hull's definition)."""
    h = p.hull
    x = (np.arange(nx) + 0.5) / nx * h.length - h.length / 2
    f = 1.0 - (2.0 * x / h.length) ** 2
    b, t = h.half_beam * f, h.canoe_draft * f
    s = (np.arange(ny) + 0.5) / ny * 2.0 - 1.0  # y / b(x)
    zeta = (np.arange(nz) + 0.5) / nz  # depth fraction
    dx = h.length / nx
    depth = t[:, None] * np.sqrt(1.0 - s[None, :] ** 2)  # (nx, ny) local depth below the waterline
    dy = (2.0 * b / ny)[:, None]
    cells = dx * dy * depth / nz  # each of the nz cells of a column
    volume = float(np.sum(cells) * nz)
    x_b = float(np.sum(cells * nz * x[:, None]) / volume)
    z_b = float(np.sum(cells[:, :, None] * -(zeta[None, None, :] * depth[:, :, None])) / volume)
    y = s[None, :] * b[:, None]
    i_t = float(np.sum(dx * dy * y**2))
    return volume, x_b, z_b, i_t


def test_hull_displacement_gm_and_lcb_by_an_independent_integral():
    p = get_boat("viel_boat")
    volume, x_b, z_b, i_t = _midpoint_hull(p)
    assert volume == pytest.approx(MASS / RHO_WATER, rel=0.02)  # weight = buoyancy
    assert abs(x_b - p.cg_x) < 0.02 * p.hull.length  # LCB under the CG: floats level
    gm = z_b + i_t / volume - p.cg_z
    assert gm == pytest.approx(GM_DESIGN, rel=0.02)
    assert p.gm_t == GM_DESIGN


def _viel_steady_speed(twa_deg, sail, seconds=60.0):
    """Viel's 3-DOF model: heading held by the rudder law below, sail at ``sail`` (ours, rad)."""
    world = VielWorld(wind=CASE_1)
    yaw = float(frames.yaw_from_heading(math.radians(180.0 - twa_deg)))  # wind from the south
    world.reset(state=[0.0, 0.0, yaw, 1.0, 0.0, 0.0])
    speeds = []
    for k in range(int(seconds / 0.1)):
        error = math.atan2(math.sin(world.yaw() - yaw), math.cos(world.yaw() - yaw))
        world.step([float(np.clip(-1.0 * error, -0.6, 0.6)), sail], 0.1)
        if k * 0.1 > seconds - 20.0:
            speeds.append(world.forward_speed())
    return float(np.mean(speeds))


def _six_dof_steady_speed(twa_deg, sail, seconds=60.0, surge=3.0):
    physics = BoatPhysics.load(params=get_boat("viel_boat"), sail_mode="actuated", wind=CASE_1,
                               forces=ForceSwitches(hydrostatics="geometric"), dofs=6)
    yaw = float(frames.yaw_from_heading(math.radians(180.0 - twa_deg)))
    physics.place((0.0, 0.0), yaw, surge)
    speeds, heels = [], []
    for k in range(int(seconds / 0.1)):
        error = math.atan2(math.sin(physics.yaw() - yaw), math.cos(physics.yaw() - yaw))
        physics.set_control([float(np.clip(-1.0 * error, -0.6, 0.6)), sail])
        physics.step(20)
        if k * 0.1 > seconds - 20.0:
            speeds.append(physics.body_velocity()[0])
            heels.append(physics.heel())
    return (float(np.mean(speeds)), math.degrees(float(np.mean(np.abs(heels)))),
            math.degrees(float(np.max(np.abs(heels)))))


def _eq15_sail(twa_deg):
    """Viel eq. 15: delta_s = (pi/2) (cos(psi_tw - theta) + 1) / 2, with psi_tw - theta = pi - TWA
    for a wind blowing towards psi_tw; boom to port on starboard tack (ours: positive)."""
    return 0.5 * math.pi * (math.cos(math.pi - math.radians(twa_deg)) + 1.0) / 2.0


# Wille's eq. 15 friction of viel_boat's hull (k = 0.15, S_H = 3.10 m^2, ITTC-1957 C_F at
# Re = v 4 m / 1.19e-6) over Viel's p2 v^2 at 1, 2, 3 m/s: 6.7/40, 23.5/160, 49.3/360 N, at most 0.17
# (computed by hand in xml/viel_boat/README.md step 6)
FRICTION_OVER_P2 = 0.17


@pytest.mark.parametrize("twa_deg", [60.0, 90.0, 135.0])
def test_sails_its_polar_like_viels_model(twa_deg):
    """Steady speed at a true wind angle, the same sail angle (eq. 15) and the same heading-hold
    rudder law in both worlds, Viel case 1 (10 m/s), both started under way at 3 m/s (Viel's
    reaching speed; from 1 m/s the 6-DOF boat at 60 deg TWA falls into a second, stalled-keel
    equilibrium, crabbing at 0.4 m/s: xml/viel_boat/README.md).

    Bounds from the identification, not from a run: the sail area makes our sail's normal force
    equal Viel's g_s at his case 1 operating point (11.7 m/s, 23.3 deg). Upper: our hull's
    friction is at most FRICTION_OVER_P2 of Viel's p2 v^2; were the sail drive the same and
    friction all the drag, the speed would scale as sqrt(p2 / R_f): < 1 / sqrt(0.17) = 2.4
    times Viel's (residuary resistance, keel and rudder drag only lower it). Lower: heel takes
    the sail's drive as ~cos^2(heel); below 50 deg of heel that is > 0.41, and the boat cannot
    be slower than sqrt(0.41) = 0.64 of Viel's unless its hull drag exceeds his p2 v^2.
    Measured (boat as built: DSYHS, finite foils, downwash, windage): 2.46 vs 3.05, 3.08 vs
    3.88, 3.23 vs 4.44 m/s, steady heel 45, 34, 9 deg: Viel's forces on a 300 kg boat heel
    it 45 deg close-reaching in 10 m/s, which his planar model cannot show.
    """
    sail = _eq15_sail(twa_deg)
    viel = _viel_steady_speed(twa_deg, sail)
    ours, heel, heel_max = _six_dof_steady_speed(twa_deg, sail)
    print(f"TWA {twa_deg:g}: sail {math.degrees(sail):.1f} deg, Viel 3-DOF {viel:.2f} m/s, "
          f"viel_boat 6-DOF {ours:.2f} m/s, heel {heel:.0f} deg, up to {heel_max:.0f}")
    assert viel > 1.0
    assert math.cos(math.radians(50.0)) * viel < ours < viel / math.sqrt(FRICTION_OVER_P2)
    # does not capsize (GM_t 1.05 m, 180 kg bulb, 11.7 m^2 rig, 10 m/s): steady heel inside the
    # lower bound's 50 deg, and no excursion near 90
    assert heel < 50.0 and heel_max < 60.0
