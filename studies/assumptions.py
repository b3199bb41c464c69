"""Assumption validation in full 6-DOF: where the papers' simplifications hold, where they break,
and what it costs the controller.

Scenarios
    * the wind plane: true wind 2-14 m/s x true wind angle 30-180 deg, steady wind, heading held
      (``heading_hold``), the Saoud robot with Saoud's optimal sail and the Wille yacht with
      Wille's heading controller and lambda100 sail; each point run four times: as built
      (6-DOF, C_T on, actuated sail), with C_T switched off, with heave and pitch held, with a
      sheeted sail;
    * the reproduction scenarios: Wille's close-hauled course hold (course controller, 6-DOF),
      Viel's position keeping (case 2, 3-DOF and 6-DOF robot), free decay and rudder steps;
    * Saoud's static optimum at a few wind angles and speeds against the heel the boat reaches.

Each row of the table gives the metric's range over its scenarios, the threshold it is judged
against, the verdict, and the effect on the controller's own figure of merit when the
assumption is made false in the simulation.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
from sailmujoco.controllers.base import Composite

from sailmujoco import frames, stability
from sailmujoco.figures import robust_limits
from sailmujoco.params import get_boat
from sailmujoco.progress import Progress

from .kit import verdict
from .kit import Report, engine_for, run_batch, run_episode, save_figure, setup_matplotlib

NAME = "assumptions"
TITLE = "Assumption validation in 6-DOF: where the papers' simplifications hold and where they break"
BOATS = {"saoud_robot": "saoud", "wille_yacht": "wille_heading"}
# the scenario `sailmujoco study assumptions --video` films: the robot on a blustery reach
VIDEO = {"boat": "saoud_robot", "task": "heading_hold", "controller": "saoud", "seconds": 40.0,
         "wind_speed": 8.0, "wind_from_deg": 70.0}
CONFIGS = {"baseline": {}, "ct_off": {"env.sail_tangential": False}, "four_dof": {"env.dofs": 4},
           "sheeted": {"env.sail_mode": "sheeted"}}
# The boat as built, each of its differences from the papers' boat switched off in turn
# (physics.ForceSwitches): (config, sweep options, row title, what the papers assume)
BUILT = (
    ("paper_hydrostatics", {"env.hydrostatics": "paper"},
     "Restoring by formula: eq. 20 / Saoud eq. 4 in place of the hull's geometric buoyancy",
     "Wille eq. 20; Saoud eq. 4"),
    ("friction_only", {"env.resistance": "friction"},
     "Friction-only resistance: no wave-making (residuary) resistance",
     "Wille eqs. 15-16 (ITTC-57 friction with form factor)"),
    ("paper_foils", {"env.foils": "paper"},
     "The papers' foil coefficients: sail slope 7.15 /rad, 2-D post-stall drag",
     "Saoud §VII-A C_N polynomial; Wille eq. 23 with the 2-D table"),
    ("no_downwash", {"env.keel_downwash": False},
     "Rudder in undisturbed flow: no keel downwash", "Wille eqs. 34-36"),
    ("no_windage", {"env.windage": False},
     "No windage on hull and rig", "Wille, Saoud (Viel has p1 on the true wind)"),
)
CONFIGS.update({name: options for name, options, _, _ in BUILT})
SPEED_HOLDS = 0.05  # an assumption "holds" where it changes the steady speed by less than 5 %
HEEL_HOLDS_DEG = 1.0  # ... and the steady heel by less than 1 deg
SPEED_FLOOR = 0.3  # m/s: below it the as-built boat is stalled (in irons, or its heading lost) and
#                    a speed change is given in m/s, not in % of ~0 (studies.kit.verdict.difference)
FROUDE_WALL = 0.45  # the displacement hull's wave-making wall (Larsson & Eliasson, ch. 5)


def plane_specs(smoke: bool) -> dict:
    """The wind-plane sweeps: {(boat, config): spec}."""
    tws = [4.0, 10.0] if smoke else [2.0, 5.0, 8.0, 11.0, 14.0]
    twa = [60.0, 150.0] if smoke else [30.0, 60.0, 90.0, 120.0, 150.0, 180.0]
    duration = 25.0 if smoke else 50.0
    specs = {}
    for boat, controller in BOATS.items():
        for config, options in CONFIGS.items():
            specs[(boat, config)] = {
                "name": f"{boat}-{config}", "boat": boat, "task": "heading_hold",
                "world": "mujoco", "controller": controller, "duration": duration,
                "options": {"task.gusts": False, "task.wander": False, "task.diagnostics": True,
                            "task.heading_jitter_deg": 0.0, "task.steady_window": duration / 3,
                            **options},
                "zip": {"task.wind_speed": [s for s in tws for _ in twa],
                        "task.wind_from_deg": [a for _ in tws for a in twa]}}
    return specs


def plane_table(specs: dict, tables: list) -> pd.DataFrame:
    frames_ = []
    for (boat, config), table in zip(specs, tables, strict=True):
        table = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa"})
        table["boat"], table["config"] = boat, config
        frames_.append(table)
    return pd.concat(frames_, ignore_index=True)


def _pivot(data, boat, config, value):
    d = data[(data["boat"] == boat) & (data["config"] == config)]
    return d.pivot_table(index="tws", columns="twa", values=value)


def _delta(data, boat, config, value):
    base = _pivot(data, boat, "baseline", value)
    other = _pivot(data, boat, config, value)
    return other - base


def speed_effects(data: pd.DataFrame, boat: str, config: str) -> pd.DataFrame:
    """Point by point over the wind plane: steady speed and heel as built and with ``config``;
    the speed change as :func:`studies.kit.verdict.difference` gives it (relative, or in m/s where the
    boat as built makes less than SPEED_FLOOR). These rows are ``effects.csv``."""
    keys, cols = ["tws", "twa"], ["steady_speed", "steady_heel"]
    sel = data[data["boat"] == boat]
    built = sel[sel["config"] == "baseline"][keys + cols]
    other = sel[sel["config"] == config][keys + cols]
    m = built.merge(other, on=keys, suffixes=("_built", "_switched"), how="outer").sort_values(keys)
    diffs = verdict.differences(m["steady_speed_switched"], m["steady_speed_built"], floor=SPEED_FLOOR,
                                unit="m/s")
    m.insert(0, "config", config)
    m.insert(0, "boat", boat)
    m["speed_change_pct"] = [100 * d.value if d.relative else np.nan for d in diffs]
    m["speed_change_ms"] = m["steady_speed_switched"] - m["steady_speed_built"]
    m["heel_change_deg"] = np.degrees(m["steady_heel_switched"] - m["steady_heel_built"])
    m.attrs["diffs"] = diffs
    return m.reset_index(drop=True)


def _pitch_summary(g: pd.DataFrame) -> str:
    """One boat's pitch amplitude (with where it is largest), trim (mean pitch, bow up +) and
    heave amplitude over the wind plane, as built."""
    if g.empty or not np.isfinite(g["pitch_amplitude"]).any():
        return "—"
    top = g.loc[g["pitch_amplitude"].idxmax()]
    return (f"{g['boat'].iloc[0]}: pitch amplitude up to {math.degrees(top['pitch_amplitude']):.1f}° "
            f"({top['tws']:g} m/s, {top['twa']:g}°, at {top['steady_speed']:.1f} m/s), trim (bow up +) "
            f"{verdict.value_range(g['mean_pitch'], 180 / math.pi, '{:+.1f}')}°, heave amplitude up to "
            f"{100 * np.nanmax(g['heave_amplitude']):.1f} cm")


def heatmap(plt, grid: pd.DataFrame, ax, title, unit, holds=None):
    """The metric over TWA x TWS, ✓ where the assumption holds (``holds(values)``). The colour
    scale is robust (2nd-98th percentile when one cell would take it over): cells beyond it
    take the end colour, print their value, and the colorbar's end is an arrow."""
    values = grid.to_numpy(dtype=float)
    vmin, vmax, extend = robust_limits(values)
    image = ax.imshow(values, origin="lower", aspect="auto", cmap="viridis", vmin=vmin, vmax=vmax)
    ax.grid(False)
    ax.set_xticks(range(len(grid.columns)), [f"{c:g}" for c in grid.columns])
    ax.set_yticks(range(len(grid.index)), [f"{i:g}" for i in grid.index])
    ax.set_xlabel("true wind angle [deg]")
    ax.set_ylabel("true wind speed [m/s]")
    ax.set_title(title, fontsize=9)
    label = f"[{unit}]" + ("" if extend == "neither" else "\n(2nd-98th percentile; beyond: value printed)")
    plt.colorbar(image, ax=ax, label=label, extend=extend)
    for (i, j), v in np.ndenumerate(values):
        if not np.isfinite(v):
            ax.text(j, i, "×", ha="center", va="center", color="red")  # capsized / no data
            continue
        mark = "✓" if holds is not None and holds(v) else ""
        if v < vmin or v > vmax:
            mark += f"{v:.3g}"
        if mark:
            ax.text(j, i, mark, ha="center", va="center", color="white" if v < vmax else "black",
                    fontsize=8 if len(mark) < 2 else 7)


