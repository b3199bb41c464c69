"""The recording loop: a task run under a controller, drawn frame by frame and encoded as an mp4.

Frame k shows the state at t = k / fps whatever the control rate. In the MuJoCo world each
control step's physics sub-steps are split at the frame times (:func:`frames_between_substeps`),
which leaves the trajectory unchanged bit for bit (:meth:`sailmujoco.physics.BoatPhysics.step`).
A paper world moves by whole control steps (its integrator is adaptive), so frame k shows the
state at the end of the control step that contains t = k / fps. A ``seconds`` run gives
``round(seconds * fps)`` frames; a run that stops early (capsize) ends with its last frame,
marked with the reason, held for one second. A controller that raises, or gives an action that is
not two finite numbers, ends the video the same way at the state it was given; the video is
kept, and :func:`record` then raises :class:`~sailmujoco.errors.ControllerFailed`. The mp4 is
encoded by the ffmpeg binary that the ``imageio-ffmpeg`` package ships.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from contextlib import contextmanager, nullcontext
from dataclasses import dataclass
from pathlib import Path

from ..boat.catalogue import boat_label
from ..errors import ControllerFailed, act
from ..ros2.record import McapLog
from .camera import ELEVATION_DEG
from .child import ChildRenderer
from .encoding import FrameWriter, encoder, partial_file
from .panel import measured_of
from .scene import CAMERAS, Snapshot, snapshot_observation, snapshot_physics


@dataclass
class Recording:
    """What :func:`record` wrote.

    Parameters
    ----------
    path : Path
        The video file.
    frames : int
        Frames written.
    fps : float
        Frames per second of video.
    sim_time : float
        Time simulated, s.
    wall_time : float
        Wall-clock time of all of it (loading the boat and the controller included), s.
    loop_time : float
        Wall-clock time from the first frame to the end (simulating, drawing, encoding), s.
    metrics : dict
        The task's metrics (``stopped`` holds the reason of an early end); empty where the
        controller failed.
    """

    path: Path
    frames: int
    fps: float
    sim_time: float
    wall_time: float
    loop_time: float
    metrics: dict

    @property
    def render_rate(self) -> float:
        """Frames per wall-clock second while recording (simulation, drawing and encoding)."""
        return self.frames / self.loop_time if self.loop_time > 0 else float("nan")


@contextmanager
def frames_between_substeps(physics, emit: Callable[[], None], due: Callable[[], float | None]):
    """Split each ``physics.step(n)`` at the times returned by ``due()`` and call ``emit()`` there.

    ``BoatPhysics`` gives the same trajectory whatever the split (forces before every sub-step).

    Parameters
    ----------
    physics : BoatPhysics
        The simulation; its ``step`` is wrapped while the context is open.
    emit : callable
        Draws a frame of the current state.
    due : callable
        The time of the next frame (s), or None when no more frames are due.
    """
    original = physics.step
    dt = float(physics.timestep())

    def step(nstep: int = 1) -> None:
        remaining = int(nstep)
        while remaining > 0:
            t_frame = due()
            if t_frame is None:
                original(remaining)
                return
            # sub-steps until the time is within half a step of the frame time
            count = math.ceil((t_frame - float(physics.data.time)) / dt - 0.5)
            count = min(max(count, 1), remaining)
            original(count)
            remaining -= count
            while (t := due()) is not None and float(physics.data.time) >= t - 0.5 * dt:
                emit()

    physics.step = step
    try:
        yield
    finally:
        del physics.step


def scene_of(boat: str, env, options: dict) -> tuple[bool, object, str, dict | None]:
    """What a scene of ``env`` draws. A paper world is drawn as the named boat with an actuated sail.

    Parameters
    ----------
    boat : str
        The boat's name, as loaded.
    env : environment
        From :func:`sailmujoco.suite.load`.
    options : dict
        The environment options it was loaded with (``boat_options``).

    Returns
    -------
    tuple
        (whether it is the MuJoCo world, the boat's parameters, the sail mode, the task's
        target area or None).
    """
    from ..boat.catalogue import get_boat
    from ..physics import BoatPhysics

    physics = env.physics
    mujoco_world = isinstance(physics, BoatPhysics)
    if mujoco_world:
        params, sail_mode = physics.params, physics.sail_mode
    else:
        params, sail_mode = get_boat(boat, **(options.get("boat_options") or {})), "actuated"
    target = None
    if getattr(env.task, "target", None) is not None:
        target = {"position": tuple(env.task.target), "start": getattr(env.task, "start", None),
                  "radii": (env.task.d_target, env.task.d_prearrival)}
    elif getattr(env.task, "half", None) is not None:  # a box or a square: its corners
        from ..tasks.course import lay

        half, center = env.task.half, env.task.center
        square = [(-half, -half), (half, -half), (half, half), (-half, half)]
        corners = lay(square, env.task.wind_from, center)
        target = {"position": tuple(map(float, center)), "start": (0.0, 0.0), "radii": (half, half),
                  "corners": [tuple(map(float, c)) for c in corners]}
    elif getattr(env.task, "marks", None) is not None:  # a course: its marks and its line
        marks = [tuple(map(float, mark)) for mark in env.task.marks]
        target = {"position": marks[0], "start": (0.0, 0.0), "radii": (env.task.radius, env.task.radius),
                  "marks": marks, "line": [tuple(map(float, end)) for end in env.task.finish]}
    return mujoco_world, params, sail_mode, target


def simulated_sea(physics):
    """The sea a simulation feels: its ``waves``, or its options' ``waves``; None without one.

    Parameters
    ----------
    physics : object
        ``env.physics`` of any world.
    """
    waves = getattr(physics, "waves", None)
    if waves is None:
        waves = getattr(getattr(physics, "options", None), "waves", None)
    return waves


def _even(name: str, value: int) -> int:
    value = int(value)
    if value < 16 or value % 2:
        raise ValueError(f"{name} must be an even number of pixels >= 16 (H.264, yuv420p), got {value}")
    return value


def check_arguments(*, camera: str, fps, seconds, width, height, follow_distance,
                    follow_bearing_deg: float | None, quality: float,
                    options: dict) -> tuple[float, int, int]:
    """Refuse bad arguments of :func:`record` before anything is loaded (one-line ``ValueError``).

    Parameters
    ----------
    camera, fps, seconds, width, height, follow_distance, follow_bearing_deg, quality, options
        As :func:`record`.

    Returns
    -------
    tuple
        (fps as a float, width, height).
    """
    if camera not in CAMERAS:
        raise ValueError(f"unknown camera {camera!r}; choose one of {CAMERAS}")
    try:
        fps = float(fps)
    except (TypeError, ValueError):
        raise ValueError(f"fps must be a positive number, got {fps!r}") from None
    if not (math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps must be a positive number, got {fps!r}")
    if seconds is not None and not (math.isfinite(seconds) and seconds > 0):
        raise ValueError(f"seconds must be a positive number of simulated seconds, got {seconds!r}")
    width, height = _even("width", width), _even("height", height)
    if follow_distance is not None and not (math.isfinite(follow_distance) and follow_distance > 0):
        raise ValueError(f"follow_distance (--distance) must be a number > 0 m, got {follow_distance!r}")
    if follow_bearing_deg is not None and not math.isfinite(follow_bearing_deg):
        raise ValueError(f"follow_bearing_deg (--bearing) must be a finite angle in degrees, "
                         f"got {follow_bearing_deg!r}")
    for key, option in (("time_limit", "seconds (--seconds)"), ("seed", "seed (--seed)")):
        if key in options:
            raise ValueError(f"{key} is set by the argument {option}, not as an environment option")
    if not 1 <= quality <= 10:
        raise ValueError(f"quality must be between 1 and 10, got {quality!r}")
    return fps, width, height


def _load_run(boat: str, task: str, world: str, controller, seed: int, seconds, controller_options,
              options: dict, waves=None):
    """(env, policy, controller name, duration in s) of the run, the policy reset with ``seed``;
    ``waves`` is given to the physics where it takes a sea."""
    from ..options import PHYSICS_FIELDS
    from ..suite import load

    if waves is not None and "waves" in PHYSICS_FIELDS:
        options = {**options, "waves": waves}
    from ..sweep import make_controller

    env = load(boat, task, world, seed=seed, time_limit=seconds, **options)
    if isinstance(controller, str):
        name = controller
        policy = make_controller(controller, env, **(controller_options or {}))
    else:
        name = getattr(controller, "__name__", type(controller).__name__)
        policy = controller(env)
    if hasattr(policy, "reset"):
        policy.reset(seed)
    return env, policy, name, float(seconds) if seconds is not None else float(env.task.duration)


def _open_scene(renderer: ChildRenderer, boat: str, task: str, world: str, name: str, env, options: dict,
                waves, **kwargs) -> bool:
    """Open the run's scene in ``renderer``: its boat, target, labels and sea (``waves``, else the
    simulation's); ``kwargs`` its size and camera. Returns whether it is the MuJoCo world."""
    from ..options import wave_config

    mujoco_world, params, sail_mode, target = scene_of(boat, env, options)
    sea = wave_config(waves) if waves is not None else simulated_sea(env.physics)
    renderer.open(params, sail_mode=sail_mode, target=target, waves=sea,
                  labels=f"{boat_label(boat)} · {task} · {name} ({world})", **kwargs)
    return mujoco_world


