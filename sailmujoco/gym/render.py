"""Rendering for the Gymnasium adapter: ``"rgb_array"`` frames from the video renderer
(:class:`sailmujoco.video.SceneRenderer`, offscreen, in a child process), ``"human"`` in
MuJoCo's passive viewer (:class:`sailmujoco.viewer.window.Window`, the window of
``sailmujoco view``, in this process).
"""

from __future__ import annotations

import os
import time

import numpy as np

RENDER_MODES = ("rgb_array", "human")


def declared_modes() -> list[str]:
    """The render modes an environment declares here: "rgb_array", and "human" where a display
    is named (``DISPLAY`` or ``WAYLAND_DISPLAY``), so that ``check_env``, which opens every
    declared mode, runs on a machine without one."""
    shown = bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    return list(RENDER_MODES) if shown else ["rgb_array"]


def _scene_args(boat, dm_env, options: dict) -> tuple:
    from ..video import scene_of

    name = boat if isinstance(boat, str) else boat.name
    return scene_of(name, dm_env, options)


def _snapshot(dm_env, mujoco_world: bool):
    from ..video import snapshot_observation, snapshot_physics

    if mujoco_world:
        return snapshot_physics(dm_env.physics)
    measured = dm_env.task.last_observation
    if measured is None:
        raise RuntimeError("render() needs reset() first")
    return snapshot_observation(measured)


class FrameRenderer:
    """``render_mode="rgb_array"``: one RGB frame of the environment's state, drawn by the video
    renderer in a child process (:class:`sailmujoco.video.child.ChildRenderer`: this process
    loads no OpenGL library), started at the first frame and ended by :meth:`close`.

    Parameters
    ----------
    width, height : int
        Frame size, pixels (>= 16 each).
    camera : str
        One of :data:`sailmujoco.video.CAMERAS`.
    labels : str
        First line of the frame's text box.
    """

    def __init__(self, width: int, height: int, camera: str, labels: str):
        self.width, self.height, self.camera, self.labels = width, height, camera, labels
        self._child = None
        self._key = None

    def _renderer(self, boat, dm_env, options):
        from ..video.child import ChildRenderer

        mujoco_world, params, sail_mode, target = _scene_args(boat, dm_env, options)
        key = (params, sail_mode, repr(target))
        if self._child is None:
            self._child = ChildRenderer()
        if key != self._key:  # a new boat only: the GL context is costly
            self._key = None
            self._child.open(params, self.width, self.height, self.camera, sail_mode=sail_mode,
                             target=target, labels=self.labels)
            self._key = key
        return mujoco_world

    def render(self, boat, dm_env, options: dict) -> np.ndarray:
        """The frame (height, width, 3) uint8 of ``dm_env``'s current state.

        Parameters
        ----------
        boat : str or BoatParams
            The boat as loaded.
        dm_env : SailEnvironment
            The environment drawn.
        options : dict
            Its ``suite.load`` keywords (``boat_options`` for a paper world's boat).
        """
        mujoco_world = self._renderer(boat, dm_env, options)
        return self._child.render(_snapshot(dm_env, mujoco_world))

    def close(self) -> None:
        """End the child process and its GL context."""
        if self._child is not None:
            self._child.close()
            self._child = None
            self._key = None


class WindowRenderer:
    """``render_mode="human"``: MuJoCo's passive viewer, redrawn each step at ``fps`` frames a
    second of wall time (the simulation waits for it).

    Parameters
    ----------
    fps : float
        Frames (control steps) per second of wall time.
    labels : str
        First line of the text.

    Raises
    ------
    sailmujoco.viewer.window.NoDisplay
        No window can be opened here (no display, or no OpenGL context on it), in one line.
    """

    def __init__(self, fps: float, labels: str):
        from ..viewer.window import NoDisplay, open_display

        try:
            open_display()
        except NoDisplay as err:
            raise NoDisplay(f"render_mode='human' needs a display: {err}; render_mode='rgb_array' "
                            f"renders offscreen (gymnasium.wrappers.RecordVideo)") from None
        self.fps, self.labels = fps, labels
        self._window = None
        self._scene = None
        self._last = None

    def show(self, boat, dm_env, options: dict) -> None:
        """Draw ``dm_env``'s current state in the window (opened on the first call).

        Parameters
        ----------
        boat : str or BoatParams
            The boat as loaded.
        dm_env : SailEnvironment
            The environment drawn.
        options : dict
            Its ``suite.load`` keywords.
        """
        from ..video import SceneRenderer
        from ..viewer.window import Window

        mujoco_world, params, sail_mode, target = _scene_args(boat, dm_env, options)
        snap = _snapshot(dm_env, mujoco_world)
        if self._window is None:
            self._scene = SceneRenderer(params, sail_mode=sail_mode, target=target,
                                        labels=self.labels, offscreen=False)
            self._window = Window(self._scene, snap, lambda key: None, forces=True, overlay=True)
        self._window.show(snap)
        if self._last is not None:
            time.sleep(max(0.0, self._last + 1.0 / self.fps - time.perf_counter()))
        self._last = time.perf_counter()

    def close(self) -> None:
        """Close the window."""
        if self._window is not None:
            self._window.close()
            self._window = None
