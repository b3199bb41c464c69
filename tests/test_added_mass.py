"""Added mass solved exactly inside the step: step forces give F / (m + A), no lag."""

import math

import mujoco
import numpy as np
import pytest
from conftest import only_hull

from sailmujoco import frames
from sailmujoco.forces.added_mass import (
    IMPULSE,
    KIRCHHOFF,
    MANOEUVRING,
    added_mass_velocity_terms,
    kirchhoff_terms,
)
from sailmujoco.forces.damping import pitch_angle_rate


def _accelerate(physics, wrench, seconds=1.0):
    physics.model.opt.gravity[:] = 0.0
    physics.set_external_wrench(wrench)
    velocities = []
    for _ in range(int(round(seconds / physics.timestep()))):
        physics.step(1)
        velocities.append(physics.body_velocity())
    return np.array(velocities)


@pytest.mark.parametrize("axis,index", [("surge", 0), ("sway", 1), ("heave", 2)])
def test_step_force_gives_f_over_m_plus_added_mass(axis, index):
    physics = only_hull("wille_yacht")
    p = physics.params
    force = 500.0
    wrench = np.zeros(6)
    wrench[index] = force
    # through the centre of rigid plus added mass, m r_G / (m + A) from CO (the added mass acts
    # at CO, the rigid mass at the CG), so the hull translates without turning:
    # (m + A) a = F and the moment about CO is m r_G x a
    share = p.mass / (p.mass - p.added_mass[index])
    wrench[3:] = share * np.cross([p.cg_x, 0.0, p.cg_z], wrench[:3])
    v = _accelerate(physics, wrench)
    dt = physics.timestep()
    # slope over the second half: the rudder and boom servos have settled by then
    half = v.shape[0] // 2
    t = np.arange(v.shape[0]) * dt
    slope = np.polyfit(t[half:], v[half:, index], 1)[0]
    expected = force / (p.mass - p.added_mass[index])
    assert slope == pytest.approx(expected, rel=0.01)
    # and without added mass, F / m: the test can tell the difference
    assert abs(expected - force / p.mass) / expected > 0.05


def test_heave_added_mass_acts_from_the_first_step():
    """No lag: the very first step already has a = F / (m + A33), with A33 > m."""
    physics = only_hull("wille_yacht")
    p = physics.params
    assert -p.added_mass[2] > p.mass
    physics.model.opt.gravity[:] = 0.0
    physics.set_external_wrench([0, 0, 1000.0, 0, 0, 0])
    physics.step(1)
    w = physics.body_velocity()[2]
    assert w / physics.timestep() == pytest.approx(1000.0 / (p.mass - p.added_mass[2]), rel=1e-9)


def test_augmented_mass_matrix_equals_dense_solve(rng):
    """The qacc MuJoCo integrates equals (M_RB + J^T M_A J)^-1 tau on a random state."""
    physics = only_hull("wille_yacht", hydrostatics="geometric", damping=True)
    m, d = physics.model.ptr, physics.data.ptr
    # one stage, so the qacc left after step(1) is the start state's (RK4 leaves its last
    # stage's, at another state; each RK4 stage solves the same augmented system)
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    d.qpos[3:7] = [math.cos(0.1), math.sin(0.1), 0.05, 0.2]
    d.qpos[3:7] /= np.linalg.norm(d.qpos[3:7])
    d.qvel[:] = rng.normal(size=m.nv) * 0.3
    before = mujoco.MjData(m)
    before.qpos[:], before.qvel[:], before.act[:] = d.qpos, d.qvel, d.act
    mujoco.mj_forward(m, before)
    rigid = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, before, rigid)
    rot = before.xmat[m.body("hull").id].reshape(3, 3)
    a = physics.params.added_mass_diagonal
    added = np.zeros((m.nv, m.nv))
    added[:3, :3] = rot @ np.diag(a[:3]) @ rot.T
    added[3:6, 3:6] = np.diag(a[3:])
    physics.step(1)
    expected = np.linalg.solve(rigid + added, d.qfrc_smooth)
    assert d.qacc == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert np.abs(np.linalg.solve(rigid, d.qfrc_smooth) - d.qacc).max() > 1e-3