def _sail(env, policy, name: str, frames: FrameWriter, mujoco_world: bool,
          log=None) -> tuple[float, ControllerFailed | None]:
    """Run the episode, drawing each frame when due (and each control step into ``log``, a
    rollout's ``record``, where given); returns the wall time of the first frame, and the
    controller's failure that ended it early (or None)."""
    physics = env.physics
    shape = env.action_spec().shape
    timestep = env.reset()
    step = 0
    if log is not None:
        log(step, timestep, None)
    start_loop = time.perf_counter()

    def now() -> Snapshot:  # the true boat now; the instruments' readings held since the control step
        snap = snapshot_physics(physics, env.task.references(physics))
        snap.measured = measured_of(env.task.last_observation)
        return snap

    def at_control_step() -> Snapshot:  # a paper world: the true state at the control step
        snap = snapshot_observation(env.task.last_true_observation)
        snap.measured = measured_of(timestep.observation)
        return snap

    frames.emit(now() if mujoco_world else at_control_step())
    hook = (frames_between_substeps(physics, lambda: frames.emit(now()), frames.due)
            if mujoco_world else nullcontext())
    with hook:
        while not timestep.last():
            try:
                action = act(policy, timestep, controller=name, time=float(physics.time()), shape=shape)
            except ControllerFailed as failure:
                return start_loop, failure
            timestep = env.step(action)
            step += 1
            if log is not None:
                log(step, timestep, action)
            if not mujoco_world:  # sample and hold at the control steps
                snap = at_control_step()
                while (t := frames.due()) is not None and snap.time >= t - 1e-9:
                    frames.emit(snap)
    return start_loop, None


