"""A Gymnasium adapter over the suite's dm_env environments (the same environments, not a copy).

    import gymnasium
    import sailmujoco.gym  # registers the ids below

    env = gymnasium.make("sailmujoco/WilleYacht-HeadingHold-v0")
    observation, info = env.reset(seed=0)
    observation, reward, terminated, truncated, info = env.step(env.action_space.sample())

Ids
    ``sailmujoco/<Boat>-<Task>-v0`` for every boat and task of :mod:`sailmujoco.suite`, the
    suite's snake_case names in CamelCase: ``wille_yacht`` -> ``WilleYacht``, ``beam_reach_roll``
    -> ``BeamReachRoll``; :func:`gym_ids` lists them. Importing ``sailmujoco.gym`` registers them;
    without that import, ``gymnasium.make("sailmujoco.gym:sailmujoco/WilleYacht-HeadingHold-v0")``
    imports it first (Gymnasium 1.x has no plugin entry points). Keyword arguments of
    ``gymnasium.make`` go to :class:`SailGymEnv` (``normalize_action``, ``include_true_state``,
    ``area``, ``render_mode``, ``render_width``, ``render_height``, ``camera``) and the rest to
    ``suite.load``: ``world="paper"``, ``seed``, ``time_limit``, ``control_timestep``, the
    physics options (``physics=``, a :class:`sailmujoco.options.PhysicsOptions` or dict, or
    field by field: ``sail_mode``, ``hydrostatics``, ...) and the task's options.
    ``SailGymEnv(boat, task, ...)`` builds the same environment without the registry.

Episodes
    Gymnasium's contract: ``reset`` first, and again after an episode ended. ``step`` before
    ``reset``, or after ``terminated`` or ``truncated``, raises ``gymnasium.error.ResetNeeded``.
    ``terminated``: the episode ended early, because the simulation stopped (capsize,
    non-finite state), the boat left the sailing area (``|x|`` or ``|y|`` > ``area``, default
    5000 m around the origin) or a quantity left its bound in the table below (the envelope);
    ``truncated``: the task's time limit came. ``info["reward_terms"]`` holds the reward's
    named terms (the reward is their sum) and, at the end, ``info["metrics"]`` the task's
    metrics, ``"stopped"`` naming why an early end came. Each id's ``max_episode_steps`` is
    the task's duration over the control step of 0.1 s (600 for ``heading_hold`` and
    ``speed_trial``, 2000 for ``course_hold`` and ``position_keeping``, 3000 for
    ``beam_reach_roll``): ``gymnasium.make`` truncates there too, so with a longer
    ``time_limit`` or a shorter ``control_timestep`` give ``max_episode_steps`` to
    ``gymnasium.make`` as well.

Reward
    The task's reward (:mod:`sailmujoco.tasks.sailing`, :mod:`sailmujoco.tasks.position`),
    whose terms are each task's, and which makes ending early never pay: a step that ends the
    episode early earns the single term ``stopped`` = ``steps * (floor - 1)``, with ``steps``
    that step and those the episode had left and ``floor`` the least reward a running step
    can earn (:meth:`sailmujoco.tasks.base.SailTask.reward_floor`):

    ================  ===============================================  =======
    task              terms of a running step                          floor
    ================  ===============================================  =======
    heading_hold      heading -(e/pi)^2, rudder -0.01 (sigma/0.6)^2    -1.274
    course_hold       course -(e/pi)^2                                 -1
    beam_reach_roll   speed max(u, -U10)/U10, heel -(phi/10 deg)^2     -82
    speed_trial       speed abs(v)/U10                                 0
    position_keeping  distance -min(d, 100 d_T)/d_T                    -100
    ================  ===============================================  =======

    Sailing on earns at least ``floor`` a step, so any way of sailing on is worth more than
    stopping, by at least one per step left: capsizing or leaving the area is never a way out
    of a bad episode.

Observations
    A flat ``gymnasium.spaces.Dict`` of 1-D float32 ``Box`` es, a scalar as shape ``(1,)``,
    every bound finite and each for the reason given: the layout that Stable-Baselines3's
    ``check_env`` and ``MultiInputPolicy`` take as it is (no 0-d arrays, no nested Dict), and
    that ``gymnasium.utils.env_checker.check_env`` passes silently. A state outside the
    bounds ends the episode (``terminated``), and its last observation is clipped onto them:

    ===============================  =====  ===============  ==========================================
    key                              unit   bounds           why
    ===============================  =====  ===============  ==========================================
    position                         m      [-area, area]    the sailing area (world x east, y north)
    velocity                         m/s    [-50, 50]        over ground, east and north; above the
                                                             sailing speed record (33.7 m/s)
    heading                          rad    [-pi, pi]        compass, wrapped
    heel                             rad    [-pi, pi]        an Euler angle; beyond 90 deg is a capsize
    roll_rate, yaw_rate              rad/s  [-25, 25]        four turns a second
    apparent_wind_angle              rad    [-pi, pi]        wrapped
    apparent_wind_speed              m/s    [0, 340]         the speed of sound: the force models are
                                                             incompressible
    desired_heading, desired_course  rad    [-pi, pi]        the task's reference, wrapped
    target_position                  m      [-area, area]    the sailing area
    last_mark, next_mark             m      [-area, area]    a course's leg (its marks)
    box_center                       m      [-area, area]    station keeping's box
    box_time_left                    s      [-time, time]    of its five minutes (negative after)
    area_center, area_half           m      [-area, area]    area scanning's square
    ===============================  =====  ===============  ==========================================

    With ``include_true_state=True`` the privileged full state (:mod:`sailmujoco.controllers.base`
    lists it) is added as the keys ``true_state_<key>``: body velocities ``u``, ``v``,
    ``w``, ``u_r``, ``v_r`` and ``current`` in [-50, 50] m/s; ``yaw`` (wrapped) and ``heel``
    in [-pi, pi], ``pitch`` in [-pi/2, pi/2], the joint angles ``rudder`` and ``sail`` in
    [-2 pi, 2 pi] rad (the boats' ranges lie within +-pi; MuJoCo's soft joint limits let an
    angle pass its limit a little); the three rates in
    [-25, 25] rad/s; ``true_wind`` and ``apparent_wind_ce`` in [-340, 340] m/s;
    ``wind_speed_10`` in [0, 100] m/s (the wind's accepted range,
    :data:`sailmujoco.forces.wind.MAX_SPEED`); ``wind_direction`` in [-pi, pi]; ``time`` in
    [0, time limit + one step] s; the six force wrenches ``<term>_wrench`` (N, N m) within
    ``rho_w (50 m/s)^2 L^2`` for a force and that times ``L`` for a moment, ``L`` the hull's
    length (:func:`sailmujoco.gym.spaces.wrench_bound` gives the reason). It is left out by
    default: an agent that reads the force wrenches and the true wind sees more than a
    boat's sensors do. ``FlattenObservation`` gives 10 numbers plus the task's references
    without it (69 with it for heading_hold).

Actions
    ``Box(-1, 1, (2,), float32)``: [rudder, sail], or with ``sail_mode="sheeted"`` [rudder,
    sheet]. Each component ``a`` is clipped to [-1, 1] and mapped linearly onto its
    actuator's range [low, high] (the dm_env action spec: the boat's rudder and sail limits in
    rad, the sheet's length range in m)::

        command = low + (a + 1) / 2 * (high - low)

    so -1 gives the minimum (full rudder to starboard, the sail or sheet at its minimum), +1
    the maximum, 0 the middle (zero rudder, zero sail angle). ``normalize_action=False``
    takes the actuators' own units and ranges instead (then ``check_env`` warns that the box
    is not normalised).

Rendering
    ``render_mode="rgb_array"``: :meth:`SailGymEnv.render` returns the frame of the videos'
    renderer (:mod:`sailmujoco.video`: the boat, the wind and force arrows, the text box),
    ``render_width`` x ``render_height`` pixels, from ``camera``, offscreen (EGL, or the
    platform ``MUJOCO_GL`` names; Mesa's EGL renders on the CPU), drawn in a child process
    started at the first frame and ended by :meth:`SailGymEnv.close`
    (:class:`sailmujoco.video.ChildRenderer`: the GL driver, and the LLVM that Mesa's brings
    and that would crash PyTorch's triton, stay out of this process);
    ``metadata["render_fps"]`` is one frame per control step, so
    ``gymnasium.wrappers.RecordVideo`` writes a real-time video (it needs the ``moviepy``
    package). ``render_mode="human"``: every step is drawn in MuJoCo's viewer
    (:mod:`sailmujoco.viewer.view`'s window) at real time; without a display the constructor raises
    :class:`sailmujoco.viewer.window.NoDisplay` in one line.

Vector environments
    ``gymnasium.make_vec(id, num_envs, vectorization_mode="vector_entry_point")`` builds a
    :class:`SailVectorEnv`: the environments step together, in the MuJoCo world in one
    compiled call, with the same spaces, rewards and envelope, Gymnasium's "next step"
    autoreset and its vector ``info`` convention (an array per key and a ``_key`` mask).

dm_control
    ``suite.load(..., flat_observation=True)`` gives dm_control's flat observation, and
    ``dm_control.rl.control.flatten_observation`` flattens the suite's observation (its
    ``true_state`` is a :class:`sailmujoco.measurement.observation.TrueState`); ``include_true_state=False``
    leaves it out there as here.
"""

