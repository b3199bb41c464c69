"""Watch a boat: MuJoCo's interactive viewer with a controller in the loop, at real time.

:func:`watch` (the command ``sailmujoco view wille_yacht heading_hold --controller pid``,
:mod:`sailmujoco.cli.view`) opens MuJoCo's viewer
(:func:`mujoco.viewer.launch_passive`) on the display copy of the boat that the videos draw
(:class:`sailmujoco.video.SceneRenderer` without its offscreen context), posed each frame from
the simulation, with the videos' wind arrow, force arrows and text box (time, speed, heel,
apparent wind, rudder and sail). A paper world (``--world paper``) has no MuJoCo model of its
own: the 6-DOF display model is posed from its state at each control step, as in the videos.

The simulation runs at real time (it falls behind where a step costs more than it simulates;
the real-time factor is printed at the end). In the MuJoCo world the frames are drawn between
the physics sub-steps at ``--fps`` per simulated second, which leaves the trajectory unchanged.

Keys (:data:`KEYS`): space pauses and resumes; while paused, the right arrow runs one control
step. The mouse turns, moves and zooms the camera, which follows the boat.

Without a display (no ``DISPLAY``, or GLFW cannot open a window with an OpenGL context) the
command prints one line that points to ``sailmujoco video`` and exits with status 2. A
controller that raises, or gives an action that is not two finite numbers, stops the run at the
state it was given: the window shows it, marked (and held open until it is closed, as at the end
of a run), and the command prints one line with the simulated time and exits with status 2.
"""

from __future__ import annotations

import math
import time
from contextlib import nullcontext

import numpy as np

from ..boat.catalogue import boat_label
from ..errors import ControllerFailed, act
from ..video import (
    SceneRenderer,
    Snapshot,
    frames_between_substeps,
    scene_of,
    simulated_sea,
    snapshot_observation,
    snapshot_physics,
)
from .window import Window, open_display

KEY_SPACE, KEY_RIGHT = 32, 262  # GLFW key codes
KEYS = """keys and mouse:
  space            pause / resume the simulation
  right arrow      while paused: run one control step
  left drag        turn the camera (it follows the boat)
  right drag       move the camera
  scroll           zoom
  Tab, Shift+Tab   show or hide MuJoCo's left and right panels
  Ctrl+P           MuJoCo's own screenshot (screenshot.png in the current folder)
  closing the window stops the run"""


class Keys:
    """The keyboard state the loop reads; ``press`` is the viewer's key callback (its thread).

    Parameters
    ----------
    paused : bool
        Start paused.
    """

    def __init__(self, paused: bool = False):
        self.paused = paused
        self.steps = 0  # control steps asked for while paused

    def press(self, key: int) -> None:
        """The viewer's key callback: space pauses or resumes, the right arrow asks for a step.

        Parameters
        ----------
        key : int
            GLFW key code.
        """
        if key == KEY_SPACE:
            self.paused = not self.paused
            self.steps = 0
        elif key == KEY_RIGHT and self.paused:
            self.steps += 1

    def may_step(self) -> bool:
        """Whether the loop may take a control step now (and counts a paused step as taken)."""
        if not self.paused:
            return True
        if self.steps > 0:
            self.steps -= 1
            return True
        return False


class RealTime:
    """Paces simulated time to the wall clock; counts the wall time spent simulating."""

    MAX_LAG = 0.25  # s behind the clock: give up catching up and re-anchor

    def __init__(self):
        self.anchor = None
        self.running_wall = 0.0
        self._last = None

    def restart(self) -> None:
        """After a pause: the next frame re-anchors the clock."""
        self.anchor = None
        self._last = None

    def wait(self, sim_time: float) -> None:
        """Sleep until the wall clock reaches ``sim_time`` (from the anchor).

        Parameters
        ----------
        sim_time : float
            Simulated time (s).
        """
        now = time.perf_counter()
        if self.anchor is None:
            self.anchor = (now, sim_time)
        due = self.anchor[0] + (sim_time - self.anchor[1])
        if due > now:
            time.sleep(due - now)
        elif now - due > self.MAX_LAG:
            self.anchor = (now, sim_time)
        end = time.perf_counter()
        if self._last is not None:
            self.running_wall += end - self._last
        self._last = end