def test_munk_moment_sign_and_size():
    """Yaw row of the velocity terms = (a11 - a22) u v (Wille eq. 10's Munk moment)."""
    a = np.array([160.0, 1200.0, 9000.0, 1000.0, 20000.0, 2400.0])
    out = np.zeros(6)
    u, v = 3.0, 0.4
    added_mass_velocity_terms(np.array([u, v, 0, 0, 0, 0.0]), a, IMPULSE, 0.0, out)
    assert out[5] == pytest.approx((a[0] - a[1]) * u * v)
    assert out[:5] == pytest.approx(np.zeros(5))
    # pure rotation about z: omega x (A2 omega) vanishes, the force is A1 (w x v) - w x (A1 v)
    added_mass_velocity_terms(np.array([u, 0, 0, 0, 0, 0.2]), a, IMPULSE, 0.0, out)
    assert out[1] == pytest.approx(a[1] * 0.2 * u - a[0] * 0.2 * u)


@pytest.mark.parametrize("coupling", [MANOEUVRING, KIRCHHOFF])
def test_velocity_terms_do_no_work(coupling, rng):
    """An ideal fluid's added-mass Coriolis terms are gyroscopic: F.v + M.omega = 0, with and
    without the heave/pitch couplings (each left-out triple is energy-neutral on its own)."""
    a = np.array([160.0, 1200.0, 9600.0, 1000.0, 26000.0, 2400.0])
    out = np.zeros(6)
    for _ in range(20):
        nu = rng.normal(size=6) * np.array([3.0, 0.5, 0.3, 0.2, 0.1, 0.2])
        kirchhoff_terms(nu, a, coupling, 0.0, out)
        assert abs(out @ nu) < 1e-9 * np.abs(out).sum() * np.abs(nu).sum()


def test_impulse_form_does_the_work_of_the_munk_moment_it_leaves_out(rng):
    """Without the pitch Munk moment (a33 - a11) u w, the kept forces of its triple do the work
    the moment would have taken: F.v + M.omega = (a11 - a33) u w q."""
    a = np.array([160.0, 1200.0, 9600.0, 1000.0, 26000.0, 2400.0])
    out = np.zeros(6)
    for _ in range(20):
        u, v, w, p, q, r = nu = rng.normal(size=6) * np.array([3.0, 0.5, 0.3, 0.2, 0.1, 0.2])
        kirchhoff_terms(nu, a, IMPULSE, -q, out)  # upright: the pitch angle's rate is -q
        power = (a[0] - a[2]) * u * w * q
        assert out @ nu == pytest.approx(power, rel=1e-9, abs=1e-9)


def _forced_heave_and_pitch(coupling, speed=2.0, period=2.5, heave=0.1, pitch=0.05, lag=0.9, n=4000):
    """The added mass's world force over one period of a prescribed heave z = Z sin(w t) and
    pitch theta = Theta sin(w t + lag) (bow up) at a constant speed ahead, in still water:
    the explicit velocity terms turned to the world, minus R A1 R^T times the world acceleration
    (the part the augmented mass matrix supplies, forces/added_mass.py). Returns the force
    samples (n, 3) and the body velocities (n, 6)."""
    a = np.array([160.0, 1200.0, 8080.0, 1000.0, 22350.0, 2400.0])  # the Wille yacht's
    omega = 2.0 * math.pi / period
    t = np.arange(n) * period / n
    theta = pitch * np.sin(omega * t + lag)
    theta_dot = pitch * omega * np.cos(omega * t + lag)
    z_dot = heave * omega * np.cos(omega * t)
    z_ddot = -heave * omega**2 * np.sin(omega * t)
    forces, nus = np.zeros((n, 3)), np.zeros((n, 6))
    out = np.zeros(6)
    for i in range(n):
        c, s = math.cos(theta[i]), math.sin(theta[i])
        rot = np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])  # body x = (cos, 0, sin)
        u, _, w = rot.T @ np.array([speed, 0.0, z_dot[i]])
        nus[i] = (u, 0.0, w, 0.0, -theta_dot[i], 0.0)  # bow up is a negative rate about body y
        added_mass_velocity_terms(nus[i], a, coupling, theta_dot[i], out)
        implicit = rot @ (a[:3] * (rot.T @ np.array([0.0, 0.0, z_ddot[i]])))
        forces[i] = rot @ out[:3] - implicit
    return forces, nus, a