from __future__ import annotations

import gymnasium

from .. import suite
from .env import SailGymEnv
from .vector import SailVectorEnv

__all__ = ["NAMESPACE", "VERSION", "SailGymEnv", "SailVectorEnv", "gym_id", "gym_ids",
           "max_episode_steps", "register_all"]

NAMESPACE = "sailmujoco"
VERSION = 0
CONTROL_TIMESTEP = 0.1  # s, suite.load's default control step


def _camel(name: str) -> str:
    return "".join(part.capitalize() for part in name.split("_"))


def gym_id(boat: str, task: str) -> str:
    """The registered id of ``suite.load(boat, task)``, e.g. "sailmujoco/WilleYacht-HeadingHold-v0".

    Parameters
    ----------
    boat : str
        A registered boat.
    task : str
        A registered task.
    """
    return f"{NAMESPACE}/{_camel(boat)}-{_camel(task)}-v{VERSION}"


def gym_ids() -> list[str]:
    """Every registered id: one per boat and task of the suite (the world is an option)."""
    return [gym_id(boat, task) for boat, task in _pairs()]


def _pairs():
    seen = []
    for boat, task, _world in suite.SUITE:
        if (boat, task) not in seen:
            seen.append((boat, task))
    return seen


def max_episode_steps(task: str) -> int:
    """Control steps of an episode of ``task`` at its default length and control step (the
    ``max_episode_steps`` of its ids).

    Parameters
    ----------
    task : str
        A registered task.
    """
    return round(suite.TASKS[task].duration / CONTROL_TIMESTEP)


def register_all() -> None:
    """Register :func:`gym_ids` with Gymnasium (done on import; calling again changes nothing)."""
    for boat, task in _pairs():
        env_id = gym_id(boat, task)
        if env_id not in gymnasium.registry:
            gymnasium.register(id=env_id, entry_point="sailmujoco.gym:SailGymEnv",
                               vector_entry_point="sailmujoco.gym:SailVectorEnv",
                               max_episode_steps=max_episode_steps(task),
                               kwargs={"boat": boat, "task": task})


register_all()
