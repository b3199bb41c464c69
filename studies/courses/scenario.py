"""What the courses study runs: each event on each shipped boat with Jaulin and Le Bars' line
following, calm with perfect instruments and servos, and in a sea with typical ones.

**The events** are the four course tasks (:mod:`sailmujoco.tasks.course`, ``station``,
``scanning``) as laid by default: the wind 5 m/s from the north with its gusts and wander, the
start on a beam reach at 1 m/s. A race's episode ends at the finish; a boat that has not finished
by :data:`DURATION` has not (a 100 m beat and run takes the slowest boat under 300 s in calm
water). Station keeping runs until its five minutes and the 30 s to leave are over for any boat
that enters by 90 s; area scanning runs its rules' 15 minutes.

**The conditions.** "calm, perfect": flat water, the instruments and servos perfect. "sea,
typical": the sea the wind raises, fully developed (Pierson-Moskowitz: Hs 0.56 m, Tp 3.7 s, a
peak wavelength of 22 m at 5 m/s; :meth:`WaveConfig.from_wind
<sailmujoco.options.WaveConfig.from_wind>`), coming from the wind's direction, and the typical
instruments and servos (``sensors="typical"``, ``actuators="typical"``: the GNSS's wander, the
compass's and the vane's errors, the servos' rate and dead band). Both run on every seed.
The lakes and harbours the events are sailed in raise a shorter chop (over 2 km of fetch: Hs
0.11 m, Tp 1.3 s, 2.8 m long); the sea model leaves out waves shorter than the hull
(:mod:`sailmujoco.forces.sea_hull`), and in that chop its coarse grid turns the 11:Metre against
full rudder, so the study sails the longer sea that every boat here can feel as modelled.

**The switches.** Where a score differs between the two conditions beyond its interval, the
second pass runs each half of the change alone on the same seeds: "sea alone" (the sea with
perfect instruments) and "instruments alone" (typical instruments in calm water); the one that
moves the score as far names the cause. The law's own switch, Jaulin's book rudder
(``rudder="sawtooth"``, a third of the listing's gain near the heading), sails the race in calm
water on every boat: where the boat cannot hold its close-hauled heading, its tacks stall.

**The seed** draws the gusts' and the wander's realisation, the start heading (within 5 deg) and
the sea's phases; a case's conditions and switches are paired seed by seed.
"""

from __future__ import annotations

import json
import math

from sailmujoco import suite, sweep
from sailmujoco.options import WaveConfig
from sailmujoco.study import Runs

NAME = "courses"
TITLE = "Courses: the events autonomous sailboats compete in, sailed by Jaulin and Le Bars' line following"
BOATS = ("eleven_metre", "viel_boat", "wille_yacht", "saoud_robot")
TASKS = ("upwind_downwind", "precision_navigation", "station_keeping", "area_scanning")
# each event's score as its rules count it: (metric, unit, the better direction)
SCORES = {"upwind_downwind": ("finish_time", "s", "lower"), "precision_navigation": ("points", "", "higher"),
          "station_keeping": ("points", "", "higher"), "area_scanning": ("cells_visited", "", "higher")}
DURATION = {"upwind_downwind": 400.0, "precision_navigation": 400.0, "station_keeping": 420.0,
            "area_scanning": 900.0}  # s
SMOKE_DURATION = {"upwind_downwind": 250.0, "precision_navigation": 200.0, "station_keeping": 120.0,
                  "area_scanning": 120.0}
WIND_SPEED = 5.0  # m/s, the tasks' default
# condition -> (a sea, the instruments' and servos' preset)
CONDITIONS = {"calm, perfect": (False, "perfect"), "sea, typical": (True, "typical")}
SWITCHES = {"sea alone": (True, "perfect"), "instruments alone": (False, "typical")}
BOOK_RUDDER = "book rudder"  # the law's switch: Jaulin's sawtooth rudder, the race in calm water
SEEDS = 2  # N: the share of `study all` its 900 s scans in a sea afford (`--seeds N` for more)
JOB = "runs"
MORE_JOB = "switches"
TRACK_EVERY = 10  # control steps between the stored track's points (1 s)
VIDEO = {"boat": "eleven_metre", "task": "upwind_downwind", "controller": "line_following",
         "seconds": 160.0, "camera": "top"}