def _finish(env, frames: FrameWriter, still, failure: ControllerFailed | None) -> dict:
    """The task's metrics (none after a controller's failure); a run that stopped early, or
    whose controller failed, ends with its last frame, marked, for 1 s."""
    metrics = {} if failure is not None else env.task.metrics()
    final = frames.last[1]
    note = failure.note if failure is not None else None
    if metrics.get("stopped"):
        note = f"stopped at t = {frames.last[0].time:.1f} s: {metrics['stopped']}"
    if note:
        final = frames.renderer.render(frames.last[0], note=note)
        frames.hold(final, max(1, round(frames.fps)))
    if still is not None:
        from PIL import Image

        Path(still).parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(final).save(still, optimize=True)
    return metrics


def record(boat: str, task: str, controller, out_path, seconds: float | None = None,
           world: str = "mujoco", fps: float = 25, width: int = 640, height: int = 480,
           camera: str = "follow", overlay: bool = True, forces: bool = True, seed: int = 0, *,
           controller_options: dict | None = None, still=None, quality: float = 6.0,
           progress: bool = False, follow_distance: float | None = None,
           follow_bearing_deg: float | None = None, follow_elevation_deg: float = ELEVATION_DEG,
           follow_lag: float = 3.0, top_center=None, top_extent: float | None = None,
           waves=None, log=None, **options) -> Recording:
    """Run ``task`` on ``boat`` under ``controller`` and write the video to ``out_path`` (mp4).

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`. In a paper world the drawn boat is ``boat``.
    controller : str or callable
        A registered controller name (:func:`sailmujoco.sweep.make_controller`, with
        ``controller_options``) or a factory ``factory(env) -> controller``.
    out_path : path
        The mp4 (H.264, yuv420p); written to a temporary name and renamed when complete.
    seconds : float, optional
        Simulated time (default: the task's duration); ``round(seconds * fps)`` frames.
    fps : float
        Frames per simulated second, independent of the control rate.
    width, height : int
        Frame size, even pixels.
    camera : {"follow", "top", "side"}
        See :mod:`sailmujoco.video`.
    overlay, forces : bool
        The panel beside the scene (map and numbers); sail/keel/rudder force arrows.
    seed : int
        Seeds the task (initial state, wind) and the controller.
    controller_options : dict, optional
        Keywords of a named controller's factory.
    still : path, optional
        Also write the last frame as a PNG.
    quality : float
        imageio-ffmpeg quality, 1-10 (6: x264 CRF 20).
    progress : bool
        Progress over frames on stderr: a bar on a terminal, a plain line per tenth elsewhere.
    follow_distance, follow_bearing_deg, follow_elevation_deg, follow_lag, top_center, top_extent
        Camera settings, see :class:`~sailmujoco.video.SceneRenderer`.
    waves : WaveConfig or mapping, optional
        The sea drawn (:mod:`sailmujoco.video.sea`; a mapping as :func:`~sailmujoco.options.wave_config`
        reads it), given to :func:`sailmujoco.suite.load` too. None: the simulation's own, or none.
    log : path, optional
        Also the run as an MCAP log of ROS 2 messages (:class:`sailmujoco.ros2.record.McapLog`).
    **options
        Passed to :func:`sailmujoco.suite.load`: environment options (``hydrostatics``,
        ``dofs``, ``control_timestep``, ``boat_options`` ...) and task options (``case=3``...).

    Returns
    -------
    Recording
        Path, frame count, simulated and wall time, and the task's metrics.

    Raises
    ------
    RenderingUnavailable
        No OpenGL platform (the message names the fix: ``MUJOCO_GL=egl`` or OSMesa).
    ControllerFailed
        The controller raised, or gave an action that is not two finite numbers: the video (and
        the still) end at that state and are kept (the exception's ``kept``: the Recording).
    """
    fps, width, height = check_arguments(
        camera=camera, fps=fps, seconds=seconds, width=width, height=height, follow_distance=follow_distance,
        follow_bearing_deg=follow_bearing_deg, quality=quality, options=options)
    encoder()
    start_wall = time.perf_counter()
    with ChildRenderer() as renderer:  # fails here, before anything is loaded, where nothing can render
        env, policy, name, duration = _load_run(boat, task, world, controller, seed, seconds,
                                                controller_options, options, waves)
        mujoco_world = _open_scene(
            renderer, boat, task, world, name, env, options, waves, width=width, height=height,
            camera=camera, forces=forces, overlay=overlay, follow_distance=follow_distance,
            follow_bearing_deg=follow_bearing_deg, follow_elevation_deg=follow_elevation_deg,
            follow_lag=follow_lag, top_center=top_center, top_extent=top_extent)
        with (McapLog(env, log) if log is not None else nullcontext()) as logger:
            return _film(env, policy, name, renderer, Path(out_path), mujoco_world=mujoco_world, fps=fps,
                         n_frames=max(1, round(duration * fps)), quality=quality, progress=progress,
                         still=still, start_wall=start_wall, log=logger)


