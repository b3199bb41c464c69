"""The controllers' fast paths give the actions of their readable forms, bit for bit.

The readable forms of the hot paths are written out here as references: the PID rudder's
step, Saoud's apparent wind (saoud_v), the Wille (2016b) look-up tables' inversion and Viel's
view of the observation; Saoud's compiled solver is compared with
:func:`controllers.saoud_optimum.optimal_sail`, the readable solver in the package. Actions are
compared on observation sequences recorded from real episodes (gusts, heel, tacks through the
wind-angle schedule) and the solver on a grid of winds.
"""

import functools
import math
import struct

import numpy as np
import pytest
from sailmujoco.controllers import factories, saoud_solver, viel, viel_law
from sailmujoco.controllers.pid import PIDHeading
from sailmujoco.controllers.sail_laws import keep_side_at_dead_run
from sailmujoco.controllers.saoud import SaoudSail, optimal_sail, sail_angle_from_saoud
from sailmujoco.controllers.saoud_solver import optimal_sail_compiled
from sailmujoco.controllers.wille_roll import SailCommand

from sailmujoco import suite
from sailmujoco.frames import saoud_theta_v, yaw_from_heading
from sailmujoco.reference.viel_model import psi_aw_from_awa, psi_tw_from_direction


# ---- the readable references (numpy forms of the fast paths) ------------------------------
def ref_scalar(observation, key):
    return float(np.asarray(observation[key]).reshape(()))


class ReferencePID(PIDHeading):
    def error(self, observation):
        desired = self.desired_heading
        if desired is None:
            desired = ref_scalar(observation, self.reference_key)
        return (ref_scalar(observation, "heading") - desired + math.pi) % (2.0 * math.pi) - math.pi

    def __call__(self, observation):
        e = self.error(observation)
        de = -ref_scalar(observation, "yaw_rate")
        command = self.kp * e + self.ki * self.integral + self.kd * de
        if abs(command) < self.max_angle or np.sign(command) != np.sign(e):
            self.integral += e * self.dt
        return float(np.clip(command, -self.max_angle, self.max_angle))


def ref_pid(pid):
    """An ReferencePID with the settings of ``pid``."""
    reference = ReferencePID.__new__(ReferencePID)
    reference.__dict__.update(vars(pid))
    return reference


def ref_saoud_v(observation):
    state = observation["true_state"]
    air = (np.asarray(state["true_wind"], dtype=float).reshape(2)
           - np.asarray(observation["velocity"], dtype=float).reshape(2))
    yaw = ref_scalar(state, "yaw")
    c, s = math.cos(yaw), math.sin(yaw)
    level = np.array([c * air[0] + s * air[1], -s * air[0] + c * air[1]])
    return saoud_theta_v((level[0], level[1])), math.hypot(*level)


class ReferenceSaoudSail(SaoudSail):
    def __call__(self, observation):
        theta_v, speed = ref_saoud_v(observation)
        if speed < self.min_speed:
            return self.last_sail_angle
        self.last_optimum = optimal_sail(theta_v, speed, self.l_phi, self.phi_max, self.params)
        self.last_sail_angle = keep_side_at_dead_run(sail_angle_from_saoud(self.last_optimum.delta),
                                                     self.last_sail_angle, theta_v)
        return self.last_sail_angle


def ref_solutions(table, beta_ws, max_jump):
    grid = table.beta_ws
    b = min(max(beta_ws, grid[0]), grid[-1])
    i = int(np.clip(np.searchsorted(grid, b) - 1, 0, grid.size - 2))
    t = (b - grid[i]) / (grid[i + 1] - grid[i])
    lam0, lam1 = table.sail_angle[i], table.sail_angle[i + 1]
    if np.max(np.abs(lam1 - lam0)) > max_jump:
        j = i if t < 0.5 else i + 1
        return table.sail_angle[j].copy(), table.surge[j].copy(), table.moment[j].copy()
    blend = lambda a: (1.0 - t) * a[i] + t * a[i + 1]  # noqa: E731
    return blend(table.sail_angle), blend(table.surge), blend(table.moment)