def watch(boat: str, task: str, controller: str, *, world: str = "mujoco",
          seconds: float | None = None, seed: int = 0, fps: float = 30.0, forces: bool = True,
          overlay: bool = True, paused: bool = False, screenshot_path=None,
          controller_options: dict | None = None, **options) -> dict:
    """Run ``task`` on ``boat`` under ``controller`` in MuJoCo's viewer, at real time.

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`.
    controller : str
        A registered controller (:func:`sailmujoco.sweep.make_controller`).
    seconds : float, optional
        Stop the run (and close the window) after this much simulated time; without it the
        task runs to its end and the window stays open, showing the last state, until it is
        closed.
    seed : int
        Seeds the task and the controller.
    fps : float
        Frames per simulated second.
    forces, overlay : bool
        Force arrows; text.
    paused : bool
        Start paused (space runs).
    screenshot_path : path, optional
        At the end, save the last state as a PNG, drawn offscreen from the viewer's camera at
        the window's size with the videos' panel (:mod:`sailmujoco.viewer.screenshot`).
    controller_options : dict, optional
        Keywords of the controller's factory.
    **options
        Passed to :func:`sailmujoco.suite.load`.

    Returns
    -------
    dict
        ``sim_time`` (s), ``wall_time`` (s spent running, pauses excluded),
        ``real_time_factor``, ``distance`` (m from the start), ``stopped`` (the stop reason of
        an early end, or None) and ``screenshot`` (what was saved).

    Raises
    ------
    NoDisplay
        No window can be opened (raised before anything is loaded).
    ControllerFailed
        The controller raised or gave a bad action: the run ends at that state, shown and saved
        as at the end of a run (the exception's ``kept``: what the screenshot saved, or None).
    """
    if not (math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps must be a number > 0, got {fps!r}")
    open_display()
    env, policy = _load(boat, task, world, controller, seed, seconds, controller_options, options)
    mujoco_world, params, sail_mode, target = scene_of(boat, env, options)
    scene = SceneRenderer(params, forces=forces, overlay=overlay, sail_mode=sail_mode, target=target,
                          labels=f"{boat_label(boat)} · {task} · {controller} ({world})", offscreen=False,
                          waves=simulated_sea(env.physics))
    timestep = env.reset()
    snap = (snapshot_physics(env.physics, env.task.references(env.physics)) if mujoco_world
            else snapshot_observation(timestep.observation))
    start = snap.position.copy()
    scene.pose(snap)

    keys = Keys(paused)
    window = Window(scene, snap, keys.press, forces=forces, overlay=overlay)
    clock = RealTime()
    try:
        snap, interrupted, failure = _sail(env, policy, controller, timestep, snap, window, keys, clock,
                                           fps, mujoco_world)
        stopped = env.task.metrics().get("stopped") or ("interrupted" if interrupted else None)
        what = _end(window, snap, failure or stopped, seconds, screenshot_path, interrupted)
    finally:
        window.close()
    sim_time = float(snap.time)
    return {"sim_time": sim_time, "wall_time": clock.running_wall,
            "real_time_factor": sim_time / clock.running_wall if clock.running_wall > 0 else float("nan"),
            "distance": float(np.linalg.norm(snap.position[:2] - start[:2])), "stopped": stopped,
            "screenshot": what}


def _load(boat: str, task: str, world: str, controller: str, seed: int, seconds, controller_options,
          options: dict):
    """(env, policy) of the run, the policy reset with ``seed``."""
    from ..suite import load
    from ..sweep import make_controller

    env = load(boat, task, world, seed=seed, time_limit=seconds, **options)
    policy = make_controller(controller, env, **(controller_options or {}))
    if hasattr(policy, "reset"):
        policy.reset(seed)
    return env, policy


PAUSE_NOTE = "PAUSED: space runs, right arrow steps"


def _sail(env, policy, name: str, timestep, snap: Snapshot, window: Window, keys: Keys, clock: RealTime,
          fps: float, mujoco_world: bool) -> tuple[Snapshot, bool, ControllerFailed | None]:
    """Run the episode in the window at real time; returns the last state, whether Ctrl+C
    ended it and the controller's failure that ended it (or None). In the MuJoCo world the
    frames are drawn between the physics sub-steps."""
    physics = env.physics
    shape = env.action_spec().shape
    frame = {"next": 0.0}

    def due() -> float:
        return frame["next"]

    def emit() -> None:
        now = snapshot_physics(physics, env.task.references(physics))
        frame["next"] = (math.floor(now.time * fps + 0.5) + 1) / fps
        window.show(now)
        clock.wait(now.time)

    hook = frames_between_substeps(physics, emit, due) if mujoco_world else nullcontext()
    interrupted, failure = False, None
    window.show(snap)
    with hook:
        try:
            while window.viewer.is_running() and not timestep.last():
                if not keys.may_step():
                    window.show(snap, PAUSE_NOTE)
                    clock.restart()
                    time.sleep(1.0 / fps)
                    continue
                try:
                    action = act(policy, timestep, controller=name, time=float(physics.time()), shape=shape)
                except ControllerFailed as err:
                    failure = err
                    break
                timestep = env.step(action)
                snap = snapshot_physics(physics, env.task.references(physics)) if mujoco_world else \
                    snapshot_observation(timestep.observation)
                if not mujoco_world:  # sample and hold at the control steps
                    window.show(snap)
                    clock.wait(snap.time)
        except KeyboardInterrupt:  # Ctrl+C in the terminal: stop as if the window closed
            interrupted = True
    return snap, interrupted, failure


def _end(window: Window, snap: Snapshot, why, seconds, screenshot_path, interrupted: bool):
    """The last state with its note (``why``: the controller's failure, the stop reason of an
    early end, or None), the screenshot, and (without ``seconds``) the window held open until it
    is closed; returns what the screenshot saved, or None. A controller's failure is raised
    then, its ``kept`` what the screenshot saved."""
    viewer = window.viewer
    running = viewer.is_running() and not interrupted
    if running:
        note = why.note if isinstance(why, ControllerFailed) else f"stopped at t = {snap.time:.1f} s: {why}"
        window.show(snap, note if why else ("finished: close the window" if seconds is None else None))
    what = None
    if screenshot_path is not None and running:
        what = window.save(screenshot_path, snap)  # the last state, whatever the viewer drew last
    if seconds is None and running:
        try:
            while viewer.is_running():  # hold the last state until the window is closed
                time.sleep(0.05)
        except KeyboardInterrupt:
            pass
    if isinstance(why, ControllerFailed):
        why.kept = what
        raise why
    return what