def time_constants() -> dict:
    """Roll period (free decay) and yaw time constant (rudder step) of both boats, 6-DOF."""
    from sailmujoco.forces.wind import WindConfig
    from sailmujoco.physics import BoatPhysics, ForceSwitches

    out = {}
    for boat in BOATS:
        p = get_boat(boat)
        physics = BoatPhysics.load(boat, wind=WindConfig(), forces=ForceSwitches(sail=False))
        with physics.reset_context():
            physics.data.qpos[3:7] = frames.quat_from_euler(math.radians(5.0), 0.0, 0.0)
        heels = []
        for _ in range(2000):
            physics.step(1)
            heels.append(physics.heel())
        heels = np.array(heels)
        t = np.arange(1, heels.size + 1) * physics.timestep()
        up = np.nonzero((heels[:-1] < 0) & (heels[1:] >= 0))[0]
        roll_period = float(np.mean(np.diff(t[up]))) if up.size > 1 else float("nan")
        # yaw: moving ahead at a typical speed (thrust held), then a 10 deg rudder step
        speed = 2.0 if boat == "wille_yacht" else 0.8
        physics = BoatPhysics.load(boat, wind=WindConfig(), forces=ForceSwitches(sail=False))
        physics.place((0.0, 0.0), 0.0, speed)
        drag = _surge_drag(physics, speed)
        physics.set_external_wrench([drag, 0, 0, 0, 0, 0])
        physics.set_control([math.radians(10.0), 0.0])
        rates = []
        for _ in range(int(30.0 / physics.timestep())):
            physics.step(1)
            rates.append(physics.yaw_rate())
        rates = np.abs(np.array(rates))
        t = np.arange(1, rates.size + 1) * physics.timestep()
        final = rates[-200:].mean()
        reach = np.nonzero(rates >= (1 - math.exp(-1)) * final)[0]
        out[boat] = {"roll_period": roll_period,
                     "yaw_time_constant": float(t[reach[0]]) if reach.size else float("nan"),
                     "roll_natural": 2 * math.pi / roll_period if roll_period else float("nan"),
                     "ixx": p.inertia[0]}
    return out


