"""Energy of the free, undamped boat: an oscillation keeps its energy.

The boat floats in calm water with the foils, the sail force and the hull damping switched
off, and the rudder and sail servos undamped (kv = 0: a lossless spring on each hinge). What
remains is conservative, so its energy

    E = T_RB + T_A + U_g + U_h + U_s

is constant along an exact solution:

* T_RB, rigid-body kinetic energy of hull, rudder and boom: sum over bodies of
  1/2 m |v_c|^2 + 1/2 w^T I_c w (velocity of each body's CG, inertia about it), plus
  1/2 armature qdot^2 of each servo hinge (the motor's reflected inertia);
* T_A, kinetic energy of the added mass: 1/2 nu^T M_A nu, with nu = (u, v, w, p, q, r) the
  hull's body-frame velocity at CO (no current) and M_A = diag(params.added_mass_diagonal).
  The augmented mass matrix and the Kirchhoff velocity terms are the equations of motion of
  exactly this kinetic energy, so it is conserved with them. The boat as built
  (``added_mass_coupling="impulse"``) leaves out the pitch Munk moment of the heave added
  mass, whose power P = (a11 - a33) u w q the kept forces of its triple then take
  (:mod:`sailmujoco.forces.added_mass`); the check is E(t) - E(0) = integral of P dt, and with
  the energy-neutral forms P = 0;
* U_g = -sum m_i g . x_i, gravity on every body;
* U_h, the hydrostatic potential (one per mode, below);
* U_s = sum 1/2 kp (act - q)^2, the servo springs (act is the filtered command, here 0).

Hydrostatic potentials, derived from the forces the kernels apply:

``geometric``: buoyancy is +rho g per unit volume below the plane z = 0 and nothing above, the
negative gradient of u(z) = -rho g min(z, 0). Over the hull U_h = -rho g int_wet z dV. The
kernel cuts each column of :func:`sailmujoco.boat.hull.column_quadrature` (footprint A, along body
z from z_bottom to z_top) exactly along its axis, so on the same columns, with body s along a
column and world height z(s) = z_CO + R20 x + R21 y + R22 s,

    U_h = -rho g sum_k A_k int_{z_bottom}^{min(z_top, s_w)} z(s) ds,   z(s_w) = 0.

``paper``: the vertical force (W - k_z (z_G - z_G0)) through G gives
-W z_G + 1/2 k_z (z_G - z_G0)^2; the generalised force -K sin(phi) cos(phi) (Wille) or
-K sin(phi) (Saoud) on the heel angle gives 1/2 K sin^2(phi) or K (1 - cos(phi)); the pitch
moment k_theta sin(theta) about the level axis y1 gives k_theta (1 - cos(theta)), with
K = rho g V GM_t, k_z = rho g A_wp, k_theta = rho g V GM_L. The moments act about level axes,
so none does work on a yaw rate. (Taken about body axes, the form kept to measure it, their component
about the world vertical does: +3.2 % in 60 s for the yacht given 0.05 rad/s of yaw rate,
whatever the integrator.) Both modes start with a yaw rate.

The tolerance: under 1 % of the oscillation energy E(0) - E(home) in 60 s at
the default step. MuJoCo's first-order integrators treat the velocity-dependent forces and
the configuration-dependent mass matrix at the start of the step and miss it by up to 17 %
(the last test shows the check can tell).
"""

import math

import mujoco
import numpy as np
import pytest
from conftest import CALM

from sailmujoco import frames
from sailmujoco.boat import hull as hull_geometry
from sailmujoco.constants import GRAVITY
from sailmujoco.forces.damping import pitch_angle_rate
from sailmujoco.physics import BoatPhysics, ForceSwitches

SECONDS = 60.0