def sea(seed: int) -> WaveConfig:
    """The sea of the "sea" conditions on ``seed``: the wind's fully developed sea, from the wind.

    Parameters
    ----------
    seed : int
        The sea's phases.
    """
    return WaveConfig.from_wind(WIND_SPEED, "fully_developed", direction_from=0.0, seed=seed)


def job(boat: str, task: str, arm: str, seed: int, smoke: bool) -> dict:
    """One run as data.

    Parameters
    ----------
    boat, task : str
        A shipped boat and a course task.
    arm : str
        A key of :data:`CONDITIONS` or :data:`SWITCHES`, or :data:`BOOK_RUDDER`.
    seed : int
        The seed.
    smoke : bool
        The short pass (:data:`SMOKE_DURATION`).
    """
    duration = (SMOKE_DURATION if smoke else DURATION)[task]
    return {"boat": boat, "task": task, "arm": arm, "seed": int(seed), "duration": duration}


def simulate(item: dict) -> dict:
    """One run: the task's metrics, the law's tacks, the time astern and the track at 1 Hz.

    Parameters
    ----------
    item : dict
        A :func:`job`.

    Returns
    -------
    dict
        The job's keys and ``metrics``, ``tacks``, ``astern`` (s going astern), ``track``
        ([t, x, y] rows at 1 Hz) and ``scene`` (the marks, line or corners videos draw).
    """
    from sailmujoco.video.recording import scene_of

    arm = item["arm"]
    waves, preset = (False, "perfect") if arm == BOOK_RUDDER else {**CONDITIONS, **SWITCHES}[arm]
    env = suite.load(item["boat"], item["task"], seed=item["seed"], time_limit=item["duration"],
                     waves=sea(item["seed"]) if waves else None, sensors=preset, actuators=preset)
    controller = sweep.make_controller("line_following", env,
                                       rudder="sawtooth" if arm == BOOK_RUDDER else "listing")
    table = suite.rollout(env, controller)
    track = table[["t", "x", "y"]].iloc[::TRACK_EVERY].round(3).to_numpy().tolist()
    # a tack that stalls leaves the boat going astern: the seconds of it
    astern = float((table["u"] < 0.0).sum() * env.control_timestep())
    metrics = {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in env.task.metrics().items()}
    target = json.loads(json.dumps(scene_of(item["boat"], env, {})[3]))  # plain lists, as stored
    return {**item, "metrics": metrics, "tacks": int(controller.controller.tacks), "astern": astern,
            "track": track, "scene": target}


def jobs_for(smoke: bool, seeds: tuple) -> list[dict]:
    """The first pass: every event on every boat in both conditions, and the race with the book's
    rudder in calm water, each on every seed (the smoke pass: Viel's boat, the race and station
    keeping).

    Parameters
    ----------
    smoke : bool
        The short pass.
    seeds : tuple of int
        The seeds.
    """
    boats = BOATS[1:2] if smoke else BOATS
    tasks = TASKS[::2] if smoke else TASKS
    jobs = [job(boat, task, arm, seed, smoke) for boat in boats for task in tasks for arm in CONDITIONS
            for seed in seeds]
    if not smoke:
        jobs += [job(boat, "upwind_downwind", BOOK_RUDDER, seed, smoke) for boat in BOATS for seed in seeds]
    return sorted(jobs, key=lambda j: -j["duration"])  # the longest first, for the worker pool


def runs(smoke: bool, seeds: tuple = (0,)) -> Runs:
    """The first pass (:func:`jobs_for`), stored under ``jobs/runs``.

    Parameters
    ----------
    smoke : bool
        The short pass.
    seeds : tuple of int
        The seeds.
    """
    return Runs(jobs={JOB: (f"{__name__}:simulate", jobs_for(smoke, seeds))}, label=f"{NAME} runs")
