"""The physics step's error on the studies' figures of merit: how large a step each boat may take.

Run: python benchmarks/timestep_convergence.py [--seeds 4] [--steps-ms 2.5,5,10,20,25,50,100]
     [--boats wille_yacht,saoud_robot,viel_boat,eleven_metre] [--worlds mujoco,paper] [--cases WORDS]
     [--workers 2] [--full] [--plain-filter] [--csv FILE]

Each case is a task a study reports, with the study's controller, figures of merit and control
step (the ``CASES`` table below): per boat, the 6-DOF boat in calm water, the same with heave and
pitch held (``dofs=4``), in a fully developed 1 m Pierson-Moskowitz sea (the assumption study's
middle sea, Tp 4.99 s, from the north, its phases drawn by the run's seed), with typical
instruments and servos (``sensors="typical", actuators="typical"``), and in the paper world
(Wille's 4-DOF equations; for position keeping Viel's 3-DOF model). Every case runs on seeds
0..N-1 at every step of ``--steps-ms`` that divides its control step (the ``timestep`` option);
the finest is the reference. Seeds pair the runs: one seed's gusts, sea, noise and start are the
same at every step.

Per figure and step: the error, the mean over seeds of |figure(step) - figure(reference)|, and
the seed spread, the standard deviation over seeds of the figure at the reference step. A step
passes a figure when its error is below its threshold, a tenth of the spread, or the figure's
stated absolute tolerance (``Figure.tolerance``, a tenth of the last digit the study prints)
where that is larger (a spread of zero or nearly so: the steady cases, whose seeds only turn the
start heading by a degree or two). A step whose run stopped on any seed (a blow-up: non-finite,
capsized) fails. A case's step is the largest that passes every figure and with it every finer
step; a boat's is the smallest over its MuJoCo cases, the paper world's apart. The error of a
step is measured against the reference, whose own error it leaves out: in 6 DOF, where MuJoCo's
RK4 is second order in the attitude (tests/test_timestep.py), a 5 ms error measured against
2.5 ms is 3/4 of the 5 ms step's own.

Episodes are shorter than the tasks' own where the figure allows, to keep the default run near
10 minutes on 2 cores (``--workers 2``): the beam reach 60 s (the figures over its last 50 s, as
Table 1's; the task runs 300 s), course keeping 100 s (200 s), position keeping 100 s (200 s;
the boat enters the target area after 30-50 s), the speed trial and heading hold their own 60 s
and 30 s. ``--full`` runs the tasks' lengths.

``--plain-filter`` integrates the servos' first-order lag as MuJoCo's plain filter (``dyntype
filter``) instead of the exact filter the boats are built with (``filterexact``, what a position
actuator's ``timeconst`` builds): the same ODE, but MuJoCo's RK4 keeps its order with the plain
filter and loses it with the exact one (first order while a command is followed,
tests/test_timestep.py). It shows how large a step the boats would allow if built so.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

import mujoco
import numpy as np

from sailmujoco import suite, sweep
from sailmujoco.boat.mjcf import TIMESTEP
from sailmujoco.reference import viel_model, wille
from sailmujoco.step.timing import STEP_TOLERANCE

BOATS = ("wille_yacht", "saoud_robot", "viel_boat", "eleven_metre")
STEPS_MS = (2.5, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0)
SEA = {"spectrum": "pm", "hs": 1.0, "tp": 4.99}  # m, s: the assumption study's 1 m developed sea
TYPICAL = {"sensors": "typical", "actuators": "typical"}
DEG = math.degrees(1.0)


@dataclass(frozen=True)
class Figure:
    """A task metric a study reports: its name, the unit it is printed in and the absolute
    tolerance (in that unit) below which a difference does not show in the study's numbers."""

    metric: str
    unit: str
    scale: float = 1.0  # from the metric's SI value to ``unit``
    tolerance: float = 1e-3


# tolerances: a tenth of the last digit each study prints (Table 1 and 2 two decimals, Saoud's speed
# ratios three digits and heels one decimal, Viel's distances one decimal and times whole seconds)
ROLL = (Figure("roll_amplitude", "deg", DEG), Figure("max_roll_rate", "deg/s", DEG),
        Figure("mean_surge", "m/s"))
COURSE = (Figure("drift_error", "deg", DEG), Figure("course_error_mean", "deg", DEG),
          Figure("mean_surge", "m/s"))
TRIAL = tuple(Figure(f"mean_{q}_{a}", u, s, t) for a in (10, 45, 80)
              for q, u, s, t in (("speed", "m/s", 1.0, 1e-4), ("heel", "deg", DEG, 0.01))) + (
    Figure("max_heel", "deg", DEG, 0.01),)