def free_boat(boat, hydrostatics, coupling="impulse"):
    """The undamped free boat: buoyancy and added mass only, lossless servo springs."""
    physics = BoatPhysics.load(boat, wind=CALM, forces=ForceSwitches(
        hydrostatics=hydrostatics, sail=False, keel=False, rudder=False, damping=False,
        added_mass=True, windage=False, added_mass_coupling=coupling))
    m = physics.model.ptr
    m.actuator_biasprm[:, 2] = 0.0  # kv = 0: the servos keep their spring, lose their damper
    return physics


def hydrostatic_potential(physics, d, rot):
    p = physics.params
    rho_g = p.rho_water * GRAVITY
    z = d.qpos[2]
    if physics.switches.hydrostatics == "geometric":
        cols = hull_geometry.column_quadrature(p.hull)
        h = z + rot[2, 0] * cols.x + rot[2, 1] * cols.y  # world height of each column's s = 0
        top = np.minimum(cols.z_top, -h / rot[2, 2])  # the wet part ends at the water plane

        def primitive(s):  # int z(s) ds
            return h * s + 0.5 * rot[2, 2] * s * s

        wet = top > cols.z_bottom
        return -rho_g * np.sum(np.where(wet, cols.area * (primitive(top) - primitive(cols.z_bottom)),
                                        0.0))
    volume = p.displaced_volume
    k_roll = rho_g * volume * p.gm_t
    k_heave = rho_g * hull_geometry.waterplane_area(p.hull)
    k_pitch = rho_g * volume * hull_geometry.gm_longitudinal(p.hull, p.cg_z)
    heel = math.atan2(rot[2, 1], rot[2, 2])
    pitch = math.asin(rot[2, 0])
    z_g = z + rot[2, 0] * p.cg_x + rot[2, 2] * p.cg_z
    u = -p.mass * GRAVITY * z_g + 0.5 * k_heave * (z_g - p.cg_z) ** 2
    u += k_roll * (0.5 * math.sin(heel) ** 2 if p.paper_righting == "sin_cos"
                   else 1.0 - math.cos(heel))
    return u + k_pitch * (1.0 - math.cos(pitch))


def energy(physics, state):
    """E of the state (qpos, qvel, act) of ``physics``'s model, from first principles."""
    m = physics.model.ptr
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:], d.act[:] = state
    mujoco.mj_forward(m, d)  # kinematics only matter here; no force of ours is involved
    kinetic = 0.0
    vel = np.zeros(6)
    for body in range(1, m.nbody):  # velocity (rot, lin) at each CG, in its principal axes
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, body, vel, 1)
        kinetic += 0.5 * m.body_mass[body] * vel[3:] @ vel[3:]
        kinetic += 0.5 * m.body_inertia[body] @ (vel[:3] ** 2)
    kinetic += 0.5 * m.dof_armature @ (d.qvel * d.qvel)  # the servo motors' inertia
    hull = m.body("hull").id
    mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_XBODY, hull, vel, 1)
    nu = np.concatenate([vel[3:], vel[:3]])  # (u, v, w, p, q, r) at CO, body axes
    added = 0.5 * physics.params.added_mass_diagonal @ (nu * nu)
    gravity = -np.sum(m.body_mass * (d.xipos @ m.opt.gravity))
    rot = d.xmat[hull].reshape(3, 3)
    springs = 0.0
    for i in range(m.nu):
        q = d.qpos[m.jnt_qposadr[m.actuator_trnid[i, 0]]]
        springs += 0.5 * m.actuator_gainprm[i, 0] * (d.act[i] - q) ** 2
    return kinetic + added + gravity + hydrostatic_potential(physics, d, rot) + springs


def impulse_power(physics):
    """P = (a11 - a33) u w q of the impulse form (module docstring), W, q the pitch angle's
    rate (:func:`sailmujoco.forces.damping.pitch_angle_rate`)."""
    if physics.switches.added_mass_coupling != "impulse":
        return 0.0
    a = physics.params.added_mass_diagonal
    u, _, w = physics.body_velocity()
    _, q, r = physics.angular_velocity()
    pitching = -pitch_angle_rate(physics.rotation(), q, r)  # the rate the form takes for q
    return (a[0] - a[2]) * u * w * pitching