def _surge_drag(physics, speed):
    physics._compute_forces()
    total = physics.force_term("damping")[0] + physics.force_term("keel")[0] + physics.force_term("rudder")[0]
    return -float(total)


def course_correction_error(smoke: bool) -> dict:
    """Wille's correction beta_b (eqs. 57-59) against the drift the 6-DOF yacht really sails at."""
    log = []

    def factory(env):
        from sailmujoco.controllers.factories import wille_course

        controller = wille_course(env)
        rudder = controller.rudder

        def logged(observation):
            sigma = rudder(observation)
            ts = observation["true_state"]
            beta = math.atan2(float(ts["v"]) * math.cos(float(observation["heel"])), float(ts["u"]))
            log.append((float(ts["time"]), rudder.last_beta_b, -beta))  # FRD drift sign
            return sigma

        return Composite(logged, controller.sail)

    metrics, traj, _ = run_episode("wille_yacht", "course_hold", "mujoco", factory, seed=0,
                                   time_limit=60.0 if smoke else 200.0)
    log = np.array(log)
    steady = log[log[:, 0] > log[-1, 0] / 2]
    return {"beta_b": float(np.mean(steady[:, 1])), "drift": float(np.mean(steady[:, 2])),
            "drift_error": metrics["drift_error"],
            "heel_max": float(np.max(np.abs(traj["heel"])))}


def saoud_steady_state(smoke: bool) -> pd.DataFrame:
    """Saoud's predicted phi* against the steady heel of the 6-DOF robot, same apparent wind."""
    rows = []
    cases = [(4.0, 90.0)] if smoke else [(w, a) for w in (3.0, 5.0, 7.0) for a in (60.0, 90.0, 120.0)]
    for boat_l_phi in ((0.1,) if smoke else (0.1, 1.0)):
        for wind, angle in cases:
            phis = []

            def factory(env, phis=phis, l_phi=boat_l_phi):
                from sailmujoco.controllers.factories import saoud

                controller = saoud(env, l_phi=l_phi, phi_max_deg=None)
                law = controller.sail

                def logged(observation):
                    angle_ = law(observation)
                    if law.last_optimum is not None:
                        phis.append((float(observation["true_state"]["time"]), law.last_optimum.phi))
                    return angle_

                return Composite(controller.rudder, logged)

            metrics, traj, _ = run_episode(
                "saoud_robot", "heading_hold", "mujoco", factory, seed=0, time_limit=40.0,
                boat_options={"l_phi": boat_l_phi}, wind_speed=wind, wind_from_deg=angle,
                gusts=False, wander=False, heading_jitter_deg=0.0, steady_window=10.0)
            phis = np.array(phis)
            steady = phis[phis[:, 0] > 30.0][:, 1] if phis.size else np.array([np.nan])
            # Saoud's body frame is FLU like ours: his phi is our heel (positive starboard down)
            rows.append({"l_phi": boat_l_phi, "tws": wind, "twa": angle,
                         # no optimum logged after 30 s (the run stopped): no value, and no
                         # numpy "Mean of empty slice" warning in the log
                         "phi_star_deg": math.degrees(float(np.mean(steady))) if steady.size else math.nan,
                         "heel_deg": math.degrees(metrics["steady_heel"]),
                         "speed": metrics["steady_speed"]})
    frame = pd.DataFrame(rows)
    frame["error_deg"] = frame["heel_deg"] - frame["phi_star_deg"]
    return frame