POLAR = (Figure("steady_speed", "m/s", tolerance=1e-4), Figure("steady_heel", "deg", DEG, 0.01))
KEEPING = (Figure("entered_at", "s", tolerance=0.1), Figure("max_distance_after_entry", "m", tolerance=0.01),
           Figure("mean_distance_after_entry", "m", tolerance=0.01))


@dataclass(frozen=True)
class Case:
    """One task as a study runs it, in one world and variant.

    ``options`` go to :func:`sailmujoco.suite.load`; ``sea`` adds :data:`SEA` with the run's seed.
    """

    boat: str
    task: str
    controller: str
    figures: tuple
    duration: float
    full_duration: float
    variant: str = "6 DOF"
    world: str = "mujoco"
    control_timestep: float = 0.1
    controller_options: dict = field(default_factory=dict)
    options: dict = field(default_factory=dict)
    sea: bool = False

    @property
    def name(self) -> str:
        return f"{self.boat} {self.task} {self.controller} ({self.variant})"

    @property
    def own_step(self) -> float:
        """The world's own step, s (the ``timestep`` option unset)."""
        if self.world == "mujoco":
            return TIMESTEP
        if self.task == "position_keeping":
            return viel_model.RK4_MAX_STEP
        return min(wille.RK4_MAX_STEP, self.control_timestep)


def _variants(boat, task, controller, figures, duration, full, *, paper=True, four_dof=True,
              **common) -> list[Case]:
    """A task's cases: 6 DOF, 4 DOF, in the sea, with typical instruments, in the paper world."""
    options = common.pop("options", {})
    cases = [Case(boat, task, controller, figures, duration, full, options=options, **common),
             *([Case(boat, task, controller, figures, duration, full, "4 DOF",
                     options={**options, "dofs": 4}, **common)] if four_dof else []),
             Case(boat, task, controller, figures, duration, full, "sea Hs 1 m", options=options, sea=True,
                  **common),
             Case(boat, task, controller, figures, duration, full, "typical instruments",
                  options={**options, **TYPICAL}, **common)]
    if paper:
        cases.append(Case(boat, task, controller, figures, duration, full, "paper world", "paper",
                          options=options, **common))
    return cases


# the studies' tasks: wille_roll_table1 (sim 3: roll control on, the true wind), wille_course_table2
# (its 50 Hz control), saoud_fig6 and saoud_fig7 (S and Bm on l_phi = 0.1 m, the start heading
# within 2 deg), viel_fig3 (case 1, Viel's 0.01 s control period), real_boats (the 11:Metre's polar)
SIM3 = {"roll_control": True, "wind": "perfect"}
JITTER = {"heading_jitter_deg": 2.0}
CASES = (
    *_variants("wille_yacht", "beam_reach_roll", "wille_roll", ROLL, 60.0, 300.0, controller_options=SIM3,
               options={"wind_speed": 10.0}),
    Case("wille_yacht", "course_hold", "wille_course", COURSE, 100.0, 200.0, control_timestep=0.02),
    Case("wille_yacht", "course_hold", "wille_course", COURSE, 100.0, 200.0, "paper world", "paper",
         control_timestep=0.02),
    *_variants("saoud_robot", "speed_trial", "saoud", TRIAL, 60.0, 60.0,
               options={"boat_options": {"l_phi": 0.1}, **JITTER}),
    Case("saoud_robot", "speed_trial", "briere", TRIAL, 60.0, 60.0,
         options={"boat_options": {"l_phi": 0.1}, **JITTER}),
    Case("saoud_robot", "heading_hold", "saoud", POLAR, 30.0, 30.0, "beam reach, steady wind",
         options={"boat_options": {"l_phi": 0.1}, "wind_speed": 5.82, "wind_from_deg": 90.0,
                  "gusts": False, "wander": False, **JITTER}),
    *_variants("viel_boat", "position_keeping", "viel", KEEPING, 100.0, 200.0, control_timestep=0.01,
               options={"case": 1}),
    # real_boats: one polar point of the two-sail 11:Metre (10 kn at 52 deg, its main at 20 deg);
    # no paper world, which has the main alone, and no 4 DOF: its crew's slide needs the free hull
    *_variants("eleven_metre", "heading_hold", "fixed_sail", POLAR, 60.0, 60.0, paper=False, four_dof=False,
               controller_options={"sail_deg": 20.0},
               options={"wind_speed": 5.144, "wind_from_deg": 52.0, "gusts": False, "wander": False,
                        **JITTER}),
)


def steps_for(case: Case, steps_ms) -> list[float]:
    """The steps of ``steps_ms`` (ms) that divide the case's control step, in s, finest first."""
    out = []
    for ms in sorted(steps_ms):
        ratio = case.control_timestep / (ms / 1000.0)
        if ratio >= 1.0 - STEP_TOLERANCE and abs(ratio - round(ratio)) <= STEP_TOLERANCE:
            out.append(ms / 1000.0)
    return out