@pytest.mark.parametrize("coupling", [IMPULSE, KIRCHHOFF])
def test_added_mass_force_has_no_mean_over_a_periodic_heave_and_pitch(coupling):
    """-d/dt of the fluid's impulse R A1 v_r: a periodic motion gives it a zero mean (Newman 1977,
    4.13). The manoeuvring form, which drops the surge term -a33 w q, keeps a mean surge force:
    the terms it leaves out, turned to the world, a33 <w q> cos(theta) to first order."""
    forces, nus, a = _forced_heave_and_pitch(coupling)
    amplitude = np.abs(forces).max(axis=0)
    assert amplitude[0] > 10.0 and amplitude[2] > 1000.0  # N: a force worth averaging
    assert np.all(np.abs(forces.mean(axis=0)) < 1e-9 * amplitude.max())
    manoeuvring, _, _ = _forced_heave_and_pitch(MANOEUVRING)
    w, q = nus[:, 2], nus[:, 4]
    assert abs(np.mean(a[2] * w * q)) > 0.1 * amplitude[0]
    assert manoeuvring.mean(axis=0)[0] == pytest.approx(np.mean(a[2] * w * q), rel=0.02)


def test_a_steady_heeled_turn_gets_no_surge_force_from_the_heave_added_mass():
    """Heeled 20 deg, turning at r with leeway v_h: body q = r sin(phi) and w = -v_h sin(phi) are
    steady but the pitch angle does not change. The impulse form takes the pitch angle's rate and
    adds nothing; the unbounded-fluid form's -a33 w q is a steady a33 v_h r sin^2(phi)."""
    a = np.array([30.0, 225.0, 955.0, 87.0, 546.0, 112.0])  # the viel_boat's
    phi, r, v_h, u = math.radians(20.0), 0.3, 0.2, 1.5
    yaw = 0.7
    rot = frames.matrix_from_euler(phi, 0.0, yaw)
    heading = frames.matrix_from_euler(0.0, 0.0, yaw)
    nu = np.concatenate([rot.T @ heading @ [u, v_h, 0.0], rot.T @ [0.0, 0.0, r]])
    assert abs(nu[2]) == pytest.approx(v_h * math.sin(phi)) and abs(nu[4]) == pytest.approx(r * math.sin(phi))
    rate = pitch_angle_rate(rot, nu[4], nu[5])
    assert rate == pytest.approx(0.0, abs=1e-12)
    impulse, manoeuvring, kirchhoff = np.zeros(6), np.zeros(6), np.zeros(6)
    kirchhoff_terms(nu, a, IMPULSE, rate, impulse)
    kirchhoff_terms(nu, a, MANOEUVRING, rate, manoeuvring)
    kirchhoff_terms(nu, a, KIRCHHOFF, rate, kirchhoff)
    assert impulse == pytest.approx(manoeuvring, abs=1e-9)
    assert abs(kirchhoff[0] - manoeuvring[0]) == pytest.approx(a[2] * v_h * r * math.sin(phi) ** 2)
    # upright, the pitch angle's rate is -q: the form is the unbounded fluid's surge and heave
    upright = frames.matrix_from_euler(0.0, 0.1, 0.7)
    assert pitch_angle_rate(upright, 0.2, 0.3) == pytest.approx(-0.2, rel=1e-12)