class ReferenceTables:
    """WilleSailTables' look-ups in their numpy form, on the same tables."""

    def __init__(self, tables):
        self.tables = tables

    def optimal_sail_angle(self, beta_ws, side=None):
        half = self.tables.table(beta_ws, side)
        return float(ref_solutions(half, beta_ws, self.tables.max_jump)[0][0])

    def sail_command(self, beta_ws, relative_moment, side=None):
        half = self.tables.table(beta_ws, side)
        lam, _, moment = ref_solutions(half, beta_ws, self.tables.max_jump)
        heeling = half.side * moment[::-1]
        angles = lam[::-1]
        wanted = half.side * relative_moment
        if wanted >= heeling[-1]:
            angle, saturation = angles[-1], 1
        elif wanted <= heeling[0]:
            angle, saturation = angles[0], -1
        else:
            k = int(np.searchsorted(heeling, wanted, side="right")) - 1
            t = (wanted - heeling[k]) / (heeling[k + 1] - heeling[k])
            angle, saturation = angles[k] + t * (angles[k + 1] - angles[k]), 0
        return SailCommand(float(angle), saturation, float(lam[0]), float(moment[0]),
                           float(moment[3]))


def ref_sign(x):
    return float(np.sign(x))


def ref_viel_view(observation, target=None):
    x, y = (float(a) for a in np.asarray(observation["position"], dtype=float).reshape(2))
    vx, vy = (float(a) for a in np.asarray(observation["velocity"], dtype=float).reshape(2))
    theta = float(yaw_from_heading(ref_scalar(observation, "heading")))
    c, s = math.cos(theta), math.sin(theta)
    if target is None:
        target = observation["target_position"]
    x_T, y_T = (float(a) for a in np.asarray(target, dtype=float).reshape(2))
    values = dict(
        x=x, y=y, theta=theta, phi=math.atan2(vy, vx), v=vx * c + vy * s, u=-vx * s + vy * c,
        omega=ref_scalar(observation, "yaw_rate"), a_aw=ref_scalar(observation, "apparent_wind_speed"),
        psi_aw=psi_aw_from_awa(ref_scalar(observation, "apparent_wind_angle")),
        psi_tw=psi_tw_from_direction(ref_scalar(observation["true_state"], "wind_direction")),
        x_T=x_T, y_T=y_T)
    return viel.VielView(**values)


# ---- helpers -------------------------------------------------------------------------------
def bits(value):
    """A float's bit pattern (so that -0.0 != 0.0 and NaN == NaN)."""
    return struct.pack("<d", float(value))


@functools.lru_cache(maxsize=4)
def recorded(boat, task, controller, steps, **options):
    """(env, observations) of an episode driven by the named controller."""
    env = suite.load(boat, task, seed=4, **options)
    policy = getattr(factories, controller)(env)
    policy.reset(4)
    timestep = env.reset()
    out = [timestep]
    for _ in range(steps):
        timestep = env.step(policy(timestep))
        out.append(timestep)
        if timestep.last():
            break
    return env, out


def assert_same_actions(fast, reference, timesteps):
    fast.reset(0)
    reference.reset(0)
    for timestep in timesteps:
        a, b = fast(timestep), reference(timestep)
        assert [bits(x) for x in a] == [bits(x) for x in b], (a, b)


# ---- tests ---------------------------------------------------------------------------------
@pytest.mark.parametrize("phi_max_deg,paper_numbers", [(30.0, False), (None, True)])
def test_saoud_actions(phi_max_deg, paper_numbers):
    """speed_trial sweeps the wind from 10 to 80 deg: thrust branch, roll limit, beam reach."""
    env, timesteps = recorded("saoud_robot", "speed_trial", "saoud", 600)
    fast = factories.saoud(env, phi_max_deg=phi_max_deg, paper_numbers=paper_numbers)
    reference = factories.saoud(env, phi_max_deg=phi_max_deg, paper_numbers=paper_numbers)
    sail = reference.sail
    reference.rudder = ref_pid(reference.rudder)
    reference.sail = ReferenceSaoudSail(l_phi=sail.l_phi, phi_max=sail.phi_max, params=sail.params)
    assert fast.sail.compiled and fast.sail._solve is optimal_sail_compiled
    assert_same_actions(fast, reference, timesteps)
    assert fast.sail.last_optimum == reference.sail.last_optimum


