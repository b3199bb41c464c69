"""Hull damping: heave and pitch damping act on the vertical motion only."""

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from sailmujoco import frames, suite, sweep
from sailmujoco.constants import GRAVITY
from sailmujoco.forces.damping import vertical_damping
from sailmujoco.physics import ForceSwitches

D33, D55 = 5.0e3, 4.0e4  # N s/m, N m s/rad: any positive pair


def _rot(heel_deg, pitch_deg, yaw_deg):
    return frames.matrix_from_euler(*np.radians([heel_deg, pitch_deg, yaw_deg]))


@pytest.mark.parametrize("flotation_x", [0.0, -0.3])
def test_zero_in_steady_sailing_straight_or_turning(flotation_x, rng):
    """Heeled, trimmed, moving horizontally with leeway, and turning at a steady rate about the
    vertical: nothing moves vertically, so no heave or pitch damping (body w, q are not zero)."""
    for _ in range(20):
        heel, trim, yaw = rng.uniform(-30, 30), rng.uniform(-5, 5), rng.uniform(-180, 180)
        rot = _rot(heel, trim, yaw)
        ground = np.array([*rng.normal(size=2) * 4.0, 0.0])  # world, horizontal
        turn = np.array([0.0, 0.0, rng.normal() * 0.2])  # world yaw rate
        # the centre of flotation moves horizontally: CO's own velocity carries the turn's
        # lever arm, v_CO = v_F - omega x r_F (world)
        r_f = rot @ np.array([flotation_x, 0.0, 0.0])
        v_co = ground - np.cross(turn, r_f)
        nu = np.concatenate([rot.T @ v_co, rot.T @ turn])
        assert abs(nu[2]) + abs(nu[4]) > 1e-3 or abs(heel) < 1 or abs(trim) < 1
        out = np.zeros(6)
        vertical_damping(rot, nu, flotation_x, D33, D55, 0.0, 0.0, out)
        assert np.abs(out).max() < 1e-9


def test_upright_values_and_dissipation(rng):
    """Upright: -d33 w and -d55 q, the linear damping's definition. Any attitude: the power is
    -d33 (dz_F/dt)^2 - d55 (dtheta/dt)^2, the rates measured by finite differences of the pose."""
    out = np.zeros(6)
    vertical_damping(np.eye(3), np.array([2.0, 0.0, 0.1, 0.0, 0.05, 0.0]), 0.0, D33, D55, 0.0, 0.0, out)
    assert out == pytest.approx([0.0, 0.0, -D33 * 0.1, 0.0, -D55 * 0.05, 0.0], abs=1e-12)
    dt = 1e-6
    for _ in range(20):
        rot = _rot(*rng.uniform([-40, -8, -180], [40, 8, 180]))
        nu = rng.normal(size=6) * np.array([3.0, 0.5, 0.3, 0.2, 0.1, 0.2])
        x_f = -0.3
        out[:] = 0.0
        vertical_damping(rot, nu, x_f, D33, D55, 0.0, 0.0, out)
        # pose a moment later (body rates: R' = R exp(omega dt))
        rot2 = rot @ Rotation.from_rotvec(nu[3:] * dt).as_matrix()
        zf_dot = (rot @ (nu[:3] + np.cross(nu[3:], [x_f, 0, 0])))[2]
        theta_dot = (math.asin(rot2[2, 0]) - math.asin(rot[2, 0])) / dt
        power = out[:3] @ nu[:3] + out[3:] @ nu[3:]
        assert power == pytest.approx(-D33 * zf_dot**2 - D55 * theta_dot**2, rel=1e-5, abs=1e-9)


@pytest.mark.parametrize("boat,wind_speed", [("wille_yacht", 6.0), ("saoud_robot", 4.5)])
def test_boat_floats_at_its_weight_in_steady_sailing(boat, wind_speed):
    """Sailing straight in a steady wind (no gusts), heeled and trimmed: the buoyancy equals the
    weight to 0.1 % and the damping has no vertical force. With damping on body w and q (the
    ``body`` form) the boat is pushed deeper."""
    def run(vertical_damping_form):
        env = suite.load(boat, "heading_hold", "mujoco", seed=0, time_limit=90.0, gusts=False,
                         wander=False, wind_speed=wind_speed, wind_from_deg=60.0,
                         forces=ForceSwitches(vertical_damping=vertical_damping_form))
        controller = sweep.make_controller("pid", env)
        controller.reset(0)
        timestep = env.reset()
        while not timestep.last():
            timestep = env.step(controller(timestep))
        physics = env.physics
        rot = physics.rotation()
        hydro = (rot @ physics.force_term("hydrostatics")[:3])[2]
        damping = (rot @ physics.force_term("damping")[:3])[2]
        weight = physics.params.mass * GRAVITY
        return hydro / weight, damping / weight, physics.heel(), physics.pitch()

    hydro, damping, heel, trim = run("world")
    assert abs(math.degrees(heel)) > 2.0 and abs(math.degrees(trim)) > 0.05  # heeled, trimmed
    assert hydro == pytest.approx(1.0, abs=1e-3)
    assert abs(damping) < 5e-4  # what is left of the approach to steady state
    old_hydro, old_damping, _, _ = run("body")
    assert old_hydro - 1.0 > 3e-3 and old_damping < -3e-3