def lateral_drift(smoke: bool) -> dict:
    """Position keeping, case 2: the lateral speed (leeway) of the 3-DOF model and of the robot."""
    out = {}
    for world in ("paper", "mujoco"):
        _, traj, _ = run_episode("saoud_robot", "position_keeping", world, "viel", seed=0, case=2,
                                 time_limit=60.0 if smoke else 200.0)
        out[world] = float(np.mean(np.abs(traj["v"])))
        out[world + "_max"] = float(np.max(np.abs(traj["v"])))
    return out


def table1_jobs(smoke: bool) -> dict:
    """Wille (2016b) Table 1 sims 1-3 (seed 0, 6-DOF) with and without residuary resistance:
    {(resistance, sim): the job of ``wille_roll_table1.simulate``}."""
    from .wille_roll_table1 import DURATION, SMOKE_DURATION, WIND

    return {(resistance, sim): dict(world="mujoco", sim=sim, seed=0, wind_speed=WIND,
                                    duration=SMOKE_DURATION if smoke else DURATION,
                                    env={"resistance": resistance})
            for resistance in ("dsyhs", "friction") for sim in ("sim1", "sim2", "sim3")}


PARTS = {"course": course_correction_error, "steady": saoud_steady_state, "drift": lateral_drift}


def part(job: dict):
    """One of the study's single runs (a job of the sweep engine): a part of ``PARTS`` or a
    Table 1 simulation (its numbers)."""
    if job["part"] == "table1":
        from .wille_roll_table1 import numbers, simulate

        return numbers(simulate(job["run"]))
    return PARTS[job["part"]](job["smoke"])


def simulations(out: Path, smoke: bool, engine, progress: bool, resume: bool):
    """The wind-plane sweeps and the course, steady-state, drift and Table 1 runs, together on
    the engine: (wind-plane table, {part: result}, Table 1 as {(resistance, sim): numbers})."""
    specs = plane_specs(smoke)
    table1 = table1_jobs(smoke)
    jobs = [{"part": name, "smoke": smoke} for name in PARTS]
    jobs += [{"part": "table1", "run": job} for job in table1.values()]
    tables, (results,) = run_batch(engine, out, sweeps=[(spec, out / "sweeps" / spec["name"]) for spec in specs.values()],
                                   jobs=[(f"{__name__}:part", jobs, "assumptions_runs")], resume=resume,
                                   progress=progress, label=f"{NAME} simulations")
    single = dict(zip(PARTS, results, strict=False))
    return plane_table(specs, tables), single, dict(zip(table1, results[len(PARTS):], strict=True))


def restoring_errors(data: pd.DataFrame) -> dict:
    """Geometric righting moment against eq. 20 and its linearisation (eq. 66) over the heel
    range the boats reached in the wind plane."""
    out = {}
    for boat in BOATS:
        p = get_boat(boat)
        reached = float(np.nanmax(np.abs(data[(data["boat"] == boat)]["steady_heel"])))
        reached = max(reached, math.radians(5.0))
        heels = np.linspace(math.radians(1.0), reached, 12)
        curve = stability.righting_curve(p, heels)
        phi_w = math.radians(10.0)
        k = p.rho_water * 9.81 * p.displaced_volume * p.gm_t
        linear = k * (1 - 2 * math.sin(phi_w) ** 2) * (heels - phi_w) + k * math.cos(phi_w) * math.sin(phi_w)
        geometric = curve["geometric"]
        model = curve["sin"] if p.paper_righting == "sin" else curve["sin_cos"]
        out[boat] = {"heel_reached_deg": math.degrees(reached),
                     "paper_formula_error": float(np.max(np.abs(model - geometric) / np.abs(geometric))),
                     "eq66_error": float(np.max(np.abs(linear - geometric) / np.abs(geometric)))}
    return out