def test_no_forward_speed_added_mass_terms_in_heave_and_pitch():
    """Impulse and manoeuvring forms: a trimmed hull at speed (u = 8, w = U sin(trim)) gets no
    pitch moment or heave force from the velocity terms; the Kirchhoff form's pitch row is the destabilising
    Munk moment (a33 - a11) u w (Fossen 2011 eq. 6.54), which the switch keeps."""
    a = np.array([160.0, 1200.0, 9600.0, 1000.0, 26000.0, 2400.0])
    u, w = 8.0, -8.0 * math.sin(math.radians(1.0))
    nu = np.array([u, 0.0, w, 0.0, 0.0, 0.0])
    out = np.zeros(6)
    for coupling in (IMPULSE, MANOEUVRING):
        kirchhoff_terms(nu, a, coupling, 0.0, out)
        assert np.all(out == 0.0)
    kirchhoff_terms(nu, a, KIRCHHOFF, 0.0, out)
    assert out[4] == pytest.approx((a[2] - a[0]) * u * w)
    # as a stiffness: -(a33 - a11) U^2 per radian of trim, 9 440 U^2 N m/rad here
    assert out[4] / math.radians(1.0) == pytest.approx(-(a[2] - a[0]) * u * u, rel=1e-4)
    # the horizontal-plane Munk moment of Wille eq. 10 stays in both forms
    v = 0.4
    for coupling in (IMPULSE, MANOEUVRING, KIRCHHOFF):
        kirchhoff_terms(np.array([u, v, 0.0, 0.0, 0.0, 0.0]), a, coupling, 0.0, out)
        assert out[5] == pytest.approx((a[0] - a[1]) * u * v)


def _four_dof_kinetic_energy(physics):
    """1/2 qdot^T (M_RB + J^T M_A J) qdot of the 4-DOF boat: MuJoCo's rigid-body matrix and the
    hull's added mass mapped through J (joints x, y, yaw, roll -> body nu), from first principles."""
    m, d = physics.model.ptr, physics.data.ptr
    mujoco.mj_forward(m, d)
    rigid = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, rigid)
    yaw, heel = d.qpos[2], d.qpos[3]
    rot = frames.matrix_from_euler(heel, 0.0, yaw)
    jac = np.zeros((6, m.nv))
    jac[0:3, 0:2] = rot.T[:, 0:2]
    jac[3:6, 2] = rot.T[:, 2]
    jac[3, 3] = 1.0
    total = rigid + jac.T @ np.diag(physics.params.added_mass_diagonal) @ jac
    return 0.5 * d.qvel @ total @ d.qvel


def test_four_dof_added_mass_conserves_kinetic_energy():
    """Heave and pitch held, no gravity, no other force: the added-mass terms are gyroscopic, so
    rolling while yawing keeps the kinetic energy. The rotational rate term (a66 - a55)
    sin(phi) cos(phi) roll_dot yaw_dot on the yaw joint is what makes that true (without it,
    0bcfa2b's 4-DOF mode, the energy changes by 5.3 % in these 5 s; with it by under 1e-5)."""
    physics = only_hull("wille_yacht", dofs=4)
    physics.model.opt.gravity[:] = 0.0
    d = physics.data.ptr
    d.qpos[3] = math.radians(-30.0)  # no restoring: in 5 s it rolls on to about -53 deg
    d.qvel[2], d.qvel[3] = 0.2, 0.05  # yaw rate, roll rate
    physics.forward()
    e0 = _four_dof_kinetic_energy(physics)
    energies = []
    for _ in range(50):
        physics.step(20)
        energies.append(_four_dof_kinetic_energy(physics))
    drift = np.max(np.abs(np.array(energies) / e0 - 1.0))
    assert drift < 1e-3