def _film(env, policy, name: str, renderer: ChildRenderer, out_path: Path, *, mujoco_world: bool, fps: float,
          n_frames: int, quality: float, progress: bool, still, start_wall: float, log=None) -> Recording:
    """Run the episode into ``out_path`` (written under a hidden name, renamed when complete);
    its :class:`Recording`. A controller's failure ends the video there; the video is kept and
    the failure raised, its ``kept`` the Recording."""
    with partial_file(out_path) as partial:
        frames = FrameWriter(renderer, partial, fps, n_frames, quality, progress)
        try:
            start_loop, failure = _sail(env, policy, name, frames, mujoco_world, log)
            metrics = _finish(env, frames, still, failure)
        finally:
            frames.close()
    end = time.perf_counter()  # the encoder has finished
    recording = Recording(path=out_path, frames=frames.count, fps=fps, sim_time=float(env.physics.time()),
                          wall_time=end - start_wall, loop_time=end - start_loop, metrics=metrics)
    if failure is not None:
        failure.kept = recording
        raise failure
    return recording


def record_study_scenario(out, boat: str, task: str, controller, *, seconds: float = 60.0,
                          name: str | None = None, **kwargs) -> Recording:
    """The video a study writes for its ``--video`` option: ``<out>/<name>.mp4``.

    A thin wrapper over :func:`record`. In a study::

        if video:
            from sailmujoco.video import record_study_scenario
            record_study_scenario(out, "wille_yacht", "beam_reach_roll", "wille_roll", seconds=60)

    Raises :class:`~sailmujoco.video.RenderingUnavailable` where no OpenGL platform loads.

    Parameters
    ----------
    out : path
        The study's results folder.
    boat, task : str
        As :func:`record`.
    controller : str or callable
        As :func:`record`.
    seconds : float
        Simulated time (s).
    name : str, optional
        The file's stem; default ``<boat>_<task>_<controller>``.
    **kwargs
        Passed to :func:`record` (``world``, ``camera``, task options...).
    """
    label = controller if isinstance(controller, str) else getattr(controller, "__name__", "controller")
    path = Path(out) / f"{name or f'{boat_label(boat)}_{task}_{label}'}.mp4"
    return record(boat, task, controller, path, seconds=seconds, **kwargs)