def run(job: tuple) -> tuple:
    """One episode: (case index, step, seed, full length, plain filter) -> (the job, {metric: value}
    or None, why it stopped)."""
    index, step, seed, full, plain = job
    case = CASES[index]
    options = dict(case.options)
    if case.sea:
        options["waves"] = {**SEA, "seed": seed}
    try:
        env = suite.load(case.boat, case.task, case.world, seed=seed, timestep=step,
                         control_timestep=case.control_timestep,
                         time_limit=case.full_duration if full else case.duration, **options)
        if plain and case.world == "mujoco":  # the servos' lag as MuJoCo's plain filter, RK4's order
            env.physics.model.ptr.actuator_dyntype[:] = int(mujoco.mjtDyn.mjDYN_FILTER)
        controller = sweep.make_controller(case.controller, env, **case.controller_options)
        if hasattr(controller, "reset"):
            controller.reset(seed)
        timestep = env.reset()
        while not timestep.last():
            timestep = env.step(controller(timestep))
        metrics = env.task.metrics()
    except Exception as err:  # a blow-up the world did not catch: a failed row, not a crash
        return job, None, f"{type(err).__name__}: {str(err).splitlines()[0]}"
    if metrics.get("stopped"):
        return job, None, str(metrics["stopped"])
    return job, {f.metric: float(metrics[f.metric]) * f.scale for f in case.figures}, None


def difference(a: float, b: float) -> float:
    """|a - b|, 0 where both are nan (a figure neither run has, e.g. never entered), inf where one is."""
    if math.isnan(a) and math.isnan(b):
        return 0.0
    if math.isnan(a) or math.isnan(b):
        return math.inf
    return abs(a - b)


def analyse(case: Case, steps: list[float], seeds: int, results: dict) -> list[dict]:
    """One row per (step, figure): error, spread, threshold and whether it passes."""
    reference = steps[0]
    rows = []
    for step in steps:
        runs = [results[step, s] for s in range(seeds)]
        stopped = sorted({why for _, why in runs if why})
        for fig in case.figures:
            ref = np.array([results[reference, s][0][fig.metric] if results[reference, s][0] else math.nan
                            for s in range(seeds)])
            spread = float(np.nanstd(ref, ddof=1)) if seeds > 1 and np.isfinite(ref).sum() > 1 else 0.0
            threshold = max(0.1 * spread, fig.tolerance)
            if stopped:
                error = worst = math.inf
            else:
                errs = [difference(m[fig.metric], r) for (m, _), r in zip(runs, ref, strict=True)]
                error, worst = float(np.mean(errs)), float(np.max(errs))
            rows.append({"boat": case.boat, "world": case.world, "variant": case.variant, "task": case.task,
                         "controller": case.controller, "control_timestep_s": case.control_timestep,
                         "step_s": step, "figure": fig.metric, "unit": fig.unit,
                         "reference_mean": float(np.nanmean(ref)) if np.isfinite(ref).any() else math.nan,
                         "spread": spread, "tolerance": fig.tolerance, "threshold": threshold,
                         "mean_abs_error": error, "max_abs_error": worst, "passes": error < threshold,
                         "stopped": "; ".join(stopped)})
    return rows


def largest_passing(rows: list[dict], steps: list[float]) -> float | None:
    """The largest step that passes every figure, every finer step passing too (None: not even
    the first above the reference)."""
    best = None
    for step in steps[1:]:
        if all(r["passes"] for r in rows if r["step_s"] == step):
            best = step
        else:
            break
    return best


def print_case(case: Case, steps: list[float], rows: list[dict], seeds: int) -> None:
    print(f"\n{case.name}, {case.world} world, control step {case.control_timestep * 1000:g} ms, "
          f"{seeds} seeds, reference {steps[0] * 1000:g} ms")
    figures = [f.metric for f in case.figures]
    head = "  ".join(f"{name[:18]:>18s}" for name in figures)
    print(f"{'':>10s}  {head}")
    ref = {r["figure"]: r for r in rows if r["step_s"] == steps[0]}
    means = (f"{ref[n]['reference_mean']:>12.4g} {ref[n]['unit']:<5s}" for n in figures)
    print(f"{'mean':>10s}  " + "  ".join(means))
    print(f"{'spread':>10s}  " + "  ".join(f"{ref[n]['spread']:>18.3g}" for n in figures))
    print(f"{'threshold':>10s}  " + "  ".join(f"{ref[n]['threshold']:>18.3g}" for n in figures))
    for step in steps[1:]:
        by = {r["figure"]: r for r in rows if r["step_s"] == step}
        if any(r["stopped"] for r in by.values()):
            print(f"{step * 1000:>7g} ms  FAILED: {next(iter(by.values()))['stopped']}")
            continue
        cells = "  ".join(f"{by[n]['mean_abs_error']:>17.3g}{' ' if by[n]['passes'] else '*'}"
                          for n in figures)
        print(f"{step * 1000:>7g} ms  {cells}")
    best = largest_passing(rows, steps)
    own = case.own_step
    verdict = "none above the reference" if best is None else f"{best * 1000:g} ms"
    print(f"  largest step within a tenth of the spread (* above it): {verdict}; the world's own: "
          f"{own * 1000:g} ms")