@pytest.mark.parametrize("wind", ["perfect", "mean_speed"])
def test_wille_roll_actions(wind):
    """A beam reach at 10 m/s heels the yacht past the switch-on: LQR, integral, saturation."""
    env, timesteps = recorded("wille_yacht", "beam_reach_roll", "wille_roll", 500, wind_speed=12.0)
    fast = factories.wille_roll(env, wind=wind)
    reference = factories.wille_roll(env, wind=wind)
    reference.rudder = ref_pid(reference.rudder)
    reference.sail.tables = ReferenceTables(reference.sail.tables)
    assert_same_actions(fast, reference, timesteps)
    saturations = []
    fast.reset(0)
    for timestep in timesteps:
        fast(timestep)
        saturations.append(fast.sail.last_step.saturation if fast.sail.last_step.active else 9)
    assert {-1, 0, 1} & set(saturations) and 9 in saturations  # on and off, inside the table


@pytest.mark.parametrize("world", ["mujoco", "paper"])
def test_viel_actions(world, monkeypatch):
    """Position keeping in wind case 5 (oscillating speed and direction): every strategy step."""
    env, timesteps = recorded("viel_boat", "position_keeping", "viel", 600, world=world, case=5)
    fast, reference = factories.viel(env), factories.viel(env)
    fast.reset(0)
    reference.reset(0)
    modes = set()
    for timestep in timesteps:
        a = fast(timestep)
        with monkeypatch.context() as patch:  # the readable reference only
            patch.setattr(viel, "viel_view", ref_viel_view)
            patch.setattr(viel, "sign", ref_sign)
            patch.setattr(viel_law, "sign", ref_sign)
            b = reference(timestep)
        assert [bits(x) for x in a] == [bits(x) for x in b], (a, b)
        modes.add(fast.info["mode"])
    assert len(modes) >= 2


def test_wille_tables_lookups():
    """Every wind angle of both halves (and NaN, and past the ends), every moment fraction."""
    tables = factories.wille_roll(suite.load("wille_yacht", "beam_reach_roll")).sail.tables
    reference = ReferenceTables(tables)
    for beta in [*np.linspace(-3.3, 3.3, 721), 0.0, -0.0, math.nan]:
        for side in (None, 1, -1):
            half = tables.table(beta, side)
            fast_rows = tables.solutions(beta, side)
            for fast_row, ref in zip(fast_rows, ref_solutions(half, beta, tables.max_jump), strict=True):
                assert fast_row.tobytes() == ref.tobytes()
            if beta != beta:
                continue
            assert (bits(tables.optimal_sail_angle(beta, side))
                    == bits(reference.optimal_sail_angle(beta, side)))
            for moment in np.linspace(-6.0, 6.0, 7):
                a, b = tables.sail_command(beta, moment, side), reference.sail_command(beta, moment, side)
                assert [bits(getattr(a, k)) for k in vars(b)] == [bits(getattr(b, k)) for k in vars(b)]


def test_saoud_solver_on_a_grid_of_winds():
    """optimal_sail_compiled equals optimal_sail on every field, with and without the roll
    limit, across the whole circle (head to wind, beam reach, dead run) and several boats."""
    rng = np.random.default_rng(11)
    cases = [(t, s, lp, pm) for t in np.linspace(-math.pi, math.pi, 181) for s in (0.7, 6.0)
             for lp in (0.1, 1.0) for pm in (None, math.radians(30.0))]
    cases += [(rng.uniform(-4.0, 4.0), rng.uniform(0.2, 15.0), rng.uniform(0.05, 2.0),
               None if rng.random() < 0.5 else rng.uniform(0.05, 1.5)) for _ in range(300)]
    roll_limited = 0
    for theta_v, speed, l_phi, phi_max in cases:
        new = optimal_sail_compiled(theta_v, speed, l_phi, phi_max)
        ref = optimal_sail(theta_v, speed, l_phi, phi_max)
        fields = ("delta", "phi", "alpha", "cost")
        assert [bits(getattr(new, k)) for k in fields] == [bits(getattr(ref, k)) for k in fields], \
            (theta_v, speed, l_phi, phi_max)
        assert new.roll_limited is ref.roll_limited
        roll_limited += ref.roll_limited
    assert roll_limited > 20  # the roll-limit candidates (brentq) were exercised
    # one compiled signature: argument types fixed (float64, bool, float64 arrays)
    assert len(getattr(saoud_solver._solve, "signatures", [None])) == 1


def test_saoud_solver_refuses_as_the_reference():
    for args in [(0.5, 0.0, 0.5, None), (0.5, 5.0, -1.0, None), (0.5, 5.0, 0.5, 2.0)]:
        with pytest.raises(ValueError) as ref:
            optimal_sail(*args)
        with pytest.raises(ValueError) as new:
            optimal_sail_compiled(*args)
        assert str(new.value) == str(ref.value)
