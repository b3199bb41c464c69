"""MuJoCo's interactive viewer on the display model of the videos: opening it, and drawing the
boat, its arrows and its text there (``sailmujoco view``).

Without a display (no ``DISPLAY``, or GLFW cannot open a window with an OpenGL context)
:func:`open_display` raises :class:`NoDisplay` before anything is loaded.
"""

from __future__ import annotations

import os
import threading

import numpy as np

from ..video import SceneRenderer, Snapshot
from .screenshot import render_state, save_frame

ASCII = {"°": " deg", "·": "-", "→": "->"}  # MuJoCo's overlay font is ASCII only


class NoDisplay(RuntimeError):
    """No window can be opened here (no display, or no OpenGL context on it)."""


def open_display() -> None:
    """Check that GLFW can open a window with an OpenGL context here; else :class:`NoDisplay`."""
    if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        raise NoDisplay("no display (DISPLAY is not set)")
    try:
        import glfw
        import mujoco.viewer  # noqa: F401  (it needs GLFW's library)
    except Exception as err:  # ImportError, RuntimeError: GLFW's library is missing
        raise NoDisplay(f"GLFW cannot load ({type(err).__name__}: {err})") from None
    reporting = glfw.ERROR_REPORTING
    glfw.ERROR_REPORTING = "raise"
    try:
        if not glfw.init():
            raise NoDisplay("GLFW could not initialise")
        glfw.window_hint(glfw.VISIBLE, glfw.FALSE)
        window = glfw.create_window(16, 16, "sailmujoco probe", None, None)
        if not window:
            raise NoDisplay("GLFW could not open a window with an OpenGL context")
        glfw.destroy_window(window)
        glfw.default_window_hints()
    except glfw.GLFWError as err:  # its message: "(code) b'description'"
        text = str(err)
        raise NoDisplay("GLFW: " + text[text.find("b'") + 2:-1] if "b'" in text else text) from None
    finally:
        glfw.ERROR_REPORTING = reporting


class LatestTexts:
    """Hands the overlay text to the viewer from a thread of its own: the viewer's ``set_texts``
    waits for its next drawn frame, which would pace the simulation to the drawing rate.

    Parameters
    ----------
    viewer : mujoco.viewer.Handle
        The viewer.
    """

    def __init__(self, viewer):
        self._viewer = viewer
        self._texts = None
        self._ready = threading.Condition()
        self._stop = False
        self._thread = threading.Thread(target=self._run, name="sailmujoco-view-texts", daemon=True)
        self._thread.start()

    def put(self, texts) -> None:
        """Hand ``texts`` to the viewer (replacing any not yet handed over).

        Parameters
        ----------
        texts : list of tuple
            As ``viewer.set_texts`` takes them.
        """
        with self._ready:
            self._texts = texts
            self._ready.notify()

    def _run(self) -> None:
        while True:
            with self._ready:
                self._ready.wait_for(lambda: self._stop or self._texts is not None)
                if self._stop:
                    return
                texts, self._texts = self._texts, None
            if self._viewer.is_running():
                self._viewer.set_texts(texts)

    def close(self, timeout: float = 1.0) -> None:
        """Stop the thread.

        Parameters
        ----------
        timeout : float
            Seconds to wait for it.
        """
        with self._ready:
            self._stop = True
            self._ready.notify()
        self._thread.join(timeout)


def _ascii(text: str) -> str:
    for old, new in ASCII.items():
        text = text.replace(old, new)
    return text


class Window:
    """MuJoCo's viewer on the display model: the videos' follow camera, arrows and text.

    Parameters
    ----------
    scene : SceneRenderer
        The display model (without an offscreen context).
    snap : Snapshot
        The first state shown: the camera starts behind it.
    key_callback : callable
        Called with the GLFW code of each key pressed in the window (from the viewer's thread).
    forces, overlay : bool
        Force arrows (and their legend); text.
    """

    def __init__(self, scene: SceneRenderer, snap: Snapshot, key_callback, *, forces: bool, overlay: bool):
        import mujoco
        import mujoco.viewer

        before = set(threading.enumerate())
        self.viewer = viewer = mujoco.viewer.launch_passive(
            scene.model, scene.data, key_callback=key_callback, show_left_ui=False, show_right_ui=False)
        self._threads = set(threading.enumerate()) - before  # the viewer's window and render loop
        self.scene, self.overlay = scene, overlay
        self.legend = ("arrows: " + ", ".join(f"{name} {colour}" for name, colour in
                                              (("sail", "red"), ("keel", "green"), ("rudder", "orange"))
                                              if forces) + (", " if forces else "")
                       + "wind cyan (where it blows to)")
        with viewer.lock():  # the videos' follow camera; it moves with the boat, the mouse turns it
            cam = viewer.cam
            cam.type = mujoco.mjtCamera.mjCAMERA_FREE
            lookat, cam.distance, cam.azimuth, cam.elevation = scene.camera_pose(snap)
            cam.lookat[:] = lookat
            viewer.opt.sitegroup[:] = 0
        self.texts = LatestTexts(viewer)
        self._followed = snap.position.copy()

    def show(self, snap: Snapshot, note: str | None = None) -> None:
        """Pose the boat as ``snap``, move the camera with it, redraw arrows and text.

        Parameters
        ----------
        snap : Snapshot
            The state shown.
        note : str, optional
            An extra last line of text.
        """
        import mujoco

        viewer, scene = self.viewer, self.scene
        with viewer.lock():
            scene.pose(snap)
            if scene.sea is not None:  # the moving surface's new heights, to the window's GPU copy
                viewer.update_hfield(scene.sea.hfield_id)
            viewer.cam.lookat[:2] += snap.position[:2] - self._followed[:2]
            self._followed = snap.position.copy()
            user = viewer.user_scn
            user.ngeom = 0
            scene.decorate(user, snap)
        if self.overlay:
            lines = ([scene.labels] if scene.labels else []) + scene.text_lines(snap)
            if note:
                lines.append(note)
            self.texts.put([(mujoco.mjtFontScale.mjFONTSCALE_150, mujoco.mjtGridPos.mjGRID_TOPLEFT,
                             _ascii("\n".join(lines)), ""),
                            (mujoco.mjtFontScale.mjFONTSCALE_100, mujoco.mjtGridPos.mjGRID_BOTTOMLEFT,
                             self.legend, "")])
        viewer.sync()

    def camera(self) -> tuple[np.ndarray, float, float, float]:
        """(look-at point, distance, azimuth deg, elevation deg) of the viewer's camera now."""
        with self.viewer.lock():
            cam = self.viewer.cam
            return np.array(cam.lookat), float(cam.distance), float(cam.azimuth), float(cam.elevation)

    def save(self, path, snap: Snapshot) -> str:
        """Save the picture of ``snap`` from the viewer's camera, at the window's size, as a PNG
        stamped with its time (:mod:`sailmujoco.viewer.screenshot`); returns what was saved.

        Parameters
        ----------
        path : str or path
            The PNG.
        snap : Snapshot
            The state drawn: the one the window shows last.
        """
        viewport = self.viewer.viewport
        width, height = (viewport.width, viewport.height) if viewport is not None else (1280, 720)
        width, height = max(16, width - width % 2), max(16, height - height % 2)
        camera = self.camera()
        return save_frame(path, render_state(self.scene, snap, camera, width, height), snap.time, camera)

    def close(self) -> None:
        """Stop the text thread and close the window (gone before Python and GLFW shut down)."""
        self.texts.close()
        self.viewer.close()
        for thread in self._threads:
            thread.join(5.0)