def built_row(effects: dict, config, title, paper_form) -> dict:
    """A row for one difference between the boat as built and the papers' boat: its effect on
    steady speed and heel over the wind plane when the papers' form is switched back on
    (``effects[(boat, config)]``: :func:`speed_effects`)."""
    speed = {b: effects[(b, config)].attrs["diffs"] for b in BOATS}
    heel = {b: effects[(b, config)]["heel_change_deg"].to_numpy(dtype=float) for b in BOATS}
    judged_speed = verdict.judge_differences(sum(speed.values(), []), SPEED_HOLDS)
    judged_heel = verdict.judge(np.concatenate(list(heel.values())), below=HEEL_HOLDS_DEG, magnitude=True)
    holds = judged_speed.holds and judged_heel.holds

    def speed_summary(diffs):
        rel = [d.value for d in diffs if d.finite and d.relative]
        median = f"median {100 * np.median(rel):+.1f} %, " if rel else ""
        return (f"{median}{verdict.range_of(diffs)}; "
                f"{verdict.judge_differences(diffs, SPEED_HOLDS).beyond} of {len(diffs)} points beyond ±"
                f"{100 * SPEED_HOLDS:g} %")

    def heel_summary(values):
        v = verdict.finite(values)
        if not v.size:
            return "—"
        return (f"median {np.median(v):+.1f}° ({verdict.value_range(v, 1.0, '{:+.1f}')}°; "
                f"{verdict.judge(values, below=HEEL_HOLDS_DEG, magnitude=True).beyond} of {len(values)} points "
                f"beyond ±{HEEL_HOLDS_DEG:g}°)")

    return {"assumption": f"{title} ({paper_form})",
            "scenarios": "both boats, wind plane",
            "metric": "steady speed and heel, the papers' form minus as built",
            "range": "; ".join(f"{b}: speed {speed_summary(speed[b])}, heel {heel_summary(heel[b])}"
                               for b in BOATS),
            "threshold": f"|speed| < {100 * SPEED_HOLDS:.0f} % (below {SPEED_FLOOR:g} m/s as built: "
                         f"< {SPEED_HOLDS * SPEED_FLOOR:g} m/s), |heel| < {HEEL_HOLDS_DEG:g} deg",
            "verdict": ("holds" if holds else "breaks") + f" (speed: {judged_speed.text()}; heel: "
                       f"{judged_heel.text()})",
            "effect": "speed and heel, as the range (the extremes are points where one of the two "
                      "boats loses its heading or stalls)"}