def drift(boat, hydrostatics, *, yaw_rate, integrator=None, coupling="impulse", surge=0.0):
    """Relative change of the oscillation energy in SECONDS from heel 10, pitch 1 deg, heave 2 cm,
    less the work of the impulse form's left-out moments; and that work, both over E(0)."""
    physics = free_boat(boat, hydrostatics, coupling)
    m, d = physics.model.ptr, physics.data.ptr
    if integrator is not None:
        m.opt.integrator = integrator
    home = (d.qpos.copy(), d.qvel.copy(), d.act.copy())
    with physics.reset_context():
        d.qpos[2] = 0.02
        d.qpos[3:7] = frames.quat_from_euler(math.radians(10.0), math.radians(1.0), 0.0)
        d.qvel[5] = yaw_rate
        d.qvel[0] = surge
    e_home = energy(physics, home)
    e_start = energy(physics, (d.qpos, d.qvel, d.act)) - e_home
    work, power, dt = 0.0, impulse_power(physics), physics.timestep()
    for _ in range(int(round(SECONDS / dt))):
        physics.step(1)
        after = impulse_power(physics)
        work += 0.5 * (power + after) * dt
        power = after
    e_end = energy(physics, (d.qpos, d.qvel, d.act)) - e_home
    return (e_end - e_start - work) / e_start, work / e_start


def test_energy_matches_the_mass_matrix():
    """T_RB from the bodies equals 1/2 qvel^T M qvel (MuJoCo's own mass matrix)."""
    physics = free_boat("saoud_robot", "geometric")
    m = physics.model.ptr
    d = mujoco.MjData(m)
    rng = np.random.default_rng(3)
    d.qpos[:] = physics.data.qpos
    d.qpos[3:7] = frames.quat_from_euler(0.3, -0.1, 1.0)
    d.qvel[:] = rng.normal(size=m.nv)
    a = physics.params.added_mass_diagonal
    mujoco.mj_forward(m, d)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    rot = d.xmat[m.body("hull").id].reshape(3, 3)
    nu = np.concatenate([rot.T @ d.qvel[0:3], d.qvel[3:6]])
    still = d.qvel.copy()
    still[:] = 0.0
    static = energy(physics, (d.qpos, still, d.act))
    total = energy(physics, (d.qpos, d.qvel, d.act))
    assert total - static == pytest.approx(0.5 * d.qvel @ full @ d.qvel + 0.5 * a @ (nu * nu),
                                           rel=1e-10)


@pytest.mark.parametrize("boat", ["wille_yacht", "saoud_robot"])
@pytest.mark.parametrize("hydrostatics", ["paper", "geometric"])
def test_undamped_oscillation_keeps_its_energy(boat, hydrostatics):
    change, _ = drift(boat, hydrostatics, yaw_rate=0.05)
    assert abs(change) < 0.01


@pytest.mark.parametrize("coupling", ["manoeuvring", "kirchhoff"])
def test_the_energy_neutral_forms_keep_it_with_no_work_term(coupling):
    change, work = drift("wille_yacht", "paper", yaw_rate=0.05, coupling=coupling)
    assert abs(change) < 0.01 and work == 0.0


def test_the_impulse_forms_work_is_what_the_energy_check_needs():
    """The yacht heeled and pitched with a yaw rate, under way at 1 m/s: the left-out moment's
    work is more than the check's 1 % of the energy in 60 s, and the balance closes with it."""
    change, work = drift("wille_yacht", "paper", yaw_rate=0.05, surge=1.0)
    assert abs(work) > 0.01
    assert abs(change) < 0.01


def test_first_order_integrator_fails_the_same_check():
    """The check can tell: implicit-fast at the same step loses 6.1 % on the robot."""
    assert drift("saoud_robot", "paper", yaw_rate=0.0, coupling="manoeuvring",
                 integrator=mujoco.mjtIntegrator.mjINT_IMPLICITFAST)[0] < -0.05