def recommend(per_case: list[tuple[Case, float | None]]) -> None:
    print("\nrecommended step (the smallest over the cases of a boat and world):")
    groups = {}
    for case, best in per_case:
        groups.setdefault((case.boat, case.world), []).append((case, best))
    for (boat, world), items in groups.items():
        finite = [(b if b is not None else 0.0, c) for c, b in items]
        step, limiting = min(finite, key=lambda x: x[0])
        own = items[0][0].own_step if world == "mujoco" else min(c.own_step for c, _ in items)
        text = "none above the reference" if step == 0.0 else f"{step * 1000:g} ms"
        print(f"  {boat:12s} {world:7s} {text:>24s}  (set by {limiting.task} {limiting.controller}, "
              f"{limiting.variant}; the world's own: {own * 1000:g} ms)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=4, help="seeds 0..N-1, paired across steps (>= 2)")
    parser.add_argument("--steps-ms", default=",".join(f"{s:g}" for s in STEPS_MS),
                        help="the steps in ms, comma-separated; the finest is the reference")
    parser.add_argument("--boats", default=",".join(BOATS), help="the boats, comma-separated")
    parser.add_argument("--worlds", default="mujoco,paper", help="the worlds, comma-separated")
    parser.add_argument("--cases", default="", help="only the cases whose name holds one of these "
                        "comma-separated words (e.g. '4 DOF,course_hold')")
    parser.add_argument("--workers", type=int, default=2, help="processes (1: in this one)")
    parser.add_argument("--full", action="store_true", help="the tasks' own episode lengths")
    parser.add_argument("--plain-filter", action="store_true",
                        help="the servos' lag as MuJoCo's plain filter (dyntype filter), not the exact one")
    parser.add_argument("--csv", help="write one row per case, step and figure here")
    args = parser.parse_args(argv)
    try:
        steps_ms = [float(s) for s in args.steps_ms.split(",")]
    except ValueError:
        parser.error(f"--steps-ms must be numbers in ms separated by commas, got {args.steps_ms!r}")
    if args.seeds < 2 or len(steps_ms) < 2 or min(steps_ms) <= 0.0:
        parser.error("--seeds must be >= 2 and --steps-ms at least two steps > 0 ms")
    boats, worlds = args.boats.split(","), args.worlds.split(",")
    unknown = sorted(set(boats) - set(BOATS)) + sorted(set(worlds) - {"mujoco", "paper"})
    if unknown:
        parser.error(f"unknown boat or world {unknown[0]!r}; boats: {', '.join(BOATS)}; "
                     "worlds: mujoco, paper")
    chosen = [(i, c, steps_for(c, steps_ms)) for i, c in enumerate(CASES)
              if c.boat in boats and c.world in worlds
              and (not args.cases or any(word in c.name for word in args.cases.split(",")))]
    chosen = [(i, c, s) for i, c, s in chosen if len(s) >= 2]
    jobs = [(i, step, seed, args.full, args.plain_filter) for i, _, steps in chosen for step in steps
            for seed in range(args.seeds)]
    print(f"{len(chosen)} cases, {len(jobs)} episodes on {args.workers} worker(s)", flush=True)
    if args.workers > 1:
        with ProcessPoolExecutor(args.workers) as pool:
            done = list(pool.map(run, jobs, chunksize=1))
    else:
        done = [run(job) for job in jobs]
    results = {(i, step, seed): (metrics, why) for (i, step, seed, _, _), metrics, why in done}
    all_rows, per_case = [], []
    for i, case, steps in chosen:
        mine = {(step, seed): results[i, step, seed] for step in steps for seed in range(args.seeds)}
        if any(mine[steps[0], s][1] for s in range(args.seeds)):
            print(f"\n{case.name}: the reference step {steps[0] * 1000:g} ms stopped "
                  f"({mine[steps[0], 0][1] or 'a seed'}); no verdict")
            per_case.append((case, None))
            continue
        rows = analyse(case, steps, args.seeds, mine)
        print_case(case, steps, rows, args.seeds)
        all_rows += rows
        per_case.append((case, largest_passing(rows, steps)))
    recommend(per_case)
    if args.csv and all_rows:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, fieldnames=list(all_rows[0]))
            writer.writeheader()
            writer.writerows(all_rows)
        print(f"\nwrote {args.csv}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