def run(out, smoke: bool = False, workers=None, progress: bool = True, video: bool = False,
        engine=None, resume: bool = False) -> dict:
    out = Path(out)
    bar = Progress(6, "assumptions", show=progress, unit="sim")
    with engine_for(engine, workers) as engine:
        data, single, table1 = simulations(out, smoke, engine, progress, resume)
    bar.update(4)
    data.to_csv(out / "wind_plane.csv", index=False)
    tc = time_constants()
    bar.update()
    course, steady, drift = single["course"], single["steady"], single["drift"]
    steady.to_csv(out / "saoud_steady_heel.csv", index=False)
    restoring = restoring_errors(data)
    bar.update()
    bar.close()

    plt = setup_matplotlib()
    base = data[data["config"] == "baseline"]
    rows, headline = [], {}

    rng_ = verdict.value_range
    effects = {(b, c): speed_effects(data, b, c) for b in BOATS for c in CONFIGS
               if c != "baseline" and (data[(data["boat"] == b) & (data["config"] == c)]).size}
    pd.concat(effects.values(), ignore_index=True).to_csv(out / "effects.csv", index=False)

    def effect(boat, config) -> list:
        """The speed changes of ``config`` against the boat as built, point by point (the rows
        of effects.csv), as :class:`studies.kit.verdict.Difference`."""
        return effects[(boat, config)].attrs["diffs"]

    def largest(diffs) -> float:
        rel = [abs(d.value) for d in diffs if d.finite and d.relative]
        return max(rel) if rel else float("nan")

    # 1. C_T << C_N
    robot = base[base["boat"] == "saoud_robot"]
    ct = robot["ct_cn_ratio"].to_numpy(dtype=float)
    ct_effect = effect("saoud_robot", "ct_off")
    headline["ct_cn_max"] = float(np.nanmax(ct)) if np.isfinite(ct).any() else float("nan")
    headline["ct_speed_effect_max"] = largest(ct_effect)
    rows.append({"assumption": "Tangential sail force negligible, C_T ≪ C_N (Saoud Assumption 4)",
                 "scenarios": "robot, wind plane", "metric": "|C_T|/|C_N| at steady state",
                 "range": rng_(ct), "threshold": f"< 0.10; speed with C_T off within {100 * SPEED_HOLDS:g} %",
                 "verdict": verdict.combined({"ratio": verdict.judge(ct, below=0.1),
                                              "speed": verdict.judge_differences(ct_effect, SPEED_HOLDS)}),
                 "effect": f"steady speed with C_T off vs on: {verdict.range_of(ct_effect)}"})
    # 2. pitch and heave small
    pitch = base["pitch_amplitude"].to_numpy(dtype=float)
    heave = base["heave_amplitude"].to_numpy(dtype=float)
    four = sum((effect(b, "four_dof") for b in BOATS), [])
    heel4 = np.concatenate([effects[(b, "four_dof")]["heel_change_deg"].to_numpy(dtype=float) for b in BOATS])
    headline["pitch_amplitude_max_deg"] = float(np.degrees(np.nanmax(pitch)))
    headline["four_dof_speed_effect_max"] = largest(four)
    rows.append({"assumption": "Pitch and heave small: 4 DOF suffice (Saoud Assumption 1; Wille §2.1)",
                 "scenarios": "both boats, wind plane",
                 "metric": "pitch / heave amplitude at steady state",
                 "range": f"{rng_(pitch, 180 / math.pi)} deg / {rng_(heave, 100)} cm; "
                          + "; ".join(_pitch_summary(base[base["boat"] == b]) for b in BOATS),
                 "threshold": f"pitch < 2 deg; speed with heave and pitch held within {100 * SPEED_HOLDS:g} %",
                 "verdict": verdict.combined({"pitch": verdict.judge(np.degrees(pitch), below=2.0),
                                              "speed": verdict.judge_differences(four, SPEED_HOLDS)}),
                 "effect": f"speed, heave+pitch held vs free: {verdict.range_of(four)}; "
                           f"heel {rng_(heel4, 1.0, '{:+.2f}')} deg"})
    # 3. roll faster than yaw; omega3^2 tan(phi) term
    om = base["omega3_ratio"].to_numpy(dtype=float)
    headline["omega3_ratio_max"] = float(np.nanmax(om))
    speed_ratio = {b: v["roll_natural"] * v["yaw_time_constant"] for b, v in tc.items()}
    headline["roll_over_yaw_speed_min"] = min(speed_ratio.values())
    rows.append({"assumption": "Roll much faster than yaw; ω3² tan φ negligible (Saoud §III)",
                 "scenarios": "free decay, rudder step, wind plane",
                 "metric": "ω_roll × τ_yaw (roll natural frequency over yaw bandwidth); "
                           "|(J33−J22) ω3² tan φ| / |restoring|",
                 "range": "; ".join(f"{b}: T_roll {v['roll_period']:.2f} s, τ_yaw {v['yaw_time_constant']:.2f} s, "
                                    f"ω_roll τ_yaw = {speed_ratio[b]:.1f}" for b, v in tc.items())
                          + f"; term ratio {rng_(om)}",
                 "threshold": "ω_roll τ_yaw > 5 (much faster); term ratio < 0.10",
                 "verdict": (f"term ratio < 0.10: {verdict.judge(om, below=0.1).text()}; ω_roll τ_yaw > 5: "
                             + verdict.judge(list(speed_ratio.values()), above=5.0).text("boats")
                             + " (roll only " + ", ".join(f"{r:.1f}×" for r in speed_ratio.values())
                             + " faster than yaw)"),
                 "effect": "the neglected term changes the roll balance by < "
                           f"{100 * np.nanmax(om):.1f} %"})
    # 4. rudder, keel, hull roll moments negligible
    keel = base["roll_share_keel"].to_numpy(dtype=float)
    others = (base["roll_share_keel"] + base["roll_share_rudder"] + base["roll_share_damping"]
              + base["roll_share_added_mass"]).to_numpy(dtype=float)
    headline["keel_roll_share_max"] = float(np.nanmax(keel))
    rows.append({"assumption": "Rudder, keel, hull roll moments negligible at roll equilibrium (Saoud eq. 4)",
                 "scenarios": "both boats, wind plane",
                 "metric": "share of |roll moment|: keel; keel + rudder + hull",
                 "range": f"{rng_(keel, 100)} %; {rng_(others, 100)} % (Wille 2016b Fig. 3: keel ≈ 8 %)",
                 "threshold": "keel + rudder + hull < 10 %", "verdict": verdict.judge(others, below=0.1).text(),
                 "effect": "enters φ* (row 8)"})
    # 5. fully actuated vs sheeted
    sheet = effect("saoud_robot", "sheeted")
    sheet_heel = effects[("saoud_robot", "sheeted")]["heel_change_deg"].to_numpy(dtype=float)
    sheet_rel = [d.value for d in sheet if d.finite and d.relative]
    headline["sheeted_speed_effect_min"] = min(sheet_rel) if sheet_rel else float("nan")
    # a loss beyond 5 %: judged as a change beyond -5 % of max(speed as built, SPEED_FLOOR)
    sheet_loss = [d.value if d.relative else d.value / max(abs(d.reference), SPEED_FLOOR) for d in sheet]
    rows.append({"assumption": "Sail fully actuated, δs free (Saoud Assumption 5) vs sheeted (Wille 2016b §2.1)",
                 "scenarios": "robot with Saoud's optimum, wind plane",
                 "metric": "steady speed and heel, sheeted minus actuated",
                 "range": f"speed {verdict.range_of(sheet)}, heel {rng_(sheet_heel, 1.0, '{:+.2f}')} deg",
                 "threshold": "speed loss < 5 %",
                 "verdict": verdict.judge(sheet_loss, above=-SPEED_HOLDS).text(),
                 "effect": "speed, as the range"})
    # 6. small drift, linear lift
    yacht = base[base["boat"] == "wille_yacht"]
    drift_deg = np.degrees(yacht["drift_angle"].to_numpy(dtype=float))
    aoa_deg = np.degrees(yacht["keel_aoa"].to_numpy(dtype=float))
    headline["keel_aoa_max_deg"] = float(np.nanmax(aoa_deg))
    rows.append({"assumption": "Small drift, v ≪ u, cos φ ≈ 1, linear lift below 10-15° (Wille eqs. 53-59)",
                 "scenarios": "yacht, wind plane; close-hauled course hold",
                 "metric": "drift angle; keel angle of attack; β_b vs the drift sailed",
                 "range": f"drift {rng_(drift_deg)} deg; keel α {rng_(aoa_deg)} deg; "
                          f"β_b {math.degrees(course['beta_b']):.2f} vs drift {math.degrees(course['drift']):.2f} deg",
                 "threshold": "keel |α| < 10 deg",
                 "verdict": verdict.judge(aoa_deg, below=10.0, magnitude=True).text(),
                 "effect": f"course error left by the correction: {math.degrees(course['drift_error']):.2f} deg "
                           f"(β_b − drift = {math.degrees(course['beta_b'] - course['drift']):+.2f} deg)"})
    # 7. restoring
    rows.append({"assumption": "Restoring ρ g ∇ GM sin φ cos φ and its linearisation about φ_w (Wille eq. 20, 2016b eq. 66)",
                 "scenarios": "geometric hull over the heel range reached",
                 "metric": "max relative error vs the geometric righting moment: eq. 20 (or Saoud eq. 4); eq. 66",
                 "range": "; ".join(f"{b}: {v['paper_formula_error'] * 100:.0f} %, {v['eq66_error'] * 100:.0f} % "
                                    f"(to {v['heel_reached_deg']:.0f} deg)" for b, v in restoring.items()),
                 "threshold": "< 10 %",
                 "verdict": "eq. 20 / Saoud eq. 4: " + verdict.judge(
                     [v["paper_formula_error"] for v in restoring.values()], below=0.1).text("boats"),
                 "effect": "heel and heading in 6-DOF, geometric vs Saoud eq. 4 (saoud_fig6 and saoud_fig7 checks)"})
    headline.update({f"{b}_restoring_error": v["paper_formula_error"] for b, v in restoring.items()})
    # 8. Saoud steady state (where the robot sails: a stalled boat has no steady apparent wind)
    sailing = steady[steady["speed"] > 0.3]
    err = sailing["error_deg"].to_numpy(dtype=float)
    headline["phi_star_error_max_deg"] = float(np.nanmax(np.abs(err))) if err.size else float("nan")
    rows.append({"assumption": "Steady state: Saoud's static optimum φ* is the heel reached (Saoud §V)",
                 "scenarios": "robot, 3-7 m/s, 60-120 deg, l_φ 0.1 and 1 m",
                 "metric": f"steady heel − φ* (deg), {len(sailing)} of {len(steady)} runs sailing",
                 "range": rng_(err), "threshold": "< 2 deg",
                 "verdict": verdict.judge(err, below=2.0, magnitude=True).text("runs"),
                 "effect": "the roll limit φ_max is not what the boat sails at"})
    # 9. lateral drift in position keeping
    headline["lateral_speed_6dof"] = drift["mujoco"]
    rows.append({"assumption": "Wind on the sail balanced by the keel; hull windage p1 only (Viel eq. 5)",
                 "scenarios": "position keeping, case 2, robot 6-DOF vs 3-DOF",
                 "metric": "mean |lateral speed| (m/s)",
                 "range": f"3-DOF {drift['paper']:.3f}, 6-DOF {drift['mujoco']:.3f} (max {drift['mujoco_max']:.2f})",
                 "threshold": "6-DOF within 0.05 m/s of 3-DOF",
                 "verdict": verdict.judge([drift["mujoco"] - drift["paper"]], below=0.05, magnitude=True).text("runs"),
                 "effect": "see viel_fig3 for the distance to target"})

    # 10-14. the boat as built: each difference from the papers' boat switched off in turn
    for config, _, title, paper_form in BUILT:
        rows.append(built_row(effects, config, title, paper_form))
        headline[f"{config}_speed_effect_max"] = largest(sum((effect(b, config) for b in BOATS), []))
    # the resistance row also reports the Froude numbers and Wille's Table 1
    yacht_length = get_boat("wille_yacht").hull.length
    froude = {c: _pivot(data, "wille_yacht", c, "steady_speed").to_numpy(dtype=float)
              / math.sqrt(9.81 * yacht_length) for c in ("baseline", "friction_only")}
    headline["yacht_froude_max"] = float(np.nanmax(froude["baseline"]))
    headline["yacht_froude_max_friction"] = float(np.nanmax(froude["friction_only"]))
    for key, value in table1.items():
        headline[f"table1_{key[1]}_{key[0]}_roll_deg"] = value["roll_amplitude"]
        headline[f"table1_{key[1]}_{key[0]}_surge"] = value["mean_surge"]
    resistance_row = next(r for r in rows if r["assumption"].startswith("Friction-only"))
    resistance_row["range"] += (f"; yacht Froude number (wind plane) up to {headline['yacht_froude_max']:.2f} "
                                f"as built, {headline['yacht_froude_max_friction']:.2f} friction only")
    resistance_row["effect"] += "; Wille Table 1 (6-DOF, seed 0), as built → friction only: " + ", ".join(
        f"{sim.replace('sim', 'sim ')} roll {table1[('dsyhs', sim)]['roll_amplitude']:.2f}° → "
        f"{table1[('friction', sim)]['roll_amplitude']:.2f}°, surge {table1[('dsyhs', sim)]['mean_surge']:.2f} → "
        f"{table1[('friction', sim)]['mean_surge']:.2f} m/s (Fn "
        f"{table1[('dsyhs', sim)]['mean_surge'] / math.sqrt(9.81 * yacht_length):.2f} → "
        f"{table1[('friction', sim)]['mean_surge'] / math.sqrt(9.81 * yacht_length):.2f})"
        for sim in ("sim1", "sim2", "sim3"))

    # figures
    fig, axes = plt.subplots(2, 3, figsize=(15, 8))
    heatmap(plt, _pivot(data, "saoud_robot", "baseline", "ct_cn_ratio"), axes[0, 0],
            "robot: |C_T|/|C_N| (✓ < 0.1)", "-", lambda v: v < 0.1)
    heatmap(plt, 100 * _delta(data, "saoud_robot", "ct_off", "steady_speed")
            / _pivot(data, "saoud_robot", "baseline", "steady_speed"), axes[0, 1],
            f"robot: speed change with C_T off (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            lambda v: abs(v) < 100 * SPEED_HOLDS)
    heatmap(plt, 100 * _delta(data, "saoud_robot", "sheeted", "steady_speed")
            / _pivot(data, "saoud_robot", "baseline", "steady_speed"), axes[0, 2],
            f"robot: speed, sheeted vs actuated (✓ > −{100 * SPEED_HOLDS:g} %)", "%",
            lambda v: v > -100 * SPEED_HOLDS)
    heatmap(plt, np.degrees(_pivot(data, "wille_yacht", "baseline", "pitch_amplitude")), axes[1, 0],
            "yacht: pitch amplitude (✓ < 2°)", "deg", lambda v: v < 2)
    heatmap(plt, 100 * _delta(data, "wille_yacht", "four_dof", "steady_speed")
            / _pivot(data, "wille_yacht", "baseline", "steady_speed"), axes[1, 1],
            f"yacht: speed, heave+pitch held vs free (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            lambda v: abs(v) < 100 * SPEED_HOLDS)
    heatmap(plt, np.degrees(_pivot(data, "wille_yacht", "baseline", "keel_aoa")), axes[1, 2],
            "yacht: keel |α| (✓ < 10°, linear lift)", "deg", lambda v: v < 10)
    fig.suptitle("Where the assumptions hold over the wind plane (× = capsized / no data)")
    save_figure(fig, out / "wind_plane.png")

    fig, ax = plt.subplots(figsize=(5, 4))
    for l_phi, group in steady.groupby("l_phi"):
        ax.scatter(group["phi_star_deg"], group["heel_deg"], label=f"l_φ = {l_phi:g} m")
    lim = max(5.0, float(np.nanmax(np.abs(steady[["phi_star_deg", "heel_deg"]].to_numpy()))) * 1.1)
    ax.plot([-lim, lim], [-lim, lim], "k--", lw=1, label="heel = φ*")
    ax.set_xlabel("Saoud's predicted φ* [deg]")
    ax.set_ylabel("6-DOF steady heel [deg]")
    ax.set_title("Static optimum vs heel reached (robot)")
    ax.legend()
    save_figure(fig, out / "phi_star_vs_heel.png")

    report = Report(TITLE)
    report.paragraph(__doc__.split("\n\n", 1)[1])
    report.table(rows, ["assumption", "scenarios", "metric", "range", "threshold", "verdict", "effect"])
    report.figure(out / "wind_plane.png", "The metrics over true wind angle × true wind speed")
    report.figure(out / "phi_star_vs_heel.png", "Saoud's φ* against the heel the 6-DOF robot reaches")
    report.paragraph("Time constants: " + "; ".join(
        f"{b}: roll period {v['roll_period']:.2f} s, yaw time constant after a 10° rudder step "
        f"{v['yaw_time_constant']:.1f} s" for b, v in tc.items()) + ".")
    report.paragraph(
        "A finding of the cross-check (tests/test_reference_wille.py): Wille's eq. 4 as printed "
        "(Fossen's q = 0 form) leaves out tan φ times the pitch moment from the yaw equation. A "
        "heeled sail's drive, acting high up, turns a boat whose pitch is held to windward; with a "
        "fixed rudder the printed model's heading drifts 33° from the rigid boat's in 60 s of 6 m/s "
        "wind, while the rigid form agrees within 1°.")
    report.write(out)
    headline["rows"] = len(rows)
    return headline
